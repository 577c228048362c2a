#!/usr/bin/python3
"""sleeve-radial against an independent implementation of its scheme: tools/bench/oracles/radial_numpy.py
(the same equations written again in vectorised numpy, tridiagonal LDL' factorisations, no shared
code with the scripts or the plugin), at nr 20, 200 steps.

The scene runs the same scheme with -stepsolver fixedpoint (its default solver, newton, solves the
same step equations by another method: checked last, below). The two differ only in round-off and
in where a loop's stopping test falls, so their curves must agree to a bound set by the loops'
tolerances:
  - each DC loop stops once the relative change of u is <= dctol, so each run's displacement, and
    with it the contact pressure (a linear function of the inner displacement, of the size of the
    interference), is within about dctol of the loop's limit: the two pressure curves differ by at
    most 2 dctol of the largest pressure (max over the union time grid, tools/bench/oracles/curve_error.py linf);
  - each fixed point stops once the relative change of T is <= fptol: the temperatures differ by at
    most 2 fptol T, plus the 12 significant digits the scene prints (half a unit of the 12th digit:
    5e-10 K at 200-300 K), as a mean over time (curve_error T_inner_l1);
  - the end state is all austenite and elastic, where neither loop truncates anything: the final
    pressures agree to round-off and the printed digits (1e-10 relative).
Run at the default tolerances (-dctol 1e-3, -fptol 1e-8) and at tight ones (-dctol 1e-10,
-fptol 1e-12), where the bound is eight orders tighter. The same first-contact and austenite
steps. The bound must also be able to fail: the numpy run with the latent heat changed by 1e-4
relative must be outside the tight bound.
The scene's default step solver (-stepsolver newton, plugin/core/step_newton.hpp: max |chi -
law(chi)| <= -steptol 1e-8 at every step) against the tight numpy run, the nearest to the scheme's
limit: its pressure curve within 2 steptol of the peak, its temperatures within 2 steptol K (a
fraction error moves T by at most L / C0 = 3.6 K per unit), the same first-contact and austenite
steps.
Writes results/checks/radial_numpy.json.
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench", "oracles"))

from checklib import ROOT, TEST_RESULTS, check, finish, record, run_scene  # noqa: E402
from curve_error import curve_error  # noqa: E402

SIZE = ["-nr", "20", "-steps", "200"]
PRINT_T = 5e-10          # K: half a unit of the 12th significant digit of T ~ 300 K (history.csv)
PRINT_RELATIVE = 1e-10   # the final pressure's printed digits (12) and round-off, with margin


def numpy_run(tag, *args):
    out = os.path.join(TEST_RESULTS, "radial-numpy-" + tag)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools", "bench", "oracles", "radial_numpy.py"), "-out", out, *args],
                   cwd=ROOT, check=True)
    return out


def compare(tag, dctol, fptol):
    """Both runs at the given tolerances; returns the measured differences."""
    tolerances = ["-dctol", repr(dctol), "-fptol", repr(fptol)]
    ff = run_scene("sleeve-radial", "radial-numpy-ff-" + tag, "-quiet", "1", "-stepsolver", "fixedpoint", *SIZE,
                   *tolerances)
    ours = numpy_run(tag, *SIZE, *tolerances)
    e = curve_error(os.path.join(ours, "history.csv"), os.path.join(ff, "history.csv"))
    sf = json.load(open(os.path.join(ff, "summary.json")))
    sn = json.load(open(os.path.join(ours, "summary.json")))
    bound_p, bound_T = 2 * dctol, 2 * fptol * 300 + PRINT_T
    check(e["linf"] <= bound_p, f"{tag}: pressure curves (FreeFEM, numpy) differ by {e['linf']:.2e} of the peak "
          f"<= 2 dctol = {bound_p:.1e} (transient L1 {e['l1_transient']:.2e})")
    check(e["T_inner_l1"] <= bound_T, f"{tag}: inner temperatures differ by {e['T_inner_l1']:.2e} K on average "
          f"<= 2 fptol T + print = {bound_T:.1e} K")
    check(e["final"] <= PRINT_RELATIVE, f"{tag}: final pressures {sf['final_pressure_mean']:.12g} and "
          f"{sn['final_pressure_mean']:.12g} Pa differ by {e['final']:.1e} <= {PRINT_RELATIVE:g} (relative)")
    check(sf["first_contact_step"] == sn["first_contact_step"] and sf["austenite_step"] == sn["austenite_step"],
          f"{tag}: first contact at step {sf['first_contact_step']} / {sn['first_contact_step']}, austenite from "
          f"step {sf['austenite_step']} / {sn['austenite_step']} (FreeFEM / numpy)")
    return {"dctol": dctol, "fptol": fptol, "pressure_linf": e["linf"], "pressure_l1_transient": e["l1_transient"],
            "T_inner_l1_K": e["T_inner_l1"], "final_pressure_relative": e["final"], "bound_pressure": bound_p,
            "bound_T_K": bound_T, "freefem": {k: sf[k] for k in ("final_pressure_mean", "fixed_point_iterations_mean",
                                                                  "dc_iterations_mean", "first_contact_step",
                                                                  "austenite_step")},
            "numpy": {k: sn[k] for k in ("final_pressure_mean", "fixed_point_iterations_mean", "dc_iterations_mean",
                                         "first_contact_step", "austenite_step")}, "ff_dir": ff}


def newton_against_tight(tight_numpy):
    """The default step solver against the tight numpy run (module docstring)."""
    steptol = 1e-8
    ff = run_scene("sleeve-radial", "radial-numpy-ff-newton", "-quiet", "1", *SIZE, "-steptol", repr(steptol))
    e = curve_error(os.path.join(tight_numpy, "history.csv"), os.path.join(ff, "history.csv"))
    sf = json.load(open(os.path.join(ff, "summary.json")))
    sn = json.load(open(os.path.join(tight_numpy, "summary.json")))
    check(sf["step_solver"] == "newton" and e["linf"] <= 2 * steptol and e["T_inner_l1"] <= 2 * steptol * 3.6
          and sf["first_contact_step"] == sn["first_contact_step"] and sf["austenite_step"] == sn["austenite_step"],
          f"newton (-steptol {steptol:g}) against the tight fixed point: pressure {e['linf']:.2e} of the peak "
          f"<= {2 * steptol:.0e}, inner T {e['T_inner_l1']:.2e} K <= {2 * steptol * 3.6:.1e} K, first contact "
          f"{sf['first_contact_step']} / {sn['first_contact_step']}, austenite {sf['austenite_step']} / "
          f"{sn['austenite_step']}")
    return {"steptol": steptol, "pressure_linf": e["linf"], "T_inner_l1_K": e["T_inner_l1"],
            "fixed_point_iterations_max": sf["fixed_point_iterations_max"]}


def main():
    figures = {"default": compare("default", 1e-3, 1e-8), "tight": compare("tight", 1e-10, 1e-12)}
    figures["newton"] = newton_against_tight(os.path.join(TEST_RESULTS, "radial-numpy-tight"))
    # The bound can fail: a 1e-4 change of one constant in the numpy run leaves it.
    tight = figures["tight"]
    perturbed = numpy_run("perturbed", *SIZE, "-dctol", "1e-10", "-fptol", "1e-12", "-latent", "3000.3")
    e = curve_error(os.path.join(perturbed, "history.csv"), os.path.join(tight["ff_dir"], "history.csv"))
    check(e["linf"] > tight["bound_pressure"], f"the tight bound sees -latent 3000.3 (1e-4 relative): pressure "
          f"difference {e['linf']:.2e} > {tight['bound_pressure']:.1e}")
    figures["perturbed_latent_pressure_linf"] = e["linf"]
    for f in ("default", "tight"):
        figures[f].pop("ff_dir")
    record("radial_numpy", figures)
    finish()


if __name__ == "__main__":
    main()
