"""Reader of the contactReport function object's files,
postProcessing/contactReport/<startTime>/<slavePatch>.dat."""
import os

COLUMNS = ["time", "normalForce", "tangentialForce", "contactArea",
           "maxPressure", "maxPenetration", "activeFaces", "outerCorrectors",
           "converged"]


def _start_time_key(name):
    try:
        return float(name)
    except ValueError:
        return -1.0


def last_row(case, patch):
    """The last row of the slave patch's report as a dict keyed by the
    column names of the '#' header (COLUMNS where there is none), taking
    the latest start-time directory last; None where there is no report."""
    base = os.path.join(case, "postProcessing", "contactReport")
    if not os.path.isdir(base):
        return None
    names, row = None, None
    for d in sorted(os.listdir(base), key=_start_time_key):
        path = os.path.join(base, d, patch + ".dat")
        if not os.path.exists(path):
            continue
        for line in open(path):
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                words = s.lstrip("#").split()
                if "normalForce" in words:
                    names = words
            else:
                row = s.split()
    if row is None:
        return None
    out = {}
    for k, v in zip(names or COLUMNS, row):
        try:
            out[k] = float(v)
        except ValueError:
            pass
    return out
