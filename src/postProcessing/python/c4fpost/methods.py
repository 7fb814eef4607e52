"""The contact methods and what each is like, read from the solver.

`solidContactFoam -listMethods` prints the run-time selection table, one
method per line with its traits (contactMethodTraits.H):

    penalty answer=penalty openStart=no slip=yes multipliers=none finiteStrain=no coeffs=penaltyScale:10,...

This module is the only place the tutorials' validation scripts, the tests
and the benchmarks learn which methods exist and how to check them; none
of them keeps a list of its own, so a new method is picked up by all.

    answer       what a contact patch test gives: exact (the exact uniform
                 stress), penalty (a spring eps = penaltyScale K/h in
                 series), constitutive (the law p = cN (-g)^n in series),
                 barrier (the clamped log barrier in series, the gap open)
    open_start   the bodies must start apart (a case opens its own gap)
    slip         Coulomb slip is allowed
    multipliers  none, augmented (Uzawa towards the exact constraint) or
                 regularised (perturbed Lagrange)
    coeffs       the defaults of <method>Coeffs, entry -> text
"""
import functools
import os
import re
import subprocess
from collections import namedtuple

from c4fpost import foamio

Method = namedtuple("Method", "name answer open_start slip multipliers finite_strain coeffs")


def parse(text):
    """Methods from -listMethods' output, by name (in its order)."""
    table = {}
    for line in text.splitlines():
        words = line.split()
        if not words:
            continue
        name, tokens = words[0], dict(w.split("=", 1) for w in words[1:])
        coeffs = {}
        if tokens.get("coeffs", "-") != "-":
            for pair in tokens["coeffs"].split(","):
                key, value = pair.split(":", 1)
                coeffs[key] = value
        table[name] = Method(
            name=name,
            answer=tokens["answer"],
            open_start=tokens["openStart"] == "yes",
            slip=tokens["slip"] == "yes",
            multipliers=tokens["multipliers"],
            finite_strain=tokens.get("finiteStrain") == "yes",
            coeffs=coeffs)
    return table


@functools.lru_cache(maxsize=None)
def table():
    """Every method of the solver's table: name -> Method."""
    p = subprocess.run(["solidContactFoam", "-listMethods"], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, stdin=subprocess.DEVNULL)
    if p.returncode:
        raise RuntimeError("solidContactFoam -listMethods failed:\n" + p.stdout)
    return parse(p.stdout)


def names():
    """The method names, sorted as the solver prints them."""
    return list(table())


def get(method):
    """The Method of `method` (KeyError naming the valid ones)."""
    t = table()
    if method not in t:
        raise KeyError("unknown contact method %s (solidContactFoam -listMethods: %s)"
                       % (method, " ".join(t)))
    return t[method]


def _case_coeffs(case, method):
    """The text of the first <method>Coeffs in the case's 0/D (where a
    case sets the slave's coefficients), None where it gives none."""
    text = foamio.strip(open(os.path.join(case, "0", "D")).read())
    try:
        return foamio.sub_dict(text, method + "Coeffs")
    except KeyError:
        return None


def coeff(case, method, entry):
    """A scalar coefficient of `method` in `case`: its <method>Coeffs entry
    in 0/D where the case gives one, else the class's default."""
    return float(coeff_text(case, method, entry))


def coeff_text(case, method, entry):
    """A coefficient of `method` in `case` as its text (a word such as
    multiplierUpdate's): the <method>Coeffs entry in 0/D where the case
    gives one, else the class's default."""
    sub = _case_coeffs(case, method)
    if sub is not None:
        try:
            return foamio.entry(sub, entry)
        except KeyError:
            pass
    defaults = get(method).coeffs
    if entry not in defaults:
        raise KeyError("%s has no entry %s in %s/0/D and no default"
                       % (method, entry, case))
    return defaults[entry]


def set_coeff(case, method, entry, value):
    """Set `entry value;` of <method>Coeffs in the case's 0/D (the
    slave's; the writing twin of coeff): in the dictionary where the case
    has one (the entry replaced, or added), else a new dictionary after the
    `method <name>;` line (the coefficients the case does not give are the
    class's defaults)."""
    d = os.path.join(case, "0/D")
    text = open(d).read()
    m = re.search(r"^\s*%sCoeffs\s*\{" % re.escape(method), text, flags=re.M)
    if m:
        end = text.index("}", m.end())
        body = text[m.end():end]
        body, n = re.subn(r"^(\s*%s\s+)[^;\s]+;" % re.escape(entry), r"\g<1>%s;" % value,
                          body, count=1, flags=re.M)
        if n == 0:
            body = " %s %s;%s" % (entry, value, body)
        text = text[:m.end()] + body + text[end:]
    else:
        text, n = re.subn(r"^(\s*method\s+\w+;)",
                          r"\1 %sCoeffs { %s %s; }" % (method, entry, value),
                          text, count=1, flags=re.M)
        if n != 1:
            raise RuntimeError("no 'method <name>;' in " + d)
    open(d, "w").write(text)
