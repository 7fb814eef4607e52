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
