#!/usr/bin/python3
"""The loads after the clamping (bending, pull-out): what their increments cost and the error they
leave, and -timeestimate 1's bound of it (a section of make bench, docs/benchmarks/stage-increments.md).

The paper's scale, mu 0.2, the clamping at -tol 1e-3 in every run:
  bending's increments: sleeve-3d -length 0.05 -bend 1e-2 in 1, 2, 4, ..., 32 increments: the final
    moment, its differences between successive counts and their ratios (the observed order),
    Richardson's limit from the two finest (order 1), each count's error against it, and the
    difference to a quarter of the increments over that error (what -timeestimate 1 reports over
    what it bounds: 3 at order 1); the stage's wall seconds (summary.json bending.seconds);
  the pull-out's increments: sleeve-3d -length 0.05 -pullout 5e-4 and sleeve-axisymmetric -pullout
    1e-3 in 1, 4 and 16 increments: the largest difference of pullout.csv's force at the
    displacements two counts share, over the largest force (a monotone pull: the same path);
  -timeestimate 1 on the bending in 8 increments: its stage bound against the error above;
  the cost at the defaults (L = 10 cm): the frictional and frictionless bending in 40 increments and
    the pull-out in 10, the clamping's loop and the stage's seconds, the whole process.
These numbers were typed by hand into docs/measurements.md#m-stage-increments and
#m-sleeve-3d-bending before this section measured them.

bench.py calls measure() and write_doc(); alone: tools/bench/bench.py --only stages-3d.
"""
import os

from common import OUT, ROOT, read_csv, run, write_whole
from markdown_wrap import wrap

DOC = os.path.join(ROOT, "docs", "benchmarks", "stage-increments.md")
SLEEVE_3D, AXISYMMETRIC = "edp/scenes/sleeve-3d.edp", "edp/scenes/sleeve-axisymmetric.edp"
BASE = ["-scale", "paper", "-mu", "0.2", "-tol", "1e-3", "-quiet", "1"]
BEND = ["-length", "0.05", "-bend", "1e-2"]
BEND_COUNTS = [1, 2, 4, 8, 16, 32]
PULL_COUNTS = [1, 4, 16]
PULLS = [("sleeve-3d", SLEEVE_3D, ["-length", "0.05", "-pullout", "5e-4"]),
         ("sleeve-axisymmetric", AXISYMMETRIC, ["-pullout", "1e-3"])]


def one(tag, script, *args):
    out = os.path.join(OUT, "stages-3d", tag)
    wall, s, _ = run(script, out, *BASE, *args)
    return out, s, wall


def measure(results):
    """Runs the cases into results/bench/stages-3d/; returns the record (also results['stages_3d'])."""
    print("bench: the stages' increments (bending, pull-out): their error, the bound, their cost", flush=True)
    bending = []
    for n in BEND_COUNTS:
        _, s, _ = one(f"bend-{n}", SLEEVE_3D, *BEND, "-bendsteps", n)
        bending.append({"increments": n, "moment": s["bending"]["moment_final"], "seconds": s["bending"]["seconds"]})
    moments = {r["increments"]: r["moment"] for r in bending}
    limit = 2 * moments[BEND_COUNTS[-1]] - moments[BEND_COUNTS[-2]]  # (Richardson at order 1)
    for i, r in enumerate(bending):
        r["error"] = abs(r["moment"] - limit) / abs(limit)
        if i > 0:
            r["difference"] = abs(r["moment"] - bending[i - 1]["moment"])
        if i > 1:
            r["ratio"] = bending[i - 1]["difference"] / r["difference"]
        quarter = moments.get(r["increments"] // 4) if r["increments"] % 4 == 0 else None
        if quarter is not None:
            r["quarter_over_error"] = abs(r["moment"] - quarter) / abs(r["moment"]) / r["error"]
    out, s, _ = one("bend-8-timeestimate", SLEEVE_3D, *BEND, "-bendsteps", 8, "-timeestimate", 1)
    stage = s["time_error_bound"]["stage"]
    estimate = {"increments": 8, "companion_increments": stage["companion_increments"], "bound": stage["moment"],
                "error": abs(s["bending"]["moment_final"] - limit) / abs(limit)}
    pulls = []
    for name, script, args in PULLS:
        curves = {}
        for n in PULL_COUNTS:
            out, _, _ = one(f"pull-{name}-{n}", script, *args, "-pullsteps", n)
            csv = read_csv(os.path.join(out, "pullout.csv"))
            curves[n] = dict(zip((round(d, 15) for d in csv["pipe_displacement"]), csv["pullout_force"]))
        largest = max(abs(f) for f in curves[PULL_COUNTS[-1]].values())
        finest = curves[PULL_COUNTS[-1]]
        worst = max(abs(f - finest[d]) for n in PULL_COUNTS[:-1] for d, f in curves[n].items() if d in finest)
        pulls.append({"scene": name, "args": " ".join(args), "counts": PULL_COUNTS, "force_final": finest[min(finest)],
                      "difference": worst / largest})
    cost = []
    for tag, args in (("bending, mu 0.2", ["-bend", "1e-2"]), ("bending, frictionless", ["-bend", "1e-2", "-mu", "0"]),
                      ("pull-out, mu 0.2", ["-pullout", "1e-3"])):
        _, s, wall = one("cost-" + tag.replace(", ", "-").replace(" ", "-"), SLEEVE_3D, *args)
        st = s["bending"] or s["pullout"]
        cost.append({"case": tag, "increments": st["steps"], "clamping_steps": s["n_steps"],
                     "clamping_seconds": s["wall_seconds"], "stage_seconds": st["seconds"],
                     "cone_sweeps_max": st["cone_sweeps_max"], "process_seconds": wall})
    record = {"bending": bending, "limit": limit, "estimate": estimate, "pulls": pulls, "cost": cost}
    results["stages_3d"] = record
    return record


def write_doc(record):
    e = record["estimate"]
    lines = ["# The stages' increments: their error, its bound, their cost", "",
             "Written by `tools/bench/stages_3d.py` (its docstring states the method); numbers from that run. The "
             "paper's scale, mu 0.2, the clamping at `-tol 1e-3`.", "",
             "## The frictional bending's final moment against its increments", "",
             f"sleeve-3d `{' '.join(BEND)}`. Error: against Richardson's limit from the two finest counts at order 1, "
             f"{record['limit']:.3f} N m. Ratio: the difference to the count before over the next one (2: order 1). "
             "Quarter / error: the difference to a quarter of the increments, over the moment, over the error: what "
             "`-timeestimate 1` reports over what it bounds.", "",
             "| increments | moment (N m) | difference (N m) | ratio | error | quarter / error | stage (s) |",
             "|---|---|---|---|---|---|---|"]
    for r in record["bending"]:
        diff = f"{r['difference']:.3f}" if "difference" in r else "-"
        ratio = f"{r['ratio']:.2f}" if "ratio" in r else "-"
        quarter = f"{r['quarter_over_error']:.2f}" if "quarter_over_error" in r else "-"
        lines.append(f"| {r['increments']} | {r['moment']:.3f} | {diff} | {ratio} | {r['error']:.2e} | {quarter} | "
                     f"{r['seconds']:.2f} |")
    lines += ["", f"`-bendsteps 8 -timeestimate 1`: the final moment's bound {e['bound']:.2e} (the companion in "
              f"{e['companion_increments']} increments, at 10 times `-tol`), {e['bound'] / e['error']:.1f} times its error "
              f"{e['error']:.2e}.", "",
              "## The pull-out's increments", "",
              "A monotone pull: the largest difference of the pull-out force at the displacements two counts share, "
              "over the largest force.", "",
              "| scene | options | increments | force at the end (kN) | largest difference |", "|---|---|---|---|---|"]
    for p in record["pulls"]:
        lines.append(f"| {p['scene']} | `{p['args']}` | {', '.join(map(str, p['counts']))} | {p['force_final'] / 1e3:.3f} | "
                     f"{p['difference']:.1e} |")
    lines += ["", "## Cost at the defaults (L = 10 cm, nr 2, nt 8)", "",
              "| case | increments | clamping steps | clamping loop (s) | stage (s) | most sweeps of a solve | process (s) |",
              "|---|---|---|---|---|---|---|"]
    for c in record["cost"]:
        lines.append(f"| {c['case']} | {c['increments']} | {c['clamping_steps']} | {c['clamping_seconds']:.2f} | "
                     f"{c['stage_seconds']:.2f} | {c['cone_sweeps_max']} | {c['process_seconds']:.2f} |")
    lines.append("")
    write_whole(DOC, wrap("\n".join(lines)))
