#!/usr/bin/python3
"""tools/install-deps.sh installs exactly the packages dpkg does not hold installed, and nothing
when every one is.

Runs a copy of the script under a scratch root (its freefem++.pref is written there) with a fake
dpkg-query and a fake apt-get first on PATH: the fake dpkg-query answers from a list of
"<package> <status>" lines as the real one does (one line per known package, nothing for an
unknown one, exit 1 if any was unknown); the fake apt-get records its arguments. Asserts the
packages given to apt-get install are those missing, unknown or only configured ("deinstall ok
config-files"), and that apt-get never runs when all are installed. Writes
results/checks/install_deps.json.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

FAKE_DPKG_QUERY = r"""#!/bin/sh
# Answers `dpkg-query -W -f=FORMAT p...` from $FAKE_STATUS ("<package> <status>" lines).
shift 2
rc=0
for p in "$@"; do
  line=$(grep "^$p " "$FAKE_STATUS") || { echo "dpkg-query: no packages found matching $p" >&2; rc=1; continue; }
  echo "$line"
done
exit $rc
"""

FAKE_APT_GET = """#!/bin/sh
echo "$*" >> "$FAKE_APT_LOG"
"""


def packages_of(script):
    """The packages the script asks for (its `packages="..."` assignment, two lines)."""
    text = open(script).read()
    m = re.search(r'^packages="([^"]*)"', text, re.M)
    return m.group(1).split()


def run(scratch, statuses, args=()):
    """Runs the copied script against the fake dpkg status; returns (exit code, apt-get calls, stderr)."""
    with open(os.path.join(scratch, "status"), "w") as f:
        f.write("".join(f"{p} {s}\n" for p, s in statuses.items()))
    log = os.path.join(scratch, "apt.log")
    if os.path.exists(log):
        os.remove(log)
    env = dict(os.environ, PATH=os.path.join(scratch, "bin") + ":" + os.environ["PATH"],
               FAKE_STATUS=os.path.join(scratch, "status"), FAKE_APT_LOG=log)
    p = subprocess.run(["sh", os.path.join(scratch, "tools", "install-deps.sh"), *args], env=env,
                       capture_output=True, text=True, timeout=60)
    calls = open(log).read().splitlines() if os.path.exists(log) else []
    return p.returncode, calls, p.stderr


def main():
    scratch = tempfile.mkdtemp(prefix="install-deps-")
    try:
        os.makedirs(os.path.join(scratch, "tools"))
        os.makedirs(os.path.join(scratch, "bin"))
        shutil.copy(os.path.join(ROOT, "tools", "install-deps.sh"), os.path.join(scratch, "tools"))
        for name, text in (("dpkg-query", FAKE_DPKG_QUERY), ("apt-get", FAKE_APT_GET)):
            path = os.path.join(scratch, "bin", name)
            with open(path, "w") as f:
                f.write(text)
            os.chmod(path, 0o755)
        wanted = packages_of(os.path.join(ROOT, "tools", "install-deps.sh"))
        check(len(wanted) >= 20 and "freefem++" in wanted and "libfreefem++-dev" in wanted,
              f"the script asks for {len(wanted)} packages, freefem++ and libfreefem++-dev among them")

        every = {p: "install ok installed" for p in wanted}
        rc, calls, err = run(scratch, every)
        check(rc == 0 and calls == [], f"every package installed: exit {rc}, apt-get calls {calls} "
              f"(none expected) {err.strip()[:200]}")
        pref = os.path.join(scratch, "freefem++.pref")
        check(os.path.isfile(pref) and f'includepath += "{scratch}/edp/lib"' in open(pref).read(),
              "the pref file is written under the script's own root")

        # cmake's line ends as make's would: each package must be judged on its own whole line.
        partial = dict(every)
        partial["freefem++"] = "deinstall ok config-files"
        del partial["make"]
        partial["python3-vtk9"] = "install ok unpacked"
        rc, calls, err = run(scratch, partial)
        installs = [c.split() for c in calls if " install " in f" {c} "]
        asked = sorted(w for c in installs for w in c if not w.startswith("-") and w != "install")
        expected = sorted(["freefem++", "make", "python3-vtk9"])
        check(rc == 0 and asked == expected and any(c.startswith("update") or " update" in c for c in calls),
              f"three packages not installed: apt-get update then install of {asked} (expected {expected})")

        rc, calls, err = run(scratch, every, ["jupyter-notebook"])
        check(rc == 0 and any("jupyter-notebook" in c.split() for c in calls)
              and not any("gmsh" in c.split() for c in calls),
              f"a package given as argument (make lab's) is installed alone when missing: {calls}")
        record("install_deps", {"test": "install_deps", "packages": len(wanted)})
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
