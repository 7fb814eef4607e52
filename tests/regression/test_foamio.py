"""c4fpost.foamio on what a user's case may hold: a field written with
writeFormat binary is refused with what to do (before, every tutorial's
validation script stopped in a UnicodeDecodeError after a good run), and
the same field in ASCII is read; set_poisson_ratio edits every law's nu
and nothing else."""
import os

import pytest

import harness
from c4fpost import foamio

HEADER = """FoamFile
{
    version     2.0;
    format      %s;
    class       volVectorField;
    object      D;
}
dimensions      [0 1 0 0 0 0 0];
"""


def write_field(path, fmt, body):
    with open(path, "wb") as f:
        f.write((HEADER % fmt).encode("ascii") + body)


def test_binary_field_refused_with_what_to_do(tmp_path):
    ck = harness.Checks()
    path = os.path.join(str(tmp_path), "D")
    # Two vectors as OpenFOAM writes them in binary: the count, then the raw
    # doubles between parentheses (bytes that are not UTF-8 among them)
    raw = bytes([0x9b, 0xd4]) + bytes(46)
    write_field(path, "binary", b"internalField nonuniform List<vector> 2(" + raw + b");\n")
    with pytest.raises(ValueError) as e:
        foamio.read_internal(path)
    msg = str(e.value)
    ck.add("foamio/binary_refused",
           all(w in msg for w in ("binary", "writeFormat ascii", "foamFormatConvert", path)),
           note="(message: %s)" % msg)

    write_field(path, "ascii", b"internalField nonuniform List<vector> 2((1 2 3) (4 5 6.5));\n")
    v = foamio.read_internal(path)
    ck.add("foamio/ascii_read", v.shape == (2, 3) and v[1][2] == 6.5, note="(%s)" % v.tolist())
    ck.verify()


MECHANICAL = """materialLaw linearElastic;
// the block: nu = 0.25, so E* = E/(2 (1 - nu^2));
linearElasticCoeffs
{
    E           1e6;
    nu          0.25;
    planeStress yes;
}
"""
ZONED = "zonedCoeffs { a { materialLaw linearElastic; linearElasticCoeffs { E 1; nu 0.3; } } }\n"


def test_set_poisson_ratio_edits_every_law(tmp_path):
    """The case's own law and each material set, inline dictionaries
    included; the comment's "nu = 0.25," stays; planeStress flips only when
    asked."""
    ck = harness.Checks()
    case = str(tmp_path)
    os.makedirs(os.path.join(case, "constant", "materials"))
    mp = os.path.join(case, "constant", "mechanicalProperties")
    ms = os.path.join(case, "constant", "materials", "zoned")
    open(mp, "w").write(MECHANICAL)
    open(ms, "w").write(ZONED)
    n = foamio.set_poisson_ratio(case, 0.49, plane_strain=True)
    text, zoned = open(mp).read(), open(ms).read()
    ck.add("foamio/set_poisson_ratio_count", n == 2, note="(%d entries)" % n)
    ck.add("foamio/set_poisson_ratio_law",
           "nu          0.49;" in text and "planeStress no;" in text)
    ck.add("foamio/set_poisson_ratio_comment_kept",
           "nu = 0.25, so E*" in text)
    ck.add("foamio/set_poisson_ratio_inline", "nu 0.49;" in zoned)
    open(mp, "w").write("materialLaw linearElastic;\n")
    open(ms, "w").write("")
    with pytest.raises(KeyError):
        foamio.set_poisson_ratio(case, 0.3)
    ck.verify()
