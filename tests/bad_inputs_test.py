#!/usr/bin/python3
"""Every bad input of docs/errors.md fails fast with its message and exit code.

Reads the table of docs/errors.md (so that the document and the test cannot drift), runs each
row's command from the repository root with $R = the root and $T = a fresh scratch directory, and
asserts for each: the exit code of the table; one line starting with "error:" in its output
(stderr for tools/ff and make, stdout for FreeFEM's cerr), matching the row's pattern; the run over in under 20 s (it must stop before the time loop); no
summary.json in $T/out (nothing that looks like a finished run). Also asserts that the table
covers every kind of bad input the project promises to catch, and that the backquoted command in
a SCENE value never ran. The plugin cases use copies under $T through SMA_PLUGIN (tools/ff):
a copy of the real plugin dated 2000 (stale), a plugin built here that reports version 2, a
missing path; the real plugin/build/sma.so is never touched.
Writes results/checks/bad_inputs.json.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

# What the table must cover (a word of the "bad input" column for each).
REQUIRED = ["unknown option", "T0 >= Tc", "omega", "mu < 0", "g < 0", "-gcontact", "-steps 0",
            "negative step count", "missing mesh file", "mesh without the expected boundary labels",
            "plugin not built", "plugin out of date", "another version", "unknown scene",
            "shell metacharacters", "option without its value", "not a number", "integer option"]

FAKE_PLUGIN = """// A stand-in SMA plugin that reports version 2 (tests/bad_inputs_test.py).
#include "ff++.hpp"
static double SmaPluginVersion() { return 2.0; }
static void Init() { Global.Add("SmaPluginVersion", "(", new OneOperator0<double>(SmaPluginVersion)); }
LOADFUNC(Init)
"""


def code(cell):
    """The text of a Markdown code span (`x` or ``x``)."""
    cell = cell.strip()
    for fence in ("``", "`"):
        if cell.startswith(fence) and cell.endswith(fence):
            return cell[len(fence):-len(fence)].strip()
    raise ValueError(f"not a code span: {cell}")


def table_rows():
    lines = open(os.path.join(ROOT, "docs", "errors.md")).read().splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("| bad input |"))
    rows = []
    for ln in lines[start + 2:]:
        if not ln.startswith("|"):
            break
        cells = [c.strip() for c in ln.strip().strip("|").split(" | ")]
        rows.append({"input": cells[0], "command": code(cells[1]), "exit": int(cells[2]),
                     "pattern": code(cells[3]), "fix": cells[4]})
    return rows


def prepare(tmp):
    """$T/stale/sma.so, $T/v2/sma.so, $T/pref/freefem++.pref (docs/errors.md)."""
    os.makedirs(os.path.join(tmp, "stale"))
    stale = os.path.join(tmp, "stale", "sma.so")
    shutil.copyfile(os.path.join(ROOT, "plugin", "build", "sma.so"), stale)
    old = time.mktime((2000, 1, 1, 0, 0, 0, 0, 0, -1))
    os.utime(stale, (old, old))
    os.makedirs(os.path.join(tmp, "v2"))
    with open(os.path.join(tmp, "v2", "sma.cpp"), "w") as f:
        f.write(FAKE_PLUGIN)
    build = subprocess.run(["ff-c++", "sma.cpp"], cwd=os.path.join(tmp, "v2"), capture_output=True, text=True)
    check(build.returncode == 0 and os.path.exists(os.path.join(tmp, "v2", "sma.so")),
          f"a version-2 stand-in plugin built with ff-c++ (exit {build.returncode})")
    os.makedirs(os.path.join(tmp, "pref"))
    with open(os.path.join(tmp, "pref", "freefem++.pref"), "w") as f:
        f.write('loadpath += "./"\n')


def main():
    rows = table_rows()
    inputs = " ".join(r["input"] for r in rows)
    missing = [w for w in REQUIRED if w not in inputs]
    check(not missing, f"docs/errors.md has {len(rows)} rows covering every required kind of bad input"
          + (f" (missing: {missing})" if missing else ""))
    # No plugin override, and no flags of an enclosing make (make test -j): the make rows must run
    # check-scene alone, first.
    env = {k: v for k, v in os.environ.items() if k not in ("SMA_PLUGIN", "MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    measured = []
    with tempfile.TemporaryDirectory(prefix="bad-inputs-") as tmp:
        prepare(tmp)
        env.update(T=tmp, R=ROOT)
        for row in rows:
            out = os.path.join(tmp, "out")
            shutil.rmtree(out, ignore_errors=True)
            t0 = time.time()
            run = subprocess.run(["bash", "-c", row["command"]], cwd=ROOT, env=env, capture_output=True,
                                 text=True, timeout=120)
            seconds = time.time() - t0
            errors = [ln for ln in (run.stderr + run.stdout).splitlines() if ln.startswith("error:")]
            matched = bool(errors) and re.search(row["pattern"], errors[0]) is not None
            check(run.returncode == row["exit"] and len(errors) == 1 and matched and seconds < 20
                  and not os.path.exists(os.path.join(out, "summary.json")),
                  f"{row['input']}: exit {run.returncode} (table {row['exit']}), {len(errors)} error line, "
                  f"{'matches' if matched else 'does not match'} the pattern, {seconds:.2f} s: "
                  f"{errors[0] if errors else run.stderr.strip()[-300:]}")
            measured.append({"input": row["input"], "exit": run.returncode, "seconds": round(seconds, 3),
                             "message": errors[0] if errors else None, "matched": matched})
        check(not os.path.exists(os.path.join(tmp, "injected")),
              "the command in backquotes in SCENE never ran ($T/injected absent)")
    check(os.path.exists(os.path.join(ROOT, "plugin", "build", "sma.so")), "the real plugin is still there")
    record("bad_inputs", {"test": "bad_inputs", "rows": len(rows), "runs": measured,
                          "slowest_seconds": max(m["seconds"] for m in measured)})
    finish()


if __name__ == "__main__":
    main()
