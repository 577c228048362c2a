"""make bench, section 3 (tools/bench/bench.py): the default scene (1500 steps, default mesh)
three times: wall time, back-solves and iteration counts, what the frames and FreeFEM's clock()
cost; the friction scene's iteration counts; the elliptic pipe's lift-off. doc() writes where the
default run's time goes and the iteration counts of docs/benchmarks.md."""
import csv
import os
import statistics

from common import OUT, QUICK, read_csv, run
from curve_error import curve_error


def elliptic_liftoff(points_csv):
    """First contact at the axis that touches first; the lowest force there before the other axis
    touches (0: the paper's lift-off)."""
    points = read_csv(points_csv)
    x = points["pressure_x_axis_Pa"]
    y = points["pressure_y_axis_Pa"]
    fx = next(i for i, v in enumerate(x) if v > 0)
    fy = next(i for i, v in enumerate(y) if v > 0)
    first, other = (y, fx) if fy < fx else (x, fy)
    start = min(fx, fy)
    peak = max(first[start:other])
    low = min(first[start + first[start:other].index(peak):other]) if other > start else peak
    return {"first_axis": "y" if fy < fx else "x", "first_contact_step": start + 1,
            "second_contact_step": other + 1, "peak_before_second_Pa": peak,
            "lowest_after_peak_Pa": low, "lift_off": low == 0}


def measure(results, reference):
    """The default runs, the friction scene and the lift-off, into `results`."""
    default_runs = []
    for k in range(1 if QUICK else 3):
        print(f"bench: sleeve-circular default, run {k + 1}", flush=True)
        wall, s, _ = run("edp/scenes/sleeve-circular.edp", os.path.join(OUT, "circular-default"),
                         "-quiet", 1)
        default_runs.append((wall, s))
    s = default_runs[-1][1]
    results["sleeve_circular_1500_wall_seconds"] = statistics.median(w for w, _ in default_runs)
    results["sleeve_circular_1500_runs"] = [w for w, _ in default_runs]
    results["sleeve_circular_1500_loop_seconds"] = statistics.median(x["wall_seconds"] for _, x in default_runs)
    results["sleeve_circular_1500_loop_over_floor"] = statistics.median(x["loop_over_floor"] for _, x in default_runs)
    results["sleeve_circular_1500_floor_seconds_per_step"] = statistics.median(
        x["backsolve_floor_seconds_per_step"] for _, x in default_runs)
    # The back-solves the algorithm needed (one per DC iteration, one heat solve per fixed-point
    # iteration, at the run's own times) and the loop over them: what the scripts add.
    for key in ("stiffness_backsolve_seconds", "heat_backsolve_seconds", "backsolves_needed_seconds",
                "loop_over_backsolves_needed", "loop_over_backsolves_needed_transient",
                "loop_over_backsolves_needed_tail"):
        results[f"sleeve_circular_1500_{key}"] = statistics.median(x[key] for _, x in default_runs)
    # Where the iterations fall: the transient (up to the step the ring is austenite for good) and the tail.
    with open(os.path.join(OUT, "circular-default", "history.csv")) as f:
        steps = list(csv.DictReader(f))
    transient = [r for r in steps if int(r["step"]) < s["austenite_step"]]
    tail = [r for r in steps if int(r["step"]) >= s["austenite_step"]]
    results["sleeve_circular_1500_phases"] = {
        name: {"steps": len(rows), "dc_per_step": sum(float(r["dc_iterations"]) for r in rows) / max(len(rows), 1),
               "fixed_point_per_step": sum(float(r["fixed_point_iterations"]) for r in rows) / max(len(rows), 1)}
        for name, rows in (("transient", transient), ("tail", tail))}
    # What the ParaView frames cost (-vtkevery 50 by default against only the three instants), and
    # what the preloaded clock() (plugin/fastclock.c) saves: the same run with FreeFEM's own.
    variants = {}
    for name, extra, env in (("no_frames", ["-vtkevery", 0], {}), ("stock_clock", [], {"SMA_FASTCLOCK": "0"}),
                             ("every_step_a_frame", ["-vtkevery", 1], {})):
        walls = []
        for k in range(1 if QUICK or name == "every_step_a_frame" else 3):
            print(f"bench: sleeve-circular default, {name}, run {k + 1}", flush=True)
            wall, x, _ = run("edp/scenes/sleeve-circular.edp", os.path.join(OUT, f"circular-{name}"), "-quiet", 1,
                             *extra, env=env)
            walls.append((wall, x["wall_seconds"]))
        variants[name] = {"wall_seconds": statistics.median(w for w, _ in walls),
                          "loop_seconds": statistics.median(l for _, l in walls)}
    results["sleeve_circular_1500_variants"] = variants
    frames = os.path.join(OUT, "circular-default", "frames")
    results["sleeve_circular_1500_frames"] = len(os.listdir(frames)) if os.path.isdir(frames) else 0
    err = curve_error(os.path.join(OUT, "circular-default", "history.csv"), reference)
    results["sleeve_circular_1500_curve_error"] = err["l1_transient"]
    results["sleeve_circular_1500_curve_error_whole_process"] = err["l1"]
    results["iterations_mean_per_step"] = {"fixed_point": s["fixed_point_iterations_mean"],
                                           "slip_threshold": s["slip_threshold_iterations_mean"],
                                           "dc": s["dc_iterations_mean"], "psor": s["psor_sweeps_mean"]}
    results["iterations_max_per_step"] = {"fixed_point": s["fixed_point_iterations_max"],
                                          "slip_threshold": s["slip_threshold_iterations_max"],
                                          "dc": s["dc_iterations_max"], "psor": s["psor_sweeps_max"]}
    # The friction scene: the slip-threshold loop only runs where mu > 0.
    print("bench: sleeve-elliptic-friction default (iteration counts with friction)", flush=True)
    wall_f, sf, _ = run("edp/scenes/sleeve-elliptic-friction.edp", os.path.join(OUT, "friction-default"),
                        "-quiet", 1, *(["-steps", 300, "-mesh", "meshes/sleeve-coarse.msh"] if QUICK else []))
    results["friction_iterations_mean_per_step"] = {
        "fixed_point": sf["fixed_point_iterations_mean"], "slip_threshold": sf["slip_threshold_iterations_mean"],
        "dc": sf["dc_iterations_mean"], "psor": sf["psor_sweeps_mean"], "wall_seconds": wall_f}

    # The elliptic pipe's lift-off with the paper's scheme (the major axis lets go before the minor
    # one touches, paper Fig. 25-28) at 750 and 1500 steps, and with the default fraction model.
    liftoff = []
    for steps in ([300, 600] if QUICK else [750, 1500]):
        print(f"bench: sleeve-elliptic {steps} steps (lift-off)", flush=True)
        out = os.path.join(OUT, f"elliptic-{steps}")
        wall, _, _ = run("edp/scenes/sleeve-elliptic.edp", out, "-steps", steps, "-quiet", 1, "-vtkevery", 0,
                         "-phasemodel", "onoff",
                         "-mesh", "meshes/sleeve-coarse.msh" if QUICK else "meshes/sleeve-quarter.msh")
        liftoff.append(dict(elliptic_liftoff(os.path.join(out, "points.csv")), steps=steps, wall_seconds=wall,
                            phase_model="onoff"))
    print("bench: sleeve-elliptic default (fraction model)", flush=True)
    out = os.path.join(OUT, "elliptic-fraction")
    wall, _, _ = run("edp/scenes/sleeve-elliptic.edp", out, "-quiet", 1, "-vtkevery", 0,
                     *(["-mesh", "meshes/sleeve-coarse.msh", "-steps", 600] if QUICK else []))
    liftoff.append(dict(elliptic_liftoff(os.path.join(out, "points.csv")), steps=600 if QUICK else 1500,
                        wall_seconds=wall, phase_model="fraction"))
    results["elliptic_liftoff"] = liftoff


def doc_time(r, w):
    """Where the default run's time goes."""
    w("## Where the default run's time goes")
    w("")
    v = r["sleeve_circular_1500_variants"]
    w(f"sleeve-circular, default mesh, 1500 steps, medians of {len(r['sleeve_circular_1500_runs'])} runs each, "
      "whole process (loop):")
    w("")
    w("| run | wall (s) | loop (s) |")
    w("|---|---|---|")
    w(f"| default (`-vtkevery 50`: {r['sleeve_circular_1500_frames']} ParaView frames) | "
      f"{r['sleeve_circular_1500_wall_seconds']:.2f} | {r['sleeve_circular_1500_loop_seconds']:.2f} |")
    w(f"| `-vtkevery 0` (the three instants only) | {v['no_frames']['wall_seconds']:.2f} | {v['no_frames']['loop_seconds']:.2f} |")
    w(f"| FreeFEM's own clock() (`SMA_FASTCLOCK=0`) | {v['stock_clock']['wall_seconds']:.2f} | {v['stock_clock']['loop_seconds']:.2f} |")
    w("")
    w(f"- **The frames** cost {r['sleeve_circular_1500_wall_seconds'] - v['no_frames']['wall_seconds']:+.2f} s "
      f"of the whole process ({r['sleeve_circular_1500_frames']} VTU files); they stay on by default.")
    if "every_step_a_frame" in v:
        every = v["every_step_a_frame"]
        w(f"- **A frame at every step** (`-vtkevery 1`, 1500 frames, one run): {every['wall_seconds']:.2f} s whole "
          f"process, {1e3 * (every['wall_seconds'] - v['no_frames']['wall_seconds']) / 1500:.2f} ms a frame: "
          "constant per frame (fields.pvd's entries formatted once, the results manifest read once, the index "
          "replaced at most once a second: a rename over a file costs ext4 a data flush).")
    w(f"- **FreeFEM's clock()**: FreeFEM reads the process CPU time, a system call, twice per statement of "
      f"every block (for a display off by default). tools/ff preloads plugin/fastclock.c, a clock() read "
      f"through the vDSO (FreeFEM's own statement and product timers: the coarse clock, the kernel's last tick): {v['stock_clock']['loop_seconds']:.2f} s -> {r['sleeve_circular_1500_loop_seconds']:.2f} s "
      f"of loop, outputs byte-identical (tests/fastclock_test.py).")
    ph = r["sleeve_circular_1500_phases"]
    w(f"- **The floor**: one stiffness and one heat back-solve per step, "
      f"{1e6 * r['sleeve_circular_1500_floor_seconds_per_step']:.0f} us with the plugin's factorisations "
      f"({1e6 * r['sleeve_circular_1500_stiffness_backsolve_seconds']:.1f} + "
      f"{1e6 * r['sleeve_circular_1500_heat_backsolve_seconds']:.1f} us; summary.json "
      f"`backsolve_floor_seconds_per_step`); the loop is {r['sleeve_circular_1500_loop_over_floor']:.1f} times "
      f"steps x floor.")
    w(f"- **What the algorithm needs** (the default step solver, `-stepsolver newton`: its evaluations and "
      f"linearised products counted in the DC column): {r['iterations_mean_per_step']['dc']:.2f} stiffness "
      f"back-solves per step (each a forward and a backward solve around the contact sweeps) and as many heat "
      f"back-solves (one of each per evaluation of the step's equations and per product by their linearisation), "
      f"in {r['iterations_mean_per_step']['fixed_point']:.2f} step-solver iterations; in the transient (the "
      f"{ph['transient']['steps']} steps before the ring is austenite for good) "
      f"{ph['transient']['dc_per_step']:.1f} stiffness back-solves and {ph['transient']['fixed_point_per_step']:.1f} "
      f"step-solver iterations per step, in the tail ({ph['tail']['steps']} steps) "
      f"{ph['tail']['dc_per_step']:.2f} and {ph['tail']['fixed_point_per_step']:.2f}. Those back-solves alone take "
      f"{r['sleeve_circular_1500_backsolves_needed_seconds']:.3f} s, "
      f"{r['sleeve_circular_1500_backsolves_needed_seconds'] / ((ph['transient']['steps'] + ph['tail']['steps']) * r['sleeve_circular_1500_floor_seconds_per_step']):.1f} "
      f"times steps x floor: no algorithm that iterates within a transforming step reaches 1.5 times the floor. The loop is "
      f"{r['sleeve_circular_1500_loop_over_backsolves_needed']:.1f} times them (summary.json "
      f"`loop_over_backsolves_needed`): the rest is the interpreter's statements around them (perf: FreeFEM's "
      "evaluator, its sparse products, and the C++ exception FreeFEM throws at every func's `return`). Split at "
      f"the transient's end: the transient's loop is "
      f"{r['sleeve_circular_1500_loop_over_backsolves_needed_transient']:.1f} times its back-solves (the steps that "
      f"iterate: the step solver's own work around its back-solves), the tail's "
      f"{r['sleeve_circular_1500_loop_over_backsolves_needed_tail']:.1f} times (one evaluation a step: the time "
      "loop's record of each step, its CSV rows, contact and chatter watch, weighs there).")


def doc_iterations(r, w):
    """The iteration counts per time step against the paper's."""
    it = r["iterations_mean_per_step"]
    itf = r["friction_iterations_mean_per_step"]
    w("## Iteration counts per time step")
    w("")
    w("| loop | paper | sleeve-circular (mean / max) | sleeve-elliptic-friction (mean) |")
    w("|---|---|---|---|")
    mx = r["iterations_max_per_step"]
    w(f"| heat <-> phases fixed point | about 3 | {it['fixed_point']:.3f} / {mx['fixed_point']} | {itf['fixed_point']:.3f} |")
    w(f"| slip threshold (Coulomb) | - | {it['slip_threshold']:.3f} / {mx['slip_threshold']} | {itf['slip_threshold']:.3f} |")
    w(f"| DC | about 4 | {it['dc']:.3f} / {mx['dc']} | {itf['dc']:.3f} |")
    w(f"| PSOR sweeps | about 10 | {it['psor']:.2f} / {mx['psor']:.0f} | {itf['psor']:.2f} |")
    w("")
