#!/usr/bin/python3
"""Verification of sleeve-circular-gvar (paper Fig. 17-20,
docs/model.md#fig-17-20-sleeve-circular-gvar) against sleeve-circular, both on
meshes/sleeve-quarter.msh with 1500 steps and the paper's on/off phases (-phasemodel onoff): these
are claims of the paper's scheme. With the default fraction model both curves are smooth
(largest one-step rise 0.27 MPa with constant g, 0.48 MPa with variable g; docs/parameters.md).

Paper: the phase change is progressive and starts at the ring-pipe interface; the force rises
by jumps much more regularly; below about -30 C the force is lower than with a constant g; it
has already reached its maximum level in the middle of the return to the initial temperature;
the final force is uniform and of the same level.
Asserts:
  - austenite starts at the interface: at the "during contact" instant (half the ring
    austenite) the austenite's mean radius is below the martensite's (with constant g the
    reverse);
  - more regular: the largest one-step rise of the mean pressure is smaller than with constant g;
  - lower below -30 C: at every inner temperature from the first contact to -35 C, the mean
    pressure is at most the constant-g one, and strictly lower somewhere;
  - the final level reached (all austenite for good) before the inner surface has covered half
    of its warming from 196 K to its final temperature;
  - the same final level (within 1e-6) and uniform within 1 %.
Writes results/checks/sleeve_gvar.json.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import KELVIN_AT_0C, check, finish, record, rows, run_scene, sleeve_outputs  # noqa: E402


def load(out):
    fields = rows(os.path.join(out, "fields-2-contact.csv"))
    radius = {0: [], 1: []}
    for r in fields:
        radius[float(r["phase"]) != 0].append(math.hypot(float(r["x"]), float(r["y"])))
    run = sleeve_outputs(out)
    return {"summary": run["summary"],
            "history": [(float(r["T_inner_mean"]) - KELVIN_AT_0C, float(r["pressure_mean"])) for r in run["history"]],
            "austenite_radius": sum(radius[0]) / len(radius[0]),
            "martensite_radius": sum(radius[1]) / max(1, len(radius[1]))}


def pressure_at(history, T):
    """Mean pressure at the first step where the inner surface reaches T (C)."""
    return next(p for t, p in history if t >= T)


def main():
    paper = ["-quiet", "1", "-phasemodel", "onoff", "-mesh", "meshes/sleeve-quarter.msh"]
    const = load(run_scene("sleeve-circular", "sleeve-gvar-constant", *paper))
    gvar = load(run_scene("sleeve-circular-gvar", "sleeve-gvar", *paper))
    for name, run in (("constant g", const), ("variable g", gvar)):
        print(f"info {name}: during contact austenite at mean radius {1e3 * run['austenite_radius']:.2f} mm, "
              f"martensite at {1e3 * run['martensite_radius']:.2f} mm")
    check(gvar["austenite_radius"] < gvar["martensite_radius"] and
          const["austenite_radius"] > const["martensite_radius"],
          "variable g: austenite starts at the interface (inside the martensite); constant g: the reverse")
    jump = {n: max(b[1] - a[1] for a, b in zip(r["history"], r["history"][1:]))
            for n, r in (("constant", const), ("gvar", gvar))}
    check(jump["gvar"] < jump["constant"], f"more regular: largest one-step rise {jump['gvar'] / 1e6:.2f} MPa "
          f"< {jump['constant'] / 1e6:.2f} MPa with constant g")
    T_first = gvar["summary"]["T_inner_first_contact"] - KELVIN_AT_0C
    grid = [T_first + k * 0.5 for k in range(int((-35 - T_first) / 0.5) + 1)]
    diffs = [pressure_at(gvar["history"], T) - pressure_at(const["history"], T) for T in grid]
    check(max(diffs) <= 0 and min(diffs) < 0,
          f"below -35 C the force is lower with variable g: at {len(grid)} temperatures from "
          f"{T_first:.1f} C, largest excess {max(diffs) / 1e6:.3f} MPa, largest deficit {-min(diffs) / 1e6:.2f} MPa")
    s = gvar["summary"]
    T_final = gvar["history"][-1][0]
    Tinit = s["parameters"]["Tinit"] - KELVIN_AT_0C
    T_max_level = s["T_inner_austenite"] - KELVIN_AT_0C
    check(T_max_level < (Tinit + T_final) / 2,
          f"final level reached at inner {T_max_level:.1f} C, before half the warming "
          f"({Tinit:.1f} C -> {T_final:.1f} C, half {0.5 * (Tinit + T_final):.1f} C)")
    final = {n: r["summary"]["final_pressure_mean"] for n, r in (("constant", const), ("gvar", gvar))}
    check(abs(final["gvar"] / final["constant"] - 1) < 1e-6,
          f"same final level: {final['gvar'] / 1e6:.4f} vs {final['constant'] / 1e6:.4f} MPa")
    check(s["final_pressure_non_uniformity"] < 0.01,
          f"final force uniform: non-uniformity {100 * s['final_pressure_non_uniformity']:.2f} % < 1 %")
    record("sleeve_gvar", {
        "test": "sleeve_gvar", "mesh": s["parameters"]["mesh"], "steps": s["n_steps"],
        "austenite_radius_m": {"constant": const["austenite_radius"], "gvar": gvar["austenite_radius"]},
        "martensite_radius_m": {"constant": const["martensite_radius"], "gvar": gvar["martensite_radius"]},
        "largest_rise_Pa": jump, "largest_excess_below_minus35C_Pa": max(diffs),
        "largest_deficit_below_minus35C_Pa": -min(diffs),
        "T_inner_all_austenite_K": {"constant": const["summary"]["T_inner_austenite"],
                                    "gvar": s["T_inner_austenite"]},
        "t_all_austenite_s": {"constant": const["summary"]["austenite_step"] * const["summary"]["parameters"]["dt"],
                              "gvar": s["austenite_step"] * s["parameters"]["dt"]},
        "final_pressure_Pa": final})
    finish()


if __name__ == "__main__":
    main()
