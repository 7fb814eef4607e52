"""pytest set-up of the contact4foam tests (see harness.py).

The controller gives the session a token before the xdist workers start
(they inherit it): a run made earlier, in another session, is never
reused. At the end it counts the check lines the tests wrote
(WORK/checks.log, one PASS/FAIL line per check)."""
import glob
import os
import time

import harness


def _controller(config):
    return not hasattr(config, "workerinput")


def pytest_configure(config):
    if _controller(config):
        os.environ["C4F_TEST_SESSION"] = "%d-%d" % (time.time() * 1e6, os.getpid())
        os.makedirs(harness.WORK, exist_ok=True)
        for f in glob.glob(os.path.join(harness.WORK, ".checks", "*.log")):
            os.remove(f)


def pytest_terminal_summary(terminalreporter, config):
    if not _controller(config):
        return
    lines = []
    for f in sorted(glob.glob(os.path.join(harness.WORK, ".checks", "*.log"))):
        with open(f) as fh:
            lines += fh.read().splitlines()
    if not lines:
        return
    path = os.path.join(harness.WORK, "checks.log")
    with open(path, "w") as f:
        f.write("\n".join(sorted(lines, key=lambda x: x.split()[1])) + "\n")
    npass = sum(1 for x in lines if x.startswith("PASS"))
    terminalreporter.write_line("checks: %d passed, %d failed (one line each in %s)"
                                % (npass, len(lines) - npass, path))


def _group(item):
    mark = item.get_closest_marker("xdist_group")
    return mark.args[0] if mark and mark.args else item.nodeid


def pytest_collection_modifyitems(config, items):
    """The longest groups first, so that --dist loadgroup hands them out
    before the short tests and no worker is left alone with a long group
    at the end: by the durations of the last full session where there are
    some (pytest's cache), else the groups with a decomposed run first
    (mpirun, decomposePar, reconstructPar), the 3D one (hertzSphere) before
    them. Otherwise the collection order (the sort is stable)."""
    durations = config.cache.get("c4f/durations", {}) if config.cache else {}
    cost = {}
    for i in items:
        if durations:
            c = durations.get(i.nodeid.split("@")[0], 0.0)
        else:
            name = i.name.lower()
            c = (1.0 if "parallel" in name else 0.0) + (1.0 if "sphere" in name else 0.0)
        cost[_group(i)] = cost.get(_group(i), 0.0) + c
    items.sort(key=lambda i: -cost[_group(i)])


def pytest_runtest_logreport(report):
    if report.when == "call":
        _durations[report.nodeid.split("@")[0]] = report.duration


_durations = {}


def pytest_sessionfinish(session):
    """Keep the durations of a session that ran every test (controller)."""
    config = session.config
    if (_controller(config) and config.cache and session.testscollected
            and len(_durations) == session.testscollected and not config.option.keyword):
        config.cache.set("c4f/durations", _durations)
