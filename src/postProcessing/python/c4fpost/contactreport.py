"""Reader of the contactReport function object's files,
postProcessing/contactReport/<startTime>/<slavePatch>.dat."""
import os

COLUMNS = ["time", "normalForce", "tangentialForce", "contactArea",
           "maxPressure", "maxPenetration", "activeFaces", "outerCorrectors",
           "converged", "multiplierUpdates", "minGap", "forceX", "forceY",
           "forceZ"]


def _start_time_key(name):
    try:
        return float(name)
    except ValueError:
        return -1.0


def _records(case, filename, key):
    """(column names, values) of every data line of the report file
    `filename` in each start-time directory, in time order (a restart's
    lines after the run's it continues); the names come from the last '#'
    header line that holds the column `key`, None before one."""
    base = os.path.join(case, "postProcessing", "contactReport")
    if not os.path.isdir(base):
        return
    for d in sorted(os.listdir(base), key=_start_time_key):
        path = os.path.join(base, d, filename)
        if not os.path.exists(path):
            continue
        names = None
        for line in open(path):
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                words = s.lstrip("#").split()
                if key in words:
                    names = words
                continue
            yield names, s.split()


def rows(case, patch):
    """Every row of the slave patch's report, as dicts keyed by the column
    names of the '#' header (COLUMNS where there is none), in file order,
    the start-time directories in time order (a restart's rows after the
    run's it continues); [] where there is no report."""
    out = []
    for names, values in _records(case, patch + ".dat", "normalForce"):
        row = {}
        for k, v in zip(names or COLUMNS, values):
            try:
                row[k] = float(v)
            except ValueError:
                pass
        out.append(row)
    return out


def last_row(case, patch):
    """The last row of the slave patch's report (rows()), None where there
    is no report."""
    r = rows(case, patch)
    return r[-1] if r else None


def row_at(case, patch, time):
    """The last row of the slave patch's report at `time` (a float), None
    where there is none."""
    r = [x for x in rows(case, patch) if abs(x.get("time", float("nan")) - time)
         <= 1e-9 * max(1.0, abs(time))]
    return r[-1] if r else None


def multipliers(case, patch):
    """The multiplier updates contactReport wrote for a method with stored
    multipliers (<patch>Multipliers.dat): a dict of numpy arrays keyed by
    the column names (time, update, x, y, z, gap, pressure, multiplier),
    one entry per face and update; None where there is no such file."""
    import numpy as np
    names, data = None, []
    for header, values in _records(case, patch + "Multipliers.dat", "multiplier"):
        names = header or names
        data.append([float(v) for v in values])
    if not data or names is None:
        return None
    a = np.array(data)
    return {k: a[:, i] for i, k in enumerate(names)}
