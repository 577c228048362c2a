#!/usr/bin/python3
"""Verification of the new-obstacle variant (edp/variants/ring-lobed.edp): a lobed pipe
r = Rp (1 + eps cos 4 theta) whose gap and normal the script computes.

Runs the variant twice into build/test-results/ (condensed PSOR, the default, and the paper's
full-system PSOR) and asserts:
  * degenerate shape (eps = 0): the script's gap and normal equal the plugin's ObstacleGap to
    round-off, and the contact reactions equal the circular run's to the solver's tolerance
    (full mode 1e-9; condensed mode 1e-7, its active-set polish accepts a law residual of 1e-8);
    the mean pressure is Lame's within 1e-3 (ring-lame: error 3e-4 at this mesh level);
  * every run: no penetration (n.u + gap >= 0), r_n >= 0, complementarity r_n (n.u + gap) = 0,
    the Coulomb cone |r_t| <= mu r_n with friction (all relative, 1e-8);
  * the shape's symmetry about the diagonal (the mesh's too): normal forces even, tangential
    forces odd under the mirror (relative 1e-6);
  * the lobes carry the load: the highest pressure on a lobe (within 10 deg of 0 or 90 deg), the
    lowest in the valley (within 10 deg of 45 deg), which starts 5 um clear of the ring and where
    the nodes out of contact (some) have an open gap;
    with friction the tangential forces do not vanish (the shape makes the ring slide).
Writes results/checks/variant_lobed.json.
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows  # noqa: E402


def run(mode):
    out = os.path.join(TEST_RESULTS, f"variant-lobed-{mode}")
    subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/variants/ring-lobed.edp", "-out", out,
                    "-psormode", mode], cwd=ROOT, check=True)
    return out, json.load(open(os.path.join(out, "summary.json")))


def main():
    measured = {}
    for mode, reaction_tol in (("condensed", 1e-7), ("full", 1e-9)):
        out, summary = run(mode)
        runs = {r["name"]: r for r in summary["runs"]}
        lame = summary["pressure_lame"]
        script = runs["circle-script"]
        check(0 <= script["geometry_gap_to_plugin"] <= 1e-12,
              f"{mode}: eps = 0, the script's gap and normal equal ObstacleGap's (largest gap "
              f"{script['geometry_gap_to_plugin']:.1e}, relative to the interference)")
        check(0 <= script["reaction_gap_to_plugin"] <= reaction_tol,
              f"{mode}: eps = 0, reactions equal the circular run's (relative {script['reaction_gap_to_plugin']:.1e} "
              f"<= {reaction_tol:.0e})")
        for name in ("circle-plugin", "circle-script"):
            err = abs(runs[name]["pressure_mean"] - lame) / lame
            check(err <= 1e-3, f"{mode} {name}: mean pressure {runs[name]['pressure_mean'] / 1e6:.3f} MPa, "
                  f"Lame {lame / 1e6:.3f} MPa (relative error {err:.1e})")
        for name, r in runs.items():
            check(r["max_penetration_over_interference"] <= 1e-8 and r["min_normal_force_over_max"] >= -1e-12
                  and r["max_complementarity"] <= 1e-8,
                  f"{mode} {name}: no penetration ({r['max_penetration_over_interference']:.1e}), r_n >= 0 "
                  f"({r['min_normal_force_over_max']:.1e}), complementarity ({r['max_complementarity']:.1e})")
            # gmsh writes the nodes to about 1e-9 relative: mirror images within 1e-7 rad
            check(r["mirror_angle_mismatch"] <= 1e-7 and r["normal_asymmetry"] <= 1e-6
                  and r["tangential_antisymmetry"] <= 1e-6,
                  f"{mode} {name}: symmetric about the diagonal (mirror nodes within {r['mirror_angle_mismatch']:.1e} rad): normal {r['normal_asymmetry']:.1e}, tangential "
                  f"(odd) {r['tangential_antisymmetry']:.1e}")
            if r["mu"] > 0:
                check(r["max_cone_excess_over_max_normal"] <= 1e-8 and r["max_tangential_over_normal"] > 0.01,
                      f"{mode} {name}: |r_t| <= mu r_n (excess {r['max_cone_excess_over_max_normal']:.1e}); "
                      f"tangential forces up to {r['max_tangential_over_normal']:.3f} of the largest normal one")
        for name in ("lobed", "lobed-friction"):
            nodes = rows(os.path.join(out, f"pressure-{name}.csv"))
            angle = [float(n["angle_deg"]) for n in nodes]
            p = [float(n["pressure"]) for n in nodes]
            top, low = angle[p.index(max(p))], angle[p.index(min(p))]
            largest = max(float(n["normal_force"]) for n in nodes)
            # out of contact: no force, up to the solver's tolerance (full-mode PSOR converges
            # linearly and stops on a change of 1e-10 per sweep: 3e-8 of the largest force is left)
            off = [(a, float(n["normal_motion"])) for a, n in zip(angle, nodes)
                   if float(n["normal_force"]) <= 1e-6 * largest]
            check((top < 10 or top > 80) and abs(low - 45) < 10,
                  f"{mode} {name}: highest pressure {max(p) / 1e6:.1f} MPa at {top:.1f} deg (a lobe), lowest "
                  f"{min(p) / 1e6:.1f} MPa at {low:.1f} deg (the valley)")
            # the valley starts Rp (1 - eps) - Ri = 5 um clear of the ring and the lobes push it out
            check(len(off) > 0 and all(abs(a - 45) < 10 and m > 0 for a, m in off),
                  f"{mode} {name}: {len(off)} nodes out of contact, all in the valley with an open gap "
                  f"(largest {max([m for _, m in off] or [0]) * 1e6:.2f} um)")
        measured[mode] = {"pressure_lame": lame, "runs": summary["runs"]}
    record("variant_lobed", {"test": "variant_lobed", "parameters": summary["parameters"], "modes": measured})
    finish()


if __name__ == "__main__":
    main()
