#!/usr/bin/python3
"""The run's own error, stated at its end (edp/problems/sleeve/run-error.idp).

1. sleeve-3d estimates its mesh's error by default (-length 0.02: its companion on -nr 1 -nt 4):
   summary.json's run_error_estimate_transient is time_error_estimate_transient +
   mesh_error_estimate_transient (to the summary's 6 digits of the first), run_error_dominant names the larger, the report's line
   gives the same numbers, and the companion's folder holds its run.
2. A mesh that does not halve (-nr 3) skips it by default: no companion, the estimate null, the
   reason (naming -nr 3) in mesh_estimate_skipped and on the line; asked for (-meshestimate 1) it is
   refused naming -nr 3; -meshestimate 0 makes none and says how to get one.
3. A default companion that fails (its launcher made to fail for it alone: a copy of tools/ff in a
   tree of links to this checkout) is a warning: the run ends (exit 0) with its results, the
   estimate null and the failure named; the same failure with -meshestimate 1 asked fails the run;
   a companion that crawls (a 60 s sleep) is stopped at its budget (10 s and 4 times the run's
   loop), the run ending well before the sleep would, saying so.
4. -timeestimate 1: its companion (-tol 10 times looser) makes no mesh companion of its own.
5. sleeve-radial (the estimate by default): the other branch, the time steps' error the larger
   (nr 160: mesh 1e-4 against time 5e-4): the sum and "time"; with -meshestimate 0 the line says the
   mesh's is not estimated and the summary's estimate is null.
6. -phasemodel onoff (sleeve-radial): the line says the time steps' error is not estimated (the
   on/off jumps; Milne's device is 12 to 200 times below the curve's change with the steps there),
   gives the mesh's where asked, and the summary's sum and dominant part are null; by default it
   makes no mesh estimate there (the jumps fall at other steps on the coarser mesh), saying why.
7. Random thresholds (sleeve-random-threshold, -cspread 10): the companion draws its own, whose
   sampling the difference holds (seed to seed 8.4e-4 to 1.3e-3 over the transient, as large as the
   estimate): no estimate by default, the reason named; asked, made, and its line says so.
Writes results/checks/run_error.json.
"""
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, own_error_line, record, run_scene_captured, summary_of  # noqa: E402

SHORT_3D = ["-length", "0.02"]


def numbers_after(line, word):
    """The number after `word ` in the line (None if absent)."""
    found = re.search(re.escape(word) + r" ([-+0-9.e]+)", line)
    return float(found.group(1)) if found else None


def with_sum(label, out, proc, dominant):
    s = summary_of(out)
    time_error, mesh_error = s["time_error_estimate_transient"], s["mesh_error_estimate_transient"]
    total = s["run_error_estimate_transient"]
    check(proc.returncode == 0 and total is not None and abs(total - (time_error + mesh_error)) <= 1e-5 * time_error,
          f"{label}: run_error_estimate_transient {total} = time {time_error} + mesh {mesh_error}")
    larger = "mesh" if mesh_error > time_error else "time"
    check(s["run_error_dominant"] == larger == dominant, f"{label}: run_error_dominant {s['run_error_dominant']!r} "
          f"= the larger ({larger}), as expected here ({dominant})")
    line = own_error_line(proc)
    shown = [numbers_after(line, "time steps"), numbers_after(line, "mesh"), numbers_after(line, "together")]
    check(all(v is not None and abs(v - w) <= 1e-5 * abs(w) for v, w in zip(shown, (time_error, mesh_error, total))),
          f"{label}: the report's line gives them (time, mesh, together {shown}): {line!r}")
    return {"time": time_error, "mesh": mesh_error, "total": total}


def without(label, out, proc, skipped_names):
    s = summary_of(out)
    line = own_error_line(proc)
    skipped = s["mesh_estimate_skipped"]
    named = skipped is not None and skipped_names in skipped if skipped_names else skipped is None
    check(proc.returncode == 0 and s["run_error_estimate_transient"] is None and s["run_error_dominant"] is None
          and s["mesh_error_estimate"] is None and named,
          f"{label}: no estimate (null), mesh_estimate_skipped {skipped!r}")
    check("the mesh's not estimated" in line and (skipped_names or "-meshestimate 1") in line,
          f"{label}: the line says so: {line!r}")


FAIL_COMPANION = 'case " $* " in *" -nr 1 "*) echo "error: sabotaged companion" >&2; exit 7 ;; esac\n'
SLOW_COMPANION = 'case " $* " in *" -nr 1 "*) sleep 60 ;; esac\n'


def sabotaged_tree(sabotage):
    """A tree of links to this checkout whose tools/ff runs `sabotage` first (on the companions' -nr 1)."""
    tree = os.path.join(TEST_RESULTS, "run-error-tree")
    shutil.rmtree(tree, ignore_errors=True)
    os.makedirs(os.path.join(tree, "tools"))
    for name in os.listdir(ROOT):
        if name not in ("tools", "build", "results", ".git"):
            os.symlink(os.path.join(ROOT, name), os.path.join(tree, name))
    for name in os.listdir(os.path.join(ROOT, "tools")):
        if name != "ff":
            os.symlink(os.path.join(ROOT, "tools", name), os.path.join(tree, "tools", name))
    with open(os.path.join(ROOT, "tools", "ff")) as f:
        launcher = f.read().split("\n", 1)
    with open(os.path.join(tree, "tools", "ff"), "w") as f:
        f.write(launcher[0] + "\n" + sabotage + launcher[1])
    os.chmod(os.path.join(tree, "tools", "ff"), 0o755)
    return tree


def main():
    figures = {}
    # 1. sleeve-3d: by default
    out, proc = run_scene_captured("sleeve-3d", "run-error-3d", *SHORT_3D)
    figures["3d"] = with_sum("sleeve-3d defaults", out, proc, "mesh")
    companion = os.path.join(out, "mesh-estimate")
    s = summary_of(out)
    check(os.path.isfile(os.path.join(companion, "summary.json")) and summary_of(companion)["parameters"]["nr"] == 1
          and summary_of(companion)["parameters"]["nt"] == 4 and s["mesh_estimate_skipped"] is None,
          f"sleeve-3d: its companion ran on -nr 1 -nt 4 ({companion})")

    # 2. a mesh that does not halve
    out, proc = run_scene_captured("sleeve-3d", "run-error-3d-odd", *SHORT_3D, "-nr", "3")
    without("sleeve-3d -nr 3", out, proc, "-nr 3")
    check(not os.path.exists(os.path.join(out, "mesh-estimate")), "sleeve-3d -nr 3: no companion")
    out, proc = run_scene_captured("sleeve-3d", "run-error-3d-odd-asked", *SHORT_3D, "-nr", "3", "-meshestimate", "1")
    errors = [line for line in (proc.stdout + proc.stderr).splitlines() if line.startswith("error:")]
    check(proc.returncode != 0 and errors and "-nr 3" in errors[0] and "-meshestimate 1" in errors[0],
          f"sleeve-3d -nr 3 -meshestimate 1: refused (exit {proc.returncode}) {errors}")
    out, proc = run_scene_captured("sleeve-3d", "run-error-3d-off", *SHORT_3D, "-meshestimate", "0")
    without("sleeve-3d -meshestimate 0", out, proc, None)

    # 3. a default companion that fails
    tree = sabotaged_tree(FAIL_COMPANION)
    for asked in ([], ["-meshestimate", "1"]):
        # (a quote in the folder's name: the skip's reason, naming the companion's log, is JSON-quoted)
        out = os.path.join(TEST_RESULTS, 'run-error-3d-sabo"taged' + ("-asked" if asked else ""))
        proc = subprocess.run([os.path.join(tree, "tools", "ff"), "edp/scenes/sleeve-3d.edp", "-out", out, *SHORT_3D,
                               *asked], cwd=tree, capture_output=True, text=True)
        if asked:
            check(proc.returncode != 0 and "the run on -nr 1 -nt 4 failed" in proc.stdout + proc.stderr,
                  f"a failing companion asked for (-meshestimate 1): the run fails (exit {proc.returncode})")
        else:
            warned = [line for line in (proc.stdout + proc.stderr).splitlines()
                      if line.startswith("warning:") and "companion" in line]
            check(proc.returncode == 0 and warned and "failed (exit 7" in warned[0],
                  f"a failing default companion: exit {proc.returncode}, warned {warned}")
            without("sleeve-3d, its companion failing", out, proc, "failed (exit 7")
    # a default companion that crawls: stopped at its budget (10 s and 4 times the run's loop)
    tree = sabotaged_tree(SLOW_COMPANION)
    out = os.path.join(TEST_RESULTS, "run-error-3d-slow")
    start = time.monotonic()
    proc = subprocess.run([os.path.join(tree, "tools", "ff"), "edp/scenes/sleeve-3d.edp", "-out", out, *SHORT_3D],
                          cwd=tree, capture_output=True, text=True)
    seconds = time.monotonic() - start
    loop = summary_of(out)["wall_seconds"] if proc.returncode == 0 else 0
    check(proc.returncode == 0 and "ran beyond its budget" in proc.stdout + proc.stderr and seconds < 30 + 4 * loop,
          f"a crawling default companion (a 60 s sleep): stopped at its budget, the run ends in {seconds:.1f} s (exit "
          f"{proc.returncode})")
    without("sleeve-3d, its companion crawling", out, proc, "ran beyond its budget")
    shutil.rmtree(tree, ignore_errors=True)

    # 4. -timeestimate's companion makes no mesh companion of its own
    out, proc = run_scene_captured("sleeve-3d", "run-error-3d-time", *SHORT_3D, "-timeestimate", "1")
    check(proc.returncode == 0 and os.path.isfile(os.path.join(out, "time-estimate", "summary.json"))
          and not os.path.exists(os.path.join(out, "time-estimate", "mesh-estimate"))
          and summary_of(os.path.join(out, "time-estimate"))["mesh_error_estimate"] is None,
          f"sleeve-3d -timeestimate 1: its companion estimated no mesh error (exit {proc.returncode})")

    # 5. sleeve-radial: by default, the time steps' the larger; -meshestimate 0 none
    out, proc = run_scene_captured("sleeve-radial", "run-error-radial")
    figures["radial"] = with_sum("sleeve-radial defaults", out, proc, "time")
    out, proc = run_scene_captured("sleeve-radial", "run-error-radial-off", "-meshestimate", "0")
    without("sleeve-radial -meshestimate 0", out, proc, None)

    # 6. the on/off phases: no time estimate claimed (their jumps are not in Milne's device)
    out, proc = run_scene_captured("sleeve-radial", "run-error-radial-onoff", "-phasemodel", "onoff", "-meshestimate", "1")
    s, line = summary_of(out), own_error_line(proc)
    out, default = run_scene_captured("sleeve-radial", "run-error-radial-onoff-default", "-phasemodel", "onoff")
    without("sleeve-radial -phasemodel onoff (by default)", out, default, "on/off phases")
    check(proc.returncode == 0 and s["run_error_estimate_transient"] is None and s["run_error_dominant"] is None
          and s["mesh_error_estimate_transient"] is not None and "the time steps' not estimated" in line
          and f"mesh {s['mesh_error_estimate_transient']:.6g}" in line,
          f"sleeve-radial -phasemodel onoff: the time steps' error not claimed, the mesh's given: {line!r}")

    # 7. random thresholds (-cspread): the companion draws its own, so not by default; asked, said
    coarse = ["-mesh", "meshes/sleeve-coarse.msh"]
    out, proc = run_scene_captured("sleeve-random-threshold", "run-error-random", *coarse)
    without("sleeve-random-threshold (by default)", out, proc, "random thresholds")
    out, proc = run_scene_captured("sleeve-random-threshold", "run-error-random-asked", *coarse, "-meshestimate", "1")
    line = own_error_line(proc)
    check(proc.returncode == 0 and summary_of(out)["mesh_error_estimate_transient"] is not None
          and "random thresholds" in line and "sampling" in line,
          f"sleeve-random-threshold -meshestimate 1: the estimate made, its line says it holds the sampling: {line!r}")

    record("run_error", figures)
    finish()


if __name__ == "__main__":
    main()
