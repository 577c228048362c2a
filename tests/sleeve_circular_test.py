#!/usr/bin/python3
"""Verification of the sleeve-circular scene (paper Fig. 12,
docs/model.md#fig-11-14-sleeve-circular) on the coarse mesh.

Asserts, on the force-temperature curve at the inner-surface point on the x axis, the four phases
of the paper's Fig. 12 in order (checklib.four_phases: zero; linear in T with R^2 > 0.99; jumps;
constant), the final pressure uniform along the surface within 1 %, every contact node's force
>= 0. Writes results/checks/sleeve_circular_phases.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, four_phases, record, run_scene, sleeve_outputs  # noqa: E402


def main():
    out = run_scene("sleeve-circular", "sleeve-circular", "-mesh", "meshes/sleeve-coarse.msh",
                    "-steps", "600", "-quiet", "1")
    run = sleeve_outputs(out)
    summary, hist, pts = run["summary"], run["history"], run["points"]
    T = [float(r["T_x_axis_K"]) for r in pts]
    p = [float(r["pressure_x_axis_Pa"]) for r in pts]
    austenite = [float(r["fraction_austenite"]) for r in hist]
    first_contact = next(i for i, r in enumerate(hist) if int(r["contact_nodes"]) > 0)
    phases = four_phases("x axis", T, p, austenite, first_contact)
    check(summary["final_pressure_non_uniformity"] <= 0.01,
          f"final pressure uniform within 1 %: {summary['final_pressure_non_uniformity']:.4f}")
    check(min(float(r["normal_force"]) for r in run["final"]) >= 0, "normal forces >= 0")
    record("sleeve_circular_phases", dict(
        phases, test="sleeve_circular_phases", mesh="meshes/sleeve-coarse.msh", steps=len(p),
        final_pressure_Pa=summary["final_pressure_mean"],
        final_non_uniformity=summary["final_pressure_non_uniformity"],
        wall_seconds=summary["wall_seconds"]))
    finish()


if __name__ == "__main__":
    main()
