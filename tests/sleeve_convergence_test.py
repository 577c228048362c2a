#!/usr/bin/python3
"""Convergence of sleeve-circular's force curve in 2D, and no chatter over the exchange range
(issue 13; docs/benchmarks.md has the full study, written by make bench).

Metric: tools/bench/oracles/curve_error.py l1_transient, the L1-in-time relative error of the mean contact
pressure over the transient (until the reference is austenite for good). Reference: the
independent 1D model of the same problem (sleeve-radial, nr 160, 1200 steps over 30 s: itself
0.16 % from its nr 640 limit, docs/benchmarks.md).

1. Refinement in 2D, dt and h together (structured quarter rings of 6, 9, 12 and 18 layers,
   dt 0.3 ... 0.1 s, 30 s): the errors decrease, at an observed order >= 1 in h from 6 to 18
   layers, with no reversal step (a point back to martensite while heating) and no pressure zigzag.
2. The scene's defaults (meshes/sleeve-aniso.msh, 1500 steps over 150 s): within 2 % of the
   reference, no chatter.
3. The exchange coefficient from 125 to 4000 W/(m^2 K) (-g and -gcontact together, default mesh):
   no reversal step and no pressure zigzag, and the same final pressure (Lame's: the end state is
   elastic) within 1e-6.
4. The paper's on/off model on the old default mesh (meshes/sleeve-quarter.msh) chatters, and its
   summary says so (reversal steps > 0).
Writes results/checks/sleeve_convergence.json.
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench", "oracles"))

from checklib import check, finish, record, run_scene  # noqa: E402
from curve_error import curve_error  # noqa: E402

LEVELS = [(6, "meshes/sleeve-coarse.msh", 100), (9, "meshes/sleeve-nr9.msh", 150),
          (12, "meshes/sleeve-nr12.msh", 200), (18, "meshes/sleeve-quarter.msh", 300)]


def outputs(out):
    return {"history": os.path.join(out, "history.csv"),
            "summary": json.load(open(os.path.join(out, "summary.json")))}


def no_chatter(s):
    return s["reversal_steps"] == 0 and s["pressure_zigzag_steps"] == 0 and not s["chatter"]


def main():
    ref = outputs(run_scene("sleeve-radial", "convergence-radial-160", "-quiet", "1", "-nr", "160",
                            "-steps", "1200", "-tend", "30"))
    figures = {"reference": "sleeve-radial nr 160, 1200 steps over 30 s"}

    # 1. 2D refinement.
    errors, chatter = [], []
    for nr, mesh, steps in LEVELS:
        run = outputs(run_scene("sleeve-circular", f"convergence-2d-nr{nr}", "-quiet", "1", "-mesh", mesh,
                                "-steps", str(steps), "-tend", "30", "-vtkevery", "0"))
        errors.append(curve_error(run["history"], ref["history"])["l1_transient"])
        chatter.append((nr, run["summary"]["reversal_steps"], run["summary"]["pressure_zigzag_steps"]))
    order = math.log(errors[0] / errors[-1]) / math.log(LEVELS[-1][0] / LEVELS[0][0])
    check(all(x > y for x, y in zip(errors, errors[1:])) and order >= 1.0,
          "2D, dt and h refined together: transient l1 " + ", ".join(
              f"{100 * e:.2f} % (nr {lv[0]})" for e, lv in zip(errors, LEVELS))
          + f" decrease, observed order {order:.2f} >= 1")
    check(all(rev == 0 and zig == 0 for _, rev, zig in chatter),
          f"no reversal step and no pressure zigzag at any level (nr, reversals, zigzags): {chatter}")
    figures.update(levels=[lv[0] for lv in LEVELS], l1_transient=errors, order=order)

    # 2. The defaults.
    default = outputs(run_scene("sleeve-circular", "convergence-default", "-quiet", "1"))
    s = default["summary"]
    e = curve_error(default["history"], ref["history"])["l1_transient"]
    check(s["parameters"]["phase_model"] == "fraction" and e <= 0.02 and no_chatter(s),
          f"defaults ({s['parameters']['mesh']}, {s['n_steps']} steps): transient l1 {100 * e:.2f} % <= 2 %, "
          f"{s['reversal_steps']} reversal steps, {s['pressure_zigzag_steps']} pressure zigzags")
    figures.update(default_l1_transient=e, default_wall_seconds=s["wall_seconds"])

    # 3. The exchange range.
    sweep = {}
    for g in (125, 250, 1000, 4000):
        run = outputs(run_scene("sleeve-circular", f"convergence-g{g}", "-quiet", "1", "-g", str(g),
                                "-gcontact", str(g), "-vtkevery", "0"))
        sweep[g] = run["summary"]
    finals = [v["final_pressure_mean"] for v in sweep.values()]
    check(all(no_chatter(v) for v in sweep.values()) and max(finals) / min(finals) - 1 <= 1e-6,
          "g 125 ... 4000: " + ", ".join(f"g {g}: {v['reversal_steps']} reversals, {v['pressure_zigzag_steps']} "
                                         f"zigzags, austenite at step {v['austenite_step']}" for g, v in sweep.items())
          + f"; final pressures agree within {max(finals) / min(finals) - 1:.1e}")
    figures["g_sweep"] = {str(g): {k: v[k] for k in ("reversal_steps", "pressure_zigzag_steps", "austenite_step",
                                                    "final_pressure_mean", "fixed_point_iterations_max")}
                          for g, v in sweep.items()}

    # 4. The paper's on/off model is caught chattering.
    onoff = outputs(run_scene("sleeve-circular", "convergence-onoff", "-quiet", "1", "-phasemodel", "onoff",
                              "-mesh", "meshes/sleeve-quarter.msh", "-vtkevery", "0"))["summary"]
    check(onoff["chatter"] and onoff["reversal_steps"] > 0,
          f"the paper's on/off model on meshes/sleeve-quarter.msh chatters and says so: {onoff['reversal_steps']} "
          f"reversal steps (up to {onoff['reversal_points_max']} triangles), {onoff['pressure_zigzag_steps']} zigzags")
    figures["onoff_quarter"] = {k: onoff[k] for k in ("reversal_steps", "reversal_points_max", "pressure_zigzag_steps")}
    record("sleeve_convergence", dict(figures, test="sleeve_convergence"))
    finish()


if __name__ == "__main__":
    main()
