#!/usr/bin/python3
"""Verification of the sleeve-radial scene (the centred circular sleeve as a 1D problem in r).

1. End state against Lame: at the end the ring is all austenite and elastic (s = 0 everywhere), so
   the contact pressure must be the closed-form shrink-fit pressure of a thick ring (plane strain,
   interference = pipe radius - inner radius) on a rigid shaft, to discretisation accuracy: the
   relative error must fall at order 2 in nr (P1 nodal reaction), over nr = 2 ... 32.
2. Convergence of the transient force curve (tools/bench/oracles/curve_error.py l1_transient) with the default
   fraction model: nr and dt refined together (20/150 ... 320/2400 steps over 30 s); the
   successive differences must decrease at an observed order >= 0.9, every level without a
   reversal step or a pressure zigzag, and the scene's defaults within 0.3 % of the finest level.
   The paper's on/off model at nr 20 / 1500 steps chatters, and its summary says so.
3. The 2D scene as an independent computation: sleeve-circular on meshes/sleeve-coarse.msh
   (6 layers, 1500 steps) against sleeve-radial at nr 6, 1500 steps: same first-contact step,
   temperatures and force history close.
4. Invariants on every run: no penetration (gap >= 0), complementarity (reaction >= 0 and zero
   unless the gap is closed), phase fractions in [0, 1] summing to 1, discrete heat balance at
   round-off (relative 1e-8: a step's stored heat is a small difference of large nodal
   values); bad input (-nr 0) fails with one line naming the option.
Writes results/checks/sleeve_radial.json.
"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench", "oracles"))

from checklib import ROOT, check, finish, record, rows, run_scene  # noqa: E402
from curve_error import curve_error  # noqa: E402
from lame import lame_pressure  # noqa: E402


def radial(tag, *args):
    out = run_scene("sleeve-radial", "sleeve-radial-" + tag, "-quiet", "1", *args)
    return {"dir": out, "history": os.path.join(out, "history.csv"),
            "summary": json.load(open(os.path.join(out, "summary.json"))),
            "rows": rows(os.path.join(out, "history.csv")),
            "final": rows(os.path.join(out, "fields-final.csv"))}


def invariants(tag, run):
    """Contact and phase invariants of one run; returns the worst figures."""
    h = run["rows"]
    delta = run["summary"]["interference"]
    reaction_max = max(float(r["reaction_per_radian"]) for r in h) or 1.0
    gap_min = min(float(r["gap_inner"]) for r in h)
    reaction_min = min(float(r["reaction_per_radian"]) for r in h)
    complementarity = max(abs(float(r["gap_inner"])) / delta * float(r["reaction_per_radian"]) / reaction_max
                          for r in h)
    fraction_low = min(min(float(r[k]) for k in ("fraction_austenite", "fraction_m1", "fraction_m2")) for r in h)
    fraction_high = max(max(float(r[k]) for k in ("fraction_austenite", "fraction_m1", "fraction_m2")) for r in h)
    fraction_sum = max(abs(sum(float(r[k]) for k in ("fraction_austenite", "fraction_m1", "fraction_m2")) - 1)
                       for r in h)
    balance = run["summary"]["heat_balance_residual_max"]
    ok = (gap_min >= -1e-9 * delta and reaction_min >= 0 and complementarity <= 1e-9 and fraction_low >= 0
          and fraction_high <= 1 and fraction_sum <= 1e-12 and balance <= 1e-8)
    check(ok, f"{tag}: gap >= {gap_min:.2e} m, reaction >= {reaction_min:.3g}, complementarity "
          f"{complementarity:.1e}, fractions in [{fraction_low}, {fraction_high}] summing to 1 within "
          f"{fraction_sum:.1e}, heat balance {balance:.1e}")
    return {"gap_min_m": gap_min, "reaction_min": reaction_min, "complementarity": complementarity,
            "fraction_sum_error": fraction_sum, "heat_balance_residual": balance}


def main():
    figures = {"invariants": {}}

    # 1. End state against Lame.
    lame_runs = {}
    for nr in (2, 4, 8, 16, 32):
        lame_runs[nr] = run = radial(f"lame-nr{nr}", "-nr", str(nr), "-steps", "300", "-tend", "30")
        figures["invariants"][f"lame-nr{nr}"] = invariants(f"nr {nr}, 300 steps", run)
    p = lame_runs[2]["summary"]["parameters"]
    a, b = p["ring_inner_radius"], p["ring_inner_radius"] + p["ring_thickness"]
    exact = lame_pressure(p["E"], p["nu"], a, b, p["pipe_A"] - a)
    errors = {}
    for nr, run in lame_runs.items():
        final_austenite = float(run["rows"][-1]["fraction_austenite"])
        s_max = max(abs(float(r["s"])) for r in run["final"])
        check(final_austenite == 1 and s_max == 0,
              f"nr {nr}: at the end all austenite ({final_austenite}) and elastic (max |s| = {s_max})")
        errors[nr] = abs(run["summary"]["final_pressure_mean"] / exact - 1)
    orders = [math.log2(errors[n] / errors[2 * n]) for n in (2, 4, 8, 16)]
    print("final pressure against Lame " + f"{exact / 1e6:.6f} MPa: "
          + ", ".join(f"nr {n} {errors[n]:.2e}" for n in errors)
          + "; orders " + ", ".join(f"{o:.3f}" for o in orders))
    check(errors[32] < 1e-5, f"nr 32: final pressure {lame_runs[32]['summary']['final_pressure_mean'] / 1e6:.6f}"
          f" MPa within {errors[32]:.1e} < 1e-5 of Lame's {exact / 1e6:.6f} MPa")
    check(all(1.9 <= o <= 2.1 for o in orders), f"order 2 in nr: observed {min(orders):.3f} to {max(orders):.3f}")
    figures.update(lame_pressure_Pa=exact, lame_relative_errors={str(n): e for n, e in errors.items()},
                   lame_orders=orders)

    # 2. Convergence of the transient force curve (the default fraction model): nr and dt refined
    #    together over the first 30 s (the transient ends near 16 s), against each other and against
    #    the finest level; every level free of chatter.
    levels = [(20, 150), (40, 300), (80, 600), (160, 1200), (320, 2400)]
    runs = [radial(f"study-{nr}-{steps}", "-nr", str(nr), "-steps", str(steps), "-tend", "30")
            for nr, steps in levels]
    for (nr, steps), run in zip(levels, runs):
        figures["invariants"][f"{nr}/{steps}/30s"] = invariants(f"nr {nr}, {steps} steps over 30 s", run)
    reference = runs[-1]
    diffs = [curve_error(c["history"], f["history"])["l1_transient"] for c, f in zip(runs, runs[1:])]
    errors = [curve_error(r["history"], reference["history"])["l1_transient"] for r in runs[:-1]]
    order = math.log2(diffs[0] / diffs[-1]) / (len(diffs) - 1)
    print("study: successive transient l1 differences " + ", ".join(f"{d:.2e}" for d in diffs)
          + "; against nr 320: " + ", ".join(f"{e:.2e}" for e in errors) + f"; observed order {order:.2f}")
    check(all(x > y for x, y in zip(diffs, diffs[1:])) and order >= 0.9,
          f"nr and dt refined together: successive transient l1 differences decrease "
          f"({', '.join(f'{x:.2e}' for x in diffs)}), observed order {order:.2f} >= 0.9 (first order expected: "
          f"the phases are constant per element)")
    chatter = [(lv, r["summary"]["reversal_steps"], r["summary"]["pressure_zigzag_steps"]) for lv, r in zip(levels, runs)]
    check(all(rev == 0 and zig == 0 for _, rev, zig in chatter),
          f"no reversal step and no pressure zigzag at any level: {chatter}")
    default = radial("default")
    default_error = curve_error(default["history"], reference["history"])["l1_transient"]
    check(default["summary"]["parameters"]["phase_model"] == "fraction" and default_error <= 3e-3,
          f"the defaults (nr {default['summary']['nr']}, {default['summary']['n_steps']} steps over 150 s): "
          f"transient l1 {100 * default_error:.3f} % <= 0.3 % from nr 320 / 2400 steps")
    onoff = radial("onoff-20-1500", "-nr", "20", "-steps", "1500", "-phasemodel", "onoff")
    s_onoff = onoff["summary"]
    check(s_onoff["chatter"] and s_onoff["reversal_steps"] > 0 and s_onoff["pressure_zigzag_steps"] > 0,
          f"the paper's on/off model at nr 20 chatters and says so: {s_onoff['reversal_steps']} reversal steps, "
          f"{s_onoff['pressure_zigzag_steps']} pressure zigzags")
    figures.update(study_levels=levels, study_tend=30, study_successive_l1_transient=diffs,
                   study_l1_transient_vs_finest=errors, study_order=order,
                   default_l1_transient_vs_finest=default_error,
                   default_wall_seconds=default["summary"]["wall_seconds"],
                   onoff_nr20_chatter={k: s_onoff[k] for k in ("reversal_steps", "pressure_zigzag_steps")})

    # 3. The 2D scene on the coarse mesh (6 layers) against the 1D at nr 6, same steps.
    circ = run_scene("sleeve-circular", "sleeve-radial-circular-coarse", "-mesh", "meshes/sleeve-coarse.msh",
                     "-quiet", "1", "-vtkevery", "0", "-steps", "1500")
    circ_history = os.path.join(circ, "history.csv")
    one_d = radial("nr6-1500", "-nr", "6", "-steps", "1500")
    figures["invariants"]["6/1500"] = invariants("nr 6, 1500 steps", one_d)
    e2d = curve_error(circ_history, one_d["history"])
    check(e2d["first_contact_dt"] == 0 and abs(e2d["first_contact_dT"]) < 0.1 and e2d["l1"] < 5e-3
          and e2d["final"] < 1e-3,
          f"sleeve-circular (coarse mesh, 1500 steps) against sleeve-radial nr 6: first contact at the same "
          f"step, T inner differs by {e2d['first_contact_dT']:.3f} K; l1 {e2d['l1']:.2e} < 0.5 %, final "
          f"{e2d['final']:.1e} < 0.1 %")
    e2d_ref = curve_error(circ_history, reference["history"])
    print(f"sleeve-circular (coarse mesh, 1500 steps) against the converged 1D reference: l1 {e2d_ref['l1']:.2e} "
          f"(transient {e2d_ref['l1_transient']:.2e}), final {e2d_ref['final']:.1e}, first contact "
          f"{e2d_ref['first_contact_dT']:+.3f} K, austenite for good {e2d_ref['austenite_dt']:+.3f} s")
    figures.update(circular_coarse_vs_nr6=e2d, circular_coarse_vs_reference=e2d_ref)

    # 4. Bad input fails naming the option.
    bad = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-nr", "0",
                          "-out", os.path.join(ROOT, "build", "test-results", "sleeve-radial-bad")],
                         cwd=ROOT, capture_output=True, text=True)
    said = [ln for ln in (bad.stdout + bad.stderr).splitlines() if ln.startswith("error:")]
    check(bad.returncode == 1 and said == ["error: sleeve-radial: -nr 0 must be >= 1"],
          f"-nr 0 fails (exit {bad.returncode}) with one line naming it: {said}")

    record("sleeve_radial", dict(figures, test="sleeve_radial"))
    finish()


if __name__ == "__main__":
    main()
