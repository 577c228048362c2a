#!/usr/bin/python3
"""Verification of the sleeve-circular scene (paper §4.2.1, Fig. 12) on the coarse mesh.

Asserts, on the force-temperature curve at the inner-surface point on the x axis, the four phases
of SPEC section 6 in order: (1) zero force before contact (at least 3 steps); (2) contact while
the ring is still all martensite, the force linear in T (R^2 > 0.99 over at least 5 steps);
(3) jumps while the ring turns back to austenite (the largest one-step rise at least 3 times the
mean rise per step of phase 2); (4) constant force once all austenite (relative spread < 1e-6).
And the final pressure uniform along the surface within 1 %, the DC Lagrangian path sane (at most
dcmaxit iterations), every contact node's force >= 0.
Writes results/checks/sleeve_circular_phases.json.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, rows, run_scene  # noqa: E402


def r_squared(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    slope = sxy / sxx
    ss_res = sum((y - my - slope * (x - mx)) ** 2 for x, y in zip(xs, ys))
    ss_tot = sum((y - my) ** 2 for y in ys)
    return 1 - ss_res / ss_tot, slope


def main():
    out = run_scene("sleeve-circular", "sleeve-circular", "-mesh", "meshes/sleeve-coarse.msh",
                    "-steps", "600", "-quiet", "1")
    summary = json.load(open(os.path.join(out, "summary.json")))
    hist = rows(os.path.join(out, "history.csv"))
    pts = rows(os.path.join(out, "points.csv"))
    T = [float(r["T_x_axis_C"]) for r in pts]
    p = [float(r["pressure_x_axis_GPa"]) * 1e9 for r in pts]
    austenite = [float(r["fraction_austenite"]) for r in hist]
    contact = [int(r["contact_nodes"]) for r in hist]
    first_contact = next(i for i, c in enumerate(contact) if c > 0)
    reversion = next(i for i, f in enumerate(austenite) if f > 0)
    # All austenite for good: phase points near T* may flip back and forth for a few steps
    # (SPEC section 4, hazard 2: on/off phases with Crank-Nicolson latent heat): the jerks.
    all_austenite = max(i for i, f in enumerate(austenite) if f < 1) + 1
    flips = sum(1 for a, b in zip(austenite[reversion:all_austenite], austenite[reversion + 1:all_austenite + 1]) if b < a)
    print(f"phases: contact at step {first_contact + 1}, reversion from {reversion + 1}, "
          f"all austenite for good at {all_austenite + 1} of {len(p)}; the austenite fraction "
          f"fell back {flips} times in phase 3")
    check(first_contact >= 3 and all(v == 0 for v in p[:first_contact]),
          f"phase 1: zero force over the {first_contact} steps before contact")
    lin_T, lin_p = T[first_contact:reversion], p[first_contact:reversion]
    check(len(lin_p) >= 5, f"phase 2 lasts {len(lin_p)} >= 5 steps (contact, still martensite)")
    r2, slope = r_squared(lin_T, lin_p) if len(lin_p) >= 3 else (0, 0)
    check(r2 > 0.99 and slope > 0, f"phase 2: force linear in T, R^2 = {r2:.5f} > 0.99, "
          f"slope {slope / 1e6:.3f} MPa/K > 0")
    rises = [b - a for a, b in zip(p[reversion - 1:all_austenite], p[reversion:all_austenite + 1])]
    mean_rise_linear = (lin_p[-1] - lin_p[0]) / max(1, len(lin_p) - 1)
    biggest = max(rises)
    check(biggest >= 3 * mean_rise_linear,
          f"phase 3: jumps, largest one-step rise {biggest / 1e6:.3f} MPa >= 3 x the mean rise "
          f"per step of phase 2 ({mean_rise_linear / 1e6:.4f} MPa)")
    final = p[all_austenite:]
    spread = (max(final) - min(final)) / final[-1]
    check(spread < 1e-6, f"phase 4: constant force once all austenite, relative spread {spread:.2e}")
    check(first_contact < reversion < all_austenite < len(p) - 5, "the four phases come in order")
    check(summary["final_pressure_non_uniformity"] <= 0.01,
          f"final pressure uniform within 1 %: {summary['final_pressure_non_uniformity']:.4f}")
    final_contact = rows(os.path.join(out, "contact-final.csv"))
    check(min(float(r["normal_force"]) for r in final_contact) >= 0, "normal forces >= 0")
    record("sleeve_circular_phases", {
        "test": "sleeve_circular_phases", "mesh": "meshes/sleeve-coarse.msh", "steps": len(p),
        "first_contact_step": first_contact + 1, "reversion_step": reversion + 1,
        "all_austenite_step": all_austenite + 1, "linear_r2": r2, "linear_slope_Pa_per_K": slope,
        "largest_jump_Pa": biggest, "austenite_fraction_decreases_in_phase_3": flips, "mean_linear_rise_Pa": mean_rise_linear,
        "final_spread": spread, "final_pressure_Pa": summary["final_pressure_mean"],
        "final_non_uniformity": summary["final_pressure_non_uniformity"],
        "wall_seconds": summary["wall_seconds"]})
    finish()


if __name__ == "__main__":
    main()
