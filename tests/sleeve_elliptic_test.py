#!/usr/bin/python3
"""Verification of the elliptic sleeves (paper Fig. 25-32, docs/model.md#fig-25-28-sleeve-elliptic)
on the default mesh.

sleeve-elliptic (mu = 0), against the paper's account:
  - contact starts on the major (vertical) axis: at the first contact step the y-axis point
    touches and the x-axis (minor) and 45-degree points do not;
  - the major axis lifts off (force back to zero) before the minor axis first touches;
  - the final force is nearly uniform (within 5 %), slightly higher on the major axis, and below
    the circular sleeve's on the same mesh (paper: about 10 % below; asserted 5 % to 15 %).
sleeve-elliptic-friction (mu = 0.2):
  - the final non-uniformity (max - min) / mean lies between 5 % and 30 % (paper: 14 % between
    the axes);
  - every contact node sticks at the end: no slip over the last step (above 1e-12 m), and every
    node strictly inside the Coulomb cone (|t| < 0.99 mu n); the cone holds everywhere
    (|t| <= mu n to 1e-6);
  - the tangential/normal force ratios are reported (paper: about 8 %).
Writes results/checks/sleeve_elliptic.json. These need the default mesh: on the coarse one
(6 layers) the major axis never lifts off. They are claims of the paper's scheme and are checked
with it (-phasemodel onoff; the circular sleeve on the same mesh, meshes/sleeve-quarter.msh). With
the default fraction model (the curve that converges, docs/benchmarks.md) the major axis does not
lift off fully and friction keeps a much smaller non-uniformity (docs/parameters.md, "Phase model").
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, run_scene, sleeve_outputs  # noqa: E402


def pressures(points, name):
    return [float(r[f"pressure_{name}_Pa"]) for r in points]


def main():
    runs = {}
    for scene in ("sleeve-circular", "sleeve-elliptic", "sleeve-elliptic-friction"):
        runs[scene] = sleeve_outputs(run_scene(scene, scene + "-onoff", "-quiet", "1", "-phasemodel", "onoff",
                                               "-mesh", "meshes/sleeve-quarter.msh"))

    # ---- sleeve-elliptic: where contact starts, the lift-off, the final level ----
    ell = runs["sleeve-elliptic"]
    major, minor, diag = (pressures(ell["points"], n) for n in ("y_axis", "x_axis", "diagonal"))
    first = next(i for i, p in enumerate(major) if p > 0)
    check(first + 1 == ell["summary"]["first_contact_step"] and minor[first] == 0 and diag[first] == 0,
          f"first contact on the major axis: step {first + 1}, major {major[first]:.3g} Pa, "
          f"minor {minor[first]:.3g} Pa, 45 degrees {diag[first]:.3g} Pa")
    minor_first = next(i for i, p in enumerate(minor) if p > 0)
    lift = [i for i in range(first, minor_first) if major[i] == 0]
    peak_before = max(major[first:minor_first])
    check(len(lift) > 0, f"the major axis lifts off before the minor axis touches (step "
          f"{minor_first + 1}): force zero at steps {[i + 1 for i in lift]}, after a peak of "
          f"{peak_before / 1e6:.3f} MPa")
    circ = runs["sleeve-circular"]["summary"]["final_pressure_mean"]
    ell_mean = ell["summary"]["final_pressure_mean"]
    below = 1 - ell_mean / circ
    check(0.05 <= below <= 0.15, f"final force {ell_mean / 1e6:.3f} MPa is {100 * below:.1f} % below "
          f"the circular sleeve's {circ / 1e6:.3f} MPa (paper: about 10 %)")
    nonuni = ell["summary"]["final_pressure_non_uniformity"]
    check(nonuni < 0.05, f"final force nearly uniform: non-uniformity {100 * nonuni:.2f} % < 5 %")
    by_angle = sorted(ell["final"], key=lambda r: float(r["angle_deg"]))
    p_minor, p_major = float(by_angle[0]["pressure"]), float(by_angle[-1]["pressure"])
    check(p_major > p_minor, f"slightly higher on the major axis: {p_major / 1e6:.4f} MPa vs "
          f"{p_minor / 1e6:.4f} MPa on the minor axis")

    # ---- sleeve-elliptic-friction: non-uniform, sticking, the cone ----
    fr = runs["sleeve-elliptic-friction"]
    fr_nonuni = fr["summary"]["final_pressure_non_uniformity"]
    check(0.05 <= fr_nonuni <= 0.30, f"with friction the final force is not uniform: "
          f"non-uniformity {100 * fr_nonuni:.2f} % in [5 %, 30 %] (paper: 14 % between the axes)")
    touching = [r for r in fr["final"] if float(r["normal_force"]) > 0]
    slips = [abs(float(r["slip_last_step"])) for r in touching]
    cone = [float(r["cone_ratio"]) for r in touching]
    check(len(touching) == len(fr["final"]), f"every node touches at the end: {len(touching)} of "
          f"{len(fr['final'])}")
    check(max(slips) <= 1e-12, f"no node slips over the last step: max |slip| {max(slips):.2e} m")
    check(max(cone) < 0.99, f"every node strictly inside the Coulomb cone: max |t|/(mu n) = {max(cone):.3f}")
    by_angle = sorted(fr["final"], key=lambda r: float(r["angle_deg"]))
    fr_minor, fr_major = float(by_angle[0]["pressure"]), float(by_angle[-1]["pressure"])
    axes = (fr_major - fr_minor) / fr["summary"]["final_pressure_mean"]
    print(f"info tangential/normal: max over nodes {fr['summary']['final_tangential_over_normal']:.3f}, "
          f"total {fr['summary']['final_tangential_over_normal_total']:.3f} (paper: about 0.08); "
          f"major minus minor axis {100 * axes:.2f} % of the mean (paper: 14 %)")
    record("sleeve_elliptic", {
        "test": "sleeve_elliptic", "mesh": ell["summary"]["parameters"]["mesh"],
        "steps": ell["summary"]["n_steps"],
        "elliptic_first_contact_step": first + 1, "elliptic_major_lift_off_steps": [i + 1 for i in lift],
        "elliptic_minor_first_contact_step": minor_first + 1,
        "elliptic_major_peak_before_lift_off_Pa": peak_before,
        "circular_final_pressure_Pa": circ, "elliptic_final_pressure_Pa": ell_mean,
        "elliptic_below_circular": below, "elliptic_non_uniformity": nonuni,
        "elliptic_final_major_Pa": p_major, "elliptic_final_minor_Pa": p_minor,
        "friction_non_uniformity": fr_nonuni, "friction_major_minus_minor_over_mean": axes,
        "friction_nodes_sticking": sum(s <= 1e-12 for s in slips), "friction_nodes": len(fr["final"]),
        "friction_max_cone_ratio": max(cone),
        "friction_tangential_over_normal_max": fr["summary"]["final_tangential_over_normal"],
        "friction_tangential_over_normal_total": fr["summary"]["final_tangential_over_normal_total"],
        "wall_seconds": {s: r["summary"]["wall_seconds"] for s, r in runs.items()}})
    finish()


if __name__ == "__main__":
    main()
