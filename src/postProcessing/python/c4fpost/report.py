"""What every validation script ends with: one PASS/FAIL line per check,
the plot, and the checks as JSON for the regression tests (tests/, pytest).

A check is a dict with name, passed, value, reference, error, tolerance
(and optionally units)."""
import argparse
import json
import os


def parse_args(doc, png, options=()):
    """The command line every validation script takes: the case directory,
    --json for the regression runner, --png for the plot's file name; and
    the script's own `options`, (flag, add_argument keywords) pairs."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--json", help="write the checks to this file")
    ap.add_argument("--png", default=png)
    for flag, kwargs in options:
        ap.add_argument(flag, **kwargs)
    return ap.parse_args()


def print_checks(checks):
    for c in checks:
        print("%s %-45s value=%-12.6g ref=%-12.6g err=%-10.4g tol=%.4g"
              % ("PASS" if c["passed"] else "FAIL", c["name"], c["value"],
                 c["reference"], c["error"], c["tolerance"]))


def finish(res, case, png, json_path, plot, complete=True):
    """Print the checks of `res`, call plot(res, path) when png is set and
    the run got far enough to plot (`complete`), write the checks to
    json_path when it is set, and return the script's exit status: 0 when
    the run is complete and every check passed, 1 otherwise."""
    print_checks(res["checks"])
    if png and complete:
        plot(res, os.path.join(case, png))
        print("plot: %s" % os.path.join(case, png))
    if json_path:
        with open(json_path, "w") as f:
            json.dump(res["checks"], f, indent=1)
    return 0 if complete and all(c["passed"] for c in res["checks"]) else 1
