#!/usr/bin/python3
"""Verification of the P2 variant with the three-point local step (edp/variants/beam-p2.edp).

Runs the variant on the three beam meshes into build/test-results/variant-p2 and asserts:
  * B is right: the trace (B' u) ./ w of a quadratic field equals its divergence at the mid-edge
    points, and the three one-point columns add up to FreeFEM's mid-edge rule qf2pT (round-off);
  * patch check: a homogeneous pressure (austenite, martensite 1, martensite 2) gives the 1D law's
    trace at every point, and the same vertex displacements on P1 and P2, to round-off;
  * P2 converges to the answer of fine P1: the tip deflection on P1 approaches the fine P2 value
    monotonically and ends within 1 %; P2 changes less from medium to fine than P1 does (faster
    convergence); the martensite area fractions of P1 and P2 on the fine mesh agree within 0.02
    (the zone stability the beam test asks across meshes);
  * Auchmuty's L_II never increases along the DC iterations, P1 and P2, every mesh (the invariant
    of tests/beam_test.py), and the P2 DC counts stay of the order of ten (<= 20, paper Fig. 10).
Writes results/checks/variant_p2.json.
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows  # noqa: E402


def main():
    out = os.path.join(TEST_RESULTS, "variant-p2")
    subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/variants/beam-p2.edp", "-out", out],
                   cwd=ROOT, check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    runs = {(r["element"], r["mesh"]): r for r in summary["runs"]}
    levels = ["coarse", "medium", "fine"]
    check(all((e, m) in runs for e in ("P1", "P2") for m in levels), "P1 and P2 runs on the three meshes")

    for m in levels:
        p2 = runs[("P2", m)]
        check(p2["points"] == 3 * p2["triangles"], f"{m}: three points per triangle ({p2['points']})")
        check(p2["quadratic_trace_rel_error"] <= 1e-10 and p2["mid_edge_rule_rel_error"] <= 1e-12,
              f"{m}: B gives the divergence of a quadratic field at the mid-edge points (rel. error "
              f"{p2['quadratic_trace_rel_error']:.1e}) and sums to the qf2pT rule ({p2['mid_edge_rule_rel_error']:.1e})")

    check(summary["patch_trace_rel_error"] <= 1e-12 and summary["patch_phase_mismatch"] == 0,
          f"patch: the 1D law's trace at every point on P1 and P2 (rel. error {summary['patch_trace_rel_error']:.1e}), "
          f"{summary['patch_phase_mismatch']} points in the wrong phase, over {len(summary['patch'])} pressures")
    check(summary["patch_p1_p2_displacement_rel_gap"] <= 1e-12,
          f"patch: P1 and P2 vertex displacements equal (rel. gap {summary['patch_p1_p2_displacement_rel_gap']:.1e})")

    tip = {e: [runs[(e, m)]["tip_deflection"] for m in levels] for e in ("P1", "P2")}
    ref = tip["P2"][-1]
    p1_err = [abs(v - ref) / ref for v in tip["P1"]]
    check(p1_err[0] > p1_err[1] > p1_err[2] and p1_err[2] < 0.01,
          f"P1 tip deflection converges to fine P2's {ref * 1e3:.4f} mm: relative gaps "
          + ", ".join(f"{e:.4f}" for e in p1_err) + " (coarse, medium, fine), the last < 1 %")
    p2_change = abs(tip["P2"][2] - tip["P2"][1]) / ref
    p1_change = abs(tip["P1"][2] - tip["P1"][1]) / ref
    check(p2_change < p1_change, f"P2 converges faster: medium -> fine change {p2_change:.5f} (P2) < {p1_change:.5f} (P1)")
    p2_coarse_gap = abs(tip["P2"][0] - ref) / ref
    check(p2_coarse_gap < p1_err[2], f"P2 on the coarse mesh ({p2_coarse_gap:.5f} from fine P2) beats P1 on the fine "
          f"mesh ({p1_err[2]:.5f})")
    fine1, fine2 = runs[("P1", "fine")], runs[("P2", "fine")]
    dm1, dm2 = abs(fine1["fraction_m1"] - fine2["fraction_m1"]), abs(fine1["fraction_m2"] - fine2["fraction_m2"])
    check(dm1 < 0.02 and dm2 < 0.02, f"fine mesh: martensite fractions P1 (M1 {fine1['fraction_m1']:.4f}, M2 "
          f"{fine1['fraction_m2']:.4f}) and P2 (M1 {fine2['fraction_m1']:.4f}, M2 {fine2['fraction_m2']:.4f}) within 0.02")

    convergence = rows(os.path.join(out, "dc-convergence.csv"))
    lagrangian = {}
    for e in ("P1", "P2"):
        for m in levels:
            seq = [v for r in convergence if r["element"] == e and r["mesh"] == m
                   for v in (float(r["lagrangian_after_global"]), float(r["lagrangian_after_local"]))]
            scale = max(abs(v) for v in seq)
            rise = max((b - a) / scale for a, b in zip(seq[:-1], seq[1:]))
            lagrangian[f"{e}-{m}"] = rise
            check(rise <= 1e-12, f"{e} {m}: L_II never increases over {len(seq) // 2} DC iterations "
                  f"(largest relative rise {rise:.1e})")
    its = [runs[("P2", m)]["dc_iterations"] for m in levels]
    check(max(its) <= 20, f"P2 DC iterations {its} <= 20 (P1: {[runs[('P1', m)]['dc_iterations'] for m in levels]})")

    record("variant_p2", {"test": "variant_p2", "tip_deflection": tip, "p1_gap_to_fine_p2": p1_err,
                          "p2_coarse_gap_to_fine_p2": p2_coarse_gap,
                          "runs": summary["runs"], "patch_trace_rel_error": summary["patch_trace_rel_error"],
                          "patch_p1_p2_displacement_rel_gap": summary["patch_p1_p2_displacement_rel_gap"],
                          "largest_lagrangian_rise": lagrangian})
    finish()


if __name__ == "__main__":
    main()
