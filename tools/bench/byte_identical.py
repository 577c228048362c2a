#!/usr/bin/python3
"""Do two builds of the project write the same results? For refactors that must keep every output.

Usage: tools/bench/byte_identical.py OLD_TREE NEW_TREE WORK
  OLD_TREE, NEW_TREE: two copies of the project, each with its plugin built (make plugin meshes);
  WORK: a scratch folder (WORK/old/<case>, WORK/new/<case>).
Runs the cases below in each tree (tools/ff) and compares every file of each case's results
folder byte for byte, summary.json after dropping its timing keys (wall clock, back-solve timings
and the ratios made from them, which differ from run to run). Exit 0 when all are identical; else
it names each differing file.
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import without_companion  # noqa: E402

# (name, scene, options): the default scenes and the step solver's other paths.
CASES = [
    ("sleeve-circular", "sleeve-circular.edp", []),
    ("sleeve-radial", "sleeve-radial.edp", []),
    ("sleeve-elliptic-friction", "sleeve-elliptic-friction.edp", []),
    ("sleeve-offset", "sleeve-offset.edp", []),
    ("sleeve-life", "sleeve-life.edp", ["-cycles", "1"]),
    ("free-ring", "free-ring.edp", []),
    ("sleeve-circular-onoff", "sleeve-circular.edp", ["-phasemodel", "onoff"]),
    ("sleeve-circular-fixedpoint", "sleeve-circular.edp", ["-stepsolver", "fixedpoint", "-steps", "300"]),
]
TIMING_WORDS = ("wall", "seconds", "timing", "elapsed", "over_backsolves", "over_floor")


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if not any(w in k.lower() for w in TIMING_WORDS)}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def files_under(root):
    return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, names in os.walk(root) for f in names)


def run(tree, out, scene, options):
    # (-meshestimate 0 unless asked: the companion's summary and log hold its own timings; a tree from
    # before the estimate's default takes it as its default)
    script = os.path.join("edp", "scenes", scene)
    cmd = [os.path.join(tree, "tools", "ff"), script, "-out", out] + options + without_companion(script, options)
    done = subprocess.run(cmd, cwd=tree, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{tree}: {' '.join(cmd[1:])} exited {done.returncode}:\n{done.stderr[-2000:]}")


def differences(old, new):
    found = []
    old_files, new_files = files_under(old), files_under(new)
    if old_files != new_files:
        found.append(f"file lists differ: {sorted(set(old_files) ^ set(new_files))}")
    for name in sorted(set(old_files) & set(new_files)):
        a, b = os.path.join(old, name), os.path.join(new, name)
        if os.path.basename(name) == "summary.json":
            with open(a) as fa, open(b) as fb:
                same = without_timings(json.load(fa)) == without_timings(json.load(fb))
        else:
            with open(a, "rb") as fa, open(b, "rb") as fb:
                same = fa.read() == fb.read()
        if not same:
            found.append(f"{name} differs")
    return found, len(old_files)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    old_tree, new_tree, work = (os.path.abspath(a) for a in sys.argv[1:])
    bad = 0
    for name, scene, options in CASES:
        old, new = os.path.join(work, "old", name), os.path.join(work, "new", name)
        run(old_tree, old, scene, options)
        run(new_tree, new, scene, options)
        found, count = differences(old, new)
        print(f"{name}: {count} files, " + ("identical" if not found else "; ".join(found)))
        bad += len(found)
    print("ALL IDENTICAL" if bad == 0 else f"{bad} DIFFERENCES")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
