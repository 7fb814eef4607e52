"""The repository's shell scripts pass shellcheck (make shellcheck)."""
import harness


def test_shellcheck():
    ck = harness.Checks()
    rc, text = harness.run(["make", "-s", "shellcheck"], cwd=harness.ROOT)
    ck.add("lint/shellcheck", rc == 0, note=text.strip()[-1500:])
    ck.verify()
