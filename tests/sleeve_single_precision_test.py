#!/usr/bin/python3
"""Single against double precision mesh coordinates (paper Fig. 15-16), coarse mesh, 600 steps.

The structured quarter ring is exactly symmetric in double precision: the clamping force at the
three inner points (0, 45 and 90 degrees) must agree within 1e-6 (relative to the largest) at
every step with contact. Rounded to float (sleeve-circular-single), the coordinates break that
symmetry: the three forces must differ by more than 1 % at some step. Also recorded: the
spread at the end, and how far the phase fractions of the two runs differ (the phase zones).
Stability (docs/stability.md, case 4): both runs end all austenite, and the final mean pressures
agree within the bound the rounding allows (2^-24 x outer radius / interference, 6.6e-5).
The scene's header quotes its defaults' runs (paper scale and -scale reduced, the fixed steps of
-tol 0) as printed: the spread at the first contact step and at the end, and the double precision
mesh's (sleeve-circular) to its order of magnitude. Three more runs, about 4 s.
Writes results/checks/sleeve_single_precision.json.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, header_quotes, record, run_scene, sci, sleeve_outputs  # noqa: E402

POINTS = ("x_axis", "diagonal", "y_axis")
COMMON = ["-mesh", "meshes/sleeve-coarse.msh", "-steps", "600", "-quiet", "1"]


def spreads(points):
    """(max - min) / max of the three points' force, at every step where one of them touches."""
    result = []
    for r in points:
        p = [float(r[f"pressure_{n}_Pa"]) for n in POINTS]
        if max(p) > 0:
            result.append(((max(p) - min(p)) / max(p), int(r["step"])))
    return result


def header_check():
    """The header's figures from the defaults' runs (paper scale and reduced, -tol 0)."""
    fixed = ["-tol", "0", "-quiet", "1", "-vtkevery", "0"]
    double = spreads(sleeve_outputs(run_scene("sleeve-circular", "single-header-double", "-scale", "paper",
                                              *fixed))["points"])
    runs = {scale: sleeve_outputs(run_scene("sleeve-circular-single", "single-header-" + scale, "-scale", scale,
                                            *fixed))["points"] for scale in ("paper", "reduced")}
    paper, reduced = spreads(runs["paper"]), spreads(runs["reduced"])
    for scale, points in runs.items():  # (the header: the three touch at the same step)
        first = next(r for r in points if max(float(r[f"pressure_{n}_Pa"]) for n in POINTS) > 0)
        touching = sum(float(first[f"pressure_{n}_Pa"]) > 0 for n in POINTS)
        check(touching == 3, f"sleeve-circular-single -scale {scale}: {touching} of the 3 points touch at the first "
              f"contact step ({first['step']})")
    worst = max(double)[0]
    bound = 10.0 ** math.ceil(math.log10(worst)) if worst > 0 else 0
    phrases = [f"the same force to {sci(bound, 1)}",
               f"at the first contact step ({paper[0][1]}) they are {100 * paper[0][0]:.0f} % apart, "
               f"{sci(paper[-1][0], 1)} at the end",
               f"(-scale reduced: at its first contact step ({reduced[0][1]}), {100 * reduced[0][0]:.0f} % apart, "
               f"{sci(reduced[-1][0], 1)} at the end"]
    header_quotes("edp/scenes/sleeve-circular-single.edp", phrases)
    # README's table gives the double precision mesh's spread as a bound: it must hold
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        m = re.search(r"the three inner points no longer agree \(double: within (\S+)\)", f.read())
    check(m is not None and worst <= float(m[1]), f"README: double precision's three points within "
          f"{m[1] if m else '(no bound found)'}: {worst:.1e}")
    return phrases


def main():
    double = sleeve_outputs(run_scene("sleeve-circular", "sleeve-circular-double", *COMMON))
    single = sleeve_outputs(run_scene("sleeve-circular-single", "sleeve-circular-single", *COMMON))
    s_double, s_single = spreads(double["points"]), spreads(single["points"])
    rounded = single["summary"]["coordinates_rounded"]
    check(rounded > 0, f"single precision moved {rounded} coordinates")
    worst_double, worst_single = max(s_double), max(s_single)
    check(worst_double[0] <= 1e-6, f"double precision: the three points agree within "
          f"{worst_double[0]:.2e} <= 1e-6 (worst at step {worst_double[1]})")
    check(worst_single[0] > 0.01, f"single precision: the three points differ by "
          f"{100 * worst_single[0]:.1f} % > 1 % (at step {worst_single[1]}); at the end "
          f"{s_single[-1][0]:.1e}")
    # The final state is all austenite and elastic: a linear fit whose only input the rounding
    # touches is the geometry. Each coordinate moves by at most 2^-24 of its size (3.6e-9 m at the
    # outer radius), so the mean pressure may move by at most that over the interference (55 um).
    p_single, p_double = single["summary"]["final_pressure_mean"], double["summary"]["final_pressure_mean"]
    par = double["summary"]["parameters"]
    interference = par["pipe_A"] - par["ring_inner_radius"]
    bound = 2.0 ** -24 * (par["ring_inner_radius"] + 0.01) / interference
    final_change = p_single / p_double - 1
    check(abs(final_change) <= bound and single["summary"]["austenite_step"] > 0,
          f"final pressure: single {p_single / 1e6:.6f} MPa vs double {p_double / 1e6:.6f} MPa, relative "
          f"{final_change:.1e} within the rounding's bound {bound:.1e} (2^-24 x outer radius / interference)")
    phases = [(abs(float(a["fraction_austenite"]) - float(b["fraction_austenite"])))
              for a, b in zip(double["history"], single["history"])]
    print(f"info phase fractions of the two runs differ by at most {max(phases):.1e}: the phase "
          f"zones stay circular")
    headers = header_check()
    record("sleeve_single_precision", {
        "headers": headers,
        "test": "sleeve_single_precision", "mesh": "meshes/sleeve-coarse.msh", "steps": 600,
        "coordinates_rounded": rounded,
        "double_max_spread": worst_double[0], "double_max_spread_step": worst_double[1],
        "single_max_spread": worst_single[0], "single_max_spread_step": worst_single[1],
        "single_final_spread": s_single[-1][0], "double_final_spread": s_double[-1][0],
        "phase_fraction_max_difference": max(phases),
        "final_pressure_single_Pa": p_single, "final_pressure_double_Pa": p_double,
        "final_pressure_relative_change": final_change, "final_pressure_bound": bound})
    finish()


if __name__ == "__main__":
    main()
