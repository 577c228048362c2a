#!/usr/bin/python3
"""A run's bound of its final contact state's time error (-timeestimate 1, edp/problems/sleeve/time-estimate.idp).

1. sleeve-elliptic-friction (coarse mesh, -tol 1e-3): summary.json's time_error_bound is, per field
   of contact-final.csv (pressure, tangential_density), the largest nodal difference between the
   run's file and its companion's (time-estimate/, -tol 1e-2) over the run's largest value, computed
   here again from the two files (1e-9); the companion's tolerance and steps are its own summary's.
2. It bounds the error: the run's largest nodal difference to a run at -tol 1e-6 (the reference) is
   below the bound, for the tangential density (friction's state, whose error the force curve's
   estimate does not see) and the pressure.
3. sleeve-3d on Coulomb's cone (-mu 0.2 -pipeB 0.0504 -length 0.02): the bound of both traction
   components likewise equals the two files' difference; sleeve-axisymmetric with friction along z
   (-mu 0.2) likewise on its bore-final.csv (which gains tangential_density with friction).
4. The stage after the clamping: the companion makes it in a quarter of the increments, and the
   bound of the stage's final values is the difference of the two curves' last rows over the run's,
   the curve's (<column>_curve) their largest difference at the loads both took over the run's
   largest value (both recomputed here, 1e-9). sleeve-3d's frictional bending (-length 0.02 -mu 0.2
   -bend 1e-2 -bendsteps 8): the final moment's bound is above its error against a run of 32
   increments (the clamping's part is 1e-10), the curve's above the curve's error at the companion's 2
   angles (rows 4 and 8; between them nothing is bounded: the error at every angle is recorded). sleeve-axisymmetric's pull-out (-pullout 1e-3
   -pullsteps 4, the run of 3.) likewise on pullout.csv. The bending's first sliding is bracketed
   by its increment: summary.json's angle before it is bend.csv's row before (0: the clamped state).
5. A run without -timeestimate leaves no companion of an earlier run in its folder.
Writes results/checks/time_estimate.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, rows, run_scene_captured, summary_of  # noqa: E402

COARSE = ["-mesh", "meshes/sleeve-coarse.msh", "-quiet", "1"]
CONE = ["-mu", "0.2", "-pipeB", "0.0504", "-length", "0.02", "-quiet", "1"]


def column(out, name, file="contact-final.csv"):
    return [float(r[name]) for r in rows(os.path.join(out, file))]


def difference(a_out, b_out, name, file="contact-final.csv"):
    a, b = column(a_out, name, file), column(b_out, name, file)
    return max(abs(x - y) for x, y in zip(a, b)) / max(abs(x) for x in a)


def stage_bound(figures, what, out, bound, file, names, increments, companion_increments):
    """The stage's bound: per column, the last rows' difference over the run's (1e-9), and the counts."""
    stage = bound["stage"]
    companion = os.path.join(out, "time-estimate")
    figures[what] = {"stage": stage}
    check(stage["increments"] == increments and stage["companion_increments"] == companion_increments
          and len(rows(os.path.join(companion, file))) == companion_increments,
          f"{what}: {stage['increments']} increments ({increments}), the companion's {stage['companion_increments']} "
          f"({companion_increments}) = the rows of its {file}")
    for name in names:
        curve, companion_curve = column(out, name, file), column(companion, name, file)
        again = abs(curve[-1] - companion_curve[-1]) / abs(curve[-1])
        # the curve's: at the loads both took (the companion's row j of m is the run's row j n / m when whole)
        n, m = len(curve), len(companion_curve)
        shared = [abs(curve[j * n // m - 1] - companion_curve[j - 1]) for j in range(1, m + 1) if j * n % m == 0]
        curve_again = max(shared) / max(abs(v) for v in curve)
        check(abs(stage[name] - again) <= 1e-9 * again + 1e-15
              and abs(stage[name + "_curve"] - curve_again) <= 1e-9 * curve_again + 1e-15,
              f"{what} {name}: the bound {stage[name]:.6e} = the last rows' difference over the run's {again:.6e}; the "
              f"curve's {stage[name + '_curve']:.6e} = its largest difference at the {len(shared)} shared loads over its "
              f"largest value {curve_again:.6e}")


def run(scene, tag, *args):
    out, proc = run_scene_captured(scene, "time-estimate-" + tag, *args)
    check(proc.returncode == 0, f"{scene} {' '.join(args)}: exit {proc.returncode} "
          f"{[l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith('error:')]}")
    return out


def main():
    figures = {}
    out = run("sleeve-elliptic-friction", "2d", *COARSE, "-tol", "1e-3", "-timeestimate", "1")
    ref = run("sleeve-elliptic-friction", "2d-reference", *COARSE, "-tol", "1e-6")
    bound = summary_of(out)["time_error_bound"]
    companion = os.path.join(out, "time-estimate")
    figures["2d"] = {"bound": bound}
    check(bound["companion_tol"] == 1e-2 and bound["companion_steps"] == summary_of(companion)["n_steps"],
          f"2D: the companion at -tol {bound['companion_tol']} (1e-2), {bound['companion_steps']} steps = its summary's")
    for name in ("pressure", "tangential_density"):
        again = difference(out, companion, name)
        actual = difference(out, ref, name)
        figures["2d"][name] = {"again": again, "actual": actual}
        check(abs(bound[name] - again) <= 1e-9 * again, f"2D {name}: the bound {bound[name]:.6e} = the two files' largest "
              f"nodal difference over the largest value {again:.6e}")
        check(actual <= bound[name], f"2D {name}: the error against -tol 1e-6 {actual:.3e} <= the bound {bound[name]:.3e} "
              f"(x{bound[name] / actual:.1f})")
    out3 = run("sleeve-3d", "cone", *CONE, "-tol", "1e-3", "-timeestimate", "1")
    bound3 = summary_of(out3)["time_error_bound"]
    figures["cone"] = {"bound": bound3}
    for name in ("pressure_filtered", "tangential_density_theta", "tangential_density_z"):
        again = difference(out3, os.path.join(out3, "time-estimate"), name)
        check(abs(bound3[name] - again) <= 1e-9 * again, f"cone {name}: the bound {bound3[name]:.6e} = the files' "
              f"{again:.6e}")
    outa = run("sleeve-axisymmetric", "axisymmetric", "-mu", "0.2", "-pullout", "1e-3", "-pullsteps", "4", "-tol", "1e-3",
               "-timeestimate", "1", "-quiet", "1")
    bounda = summary_of(outa)["time_error_bound"]
    figures["axisymmetric"] = {"bound": bounda}
    for name in ("pressure", "tangential_density"):
        again = difference(outa, os.path.join(outa, "time-estimate"), name, "bore-final.csv")
        check(abs(bounda[name] - again) <= 1e-9 * max(again, 1e-300), f"axisymmetric {name}: the bound {bounda[name]:.6e} = "
              f"bore-final.csv's {again:.6e}")
    # 4. the stages: the final values' bound is the two curves' last rows' difference
    stage_bound(figures, "axisymmetric pull-out", outa, bounda, "pullout.csv", ("pullout_force", "normal_force_total"), 4, 1)
    bend_args = ("-length", "0.02", "-mu", "0.2", "-bend", "1e-2", "-quiet", "1")
    outb = run("sleeve-3d", "bend", *bend_args, "-bendsteps", "8", "-tol", "1e-3", "-timeestimate", "1")
    refb = run("sleeve-3d", "bend-reference", *bend_args, "-bendsteps", "32")
    boundb = summary_of(outb)["time_error_bound"]
    stage_bound(figures, "bending", outb, boundb, "bend.csv", ("moment", "normal_force_total"), 8, 2)
    moment, moment_ref = column(outb, "moment", "bend.csv")[-1], column(refb, "moment", "bend.csv")[-1]
    actual = abs(moment - moment_ref) / abs(moment)
    figures["bending"]["moment_error_against_32_increments"] = actual
    check(0 < actual <= boundb["stage"]["moment"], f"bending: the final moment's error against 32 increments "
          f"{actual:.3e} <= its bound {boundb['stage']['moment']:.3e}")
    # the curve at the companion's loads (rows 4 and 8 of 8, rows 16 and 32 of 32: the same angles);
    # between them it bounds nothing: the whole curve's error is recorded, not checked (the first
    # increment's, at a load the companion did not take, is the largest: measured 7.5e-4 against the
    # shared loads' bound 5.8e-4)
    moments, moments_ref = column(outb, "moment", "bend.csv"), column(refb, "moment", "bend.csv")
    scale = max(abs(a) for a in moments)
    errors = [abs(a - moments_ref[4 * (i + 1) - 1]) / scale for i, a in enumerate(moments)]
    at_shared = max(errors[3], errors[7])
    figures["bending"]["moment_curve_error_against_32_increments"] = {"shared_loads": at_shared, "every_load": max(errors)}
    check(0 < at_shared <= boundb["stage"]["moment_curve"], f"bending: the moment curve's error against 32 increments at "
          f"the companion's loads {at_shared:.3e} <= its bound {boundb['stage']['moment_curve']:.3e} (at every load: "
          f"{max(errors):.3e}, not bounded)")
    bent, angles = summary_of(outb)["bending"], column(outb, "angle", "bend.csv")
    k = angles.index(bent["first_sliding_angle"])
    check(bent["first_sliding_angle_before"] == (angles[k - 1] if k > 0 else 0)
          and abs(bent["first_sliding_moment"] - column(outb, "moment", "bend.csv")[k]) <= 1e-9 * abs(bent["first_sliding_moment"]),
          f"bending: the first sliding bracketed by its increment ({bent['first_sliding_angle_before']}, "
          f"{bent['first_sliding_angle']}] rad, at {bent['first_sliding_moment']:.6g} N m (bend.csv row {k + 1})")
    # 5. the same folder without the estimate: the earlier companion goes
    run("sleeve-3d", "cone", *CONE, "-tol", "1e-3")
    check(not os.path.exists(os.path.join(out3, "time-estimate")) and summary_of(out3)["time_error_bound"] is None,
          "a run without -timeestimate removes the earlier run's companion and reports no bound")
    record("time_estimate", figures)
    finish()


if __name__ == "__main__":
    main()
