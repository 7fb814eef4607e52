"""What the regression tests share: running a tutorial's Allrun on a fresh
copy once per pytest session, the checks a test asserts, and the
comparisons of two runs.

Runs. A tutorial run is expensive and several tests read it (its own
closed-form checks, a restart from it, a parallel run compared with it), so
`once(name, make)` makes it at most once per session, across pytest-xdist
workers: the first test that needs it runs it under a file lock, the others
wait for it and read its result (JSON in WORK/.once). The tests that share
runs carry the same `xdist_group` mark, so `--dist loadgroup` keeps them on
one worker and nobody waits. Work directories go to $C4F_PREFIX/run/tests.

Checks. A test collects its checks in a `Checks` (one line each: name,
value, reference, error, tolerance, as the validation scripts print them)
and ends with `verify()`, which fails with the lines of the failed checks.
Every line also goes to WORK/.checks/<worker>.log; conftest.py counts them
at the end of the session.
"""
import fcntl
import importlib.util
import json
import os
import re
import shutil
import subprocess
import time

import numpy as np
import pytest

from c4fpost import contactreport, foamio, methods

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PREFIX = os.environ.get("C4F_PREFIX", os.path.expanduser("~/.contact4foam"))
WORK = os.path.join(PREFIX, "run", "tests")
SOLVER = "solidContactFoam"


def session():
    """The token of this pytest session (conftest.py sets it before the
    workers start, so they inherit it)."""
    return os.environ.get("C4F_TEST_SESSION", "standalone")


def worker():
    return os.environ.get("PYTEST_XDIST_WORKER", "main")


# --------------------------------------------------------------------------
# Commands and case copies
def _gap(text):
    """A smallest gap the solver printed: "none" where no face was in range."""
    return float("inf") if text == "none" else float(text)


def run(cmd, cwd, env=None, log=None):
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True,
                       stdin=subprocess.DEVNULL)
    if log:
        with open(log, "w") as f:
            f.write(p.stdout)
    return p.returncode, p.stdout


def fresh_copy(tutorial, name):
    dst = os.path.join(WORK, name)
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "tutorials", tutorial), dst,
                    ignore=shutil.ignore_patterns("[1-9]*", "processor*", "log.*",
                                                  "VTK", "postProcessing", "*.png"))
    return dst


def times_written(case):
    """The time directories after 0 in case (a refused run writes none)."""
    return [d for d in os.listdir(case) if re.fullmatch(r"[1-9][0-9.e+-]*", d)]


def refused(case, args, words):
    """Allrun with `args` in case fails, the solver's log has a FatalIOError
    with every one of `words`, and no time directory was written: (ok,
    note)."""
    rc, _ = run(["./Allrun"] + list(args), cwd=case, log=os.path.join(case, "log.Allrun"))
    log = os.path.join(case, "log.solidContactFoam")
    text = open(log).read() if os.path.exists(log) else ""
    wrote = times_written(case)
    ok = rc != 0 and "FOAM FATAL IO ERROR" in text and all(w in text for w in words) \
        and not wrote
    return ok, "(rc=%d, times written %s%s)" % (rc, wrote, "" if ok else ", see %s" % log)


def add_controls(case, controls):
    """Entries added to solidMechanics of system/fvSolution."""
    fv = os.path.join(case, "system/fvSolution")
    text, n = re.subn(r"^(solidMechanics\s*\{)", r"\1\n    " + controls,
                      open(fv).read(), count=1, flags=re.M)
    if n != 1:
        raise RuntimeError("no solidMechanics dictionary in " + fv)
    open(fv, "w").write(text)


def set_solid_tolerance(case, tol):
    """The outer correctors' tolerance of solidMechanics in system/fvSolution."""
    fv = os.path.join(case, "system/fvSolution")
    text, n = re.subn(r"^(\s*tolerance\s+)1e-9;", r"\g<1>%s;" % tol, open(fv).read(),
                      count=1, flags=re.M)
    if n != 1:
        raise RuntimeError("no 'tolerance 1e-9;' in " + fv)
    open(fv, "w").write(text)


def validation(tutorial, script):
    """A tutorial's validation script as a module (its compare() and
    tolerances), loaded from its file."""
    path = os.path.join(ROOT, "tutorials", tutorial, "validation", script + ".py")
    spec = importlib.util.spec_from_file_location("%s_%s" % (tutorial, script), path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def friction_models():
    """(models, None) from solidContactFoam -listFrictionModels, or (None,
    reason) where it fails."""
    rc, out = run([SOLVER, "-listFrictionModels"], cwd=ROOT)
    if rc:
        lines = [x.strip() for x in out.splitlines() if x.strip()]
        said = [x for x in lines if re.search(r"invalid|unknown|error", x, flags=re.I)]
        return None, "solidContactFoam -listFrictionModels failed (rc=%d: %s)" % (
            rc, (said or lines or ["no output"])[0])
    return [m for m in out.split() if m], None


# --------------------------------------------------------------------------
# Once per session
def once(name, make):
    """make() once per pytest session across xdist workers; its value (JSON).
    An exception of make() is kept too: every test that needs the value
    fails with it, and nobody makes it again."""
    d = os.path.join(WORK, ".once")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name + ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        path = os.path.join(d, name + ".json")
        if os.path.exists(path):
            with open(path) as f:
                kept = json.load(f)
            if kept.get("session") == session():
                if "error" in kept:
                    raise RuntimeError("%s failed earlier in this session: %s"
                                       % (name, kept["error"]))
                return kept["value"]
        try:
            value = make()
            kept = dict(session=session(), value=value)
        except Exception as e:  # noqa: BLE001 (kept for the other tests)
            kept = dict(session=session(), error="%s: %s" % (type(e).__name__, e))
            with open(path, "w") as f:
                json.dump(kept, f)
            raise
        with open(path, "w") as f:
            json.dump(kept, f)
        return value


def tutorial_run(tutorial, name, args=(), controls="", edit=None):
    """A tutorial's Allrun on a fresh copy WORK/name, once per session:
    dict(case, rc, wall, checks) where checks are its validation script's
    (C4F_CHECKS_JSON; None where it wrote none), their names starting with
    `name`. controls are entries added to solidMechanics of
    system/fvSolution, edit(case) a change of the copy before it runs."""
    def make():
        case = fresh_copy(tutorial, name)
        if edit:
            edit(case)
        if controls:
            add_controls(case, controls)
        checks_json = os.path.join(case, "checks.json")
        env = dict(os.environ, C4F_CHECKS_JSON=checks_json)
        t0 = time.time()
        rc, _ = run(["./Allrun"] + list(args), cwd=case, env=env,
                    log=os.path.join(case, "log.Allrun"))
        checks = None
        if os.path.exists(checks_json):
            checks = json.load(open(checks_json))
            for c in checks:
                c["name"] = c["name"].replace(tutorial + "/", name + "/", 1)
        return dict(case=case, rc=rc, wall=time.time() - t0, checks=checks)
    return once(name, make)


def total_correctors(case):
    """The outer correctors of every load step of the case's solver log."""
    text = open(os.path.join(case, "log.solidContactFoam")).read()
    return sum(int(n) for n in re.findall(r"^Time = \S+\s+correctors = (\d+)", text,
                                          flags=re.M))


def need(r, what=None):
    """The case of a run another test made; fails this test where that run
    did not finish."""
    if r["rc"] != 0 or not os.path.exists(os.path.join(r["case"], "log.solidContactFoam")):
        pytest.fail("prerequisite run %s failed (rc=%d), see %s/log.*"
                    % (what or os.path.basename(r["case"]), r["rc"], r["case"]))
    return r["case"]


def restart_mid_load(ck, ref, name, patch, start, steps, tol=1e-6):
    """Restart the finished run `ref` from time `start` (the later times
    and postProcessing removed) to its last time `steps[-1]`: it must redo
    exactly `steps` (time names) and report the same normal force of
    `patch` at each to `tol` relative (checks <name>/run and
    <name>/force_t<t>_equals_uninterrupted)."""
    def trim(case):
        for t in steps:
            shutil.rmtree(os.path.join(case, t), ignore_errors=True)
        shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)

    r = restart_run(ref, end_time=steps[-1], suffix="_restart" + start, prepare=trim)
    done = re.findall(r"^Time = (\S+)\s+correctors", r["out"], flags=re.M)
    ok = r["rc"] == 0 and done == list(steps)
    ck.add(name + "/run", ok, note="rc=%d, steps %s, see %s" % (r["rc"], done, r["case"]))
    if ok:
        rows = {x["time"]: x for x in contactreport.rows(r["case"], patch)}
        refs = {x["time"]: x for x in contactreport.rows(ref, patch)}
        for t in (float(x) for x in steps):
            f, f0 = rows[t]["normalForce"], refs[t]["normalForce"]
            err = abs(f - f0) / abs(f0)
            ck.add("%s/force_t%g_equals_uninterrupted" % (name, t), err <= tol, f, f0,
                   err, tol)


def forces_agree(ck, case, ref, patch, name, tol, what):
    """Check that two runs of the same steps report the same normal force
    of `patch` at every time, to `tol` relative (checks
    <name>/same_steps and <name>/force_t<t>_<what>)."""
    rows = {x["time"]: x for x in contactreport.rows(case, patch)}
    refs = {x["time"]: x for x in contactreport.rows(ref, patch)}
    ck.add(name + "/same_steps", sorted(rows) == sorted(refs),
           note="(%d and %d steps)" % (len(rows), len(refs)))
    for t in sorted(set(rows) & set(refs)):
        f, f0 = rows[t]["normalForce"], refs[t]["normalForce"]
        err = abs(f - f0) / abs(f0)
        ck.add("%s/force_t%g_%s" % (name, t, what), err <= tol, f, f0, err, tol)


# --------------------------------------------------------------------------
class Checks:
    """The checks of one test: add() each, verify() at the end."""

    def __init__(self):
        self.lines = []
        self.failed = []
        d = os.path.join(WORK, ".checks")
        os.makedirs(d, exist_ok=True)
        self.log = os.path.join(d, "%s-%s.log" % (session(), worker()))

    def add(self, name, passed, value=None, reference=None, error=None,
            tolerance=None, note=""):
        parts = ["PASS" if passed else "FAIL", "%-52s" % name]
        if value is not None:
            parts.append("value=%-12.6g ref=%-12.6g err=%-10.4g tol=%.4g"
                         % (value, reference, error, tolerance))
        if note:
            parts.append(note)
        line = " ".join(parts)
        self.lines.append(line)
        if not passed:
            self.failed.append(line)
        print(line, flush=True)
        with open(self.log, "a") as f:
            f.write(line + "\n")
        return passed

    def add_checks(self, checks):
        for c in checks:
            self.add(c["name"], c["passed"], c["value"], c["reference"],
                     c["error"], c["tolerance"])

    def verify(self):
        if self.failed:
            pytest.fail("%d of %d checks failed:\n%s"
                        % (len(self.failed), len(self.lines), "\n".join(self.failed)),
                        pytrace=False)

    # ----------------------------------------------------------------------
    # What a run checks of itself
    def run(self, r, name):
        """A run's own checks: Allrun succeeded and wrote its checks, every
        load step converged, the validation script's checks. False where
        Allrun failed (the rest is not checked)."""
        case = r["case"]
        if r["rc"] != 0 or r["checks"] is None:
            self.add("%s/Allrun" % name, False,
                     note="Allrun failed (rc=%d), see %s/log.*" % (r["rc"], case))
            return False
        self.add("%s/Allrun" % name, True, note="(%.1f s)" % r["wall"])
        self.steps_converged(case, name)
        self.add_checks(r["checks"])
        return True

    def steps_converged(self, case, name):
        """Every load step of the solver's log converged (no 'NOT CONVERGED'
        step line, the run reached End) and, where there is a contactReport,
        its last row says converged = 1."""
        log = os.path.join(case, "log.solidContactFoam")
        text = open(log).read() if os.path.exists(log) else ""
        steps = re.findall(r"^Time = \S+\s+correctors = (\d+)\s+residual = \S+(.*)$", text,
                           flags=re.M)
        bad = [s for s in steps if "NOT CONVERGED" in s[1]]
        ok = bool(steps) and not bad and re.search(r"^End\s*$", text, flags=re.M) is not None
        rep = os.path.join(case, "postProcessing", "contactReport", "0")
        for d in (os.listdir(rep) if os.path.isdir(rep) else []):
            if d.endswith("Multipliers.dat"):
                # the multiplier updates of the steps, not a step report
                continue
            row = contactreport.last_row(case, os.path.splitext(d)[0])
            if row is None or row.get("converged") != 1:
                ok = False
        self.add("%s/steps_converged" % name, ok,
                 note="(%d steps, correctors %s)" % (len(steps), ",".join(s[0] for s in steps))
                 if ok else "not converged: see %s" % log)

    def decomposed(self, case, name, nprocs=2):
        log = open(os.path.join(case, "log.solidContactFoam")).read()
        ok = ("nProcs : %d" % nprocs) in log and os.path.isdir(os.path.join(case, "processor1"))
        self.add(name, ok, note="(ran on %d processors)" % nprocs if ok else "not decomposed")

    def vtk_written(self, case, name, fields):
        blobs = ""
        for dirpath, _, files in os.walk(os.path.join(case, "VTK")):
            for f in files:
                if f.endswith((".vtu", ".vtk", ".vtp")):
                    with open(os.path.join(dirpath, f), "rb") as fh:
                        blobs += fh.read().decode("latin-1")
        names = set(re.findall(r"Name=[\"'](\w+)[\"']", blobs))
        missing = [f for f in fields if f not in names]
        self.add("%s/foamToVTK_fields" % name, not missing,
                 note="missing: %s" % missing if missing else "(%s)" % ", ".join(fields))

    def barrier_gaps_open(self, case, name):
        """The barrier's answer keeps every gap open, above the law's
        extension (extensionScale dhat: the case's entry or the method's
        default, dhat from the log's 'barrier dhat = d m' line): the step
        summaries' minGap. An iterate of the
        segregated correctors may cross g = 0 at a face the law couples
        (the extension pushes it back); with verbose output every corrector
        prints the smallest gap of the iterate it starts from ('contact
        <patch>: corrector N ... minGap = g'), one line per corrector (so
        that the log is the whole run's), and the note gives the smallest."""
        text = open(os.path.join(case, "log.solidContactFoam")).read()
        gaps = [_gap(g) for g in re.findall(r"^\s*contact \w+: corrector \d+ .*minGap = (\S+)",
                                             text, flags=re.M)]
        final = [_gap(g) for g in re.findall(r"^Time = .*minGap = (\S+)", text, flags=re.M)]
        dhat = [float(d) for d in re.findall(r"barrier dhat = (\S+) m", text)]
        floor = (methods.coeff(case, "barrier", "extensionScale") * min(dhat)
                 if dhat else float("inf"))
        ncorr = total_correctors(case)
        ok = bool(gaps) and len(gaps) == ncorr and bool(final) and min(final) > floor
        self.add("%s/min_gap_above_extension_converged" % name, ok,
                 note="(%d correctors, final %s, extension %.3g m; smallest iterate gap %.3g m)"
                 % (len(gaps), ", ".join("%.3g" % g for g in final), floor,
                    min(gaps) if gaps else float("nan")))

    def barrier_initial_gap(self, case, name, gap):
        """The barrier's first corrector starts from the lift Allrun -gap
        gave (flat surfaces: every gap equals it, along the normal that
        -rotate turns; a lift along the unturned axis would leave cos of the
        angle between them, 0.95 here): its line 'barrier dhat = ... min gap
        = g m' against `gap`, to 1e-6 (the rotated points carry 12 digits)."""
        text = open(os.path.join(case, "log.solidContactFoam")).read()
        m = re.search(r"barrier dhat = .* min gap = (\S+) m", text)
        if not m:
            self.add(name + "/initial_gap", False, note="no barrier start line in the log")
            return
        g = float(m.group(1))
        err = abs(g - gap) / gap
        self.add(name + "/initial_gap", err <= 1e-6, g, gap, err, 1e-6)

    # ----------------------------------------------------------------------
    # Two runs compared
    def displacements_agree(self, ref, case, name, tol):
        """D of the last times, max |difference| over max |D of ref|."""
        ds = foamio.read_internal(os.path.join(ref, foamio.latest_time(ref), "D"))
        dp = foamio.read_internal(os.path.join(case, foamio.latest_time(case), "D"))
        if ds.shape != dp.shape:
            self.add(name, False, note="shapes differ %s %s" % (ds.shape, dp.shape))
            return
        err = np.abs(ds - dp).max() / np.abs(ds).max()
        self.add(name, err <= tol, err, 0.0, err, tol)

    def stress_fields_agree(self, ref, case, name, tol):
        """sigma of the last times, max |difference| over max |sigma of ref|."""
        sr = foamio.read_internal(os.path.join(ref, foamio.latest_time(ref), "sigma"))
        sc = foamio.read_internal(os.path.join(case, foamio.latest_time(case), "sigma"))
        if sr.shape != sc.shape:
            self.add(name, False, note="shapes differ %s %s" % (sr.shape, sc.shape))
            return
        err = float(np.abs(sc - sr).max() / np.abs(sr).max())
        self.add(name, err <= tol, err, 0.0, err, tol)

    def contact_agrees(self, ref, case, name, tol, ref_name="serial",
                       patch="cylinderContact"):
        """Peak pressure and total normal force of the slave patch, from the
        contactReport rows of `ref` (named ref_name) and `case`."""
        s = contactreport.last_row(ref, patch)
        p = contactreport.last_row(case, patch)
        if s is None or p is None:
            self.add(name + "/contactReport", False, note="no contactReport rows")
            return
        for col, what in (("normalForce", "normal_force"), ("maxPressure", "peak_pressure")):
            err = abs(p[col] - s[col]) / abs(s[col]) if s[col] else 1.0
            self.add("%s/%s_equals_%s" % (name, what, ref_name), err <= tol, p[col], s[col],
                     err, tol)

    def friction_fields_agree(self, ref, case, name, patch, tol, slip_may_stick=False):
        """The friction state of the last times of two runs: contactStick
        identical face by face, contactSlip to tol of its largest magnitude,
        and contactReport's tangential force to tol. slip_may_stick: a face
        slipping in ref may stick in case (a step at the same load: a face on
        the cone's edge, |t_T| = mu p_N, is not driven any further)."""
        n = foamio.patch_face_cells(ref, patch).size
        tr, tc = foamio.latest_time(ref), foamio.latest_time(case)
        try:
            sr = foamio.read_patch(os.path.join(ref, tr, "contactStick"), patch, n)
            sc = foamio.read_patch(os.path.join(case, tc, "contactStick"), patch, n)
            gr = foamio.read_patch(os.path.join(ref, tr, "contactSlip"), patch, n)
            gc = foamio.read_patch(os.path.join(case, tc, "contactSlip"), patch, n)
        except (OSError, KeyError, ValueError) as e:
            self.add(name + "/friction_state", False,
                     note="cannot read the friction fields: %s" % e)
            return
        same = np.rint(sr) == np.rint(sc)
        if slip_may_stick:
            same |= (np.rint(sr) == 0) & (np.rint(sc) == 1)
        differ = int((~same).sum())
        self.add(name + "/contactStick_equal", differ == 0, note="(%d faces differ)" % differ)
        scale = float(np.abs(gr).max()) or 1.0
        err = float(np.abs(gc - gr).max()) / scale
        self.add(name + "/contactSlip_equal", err <= tol, err, 0.0, err, tol)
        r, c = contactreport.last_row(ref, patch), contactreport.last_row(case, patch)
        if r is None or c is None or not r.get("tangentialForce"):
            self.add(name + "/tangential_force_equal", False, note="no tangential force reported")
            return
        err = abs(c["tangentialForce"] - r["tangentialForce"]) / abs(r["tangentialForce"])
        self.add(name + "/tangential_force_equal", err <= tol, c["tangentialForce"],
                 r["tangentialForce"], err, tol)


# --------------------------------------------------------------------------
# Restarts
def restart_run(finished, end_time=None, suffix="_restart", prepare=None):
    """Copy a finished case to finished + suffix and continue it with the
    solver to end_time (default: one more step at the same load, endTime 2
    of a one-step run), once per session; prepare(case), if given, edits
    the copy first (e.g. removes the last times). dict(case, rc, out)."""
    case = finished + suffix

    def make():
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(finished, case,
                        ignore=shutil.ignore_patterns("processor*", "VTK", "log.*"))
        if prepare:
            prepare(case)
        cd = os.path.join(case, "system/controlDict")
        end = end_time or "2"
        text = re.sub(r"^endTime\s+[^;]+;", "endTime %s;" % end, open(cd).read(), flags=re.M)
        text = re.sub(r"^startFrom\s+[^;]+;", "startFrom latestTime;", text, flags=re.M)
        open(cd, "w").write(text)
        rc, out = run([SOLVER], cwd=case, log=os.path.join(case, "log.solidContactFoam"))
        return dict(case=case, rc=rc, out=out)
    return once(os.path.basename(case), make)


# --------------------------------------------------------------------------
# The contact methods of the solver's selection table and their traits
def methods_where(**traits):
    """The names of the methods whose traits have these values, e.g.
    methods_where(slip=False), methods_where(answer="exact")."""
    return [m.name for m in methods.table().values()
            if all(getattr(m, k) == v for k, v in traits.items())]


def methods_with_coeff(entry):
    """The methods with a default coefficient `entry` (e.g. gamma0)."""
    return [m.name for m in methods.table().values() if entry in m.coeffs]
