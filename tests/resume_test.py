#!/usr/bin/python3
"""A sleeve run stopped half-way and resumed (-checkpoint N, -resume 1) equals the uninterrupted run.

For sleeve-circular and sleeve-elliptic-friction (coarse mesh: the friction scene covers the
contact warm start, the slip thresholds and the slip history), sleeve-radial and a variant whose
heat-condition hook depends on time (tests/hooks/heat-ramp.edp, docs/hooks.md), 300 steps,
a checkpoint every 50 (and sleeve-circular with moving layers, -movinglayers 1, whose layers
move after steps 116-137: a checkpoint every 10, stopped after 125, so that the checkpoint of
step 120 holds a moved mesh and the resumed run moves it again; and sleeve-circular stopped after
its time loop, its per-step files published whole: a stop during its mesh-error companion, which
a resume must continue from the published files cut back, where it failed on the missing
unfinished copies):
  - A: the uninterrupted run with -checkpoint 50; its outputs equal, byte for byte, those of the
    same run without -checkpoint (writing checkpoints changes nothing) and it leaves no
    checkpoint.txt behind (a finished run has nothing to resume);
  - B: the same run stopped after step 130 by -stopafter 130 (exit 4, as a crash: nothing
    published, history.csv.partial holding the 30 rows past the checkpoint of step 100), in the
    folder of the plain run, which stays whole in previous-run/ until B completes, with a
    half-written checkpoint.txt.partial added as a kill during a checkpoint's write leaves it;
    then resumed with -resume 1 (exit 0);
  - every file of B (CSVs, fields, VTU frames, fields.pvd) equals A's byte for byte, and B's
    summary.json equals A's but for the wall-clock time and its "resumed_from_step": 100.
Why -stopafter rather than SIGKILL at a random time: these runs take about a second, so a kill
after the checkpoint of step 100 and before the end would be a race; the state a kill leaves (a
published checkpoint, CSVs longer than it records, a stray .partial) is made here exactly, and
the resume reads nothing else. Writes results/checks/resume.json.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402
from checklib import files_under as files  # noqa: E402

# (scene, options, checkpoint every, stopped after): resumed from the last checkpoint before the stop
CASES = [("sleeve-circular", ["-mesh", "meshes/sleeve-coarse.msh"], 50, 130),
         ("sleeve-elliptic-friction", ["-mesh", "meshes/sleeve-coarse.msh"], 50, 130),
         ("sleeve-radial", [], 50, 130),
         # a variant's hook that depends on time through sleeveTime (docs/hooks.md, rule 3)
         ("tests/hooks/heat-ramp.edp", [], 50, 130),
         # the moving layers' mesh, moved before the checkpoint and after it
         ("sleeve-circular", ["-movinglayers", "1"], 10, 125),
         # the contact's own heat transfer: the heat condition switches and is solved again (its
         # counts in summary.json, which a resumed run counted from 0 again)
         ("sleeve-radial", ["-gcontact", "2000"], 50, 130),
         # stopped after its time loop (during its mesh-error companion, its summary): the per-step
         # files are published, longer than the checkpoint records
         ("sleeve-circular", ["-mesh", "meshes/sleeve-coarse.msh"], 50, 130, "after its loop")]
# (-meshestimate 0: the companion's summary and log hold its own timings, which no two runs share)
COMMON = ["-steps", "300", "-quiet", "1", "-meshestimate", "0"]
TIMING = ("wall_seconds", "resumed_from_step", "backsolve_floor_seconds_per_step", "loop_over_floor",
          "stiffness_backsolve_seconds", "heat_backsolve_seconds", "backsolves_needed_seconds",
          "loop_over_backsolves_needed", "loop_over_backsolves_needed_transient", "loop_over_backsolves_needed_tail",
          "layer_move_seconds")


def run(scene, out, *extra):
    script = scene if scene.endswith(".edp") else f"edp/scenes/{scene}.edp"
    return subprocess.run([os.path.join(ROOT, "tools", "ff"), script, *COMMON, *extra,
                           "-out", out], cwd=ROOT, capture_output=True, text=True, timeout=300)




def same_files(a, b, skip=("summary.json",)):
    """Names of the files that differ or are in one folder only (summary.json compared apart)."""
    fa, fb = files(a), files(b)
    differ = sorted(set(fa) ^ set(fb))
    for name in sorted(set(fa) & set(fb)):
        if name in skip:
            continue
        if name == ".sma-results":  # the manifests: the same entries, the checkpoint's apart
            with open(fa[name]) as x, open(fb[name]) as y:
                if set(x.read().splitlines()) - {"checkpoint.txt"} != set(y.read().splitlines()) - {"checkpoint.txt"}:
                    differ.append(name)
            continue
        with open(fa[name], "rb") as x, open(fb[name], "rb") as y:
            if x.read() != y.read():
                differ.append(name)
    return differ, len(fa)


def main():
    measured, temperatures = [], {}
    with tempfile.TemporaryDirectory(prefix="resume-") as tmp:
        for case, (scene, options, every, stop, *when) in enumerate(CASES):
            name = os.path.basename(scene) + ("" if case == 0 or scene != CASES[0][0] else f"-{case}")
            label = f"{scene} {' '.join(options)}".strip() + (f", stopped {when[0]}" if when else "")
            at = stop - stop % every  # the checkpoint the resumed run starts from
            plain, full = (os.path.join(tmp, f"{name}-{k}") for k in ("plain", "A"))
            r0 = run(scene, plain, *options)
            ra = run(scene, full, *options, "-checkpoint", str(every))
            check(r0.returncode == 0 and ra.returncode == 0,
                  f"{label}: the runs without and with -checkpoint {every} finish (exit {r0.returncode}, {ra.returncode})"
                  + ("" if r0.returncode == ra.returncode == 0 else (r0.stdout + ra.stdout)[-400:]))
            differ, count = same_files(plain, full, skip=())
            differ = [d for d in differ if d != "summary.json"]
            sa, s0 = (json.load(open(os.path.join(f, "summary.json"))) for f in (full, plain))
            for s in (sa, s0):
                for key in TIMING:
                    s.pop(key, None)
            check(not differ and sa == s0 and not os.path.exists(os.path.join(full, "checkpoint.txt")),
                  f"{label}: writing checkpoints changes none of the {count} output files "
                  f"(differ: {differ}; summary {'equal' if sa == s0 else 'DIFFERS'}) and the finished run "
                  "leaves no checkpoint.txt")

            # B runs in the plain run's folder: that complete run is kept whole in previous-run/
            # while B has not completed, and said so at B's exit; B's completion removes it.
            stopped = plain
            with open(os.path.join(plain, "summary.json"), "rb") as f:
                complete_summary = f.read()
            rb = run(scene, stopped, *options, "-checkpoint", str(every), "-stopafter", str(stop))
            kept = os.path.join(stopped, "previous-run", "summary.json")
            check(os.path.isfile(kept) and open(kept, "rb").read() == complete_summary
                  and f"are kept whole in {stopped}/previous-run" in rb.stderr,
                  f"{label}: the stopped run leaves the folder's complete run whole in previous-run/ "
                  f"({'kept' if os.path.isfile(kept) else 'MISSING'}) and says so at its exit")
            checkpoint = os.path.join(stopped, "checkpoint.txt")
            text = open(checkpoint).read() if os.path.exists(checkpoint) else ""
            rows = sum(1 for _ in open(os.path.join(stopped, "history.csv.partial"))) - 1 \
                if os.path.exists(os.path.join(stopped, "history.csv.partial")) else -1
            check(f"-resume 1 continues from the checkpoint of step {at})" in rb.stdout,
                  f"{label}: the stop's line names the checkpoint a resume continues from (step {at})")
            check(rb.returncode == 4 and f"\nstep {at}\n" in text and rows == stop
                  and not os.path.exists(os.path.join(stopped, "summary.json")),
                  f"{label}: -stopafter {stop} exits 4 (got {rb.returncode}) leaving the checkpoint of step {at} "
                  f"({'found' if f'step {at}' in text else 'MISSING'}), {rows} history rows ({stop}: {stop - at} "
                  "to cut), no summary.json")
            if "-movinglayers" in options:
                # (the case tests the moved mesh only if the layers moved before the checkpoint and after)
                with open(os.path.join(full, "mesh-moves.csv")) as f:
                    moves = [int(line.split(",")[0]) for line in list(f)[1:]]
                check(any(m <= at for m in moves) and any(m > at for m in moves) and "\nlayersR " in text,
                      f"{label}: the layers moved before the checkpoint of step {at} and after it (after steps "
                      f"{moves}), and the checkpoint holds their radii")
            with open(os.path.join(stopped, "checkpoint.txt.partial"), "w") as f:
                f.write("sma-sleeve-checkpoint 1\nscene half-writ")  # a kill during the next write
            if when:  # the loop's end publishes its per-step files whole (time-loop.idp), then a stop
                for stream in ("history.csv", "points.csv"):
                    os.replace(os.path.join(stopped, stream + ".partial"), os.path.join(stopped, stream))
            rr = run(scene, stopped, *options, "-checkpoint", str(every), "-resume", "1")
            check(rr.returncode == 0, f"{label}: -resume 1 finishes (exit {rr.returncode})"
                  + ("" if rr.returncode == 0 else " " + (rr.stdout + rr.stderr)[-400:]))
            check(not os.path.exists(os.path.join(stopped, "previous-run")),
                  f"{label}: the resumed run's completion removes previous-run/")
            differ, count = same_files(full, stopped)
            sb = json.load(open(os.path.join(stopped, "summary.json")))
            resumed_from = sb.get("resumed_from_step")
            sa = json.load(open(os.path.join(full, "summary.json")))
            for s in (sa, sb):
                for k in TIMING:
                    s.pop(k, None)
            check(not differ and sa == sb and resumed_from == at,
                  f"{label}: the resumed run's {count} files equal the uninterrupted run's byte for byte "
                  f"(differ: {differ}), its summary.json too but for the timing "
                  f"({'equal' if sa == sb else 'DIFFERS'}), resumed_from_step {resumed_from} ({at})")
            with open(os.path.join(full, "history.csv")) as f:
                lines = [line.split(",") for line in f]
                column = lines[0].index("T_inner_mean")
                temperatures[label] = [words[column] for words in lines[1:]]
            measured.append({"scene": label, "checkpoint_every": every, "stopped_after": stop, "files": count, "differ": differ, "summary_equal": sa == sb,
                             "resumed_from_step": resumed_from, "rows_at_stop": rows})
            for folder in (plain, full):
                shutil.rmtree(folder, ignore_errors=True)
    # A resumed run stopped again says which checkpoint is left, whatever its own -checkpoint: the one
    # it resumed from (it said "nothing to resume" with -checkpoint 0, or before its own first one).
    with tempfile.TemporaryDirectory(prefix="resume-again-") as tmp:
        out = os.path.join(tmp, "out")
        first = run("sleeve-radial", out, "-checkpoint", "20", "-stopafter", "30")
        said = [first.stdout.strip().splitlines()[-1:]]
        for every in ("0", "50"):
            again = run("sleeve-radial", out, "-checkpoint", every, "-resume", "1", "-stopafter", "45")
            said.append(again.stdout.strip().splitlines()[-1:])
            check(again.returncode == 4 and "continues from the checkpoint of step 20)" in again.stdout,
                  f"sleeve-radial resumed from step 20 with -checkpoint {every}, stopped after 45: exit "
                  f"{again.returncode} (4), its line names the checkpoint of step 20: {said[-1]}")
        final = run("sleeve-radial", out, "-checkpoint", "0", "-resume", "1")
        check(final.returncode == 0 and not os.path.exists(os.path.join(out, "checkpoint.txt")),
              f"then resumed to the end (exit {final.returncode}), the checkpoint removed")

    # The hook acted: its air temperature, swinging with sleeveTime, moved the inner temperature
    # away from sleeve-circular's on the same mesh (a hook that saw sleeveTime = 0 would not).
    ramp = temperatures.get("tests/hooks/heat-ramp.edp", [])
    base = temperatures.get("sleeve-circular -mesh meshes/sleeve-coarse.msh", [])
    differing = sum(1 for a, b in zip(ramp, base) if a != b)
    check(len(ramp) == len(base) == 300 and differing > 200,
          f"the time-dependent hook changes the inner temperature at {differing} of {len(ramp)} steps")
    record("resume", {"test": "resume", "steps": 300, "runs": measured})
    finish()


if __name__ == "__main__":
    main()
