#!/usr/bin/python3
"""Time steps chosen by the error (-tol), the retry of a step whose solve fails, and each run's
estimate of its own time error (edp/problems/sleeve/step-control.idp; docs/parameters.md, "Time
steps").

sleeve-radial at the paper's scale (its defaults, nr 160), against its own run of 10000 fixed
steps (the time discretisation's reference on the same mesh: the 1000-step default is 4e-6 from
it over the run):
  - effectivity: summary.json's time_error_estimate (and _transient) over the error measured
    against that reference (tools/bench/oracles/curve_error.py l1, l1_transient) within [0.5, 2.5],
    for -tol 1e-3, -tol 3e-4 and the fixed -steps 150 (2.2-2.3 there since the first contact's kink
    is counted at its worst case, h |dp| / 2, as the phase events': docs/measurements.md#m-estimate-audit);
  - with -tol: some steps were rejected and taken again (steps_rejected > 0), every accepted
    step's ratio <= 1, the rows' dt are the differences of their t and end at -tend, no step
    longer than -dtmax, the heat balance of the variable steps to round-off, the final pressure
    Lame's; the error measured is below 3 tol over the transient;
  - a fixed-step run's t is n dt and its dt column dt, to the last bit;
  - an adaptive run stopped by -stopafter and resumed from its checkpoint equals the whole run.
sleeve-circular-gvar (g switching where the ring touches) at -tol 1e-3, against its 15000 fixed
steps: the effectivity within [0.5, 3], the switched condition's part of the estimate > 0 (2.59:
since the phase events' rule holds its onset step, step-control.idp, its error halved, 3.68e-4 ->
1.69e-4 over the run, while the switched condition's part, 2.7e-4, stayed; before, 1.10).
sleeve-elliptic-friction at -steps 100 (the step the nested loops could not solve, step 39 of
100: a slip-threshold fixed point at its limit) is solved in halves: exit 0, steps_retried >= 1,
step_splits >= 1, every node inside the Coulomb cone at the end.
sleeve-elliptic at -tol 1e-3 (its steps at the reversion's onset cost up to 14 000 products whole),
with the step solver's trace (SMA_STEP_TRACE=1): a trial the step solver gives up (its budget of
products, errors.idp stepTrialWorkMax, spent, or negative-curvature moves that do not halve the
residual) is taken again shorter, not by the nested loops: exit 0, steps_retried >= 1 and at least
one trial given up on stalled curvature moves, step_fallbacks 0, the products of the solves not
converged summing to summary.json's step_products_retried and those of all solves to its
step_products, no accepted step above the budget, and the final pressure the 1500-step run's to
1e-6; its runs of failed solves shorten the steps less than a quarter of the limit (1024) at which
tries stop being trials.
sleeve-elliptic-friction with the nested loops and -slipmaxit 20 (its slip-threshold loop fails at
every step length): exit 1 within 100 steps of its run of failures, one error line naming the loop
and the shortening, in [1024, 4096) and equal to the lengths it quotes (before: the steps shrank to
the shortest and the run crawled).
Runs into build/test-results/time-steps-*/; writes results/checks/time_steps.json.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record, rows, run_scene_captured, summary_of  # noqa: E402
from curve_error import curve_error  # noqa: E402


# the shortening of a run of failed solves at which tries stop being trials, as the scripts set it
with open(os.path.join(ROOT, "edp/problems/sleeve/step-control.idp")) as f:
    LIMIT = int(re.search(r"^real stepFailureShorteningLimit = (\d+);", f.read(), re.M)[1])


def run(scene, name, *args):
    """The scene into build/test-results/time-steps-<name> (checklib), quiet; (folder, process)."""
    return run_scene_captured(scene, "time-steps-" + name, "-quiet", "1", *args)


def main():
    data = {}
    ref, proc = run("sleeve-radial", "ref", "-steps", "10000")
    check(proc.returncode == 0, f"sleeve-radial -steps 10000 (the reference) exit {proc.returncode} {proc.stderr[-300:]}")
    for name, args in (("tol1e-3", ["-tol", "1e-3"]), ("tol3e-4", ["-tol", "3e-4"]),
                       ("steps150", ["-steps", "150"])):
        out, proc = run("sleeve-radial", name, *args)
        check(proc.returncode == 0, f"sleeve-radial {' '.join(args)} exit {proc.returncode} {proc.stderr[-300:]}")
        if proc.returncode != 0:
            continue
        s, e = summary_of(out), curve_error(os.path.join(out, "history.csv"), os.path.join(ref, "history.csv"))
        eff = s["time_error_estimate"] / e["l1"]
        eff_tr = s["time_error_estimate_transient"] / e["l1_transient"]
        data[name] = {"steps": s["n_steps"], "rejected": s["steps_rejected"], "l1": e["l1"],
                      "estimate": s["time_error_estimate"], "effectivity": eff,
                      "l1_transient": e["l1_transient"], "estimate_transient": s["time_error_estimate_transient"],
                      "effectivity_transient": eff_tr, "l1_reversion": e["l1_reversion"]}
        check(0.5 <= eff <= 2.5, f"{name}: estimate {s['time_error_estimate']:.3e} over the measured "
                                 f"{e['l1']:.3e} = {eff:.2f}, in [0.5, 2.5]")
        check(0.5 <= eff_tr <= 2.5, f"{name}: transient estimate {s['time_error_estimate_transient']:.3e} over "
                                    f"the measured {e['l1_transient']:.3e} = {eff_tr:.2f}, in [0.5, 2.5]")
        history = rows(os.path.join(out, "history.csv"))
        t = [float(r["t"]) for r in history]
        dt = [float(r["dt"]) for r in history]
        check(abs(s["final_pressure_mean"] / s["lame_pressure"] - 1) < 1e-6,
              f"{name}: final pressure {s['final_pressure_mean']:.6e} = Lame {s['lame_pressure']:.6e}")
        check(s["heat_balance_residual_max"] < 1e-9,
              f"{name}: heat balance of every step {s['heat_balance_residual_max']:.2e} < 1e-9")
        if "tol" in name:
            tol = float(args[1])
            check(s["steps_rejected"] > 0 and s["step_error_ratio_max"] <= 1,
                  f"{name}: {s['steps_rejected']} steps rejected and taken again, accepted ratios <= 1 "
                  f"(max {s['step_error_ratio_max']:.3f})")
            gaps = max(abs(dt[i] - (t[i] - (t[i - 1] if i else 0.0))) for i in range(len(t)))
            # (history.csv writes 12 significant digits: t = 102.174398274 is known to 5e-10)
            check(gaps <= 1e-11 * t[-1] and t[-1] == s["parameters"]["tend"] and
                  max(dt) <= s["dt_max"] * (1 + 1e-12) and all(x > 0 for x in dt),
                  f"{name}: {len(t)} rows, dt = the differences of t (to {gaps:.1e}), 0 < dt <= dt_max "
                  f"{s['dt_max']}, the last t {t[-1]} = tend")
            check(e["l1_transient"] <= 3 * tol, f"{name}: measured transient error {e['l1_transient']:.2e} "
                                                 f"<= 3 tol = {3 * tol:.1e}")
        else:
            step = s["parameters"]["dt"]
            check(all(float(r["t"]) == int(r["step"]) * step and float(r["dt"]) == step for r in history),
                  f"{name}: every row's t = step x dt ({step}) and dt = {step}, bit for bit")
    # A heat condition that switches inside steps (g 2000 where the ring touches, 500 elsewhere): its
    # lag is in the estimate (without its part the effectivity was 0.35).
    ref, proc_ref = run("sleeve-circular-gvar", "gvar-ref", "-steps", "15000", "-vtkevery", "0")
    out, proc = run("sleeve-circular-gvar", "gvar", "-tol", "1e-3", "-vtkevery", "0")
    check(proc.returncode == 0 == proc_ref.returncode,
          f"sleeve-circular-gvar -tol 1e-3 exit {proc.returncode}, -steps 15000 exit {proc_ref.returncode}")
    if proc.returncode == 0 == proc_ref.returncode:
        s, e = summary_of(out), curve_error(os.path.join(out, "history.csv"), os.path.join(ref, "history.csv"))
        eff = s["time_error_estimate"] / e["l1"]
        data["gvar_tol1e-3"] = {"steps": s["n_steps"], "l1": e["l1"], "estimate": s["time_error_estimate"],
                                "estimate_condition": s["time_error_estimate_condition"], "effectivity": eff}
        check(s["time_error_estimate_condition"] > 0 and 0.5 <= eff <= 3,
              f"sleeve-circular-gvar -tol 1e-3: estimate {s['time_error_estimate']:.3e} (the switched condition's "
              f"part {s['time_error_estimate_condition']:.2e}) over the measured {e['l1']:.3e} = {eff:.2f}, in [0.5, 3]")
    # An adaptive run stopped and resumed equals the whole one.
    adaptive = ["-tol", "1e-3", "-checkpoint", "10"]
    whole, p1 = run("sleeve-radial", "whole", *adaptive)
    part, p2 = run("sleeve-radial", "part", *adaptive, "-stopafter", "25")
    part, p3 = run("sleeve-radial", "part", *adaptive, "-resume", "1")
    same = (p1.returncode, p2.returncode, p3.returncode) == (0, 4, 0)
    if same:
        with open(os.path.join(whole, "history.csv")) as a, open(os.path.join(part, "history.csv")) as b:
            same = a.read() == b.read()
    check(same, f"-tol 1e-3 stopped after step 25 and resumed from the checkpoint of step 20: history.csv "
                f"equals the whole run's (exits {p1.returncode} {p2.returncode} {p3.returncode})")
    # A step the solvers cannot take whole is taken in halves.
    out, proc = run("sleeve-elliptic-friction", "friction100", "-steps", "100", "-vtkevery", "0")
    check(proc.returncode == 0, f"sleeve-elliptic-friction -steps 100 exit {proc.returncode} {proc.stderr[-300:]}")
    if proc.returncode == 0:
        s = summary_of(out)
        data["friction100"] = {k: s[k] for k in ("steps_retried", "step_splits", "final_nodes_inside_cone",
                                                  "final_nodes_in_contact")}
        check(s["steps_retried"] >= 1 and s["step_splits"] >= 1,
              f"sleeve-elliptic-friction -steps 100: {s['steps_retried']} step(s) retried in "
              f"{s['step_splits']} splits")
        check(s["final_nodes_inside_cone"] == s["final_nodes_in_contact"] > 0,
              f"sleeve-elliptic-friction -steps 100: {s['final_nodes_inside_cone']} of "
              f"{s['final_nodes_in_contact']} nodes in contact inside the Coulomb cone")
    # A trial that spends the step solver's budget is taken again shorter.
    os.environ["SMA_STEP_TRACE"] = "1"
    try:
        out, proc = run("sleeve-elliptic", "elliptic-budget", "-tol", "1e-3", "-vtkevery", "0")
    finally:
        del os.environ["SMA_STEP_TRACE"]
    ref, proc_ref = run("sleeve-elliptic", "elliptic-fixed", "-vtkevery", "0")
    check(proc.returncode == 0 == proc_ref.returncode,
          f"sleeve-elliptic -tol 1e-3 exit {proc.returncode}, default exit {proc_ref.returncode}"
          + (f": {proc.stderr[-300:]}" if proc.returncode else ""))
    if proc.returncode == 0 == proc_ref.returncode:
        s, fixed = summary_of(out), summary_of(ref)
        accepted_max = max(int(r["dc_iterations"]) for r in rows(os.path.join(out, "history.csv")))
        data["elliptic_budget"] = {"steps_retried": s["steps_retried"], "step_fallbacks": s["step_fallbacks"],
                                   "step_products": s["step_products"], "accepted_step_solves_max": accepted_max}
        ends = re.findall(r"^step end: (.*), (\d+) products$", proc.stderr, re.M)
        given_up = [int(n) for why, n in ends if why != "converged"]
        curvature = sum("negative-curvature" in why for why, _ in ends)
        data["elliptic_budget"].update({"solves": len(ends), "given_up": len(given_up),
                                        "given_up_on_curvature": curvature,
                                        "step_products_retried": s["step_products_retried"]})
        check(s["steps_retried"] >= 1 and curvature >= 1 and s["step_fallbacks"] == 0,
              f"sleeve-elliptic -tol 1e-3: {s['steps_retried']} trial(s) taken again shorter, {curvature} given up "
              f"on stalled curvature moves, {s['step_fallbacks']} given to the nested loops (want >= 1, >= 1, 0)")
        check(sum(given_up) == s["step_products_retried"] and
              sum(int(n) for _, n in ends) == s["step_products"],
              f"sleeve-elliptic -tol 1e-3: the trace's solves not converged spent {sum(given_up)} products, all "
              f"{sum(int(n) for _, n in ends)}; summary.json: step_products_retried {s['step_products_retried']}, "
              f"step_products {s['step_products']}")
        check(accepted_max <= 2000 + 600, f"sleeve-elliptic -tol 1e-3: an accepted step took {accepted_max} "
              "stiffness solves, above the trial budget (2000 products and the last Newton iteration's)")
        check(abs(s["final_pressure_mean"] / fixed["final_pressure_mean"] - 1) < 1e-6,
              f"sleeve-elliptic -tol 1e-3: final pressure {s['final_pressure_mean']:.6e} against the fixed "
              f"steps' {fixed['final_pressure_mean']:.6e}")
        # The run of failures its retries made stays well below the limit where tries stop being trials.
        check(1 < s["step_failure_shortening_max"] < LIMIT / 4,
              f"sleeve-elliptic -tol 1e-3: its failures shortened the steps {s['step_failure_shortening_max']:g} times "
              f"at most below their reference (want in (1, {LIMIT // 4}): at {LIMIT} no try is a trial)")
        data["elliptic_budget"]["step_failure_shortening_max"] = s["step_failure_shortening_max"]
    # A loop that fails at every step length stops the run, not shorter and shorter steps.
    out, proc = run("sleeve-elliptic-friction", "slip-fails", "-stepsolver", "fixedpoint",
                    "-mesh", "meshes/sleeve-coarse.msh", "-slipmaxit", "20", "-vtkevery", "0")
    errors = [line for line in (proc.stdout + proc.stderr).splitlines() if line.startswith("error:")]
    m = re.search(r"^error: time step (\d+) \(shorter steps do not help: since step (\d+) \(t = \S+ s, (\S+) s long\) "
                  r"its failures have shortened the steps (\d+) times, to (\S+) s, and it still fails\): "
                  r"slip-threshold fixed point \(Coulomb\) did not converge: 20 iterations", errors[0] if errors else "")
    check(proc.returncode == 1 and len(errors) == 1 and m is not None,
          f"sleeve-elliptic-friction -stepsolver fixedpoint -slipmaxit 20: exit {proc.returncode} (want 1), one "
          f"error line naming the run of failures and the loop: {errors}")
    if m:
        step, since, reference, times, shortest = int(m[1]), int(m[2]), float(m[3]), int(m[4]), float(m[5])
        data["slip_fails"] = {"step": step, "since": since, "reference_s": reference, "shortening": times,
                              "shortest_s": shortest}
        # the tries go down by quarters: the one that reached the limit is at most 4 times below it; and
        # the run stops within a few steps of it (before: 36 707 steps at -slipmaxit 5, a crawl)
        check(LIMIT <= times < 4 * LIMIT and abs(reference / shortest / times - 1) < 1e-3 and since < step < since + 100,
              f"-slipmaxit 20: stopped at step {step}, {step - since} steps after its run of failures began, the "
              f"steps shortened {times} times ({reference:g} s / {shortest:g} s), want in [{LIMIT}, {4 * LIMIT})")
    record("time_steps", data)
    finish()


if __name__ == "__main__":
    main()
