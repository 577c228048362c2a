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
4. A run without -timeestimate leaves no companion of an earlier run in its folder.
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
    outa = run("sleeve-axisymmetric", "axisymmetric", "-mu", "0.2", "-tol", "1e-3", "-timeestimate", "1", "-quiet", "1")
    bounda = summary_of(outa)["time_error_bound"]
    figures["axisymmetric"] = {"bound": bounda}
    for name in ("pressure", "tangential_density"):
        again = difference(outa, os.path.join(outa, "time-estimate"), name, "bore-final.csv")
        check(abs(bounda[name] - again) <= 1e-9 * max(again, 1e-300), f"axisymmetric {name}: the bound {bounda[name]:.6e} = "
              f"bore-final.csv's {again:.6e}")
    # 4. the same folder without the estimate: the earlier companion goes
    run("sleeve-3d", "cone", *CONE, "-tol", "1e-3")
    check(not os.path.exists(os.path.join(out3, "time-estimate")) and summary_of(out3)["time_error_bound"] is None,
          "a run without -timeestimate removes the earlier run's companion and reports no bound")
    record("time_estimate", figures)
    finish()


if __name__ == "__main__":
    main()
