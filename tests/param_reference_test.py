#!/usr/bin/python3
"""docs/parameter-reference.md is up to date, and every option tools/param_reference.py finds is
one the script really reads.

  * regenerates the reference into a temporary file and asserts docs/parameter-reference.md is
    byte-identical (run `make docs` after changing a scene's options);
  * probe run per script: tools/ff <script> with every option the generator found set to its
    default, then one unknown option last. A script's CheckOptions (edp/lib/errors.idp) goes
    through the command line in order and fails on the first name the script has not read: if
    it names the probe, every generated option was accepted (and parses as the type the default
    gives); its message lists the names the script read, which must be exactly the generated
    set (nothing missed, nothing invented). The run stops at the end of the parameter block, so
    the whole probe takes a few seconds.
  * every script calls CheckOptions (else its options cannot be checked, and a typo in an option
    name would be silently ignored).
Writes results/checks/param_reference.json.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

PROBE = "-paramreferenceprobe"


def main():
    tool = os.path.join(ROOT, "tools", "param_reference.py")
    with tempfile.TemporaryDirectory() as tmp:
        fresh = os.path.join(tmp, "parameter-reference.md")
        subprocess.run([sys.executable, tool, "--out", fresh], check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
        current_path = os.path.join(ROOT, "docs", "parameter-reference.md")
        current = open(current_path).read() if os.path.exists(current_path) else ""
        check(open(fresh).read() == current,
              "docs/parameter-reference.md is up to date with the scripts (else: make docs)")
    scripts = json.loads(subprocess.run([sys.executable, tool, "--json"], check=True, cwd=ROOT,
                                        capture_output=True, text=True).stdout)
    measured = {}
    for name, s in scripts.items():
        options = s["options"]
        unresolved = [o["name"] for o in options if o["type"] == "expression"]
        check(not unresolved, f"{name}: every default resolved to a value ({unresolved or 'all'})")
        check(s["checks_options"], f"{name}: calls CheckOptions (unknown options are refused)")
        if not s["checks_options"] or unresolved:
            continue
        argv = [os.path.join(ROOT, "tools", "ff"), s["path"]]
        for o in options:
            argv += [o["name"], str(o["default"])]
        argv += [PROBE, "1"]
        try:
            run = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, timeout=60)
        except subprocess.TimeoutExpired:
            check(False, f"{name}: the probe run did not stop in CheckOptions within 60 s")
            continue
        message = next((line for line in (run.stdout + run.stderr).splitlines() if "unknown option" in line), "")
        check(run.returncode != 0 and f"unknown option {PROBE} " in message,
              f"{name}: all {len(options)} options accepted at their defaults, the probe refused"
              + ("" if message else f" (no 'unknown option' message; exit {run.returncode}: "
                 f"{(run.stdout + run.stderr).strip()[-300:]})"))
        read = re.search(r" reads (.*)\)\s*$", message)
        registered = set(read.group(1).split()) if read else set()
        generated = {o["name"] for o in options}
        check(registered == generated,
              f"{name}: the generator's options are the ones the script reads ({len(generated)}; missed "
              f"{sorted(registered - generated)}, invented {sorted(generated - registered)})")
        measured[name] = {"options": len(options), "registered": len(registered),
                          "missed": sorted(registered - generated), "invented": sorted(generated - registered)}
    record("param_reference", {"test": "param_reference", "scripts": measured})
    finish()


if __name__ == "__main__":
    main()
