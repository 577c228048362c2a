#!/usr/bin/python3
"""Time steps chosen by the error (-tol) against fixed steps, at the paper's scale, in one run.

For sleeve-circular (default mesh), sleeve-radial (nr 160) and sleeve-circular-gvar (g switching
where the ring touches: a heat condition that changes inside steps): a reference of the time
discretisation on the same mesh (fixed steps, 10 times the scene's -steps; gvar's is 3.9e-6 from
its 150000 steps, docs/measurements.md#m-condition-lag), then fixed steps (150,
300, the scene's -steps: sleeve-circular's 1500, the paper's) and -tol 3e-3, 1e-3 (the default),
3e-4; for each the steps (rejected, retried), the loop's wall time (summary.json wall_seconds) and
its ratio to the fixed -steps run's in this run, the error of the
force curve against the reference (tools/bench/oracles/curve_error.py: relative L1 over the run,
the transient and the reversion window) and the run's own estimate (time_error_estimate) with its
effectivity (estimate over measured). The mesh's error is not in these figures (docs/reference.md).

    tools/bench/time_steps.py            writes results/bench/time-steps.json and
                                         docs/benchmarks/time-steps.md
Also a section of make bench (tools/bench/bench.py).
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import OUT, ROOT, run, write_whole  # noqa: E402
from curve_error import curve_error  # noqa: E402

DOC = os.path.join(ROOT, "docs", "benchmarks", "time-steps.md")
SCENES = [("sleeve-circular", "edp/scenes/sleeve-circular.edp", 1500, ["-vtkevery", 0]),
          ("sleeve-radial", "edp/scenes/sleeve-radial.edp", 1000, []),
          ("sleeve-circular-gvar", "edp/scenes/sleeve-circular-gvar.edp", 1500, ["-vtkevery", 0])]
# "fixed": the scene's fixed steps (-tol 0: sleeve-circular's 1500, the paper's; sleeve-radial's 1000),
# the base of the ratios; the default is -tol 1e-3.
CASES = [("-steps 150", ["-steps", 150]), ("-steps 300", ["-steps", 300]), ("fixed", ["-tol", 0]),
         ("-tol 3e-3", ["-tol", 3e-3]), ("default, -tol 1e-3", ["-tol", 1e-3]), ("-tol 3e-4", ["-tol", 3e-4]),
         # the hard ends (docs/measurements.md#m-phase-events): few steps, and steps as long as the
         # controller lets them be
         ("-steps 5", ["-steps", 5]), ("-steps 20", ["-steps", 20]),
         ("-tol 0.03 -dtmax 1000", ["-tol", 0.03, "-dtmax", 1000])]


def measure(results):
    table = {}
    for name, script, default_steps, extra in SCENES:
        base = os.path.join(OUT, "time-steps", name)
        ref_out = os.path.join(base, "reference")
        _, ref_summary, error = run(script, ref_out, "-scale", "paper", "-quiet", 1, "-steps", 10 * default_steps,
                                    *extra)
        if ref_summary is None:
            raise RuntimeError(f"time steps: {name}'s reference failed: {error}")
        rows = []
        for label, args in CASES:
            out = os.path.join(base, label.replace(" ", "").replace("-", "") or "default")
            _, s, error = run(script, out, "-scale", "paper", "-quiet", 1, *extra, *args, allow_failure=True)
            if s is None:
                rows.append({"case": label, "error": error})
                continue
            e = curve_error(os.path.join(out, "history.csv"), os.path.join(ref_out, "history.csv"))
            rows.append({"case": label, "steps": s["n_steps"], "rejected": s["steps_rejected"],
                         "retried": s["steps_retried"], "loop_seconds": s["wall_seconds"],
                         "l1": e["l1"], "l1_transient": e["l1_transient"], "l1_reversion": e["l1_reversion"],
                         "estimate": s["time_error_estimate"], "estimate_transient": s["time_error_estimate_transient"],
                         "estimate_unknown": s["time_error_estimate_unknown"],
                         "effectivity": (s["time_error_estimate"] / e["l1"]
                                         if e["l1"] > 0 and s["time_error_estimate"] is not None else None),
                         "effectivity_transient": (s["time_error_estimate_transient"] / e["l1_transient"]
                                                   if e["l1_transient"] > 0 and s["time_error_estimate_transient"] is not None
                                                   else None)})
        fixed = next(r for r in rows if r["case"] == "fixed")
        for r in rows:
            if "loop_seconds" in r:
                r["loop_over_fixed"] = r["loop_seconds"] / fixed["loop_seconds"]
        table[name] = {"reference_steps": 10 * default_steps, "rows": rows}
    results["time_steps"] = table
    return table


def fmt(x, spec=".2e", none="-"):
    return none if x is None else format(x, spec)


def write_doc(table):
    lines = ["# Time steps chosen by the error against fixed steps", "",
             "Written by `tools/bench/time_steps.py` (its docstring states the method); numbers from that run, "
             "at the paper's scale. Errors: relative L1 in time of the mean contact pressure against the same "
             "scene with 10 times its -steps as fixed steps (the time discretisation's error only, not the "
             "mesh's); the estimate is the run's own summary.json `time_error_estimate` (over the run) and "
             "`_transient`; effectivity = estimate / measured. Loop: summary.json `wall_seconds`, and its "
             "ratio to the fixed -steps run's (\"fixed\": 1500 steps for the 2D scenes, the paper's; 1000 for "
             "sleeve-radial) in this run. In sleeve-circular-gvar each node's exchange switches where it "
             "touches, inside a step: a fixed step's error there depends on where in the step the switch fell, "
             "which the estimate takes at its mean (docs/measurements.md#m-condition-lag). The scenes' default is `-tol 1e-3`. "
             "The last three cases are the hard ends: few equal steps (not estimated where the first three steps, which "
             "Milne's device cannot estimate, carry more than half the transient's force integral: "
             "`time_error_estimate_unknown`) and steps as long as the controller lets them be, where the reversion's "
             "onset and end fall inside steps (docs/measurements.md#m-phase-events).", ""]
    for name, data in table.items():
        lines += [f"## {name} (reference: {data['reference_steps']} fixed steps)", "",
                  "| case | steps | rejected | retried | loop (s) | loop / fixed | L1 run | estimate | "
                  "effectivity | L1 transient | estimate | effectivity | L1 reversion window |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in data["rows"]:
            if "error" in r:
                lines.append(f"| {r['case']} | failed: {r['error'][:120]} |" + " |" * 11)
                continue
            lines.append(f"| {r['case']} | {r['steps']} | {r['rejected']} | {r['retried']} | {r['loop_seconds']:.3f} | "
                         f"{r['loop_over_fixed']:.2f} | {fmt(r['l1'])} | {fmt(r['estimate'], none='not estimated')} | "
                         f"{fmt(r['effectivity'], '.2f')} | {fmt(r['l1_transient'])} | "
                         f"{fmt(r['estimate_transient'], none='not estimated')} | "
                         f"{fmt(r['effectivity_transient'], '.2f')} | {fmt(r['l1_reversion'])} |")
        lines.append("")
    write_whole(DOC, "\n".join(lines))


def main():
    results = {}
    table = measure(results)
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "time-steps.json"), "w") as f:
        json.dump(table, f, indent=2, allow_nan=False)
    write_doc(table)
    print(f"time steps: results/bench/time-steps.json, {os.path.relpath(DOC, ROOT)}")


if __name__ == "__main__":
    main()
