#!/usr/bin/python3
"""A sweep stopped part-way and run again with -resume 1 continues: its finished runs are kept,
those with a checkpoint resume from it, the others run; the result equals the uninterrupted sweep.

sleeve-radial over -steps 100 600 700 with -checkpoint 100 (the runs differ in length, so that one
finishes before the stop):
  - A: the uninterrupted sweep;
  - B: the same sweep with -stopafter 150: the 100-step run finishes, the two others stop after
    step 150 with the checkpoint of step 100 (exit 4: the sweep exits 1 naming them); the
    700-step run's checkpoint is then removed, as a run stopped before its first checkpoint
    leaves it;
  - B again with other options and -resume 1: refused (exit 2) naming the difference, nothing
    touched; then with the same options and -resume 1: exit 0, the 100-step run kept (its
    summary.json the same bytes), the 600-step one resumed from step 100, the 700-step one run
    whole; sweep.json says which; every run's history.csv equals A's byte for byte, and the
    table A's but for the timing columns;
  - sma.sweep(..., fixed={"resume": 1}) on the finished sweep keeps all three and returns the table;
  - C, stopped as B: a changed checkpoint (its continued CSV edited) and a run of other options put
    by hand into a run's folder: the resumed sweep keeps its finished run and runs both others
    again, a note each (the plan records each finished run's summary.json: a run it did not record
    is not kept);
  - -resume 1 in a folder that holds no sweep is refused (exit 2).
Before, -resume 1 went to every run as it was: the sweep took its folder afresh first, which
removed the stopped runs' checkpoints, and every run then failed finding none.
"""
import csv
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, TEST_RESULTS, check, finish, record  # noqa: E402

PYTHON = "/usr/bin/python3"
VALUES = ["100", "600", "700"]
TIMING = ("wall", "seconds")  # table columns that hold timings


def sweep(out, *options):
    return subprocess.run([PYTHON, os.path.join(ROOT, "tools", "sweep.py"), "sleeve-radial", "steps", *VALUES,
                           "--out", out, "--", "-checkpoint", "100", *options],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)


def table(out):
    """table.csv's rows without its timing columns."""
    with open(os.path.join(out, "table.csv")) as f:
        rows = list(csv.reader(f))
    keep = [k for k, name in enumerate(rows[0]) if not any(t in name for t in TIMING)]
    return [[row[k] for k in keep] for row in rows]


def read(path):
    with open(path, "rb") as f:
        return f.read()


def main():
    tmp = os.path.join(TEST_RESULTS, "sweep-resume")
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    a, b = os.path.join(tmp, "A"), os.path.join(tmp, "B")
    ra = sweep(a)
    check(ra.returncode == 0, f"the uninterrupted sweep finishes (exit {ra.returncode}) {ra.stderr[-300:]}")

    rb = sweep(b, "-stopafter", "150")
    states = {v: sorted(os.listdir(os.path.join(b, f"steps={v}"))) for v in VALUES}
    check(rb.returncode == 1 and "summary.json" in states["100"]
          and all("checkpoint.txt" in states[v] and "summary.json" not in states[v] for v in ("600", "700")),
          f"-stopafter 150: the sweep exits 1 (got {rb.returncode}), the 100-step run finished, the others hold "
          "a checkpoint and no summary.json")
    os.remove(os.path.join(b, "steps=700", "checkpoint.txt"))  # as a run stopped before its first checkpoint
    kept = read(os.path.join(b, "steps=100", "summary.json"))
    before = {v: sorted(os.listdir(os.path.join(b, f"steps={v}"))) for v in VALUES}

    other = sweep(b, "-g", "600", "-resume", "1")
    after = {v: sorted(os.listdir(os.path.join(b, f"steps={v}"))) for v in VALUES}
    check(other.returncode == 2 and "-resume 1: the sweep in" in other.stderr and '"g": "600"' in other.stderr
          and after == before,
          f"-resume 1 with another option (-g 600) is refused (exit {other.returncode}) naming it, nothing touched: "
          f"{other.stderr.strip()[:200]}")

    rr = sweep(b, "-resume", "1")
    check(rr.returncode == 0 and "1 run(s) finished before are kept, 1 resume from their checkpoint, 1 run" in rr.stdout,
          f"-resume 1 finishes (exit {rr.returncode}) keeping 1 run, resuming 1, running 1: "
          f"{(rr.stdout + rr.stderr).strip()[-300:]}")
    check(read(os.path.join(b, "steps=100", "summary.json")) == kept,
          "the finished run is kept as it was (its summary.json the same bytes: not run again)")
    runs = {r["value"]: r for r in json.load(open(os.path.join(b, "sweep.json")))["runs"]}
    said = {v: runs[v].get("resumed", "") for v in VALUES}
    check(said == {"100": "kept", "600": "from its checkpoint", "700": ""}
          and all(runs[v]["status"] == "done" for v in VALUES),
          f"sweep.json says how each run continued: {said}")
    resumed = json.load(open(os.path.join(b, "steps=600", "summary.json"))).get("resumed_from_step")
    check(resumed == 100, f"the 600-step run resumed from the checkpoint of step 100 (resumed_from_step {resumed})")
    differ = [v for v in VALUES if read(os.path.join(a, f"steps={v}", "history.csv"))
              != read(os.path.join(b, f"steps={v}", "history.csv"))]
    check(not differ, f"every run's history.csv equals the uninterrupted sweep's byte for byte (differ: {differ})")
    ta, tb = table(a), table(b)
    check(ta == tb and len(ta) == 4, f"table.csv equals the uninterrupted sweep's but for its timings "
          f"({len(tb) - 1} rows, {'equal' if ta == tb else 'DIFFERENT'})")

    sys.path.insert(0, os.path.join(ROOT, "python"))
    import sma
    frame = sma.sweep("sleeve-radial", {"steps": [int(v) for v in VALUES]}, fixed={"checkpoint": 100, "resume": 1},
                      out=b)
    runs = {r["value"]: r for r in json.load(open(os.path.join(b, "sweep.json")))["runs"]}
    check(len(frame) == 3 and all(runs[v].get("resumed") == "kept" for v in VALUES)
          and read(os.path.join(b, "steps=100", "summary.json")) == kept,
          f"sma.sweep with resume=1 on the finished sweep keeps its {len(frame)} runs and returns the table")

    # C: stopped as B, then the 600-step run's continued CSV changed (its checkpoint cannot be
    # continued) and a run of other options put by hand into the 700-step run's folder: the resumed
    # sweep keeps its finished run, starts both others again with a note each (it refused the whole
    # sweep, advising a fresh one that deleted the finished run; it kept the hand-made run, whose
    # 700 steps at -g 600 joined the table as this sweep's)
    c = os.path.join(tmp, "C")
    sweep(c, "-stopafter", "150")
    partial = os.path.join(c, "steps=600", "history.csv.partial")
    with open(partial) as f:
        lines = f.read().split("\n")
    lines[2] = lines[2].replace(",", " ,", 1)
    with open(partial, "w") as f:
        f.write("\n".join(lines))
    os.remove(os.path.join(c, "steps=700", "checkpoint.txt"))
    hand = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-steps", "700", "-g", "600",
                           "-quiet", "1", "-out", os.path.join(c, "steps=700")], cwd=ROOT, capture_output=True, text=True)
    kept_c = read(os.path.join(c, "steps=100", "summary.json"))
    rc = sweep(c, "-resume", "1")
    said = [ln for ln in rc.stderr.splitlines() if ln.startswith("note: ")]
    again = [v for v in ("600", "700") if read(os.path.join(a, f"steps={v}", "history.csv"))
             == read(os.path.join(c, f"steps={v}", "history.csv"))]
    check(hand.returncode == 0 and rc.returncode == 0 and read(os.path.join(c, "steps=100", "summary.json")) == kept_c
          and any("-steps 600: its checkpoint cannot be continued" in ln for ln in said)
          and any("-steps 700: its summary.json is not one this sweep recorded" in ln for ln in said)
          and again == ["600", "700"],
          f"a changed checkpoint and a hand-made run: the resumed sweep exits {rc.returncode}, keeps its finished run, "
          f"runs both others again (equal to the uninterrupted sweep's: {again}), saying so: {[ln[:90] for ln in said]}")

    none = sweep(os.path.join(tmp, "empty"), "-resume", "1")
    check(none.returncode == 2 and "holds no sweep to resume" in none.stderr,
          f"-resume 1 where no sweep ran is refused (exit {none.returncode}): {none.stderr.strip()[:160]}")
    record("sweep_resume", {"test": "sweep_resume", "values": VALUES, "resumed": said})
    finish()


if __name__ == "__main__":
    main()
