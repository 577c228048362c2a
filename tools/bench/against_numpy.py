"""make bench, section 8 (tools/bench/bench.py): sleeve-radial against numpy: the scene against
tools/bench/oracles/radial_numpy.py (the same scheme written again in vectorised numpy), whole
process and loop time, and the curve difference. doc() writes its part of docs/benchmarks.md."""
import json
import os
import statistics
import subprocess
import sys
import time

from common import OUT, QUICK, ROOT, run
from curve_error import curve_error

# sleeve-radial against numpy (elements, steps): the default first. The finer levels pass
# -fpmaxit 1000 to both: their fixed point takes up to about 200 iterations at some steps (the
# default limit), and a run that stops at the limit measures nothing.
NUMPY_LEVELS = [(160, 1000), (320, 1600), (640, 3200)]
NUMPY_REPEATS = 3
if QUICK:
    NUMPY_LEVELS = [(20, 200), (40, 300)]
    NUMPY_REPEATS = 1


def radial_against_numpy():
    """Section 8: sleeve-radial (tools/ff) against tools/bench/oracles/radial_numpy.py at NUMPY_LEVELS; times
    are medians of NUMPY_REPEATS runs, whole process and loop alone."""
    rows = []
    for nr, steps in NUMPY_LEVELS:
        extra = [] if (nr, steps) == NUMPY_LEVELS[0] else ["-fpmaxit", 1000]
        args = ["-nr", nr, "-steps", steps, *extra]
        ff_dir, np_dir = os.path.join(OUT, f"numpy-ff-{nr}-{steps}"), os.path.join(OUT, f"numpy-np-{nr}-{steps}")
        ff_runs, np_runs = [], []
        for k in range(NUMPY_REPEATS):
            print(f"bench: sleeve-radial against numpy, nr {nr} steps {steps}, run {k + 1}", flush=True)
            wall, s, _ = run("edp/scenes/sleeve-radial.edp", ff_dir, "-quiet", 1, *args)
            ff_runs.append((wall, s["wall_seconds"]))
            os.makedirs(np_dir, exist_ok=True)
            start = time.perf_counter()
            proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools", "bench", "oracles", "radial_numpy.py"),
                                   "-out", np_dir, *map(str, args)], cwd=ROOT, capture_output=True, text=True)
            wall = time.perf_counter() - start
            if proc.returncode != 0:
                sys.exit(f"bench: tools/bench/oracles/radial_numpy.py {' '.join(map(str, args))} failed: {proc.stderr.strip()}")
            ns = json.load(open(os.path.join(np_dir, "summary.json")))
            np_runs.append((wall, ns["loop_seconds"]))
        err = curve_error(os.path.join(np_dir, "history.csv"), os.path.join(ff_dir, "history.csv"))
        # What the DC loop's tolerance fixes: the same scene at -dctol 1e-9 against itself.
        tight_dir = os.path.join(OUT, f"numpy-ff-{nr}-{steps}-dctol1e-9")
        print(f"bench: sleeve-radial nr {nr} steps {steps} at -dctol 1e-9", flush=True)
        _, tight_summary, tight_failure = run("edp/scenes/sleeve-radial.edp", tight_dir, "-quiet", 1, *args,
                                              "-dctol", 1e-9, allow_failure=True)
        tight = (curve_error(os.path.join(tight_dir, "history.csv"), os.path.join(ff_dir, "history.csv"))
                 if tight_summary else {"l1_transient": None, "linf": None})
        ff_whole, ff_loop = (statistics.median(x[i] for x in ff_runs) for i in (0, 1))
        np_whole, np_loop = (statistics.median(x[i] for x in np_runs) for i in (0, 1))
        rows.append({"nr": nr, "steps": steps, "options": " ".join(map(str, extra)),
                     "freefem_wall_seconds": ff_whole, "freefem_loop_seconds": ff_loop,
                     "numpy_wall_seconds": np_whole, "numpy_loop_seconds": np_loop,
                     "ratio_wall": ff_whole / np_whole, "ratio_loop": ff_loop / np_loop,
                     "freefem_runs": ff_runs, "numpy_runs": np_runs,
                     "curve_difference": err["l1_transient"], "curve_difference_whole": err["l1"],
                     "curve_difference_linf": err["linf"], "final_pressure_difference": err["final"],
                     "dctol_1e-9_difference": tight["l1_transient"], "dctol_1e-9_difference_linf": tight["linf"],
                     "dctol_1e-9_failure": tight_failure or None,
                     "freefem_fixed_point_iterations_mean": s["fixed_point_iterations_mean"],
                     "numpy_fixed_point_iterations_mean": ns["fixed_point_iterations_mean"],
                     "freefem_dc_iterations_mean": s["dc_iterations_mean"],
                     "numpy_dc_iterations_mean": ns["dc_iterations_mean"]})
    return rows


def doc(r, w):
    """sleeve-radial against numpy."""
    w("## sleeve-radial against numpy")
    w("")
    w("The same discretisation computed twice: `edp/scenes/sleeve-radial.edp` (FreeFEM, the scripts and the plugin, "
      "its default step solver `-stepsolver newton`) and `tools/bench/oracles/radial_numpy.py` (the paper's nested loops: the "
      "same step equations solved by another method, docs/parameters.md, Step solver), written again from the equations in vectorised numpy (tridiagonal "
      "stiffness and heat matrices LDL' factorised once by LAPACK, the local step over all points at "
      "once; Python loops only over steps, fixed-point and DC iterations). Same defaults; the finer "
      "levels pass `-fpmaxit 1000` to both. Wall times: median of "
      f"{NUMPY_REPEATS} run{'s' if NUMPY_REPEATS > 1 else ''}; *whole*: the process (FreeFEM or Python start, "
      "setup, loop, output), *loop*: the time loop alone (the scene's `wall_seconds`, the script's "
      "`loop_seconds`); ratio = FreeFEM / numpy. Curve difference: tools/bench/oracles/curve_error.py of the numpy "
      "history against FreeFEM's (transient L1, max over the curve, final pressure); *-dctol 1e-9*: the "
      "scene at `-dctol 1e-9` against itself at the default 1e-3, the digits the DC loop's tolerance "
      "fixes. The final state is elastic, where no loop truncates: there the two agree to round-off.")
    w("")
    w("| elements | steps | whole FreeFEM (s) | whole numpy (s) | ratio | loop FreeFEM (s) | loop numpy (s) | ratio | "
      "curve difference (transient) | max | final pressure | -dctol 1e-9 (transient / max) | "
      "fixed-point its mean FreeFEM / numpy |")
    w("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for x in r["radial_numpy"]:
        w(f"| {x['nr']} | {x['steps']} | {x['freefem_wall_seconds']:.2f} | {x['numpy_wall_seconds']:.2f} | "
          f"{x['ratio_wall']:.2f} | {x['freefem_loop_seconds']:.2f} | {x['numpy_loop_seconds']:.2f} | "
          f"{x['ratio_loop']:.2f} | {x['curve_difference']:.1e} | {x['curve_difference_linf']:.1e} | "
          f"{x['final_pressure_difference']:.1e} | "
          + (f"{x['dctol_1e-9_difference']:.1e} / {x['dctol_1e-9_difference_linf']:.1e}"
             if x["dctol_1e-9_difference"] is not None else f"failed: {x['dctol_1e-9_failure']}")
          + f" | {x['freefem_fixed_point_iterations_mean']:.2f} / "
          f"{x['numpy_fixed_point_iterations_mean']:.2f} |")
    w("")
