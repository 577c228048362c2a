#!/usr/bin/python3
"""Verification of the asymmetric tension/compression variant (edp/variants/beam-asymmetric.edp).

Runs the variant into build/test-results/variant-asymmetric (coarse and medium beam meshes) and asserts:
  * alpha_minus = alpha_plus: the .edp projection equals the plugin's PhaseProject exactly at
    random points (ties included), same change count, same local part of L_II; on the beam the
    .edp DC loop gives the plugin DC solve's displacement to round-off;
  * at random asymmetric points, the projected s minimises phi2*(s) - t s: a brute-force
    minimisation over 20001 values of s in [-alpha_minus, alpha_plus] (numpy, independent of the
    .edp) finds nothing lower, and the minimum equals -phi2(t) (Fenchel equality);
  * on the beam, Auchmuty's L_II never increases along the asymmetric DC iterations;
  * the sign symmetry of the law: alphas swapped and load reversed gives -u and the two
    martensites swapped (exact for the discrete problem: fractions and deflection to round-off);
  * alpha_minus < alpha_plus raises the compression threshold c/alpha_minus: the compression
    martensite (M2) shrinks against the symmetric run on every mesh.
Writes results/checks/variant_asymmetric.json.
"""
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows  # noqa: E402


def conjugate(s, ap, am, c):
    """phi2*(s) of the asymmetric law, written from its definition (inf outside the domain)."""
    s = np.asarray(s, dtype=float)
    inside = (s <= ap) & (s >= -am)
    value = np.where(c < 0, c, np.where(s >= 0, c / ap * s, -c / am * s))
    return np.where(inside, value, np.inf)


def main():
    out = os.path.join(TEST_RESULTS, "variant-asymmetric")
    subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/variants/beam-asymmetric.edp", "-out", out,
                    "-levels", "coarse medium"], cwd=ROOT, check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))

    red = summary["symmetric_reduction"]
    check(red["max_s_difference"] == 0 and red["phases_differing"] == 0,
          f"alpha_minus = alpha_plus: s and phases equal the plugin's PhaseProject at {red['points']} random "
          f"points (max |ds| {red['max_s_difference']}, {red['phases_differing']:.0f} phases differ)")
    check(red["changed_plugin"] == red["changed_ours"],
          f"same count of phase changes ({red['changed_ours']} vs the plugin's {red['changed_plugin']})")
    check(red["local_lagrangian_rel_gap"] <= 1e-14,
          f"local part of L_II equals the plugin's AuchmutyLocal (relative gap {red['local_lagrangian_rel_gap']:.1e})")

    points = rows(os.path.join(out, "pointwise-check.csv"))
    grid = np.linspace(0.0, 1.0, 20001)
    worst_gap, worst_fenchel, ties = -np.inf, 0.0, 0
    for r in points:
        t, ap, am, c, s = (float(r[k]) for k in ("trace", "alpha_plus", "alpha_minus", "c", "s"))
        scale = max(abs(c), (ap + am) * abs(t)) + 1.0
        sg = -am + (ap + am) * grid
        brute = np.min(conjugate(sg, ap, am, c) - t * sg)
        chosen = float(conjugate(s, ap, am, c)) - t * s
        phi2 = max(ap * max(t, 0) + am * max(-t, 0) - c, 0)
        worst_gap = max(worst_gap, (chosen - brute) / scale)
        worst_fenchel = max(worst_fenchel, abs(chosen + phi2) / scale)
        ties += c > 0 and (t == c / ap or t == -c / am)
    check(worst_gap <= 1e-13,
          f"brute force over 20001 values of s at {len(points)} random points ({ties} on a threshold): "
          f"the projection is never beaten, largest (projection - grid minimum)/scale {worst_gap:.1e}")
    check(worst_fenchel <= 1e-13,
          f"Fenchel equality phi2*(s) - t s = -phi2(t) at every point (largest error {worst_fenchel:.1e}), "
          f"the .edp's own figure {summary['pointwise']['max_fenchel_error']:.1e}")

    runs = {(r["law"], r["mesh"]): r for r in summary["runs"]}
    meshes = sorted({m for _, m in runs}, key=["coarse", "medium", "fine"].index)
    convergence = rows(os.path.join(out, "dc-convergence.csv"))
    figures = {}
    for mesh in meshes:
        sym, plug = runs[("symmetric", mesh)], runs[("symmetric-plugin", mesh)]
        asym, mirror = runs[("asymmetric", mesh)], runs[("asymmetric-mirrored", mesh)]
        check(0 <= sym["displacement_gap_to_plugin"] <= 1e-12 and sym["dc_iterations"] == plug["dc_iterations"],
              f"{mesh}: the .edp DC loop with equal alphas gives the plugin DC solve's u (relative gap "
              f"{sym['displacement_gap_to_plugin']:.1e}, {sym['dc_iterations']} iterations both)")
        seq = [(float(r["lagrangian_after_global"]), float(r["lagrangian_after_local"]))
               for r in convergence if r["law"] == "asymmetric" and r["mesh"] == mesh]
        scale = max(abs(v) for pair in seq for v in pair)
        rises = [(b - a) / scale for a, b in zip([v for p in seq for v in p][:-1], [v for p in seq for v in p][1:])]
        check(max(rises) <= 1e-12, f"{mesh}: asymmetric L_II never increases over {len(seq)} DC iterations "
              f"(largest relative rise {max(rises):.1e})")
        mirror_gap = max(abs(asym["fraction_m1"] - mirror["fraction_m2"]), abs(asym["fraction_m2"] - mirror["fraction_m1"]),
                         abs(asym["tip_deflection"] + mirror["tip_deflection"]) / asym["tip_deflection"])
        check(mirror_gap <= 1e-9, f"{mesh}: alphas swapped and load reversed: martensites swapped and deflection "
              f"reversed (largest gap {mirror_gap:.1e})")
        check(asym["fraction_m2"] < sym["fraction_m2"],
              f"{mesh}: alpha_minus {asym['alpha_minus']:.3g} < alpha_plus: compression martensite shrinks "
              f"({sym['fraction_m2']:.4f} -> {asym['fraction_m2']:.4f}); tension {sym['fraction_m1']:.4f} -> "
              f"{asym['fraction_m1']:.4f}; tip deflection {sym['tip_deflection']:.5f} -> {asym['tip_deflection']:.5f} m")
        figures[mesh] = {"symmetric": {k: sym[k] for k in ("fraction_m1", "fraction_m2", "tip_deflection", "dc_iterations")},
                         "asymmetric": {k: asym[k] for k in ("fraction_m1", "fraction_m2", "tip_deflection", "dc_iterations")},
                         "gap_to_plugin": sym["displacement_gap_to_plugin"], "mirror_gap": mirror_gap,
                         "largest_lagrangian_rise": max(rises)}
    record("variant_asymmetric", {"test": "variant_asymmetric", "parameters": summary["parameters"],
                                  "symmetric_reduction": red, "brute_force_worst_gap": worst_gap,
                                  "fenchel_worst": worst_fenchel, "meshes": figures})
    finish()


if __name__ == "__main__":
    main()
