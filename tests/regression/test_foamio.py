"""c4fpost.foamio on what a user's case may hold: a field written with
writeFormat binary is refused with what to do (before, every tutorial's
validation script stopped in a UnicodeDecodeError after a good run), and
the same field in ASCII is read."""
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
