#!/usr/bin/python3
"""Verification of sleeve-random-threshold (paper Fig. 33-36,
docs/model.md#fig-33-36-sleeve-random-threshold) on the coarse mesh.

- Reproducible draws: two runs with the same seed write byte-identical CSV files (history,
  points, final contact, fields at the three instants); a run with another seed writes different
  ones.
- The draw itself: the sample of T0 per triangle has the requested standard deviation (within
  15 %) and mean T0 (within 4 standard errors).
- The paper's peak: some inner-surface node sees a pressure above its final value (asserted
  > 10 % above; paper: about 50 %), while the homogeneous material (spread 0, the control) stays
  within 1 % of its final value everywhere. Not 1e-6: with martensite fractions (the default
  model) the triangles of one layer of the coarse mesh (alternating diagonals) sit at slightly
  different fractions during the last step of the reversion, and a node's pressure there exceeds
  its final value by 0.6 %; the paper's on/off layers flip whole and stay within 1e-6.
Writes results/checks/sleeve_random_threshold.json.
"""
import filecmp
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import KELVIN_AT_0C, check, finish, record, run_scene  # noqa: E402

FILES = ["history.csv", "points.csv", "contact-final.csv", "fields-1-dilated.csv",
         "fields-2-contact.csv", "fields-3-end.csv"]
COMMON = ["-mesh", "meshes/sleeve-coarse.msh", "-steps", "600", "-quiet", "1"]


def main():
    runs = {name: run_scene("sleeve-random-threshold", "sleeve-random-threshold-" + name, *COMMON, *args)
            for name, args in (("seed1", ["-seed", "1"]), ("seed1-again", ["-seed", "1"]),
                               ("seed2", ["-seed", "2"]), ("homogeneous", ["-cspread", "0"]))}
    summary = {n: json.load(open(os.path.join(d, "summary.json"))) for n, d in runs.items()}
    same = [f for f in FILES if filecmp.cmp(os.path.join(runs["seed1"], f),
                                            os.path.join(runs["seed1-again"], f), shallow=False)]
    check(len(same) == len(FILES), f"same seed, byte-identical files: {len(same)} of {len(FILES)}")
    differ = [f for f in FILES if not filecmp.cmp(os.path.join(runs["seed1"], f),
                                                  os.path.join(runs["seed2"], f), shallow=False)]
    check(len(differ) == len(FILES), f"another seed, different files: {len(differ)} of {len(FILES)}")

    s = summary["seed1"]
    spread, T0 = s["parameters"]["threshold_spread_K"], s["parameters"]["T0"]
    n = s["triangles"]
    check(abs(s["T0_local_std"] / spread - 1) < 0.15,
          f"sample standard deviation {s['T0_local_std']:.3f} K for {spread} K requested ({n} triangles)")
    check(abs(s["T0_local_mean"] - T0) < 4 * spread / math.sqrt(n),
          f"sample mean {s['T0_local_mean']:.3f} K for T0 = {T0} K (4 standard errors: "
          f"{4 * spread / math.sqrt(n):.3f} K)")

    peaks = {k: v["node_peak_over_final_max"] for k, v in summary.items()}
    check(min(peaks["seed1"], peaks["seed2"]) > 1.1,
          f"a node's pressure peaks above its final value: {peaks['seed1']:.3f} x (seed 1, at "
          f"{summary['seed1']['node_peak_over_final_angle_deg']:.0f} deg), {peaks['seed2']:.3f} x (seed 2)")
    check(peaks["homogeneous"] <= 1.01,
          f"control, homogeneous material: peak / final {peaks['homogeneous']:.9f} <= 1.01")
    check(abs(s["final_pressure_mean"] / summary["homogeneous"]["final_pressure_mean"] - 1) < 1e-6,
          f"same final level as the homogeneous ring once all austenite: {s['final_pressure_mean'] / 1e6:.4f} "
          f"vs {summary['homogeneous']['final_pressure_mean'] / 1e6:.4f} MPa")
    print(f"info austenite for good at inner {s['T_inner_austenite'] - KELVIN_AT_0C:.1f} C (homogeneous "
          f"{summary['homogeneous']['T_inner_austenite'] - KELVIN_AT_0C:.1f} C)")
    record("sleeve_random_threshold", {
        "test": "sleeve_random_threshold", "mesh": "meshes/sleeve-coarse.msh", "steps": s["n_steps"],
        "spread_K": spread, "law": s["parameters"]["threshold_law"], "triangles": n,
        "sample_std_K": s["T0_local_std"], "sample_mean_K": s["T0_local_mean"],
        "identical_files_same_seed": same, "different_files_other_seed": differ,
        "node_peak_over_final": peaks,
        "T_inner_austenite_K": {k: v["T_inner_austenite"] for k, v in summary.items()},
        "final_pressure_Pa": {k: v["final_pressure_mean"] for k, v in summary.items()}})
    finish()


if __name__ == "__main__":
    main()
