"""The GoogleTest unit tests of the kernels ($C4F_PREFIX/build/unit/
unitTests): one pytest test per GoogleTest case, from one run of the
binary per session (its JSON report)."""
import json
import os

import pytest

import harness

EXE = os.path.join(harness.PREFIX, "build", "unit", "unitTests")


def gtest_cases():
    """Suite.Name of every case, from unitTests --gtest_list_tests."""
    rc, out = harness.run([EXE, "--gtest_list_tests"], cwd=harness.ROOT) \
        if os.path.exists(EXE) else (1, "no " + EXE)
    if rc:
        return ["unitTests_list_failed"]
    cases, suite = [], None
    for line in out.splitlines():
        if not line.strip() or line.startswith("Running main"):
            continue
        if not line.startswith(" "):
            suite = line.split()[0]
        else:
            cases.append(suite + line.split()[0])
    return cases


def gtest_results():
    def make():
        os.makedirs(harness.WORK, exist_ok=True)
        out = os.path.join(harness.WORK, "unitTests.json")
        if os.path.exists(out):
            os.remove(out)
        rc, text = harness.run([EXE, "--gtest_output=json:" + out], cwd=harness.WORK)
        if not os.path.exists(out):
            return dict(error="did not run (rc=%d)\n%s" % (rc, text[-2000:]))
        data = json.load(open(out))
        return {"%s.%s" % (s["name"], t["name"]):
                ("" if not t.get("failures") else t["failures"][0]["failure"])
                for s in data.get("testsuites", []) for t in s.get("testsuite", [])}
    return harness.once("unitTests", make)


@pytest.mark.xdist_group("unitTests")
@pytest.mark.parametrize("case", gtest_cases())
def test_kernel(case):
    ck = harness.Checks()
    res = gtest_results()
    if "error" in res:
        ck.add("unit/unitTests", False, note=res["error"])
    elif case not in res:
        ck.add("unit/%s" % case, False, note="not in unitTests' JSON report")
    else:
        ck.add("unit/%s" % case, not res[case],
               note=res[case].splitlines()[0] if res[case] else "")
    ck.verify()
