#!/usr/bin/python3
"""A resumed run verifies the result files it keeps from before its checkpoint (checkpoint.idp, "kept").

sleeve-circular on the coarse mesh, 300 steps, a checkpoint every 50, a ParaView frame every 50
(-vtkevery 50), stopped after step 130 (-stopafter 130, exit 4): its checkpoint of step 100 lists
as kept the instant 1-dilated's fields and the frames of steps 50 and 100 (files the remaining
steps do not write again), each with its checksum. Three copies of the stopped folder, resumed:
  - untouched: the resume finishes (exit 0) and every file equals the uninterrupted run's byte for
    byte (summary.json but for the timing and resumed_from_step);
  - a kept frame changed (a byte appended): the resume fails (exit 1) with one error line naming
    that file, before anything is touched (no summary.json; the frame as it was left);
  - a kept instant's file removed: the resume fails naming it.
Also sleeve-radial (no frames): its kept fields-1-dilated.csv changed fails the same way.
Writes results/checks/resume_kept.json.
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

# (-meshestimate 0: the companion's summary and log hold its own timings, which no two runs share)
COMMON = ["-steps", "300", "-quiet", "1", "-meshestimate", "0"]
TIMING = ("wall_seconds", "resumed_from_step", "backsolve_floor_seconds_per_step", "loop_over_floor",
          "stiffness_backsolve_seconds", "heat_backsolve_seconds", "backsolves_needed_seconds",
          "loop_over_backsolves_needed", "loop_over_backsolves_needed_transient", "loop_over_backsolves_needed_tail")


def run(scene, out, *extra):
    return subprocess.run([os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", *COMMON, *extra,
                           "-out", out], cwd=ROOT, capture_output=True, text=True, timeout=300)




def differing(a, b):
    fa, fb = files(a), files(b)
    out = sorted(set(fa) ^ set(fb))
    for name in sorted(set(fa) & set(fb)):
        if name in ("summary.json", ".sma-results"):
            continue
        with open(fa[name], "rb") as x, open(fb[name], "rb") as y:
            if x.read() != y.read():
                out.append(name)
    return out


def error_lines(p):
    return [line for line in (p.stdout + p.stderr).splitlines() if line.startswith("error:")]


def kept_of(folder):
    with open(os.path.join(folder, "checkpoint.txt")) as f:
        for line in f:
            if line.startswith("kept"):
                words = line.split()[1:]
                return dict(zip(words[0::2], words[1::2]))
    return None


def main():
    measured = {}
    with tempfile.TemporaryDirectory(prefix="resume-kept-") as tmp:
        # ---- sleeve-circular: instants and frames ----
        options = ["-mesh", "meshes/sleeve-coarse.msh", "-vtkevery", "50", "-checkpoint", "50"]
        full, stopped = os.path.join(tmp, "full"), os.path.join(tmp, "stopped")
        ra = run("sleeve-circular", full, *options)
        rb = run("sleeve-circular", stopped, *options, "-stopafter", "130")
        check(ra.returncode == 0 and rb.returncode == 4,
              f"sleeve-circular: the uninterrupted run finishes (exit {ra.returncode}) and -stopafter 130 exits 4 "
              f"(got {rb.returncode})")
        kept = kept_of(stopped) or {}
        expected = {"fields-1-dilated.vtu", "fields-1-dilated.csv", "frames/step-000050.vtu", "frames/step-000100.vtu"}
        check(expected <= set(kept) and not {"fields.pvd", "history.csv", "points.csv", "checkpoint.txt"} & set(kept)
              and not any(k.startswith("frames/step-00015") for k in kept),
              f"the checkpoint of step 100 keeps the files published before it that the rest does not rewrite: "
              f"{sorted(kept)}")
        copies = {k: os.path.join(tmp, k) for k in ("untouched", "frame", "removed")}
        for path in copies.values():
            shutil.copytree(stopped, path)

        r = run("sleeve-circular", copies["untouched"], *options, "-resume", "1")
        diff = differing(full, copies["untouched"])
        sa, sb = (json.load(open(os.path.join(f, "summary.json"))) for f in (full, copies["untouched"]))
        for s in (sa, sb):
            for key in TIMING:
                s.pop(key, None)
        check(r.returncode == 0 and not diff and sa == sb,
              f"an untouched resume finishes (exit {r.returncode}) and equals the uninterrupted run byte for byte "
              f"(differ: {diff}; summary {'equal' if sa == sb else 'DIFFERS'})")
        measured["untouched_differ"] = diff

        frame = os.path.join(copies["frame"], "frames", "step-000050.vtu")
        with open(frame, "ab") as f:
            f.write(b"\n")
        before = open(frame, "rb").read()
        r = run("sleeve-circular", copies["frame"], *options, "-resume", "1")
        errors = error_lines(r)
        check(r.returncode == 1 and len(errors) == 1 and "frames/step-000050.vtu" in errors[0]
              and "changed since the checkpoint" in errors[0],
              f"a kept frame changed since the checkpoint: the resume fails (exit {r.returncode}) naming it: {errors}")
        check(not os.path.exists(os.path.join(copies["frame"], "summary.json"))
              and open(frame, "rb").read() == before
              and os.path.exists(os.path.join(copies["frame"], "history.csv.partial")),
              "... before anything is touched (no summary.json, the frame and history.csv.partial as they were)")
        measured["frame_error"] = errors

        os.remove(os.path.join(copies["removed"], "fields-1-dilated.vtu"))
        r = run("sleeve-circular", copies["removed"], *options, "-resume", "1")
        errors = error_lines(r)
        check(r.returncode == 1 and len(errors) == 1 and "fields-1-dilated.vtu" in errors[0] and "missing" in errors[0],
              f"a kept instant's file removed: the resume fails (exit {r.returncode}) naming it: {errors}")
        measured["removed_error"] = errors

        # ---- sleeve-radial: its instant's CSV ----
        radial = os.path.join(tmp, "radial")
        rr = run("sleeve-radial", radial, "-checkpoint", "50", "-stopafter", "130")
        kept = kept_of(radial) or {}
        check(rr.returncode == 4 and "fields-1-dilated.csv" in kept,
              f"sleeve-radial: -stopafter 130 exits 4 (got {rr.returncode}), its checkpoint keeps {sorted(kept)}")
        with open(os.path.join(radial, "fields-1-dilated.csv"), "a") as f:
            f.write("0,0,0\n")
        r = run("sleeve-radial", radial, "-checkpoint", "50", "-resume", "1")
        errors = error_lines(r)
        check(r.returncode == 1 and len(errors) == 1 and "fields-1-dilated.csv" in errors[0],
              f"sleeve-radial: a kept CSV changed: the resume fails (exit {r.returncode}) naming it: {errors}")
        measured["radial_error"] = errors
    record("resume_kept", {"test": "resume_kept", **measured})


if __name__ == "__main__":
    main()
    finish()
