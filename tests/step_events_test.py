#!/usr/bin/python3
"""The run's time error estimate where its steps are few or long (edp/problems/sleeve/step-control.idp:
the coverage and the phase events).

1. Too few steps: sleeve-radial -steps 3 (the first three steps, which Milne's device cannot
   estimate, carry the whole transient). Before: time_error_estimate_transient 0.195 against 0.238
   measured, and 0 in sleeve-3d, -axisymmetric, -elliptic (0.17 to 0.18 measured). Now the estimate
   is null, time_error_estimate_unknown says why, the run's total and dominant part are null, the
   mesh's is not estimated either (no companion: two curves of so few steps show no mesh error;
   -steps 1 said "mesh 0"), and the line says so; time_error_estimate_coverage equals the share
   recomputed from history.csv (the steps after the third over the transient's force integral).
2. -steps 20: the coverage (recomputed) is above one half, the estimate stands, and is within
   [0.5, 4] of the error measured against -tol 1e-5.
3. Long steps: sleeve-radial and sleeve-axisymmetric at -tol 0.03 -dtmax 1000 (before: the reversion
   started or ended inside steps of 30 s and the estimates were 0.44 and 0.59 of the error). The
   estimate is within [0.5, 4] of the error measured against -tol 1e-5; its phase events' part
   (time_error_estimate_events) equals the one recomputed from history.csv (onset, landing and first
   contact steps: h |dp - s h| / 2, s the last step's slope, over the run's force integral); step_event_ratio_max
   equals the recomputed worst case (the onset's part, the landing's h |dp| / 2) over tol times the
   force integral before the step, and is at most 1 (the controller's bound: without it the landing
   step of the whole reversion was 9 to 15 times the bound).
4. A small interference (sleeve-radial -interference 1e-5): the ring presses the pipe after 57 s of
   heating, whose errors the force inherits as a lag (step-control.idp stepHeatBeforeContact): the
   estimate within [0.5, 4] of the error against -tol 1e-6 (before: 0.06), and, above a tenth, a
   warning.
5. Runs whose curve the estimate does not see say why they have none (time_error_estimate_unknown, the
   last line): a rise in one step (-interference 1e-5 -steps 30: 0 estimated against 1.5; the steps
   where the force changes recomputed), the transformation inside the first step (-tend 1e4 -steps
   100), -theta 1 and -rannacher 10 (schemes the estimate is not measured for); an event step with
   no force before it (-interference 1e-4 -steps 10) writes a finite ratio (an inf failed the run).
Writes results/checks/step_events.json.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench", "oracles"))

from checklib import check, finish, own_error_line, record, rows, run_scene_captured, summary_of  # noqa: E402
from curve_error import curve_error  # noqa: E402

data = {}


def run(scene, tag, *args):
    out, proc = run_scene_captured(scene, "step-events-" + tag, "-quiet", "1", *args)
    check(proc.returncode == 0, f"{scene} {' '.join(args)}: exit {proc.returncode} {proc.stderr[-300:]}")
    return out, proc


def history(out):
    """t, p, f (austenite fraction) with the initial state (0, 0, 0) first."""
    history = rows(os.path.join(out, "history.csv"))
    return tuple([0.0] + [float(row[key]) for row in history] for key in ("t", "pressure_mean", "fraction_austenite"))


def coverage(t, p, f):
    """The transient's (steps up to the last not all austenite, the first included) force integral
    over the steps after the third, over the whole."""
    n = len(t) - 1
    last = max(k for k in range(1, n + 1) if f[k] < 1 - 1e-9 or k == 1)
    whole = sum((t[k] - t[k - 1]) * abs(p[k]) for k in range(1, last + 1))
    blind = sum((t[k] - t[k - 1]) * abs(p[k]) for k in range(1, min(3, last) + 1))
    return 1 - blind / whole


def events(t, p, f, tol):
    """The events' part over the run's force integral, and the largest worst case over tol times the
    integral before its step."""
    part, ratio, integral = 0.0, 0.0, 0.0
    for k in range(1, len(t)):
        h = t[k] - t[k - 1]
        onset = f[k - 1] <= 1e-9 < f[k]
        landing = f[k - 1] < 1 - 1e-9 <= f[k]
        # the first contact (the force leaves 0: 1 Pa, between the round-off and any contact's)
        touching = abs(p[k - 1]) <= 1.0 < abs(p[k])
        if onset or landing or touching:
            slope = (p[k - 1] - p[k - 2]) / (t[k - 1] - t[k - 2]) if k >= 2 else 0.0
            trend = 0.5 * h * abs(p[k] - p[k - 1] - slope * h)
            part += trend
            worst = (trend if onset else 0.0) + (0.5 * h * abs(p[k] - p[k - 1]) if landing else 0.0)
            # (against the step's own integral where no force came before it: step-control.idp)
            before = integral if integral > 0 else h * abs(p[k])
            if worst > 0 and before > 0:
                ratio = max(ratio, worst / (tol * before))
        integral += h * abs(p[k])
    return part / integral, ratio


refs = {scene: run(scene, scene + "-ref", "-tol", "1e-5", "-meshestimate", "0")[0] for scene in ("sleeve-radial", "sleeve-axisymmetric")}

# 1. too few steps (the mesh's estimate asked by default: not made either)
out, proc = run("sleeve-radial", "sleeve-radial-steps3", "-tol", "0", "-steps", "3")
s = summary_of(out)
t, p, f = history(out)
line = own_error_line(proc)
data["steps3"] = {k: s.get(k) for k in ("time_error_estimate", "time_error_estimate_transient", "time_error_estimate_coverage",
                                        "time_error_estimate_unknown", "run_error_estimate_transient", "mesh_estimate_skipped")}
check(s["time_error_estimate"] is None and s["time_error_estimate_transient"] is None
      and "too few steps" in (s["time_error_estimate_unknown"] or ""),
      f"sleeve-radial -steps 3: no time estimate ({s['time_error_estimate_transient']}), why: {s['time_error_estimate_unknown']!r}")
check(s["run_error_estimate_transient"] is None and s["run_error_dominant"] is None
      and s.get("mesh_error_estimate_transient") is None and (s["mesh_estimate_skipped"] or "").startswith("too few steps")
      and not os.path.exists(os.path.join(out, "mesh-estimate")),
      f"sleeve-radial -steps 3: the run's total null ({s['run_error_estimate_transient']}), and the mesh's not estimated "
      f"either, no companion run (two curves of 3 steps show no mesh error: -steps 1 said 'mesh 0'): "
      f"{(s['mesh_estimate_skipped'] or '')[:60]!r}")
check("the time steps' not estimated (too few steps" in line, f"sleeve-radial -steps 3: the line says so: {line[:220]!r}")
mine = coverage(t, p, f)
check(abs(mine - s["time_error_estimate_coverage"]) <= 1e-5 and mine < 0.5,
      f"sleeve-radial -steps 3: coverage {s['time_error_estimate_coverage']} = recomputed {mine:.6f} < 0.5")

# 2. enough steps
out, proc = run("sleeve-radial", "sleeve-radial-steps20", "-tol", "0", "-steps", "20", "-meshestimate", "0")
s = summary_of(out)
t, p, f = history(out)
mine = coverage(t, p, f)
err = curve_error(os.path.join(out, "history.csv"), os.path.join(refs["sleeve-radial"], "history.csv"))["l1_transient"]
est = s["time_error_estimate_transient"]
data["steps20"] = {"coverage": s["time_error_estimate_coverage"], "estimate": est, "error": err}
check(abs(mine - s["time_error_estimate_coverage"]) <= 1e-5 and mine >= 0.5 and s["time_error_estimate_unknown"] is None,
      f"sleeve-radial -steps 20: coverage {s['time_error_estimate_coverage']} = recomputed {mine:.6f} >= 0.5, estimated")
check(est is not None and 0.5 <= est / err <= 4,
      f"sleeve-radial -steps 20: estimate {est} over the error {err:.3e} = {est / err if est else 0:.2f} in [0.5, 4]")

# 3. long steps
for scene in ("sleeve-radial", "sleeve-axisymmetric"):
    out, proc = run(scene, scene + "-long", "-tol", "0.03", "-dtmax", "1000", "-meshestimate", "0")
    s = summary_of(out)
    t, p, f = history(out)
    err = curve_error(os.path.join(out, "history.csv"), os.path.join(refs[scene], "history.csv"))["l1_transient"]
    est = s["time_error_estimate_transient"]
    part, ratio = events(t, p, f, 0.03)
    data[scene + "-long"] = {"steps": s["n_steps"], "estimate": est, "error": err, "events": s["time_error_estimate_events"],
                             "events_recomputed": part, "event_ratio_max": s["step_event_ratio_max"], "ratio_recomputed": ratio}
    check(est is not None and 0.5 <= est / err <= 4,
          f"{scene} -tol 0.03 -dtmax 1000 ({s['n_steps']} steps): estimate {est} over the error {err:.3e} = "
          f"{est / err if est else 0:.2f} in [0.5, 4]")
    check(part > 0 and abs(part - s["time_error_estimate_events"]) <= 1e-5 * part,
          f"{scene} -tol 0.03 -dtmax 1000: the events' part {s['time_error_estimate_events']} = recomputed {part:.6e}")
    check(abs(ratio - s["step_event_ratio_max"]) <= 1e-5 * ratio and ratio <= 1,
          f"{scene} -tol 0.03 -dtmax 1000: the event steps' worst case over tol times the integral "
          f"{s['step_event_ratio_max']} = recomputed {ratio:.6f} <= 1")

# 4. A small interference (1e-5 m): the ring presses the pipe late, after 57 s of heating whose
# errors the force inherits as a lag (before: 7.5e-3 estimated against 0.118 measured); an estimate
# above a tenth is warned of.
ref_small, _ = run("sleeve-radial", "sleeve-radial-small-ref", "-interference", "1e-5", "-tol", "1e-6", "-meshestimate", "0")
out, proc = run("sleeve-radial", "sleeve-radial-small", "-interference", "1e-5", "-meshestimate", "0")
s = summary_of(out)
err = curve_error(os.path.join(out, "history.csv"), os.path.join(ref_small, "history.csv"))["l1_transient"]
est = s["time_error_estimate_transient"]
data["interference-1e-5"] = {"estimate": est, "error": err}
check(est is not None and 0.5 <= est / err <= 4,
      f"sleeve-radial -interference 1e-5: estimate {est} over the error {err:.3e} = {est / err if est else 0:.2f} in [0.5, 4]")
check((est > 0.1) == ("warning: sleeve-radial: the run's own error over the transient is above a tenth" in proc.stdout + proc.stderr),
      f"sleeve-radial -interference 1e-5: an estimate of {est} warned of where above a tenth")

# 5. Runs whose curve no part of the estimate sees (an audit of 413 runs: docs/measurements.md#m-estimate-audit):
# they say why they have no estimate, where they stated 0 or a hundredth of their error.
unseen = {
    # touching and turning in one step: the force changes in one step (estimated 0 against 1.5)
    "one-step-rise": (["-interference", "1e-5", "-tol", "0", "-steps", "30"], "the force changes in 1 of the transient's steps"),
    # the whole transformation inside the first step (2.1e-3 against 0.21)
    "first-step": (["-tend", "1e4", "-tol", "0", "-steps", "100"], "no step ends with the ring transforming"),
    # schemes the estimate is not measured for (0.03-0.15 of their errors)
    "theta-1": (["-theta", "1"], "not for -theta 1 -rannacher 2"),
    "rannacher-10": (["-rannacher", "10"], "not for -theta 0.5 -rannacher 10"),
}
for tag, (args, why) in unseen.items():
    out, proc = run("sleeve-radial", "sleeve-radial-" + tag, "-meshestimate", "0", *args)
    s = summary_of(out)
    data[tag] = {k: s.get(k) for k in ("time_error_estimate_transient", "time_error_estimate_unknown",
                                      "time_error_estimate_rise_steps")}
    check(s["time_error_estimate_transient"] is None and why in (s["time_error_estimate_unknown"] or "")
          and "time steps' not estimated" in own_error_line(proc),
          f"sleeve-radial {' '.join(args)}: not estimated, saying why: {s['time_error_estimate_unknown']}")
    if tag == "one-step-rise":
        t, p, f = history(out)
        last = max(k for k in range(1, len(t)) if f[k - 1] < 1 - 1e-9)  # (the landing step included)
        rises = sum(1 for k in range(1, last + 1) if abs(p[k] - p[k - 1]) > 1.0)
        check(rises == s["time_error_estimate_rise_steps"] == 1,
              f"{' '.join(args)}: the steps where the force changes, {s['time_error_estimate_rise_steps']} = recomputed {rises}")
# an event with no force before it: its ratio against its own step (an inf there failed the run at its end)
out, proc = run("sleeve-radial", "sleeve-radial-event-first-force", "-interference", "1e-4", "-tol", "0", "-steps", "10",
                "-meshestimate", "0")
check(os.path.exists(os.path.join(out, "summary.json")) and 0 < summary_of(out)["step_event_ratio_max"] < 1e3,
      f"-interference 1e-4 -tol 0 -steps 10: summary.json written, step_event_ratio_max "
      f"{summary_of(out)['step_event_ratio_max'] if os.path.exists(os.path.join(out, 'summary.json')) else None} finite")

record("step_events", data)
finish()
