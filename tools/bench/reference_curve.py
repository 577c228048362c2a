#!/usr/bin/python3
"""An accuracy reference for the sleeve's force curve that is not one run of the scheme itself:
the Richardson extrapolation of the radial model's fraction curve to h, dt -> 0, with its
assumptions stated and tested, and the paper's on/off scheme measured against it as an
independent check (issue 30, item 4).

    /usr/bin/python3 tools/bench/reference_curve.py [--scale reduced|paper] [--quick] [--out DIR] [--doc FILE]

Writes DIR/reference.csv (t, the extrapolated mean contact pressure p*, its uncertainty band),
DIR/summary.json (every level, every test below, the defaults' errors) and, unless --quick, the
document docs/reference.md (--doc to write it elsewhere). DIR defaults to results/reference
(results/reference-quick with --quick). Exits 1 when an assumption fails, naming it.

What is extrapolated. The centred circular sleeve is radially symmetric: edp/scenes/sleeve-radial.edp
solves it in r. Over the first 30 s (contact, the linear stage, the reverse transformation: the
transient ends near 16 s), levels l = 0..N with nr_l = nr_0 2^l elements and 7.5 nr_l steps
(dt and h halved together), the default fraction model and step solver. Each run's mean contact
pressure p_l(t) is piecewise linear in t through its steps; the coarsest grid's times are nodes of
every finer grid. Norms: |f| = int_0^tA |f| dt / int_0^tA |p*| dt over the transient [0, tA], tA
the time from which the finest run is austenite for good (tools/bench/oracles/curve_error.py's l1_transient),
evaluated on the finest grid (the curves are linear between its nodes).

The model of the error, and its tests (each must pass, else the tool fails):
  E  p_l(t) = p*(t) + C(t) h_l^k + o(h_l^k): one order k, one error shape C(t).
  Then the successive differences d_l = p_l+1 - p_l obey |d_l| / |d_l+1| = 2^k, and
  p* = p_N + d_N-1 / (2^k - 1).
  A1 (asymptotic range) the orders k_l = log2(|d_l| / |d_l+1|) of the last three pairs agree
     within 0.35 (a scheme still in its pre-asymptotic range gives drifting orders);
  A2 (one error shape) the finer difference, rescaled, is the coarser one pointwise in t, not
     only in norm: the mismatch m = |d_N-2 - 2^k d_N-1| / |d_N-2| (0 under E) puts an error of
     about m |d_N-1| / (2^k - 1) into p*; that must be below the finest level's own error
     |p_N - p*| (the reference more accurate than the best run);
  A3 (stable extrapolant) the extrapolant from the pair (N-2, N-1) with the order measured on
     the levels before it (N-3, N-2, N-1) and the one from (N-1, N) differ by less than the
     finest level's own estimated error |p_N - p*|: dropping the finest level moves the reference
     less than the error it is used to measure (a drifting order or shape moves it).
The reference's uncertainty is the larger of A2's and A3's left sides, reported beside every error.

The independent check: the paper's on/off scheme (-phasemodel onoff, every element all martensite
or all austenite: no fraction, another discretisation of the same continuum problem; the fraction
model is its relaxation, the laminate) at levels nr 40 .. nr_max, its error against p* fitted to
c h^k: it must fall with h. Its observed order is reported as measured.
The defaults (what a user runs, 150 s) are then measured against p* on [0, tA].

--scale paper: the same at the paper's scale (sleeve-radial's default, -scale paper: contact near
1.5 s, the reversion roughly 57-70 s, austenite for good near 70 s): TEND 80 s, the same time step
per element size scaled to it (20 nr steps over 80 s: dt = 4 / nr s, as 7.5 nr over 30 s), levels
nr 20-640 (the finest about 10 s; nr 1280 takes about 40 s). No on/off study. Writes
results/reference-paper and docs/reference-paper.md (docs/reference.md, the reduced scale's, is
left as it is). The defaults measured there: sleeve-radial and sleeve-circular (-vtkevery 0) at
their defaults, each over the transient [0, tA] and over the reversion window [tR, tA]
(curve_error.py's l1_transient and l1_reversion, against DIR/reference-history.csv: p* on the
finest grid with the finest run's fraction_austenite and contact_nodes, whose tR and tA it takes).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io
import results_io  # noqa: E402  (first: the sma package sets numpy's threads before numpy loads)
import numpy as np  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import without_companion  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TEND = 30.0
STEPS_PER_ELEMENT = 7.5
FRACTION_LEVELS = [40, 80, 160, 320, 640, 1280]
ONOFF_LEVELS = [40, 80, 160, 320, 640, 1280, 2560]
QUICK_FRACTION_LEVELS = [20, 40, 80, 160]
QUICK_ONOFF_LEVELS = [20, 40, 80, 160]
ORDER_SPREAD = 0.35   # A1
# The defaults measured against the reference: (name, script, options).
DEFAULTS = [
    ("sleeve-radial (default: nr 160, steps chosen by -tol 1e-3)", "edp/scenes/sleeve-radial.edp", []),
    ("sleeve-radial (nr 160, 1000 fixed steps: -tol 0)", "edp/scenes/sleeve-radial.edp", ["-tol", 0]),
    ("sleeve-circular (default mesh, steps chosen by -tol 1e-3)", "edp/scenes/sleeve-circular.edp", ["-vtkevery", 0]),
    ("sleeve-circular (default mesh, the paper's 1500 fixed steps: -tol 0)", "edp/scenes/sleeve-circular.edp",
     ["-vtkevery", 0, "-tol", 0]),
    ("sleeve-circular -phasemodel onoff -mesh meshes/sleeve-quarter.msh (the paper's scheme)",
     "edp/scenes/sleeve-circular.edp", ["-phasemodel", "onoff", "-mesh", "meshes/sleeve-quarter.msh",
                                         "-vtkevery", 0]),
]


def run(script, out, args, scale_name="reduced"):
    """tools/ff script -out out -quiet 1 -scale scale_name args; returns the history (t, pressure_mean,
    fraction_austenite, contact_nodes as numpy arrays) and the wall time. Fails naming the run and its output."""
    os.makedirs(out, exist_ok=True)
    # The reference is the reduced scale's (docs/reference.md) unless --scale paper: -scale
    # scale_name unless args say.
    scale = ["-scale", scale_name] if "-scale" not in args else []
    command = [os.path.join(ROOT, "tools", "ff"), script, "-out", out, "-quiet", "1", *scale, *map(str, args),
               *without_companion(script, args)]
    start = time.perf_counter()
    proc = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        # Beside the run's folder, not in it, and listed in the enclosing results folder's manifest:
        # a file of ours inside a folder the scene did not claim would make the next run refuse it.
        log = out.rstrip(os.sep) + ".log"
        results_io.record(log)
        with open(log, "w") as f:
            f.write(proc.stdout + proc.stderr)
        sys.exit(f"reference_curve: {' '.join(command[1:])} failed (exit {proc.returncode}); its output: {log}")
    path = os.path.join(out, "history.csv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        history = {k: np.array([float(r[k]) for r in rows]) for k in ("t", "pressure_mean", "fraction_austenite")}
        if rows and "contact_nodes" in rows[0]:
            history["contact_nodes"] = np.array([float(r["contact_nodes"]) for r in rows])
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"reference_curve: {path}: cannot read the history ({e})")
    if len(history["t"]) == 0:
        sys.exit(f"reference_curve: {path}: no rows")
    return history, wall


def on_grid(history, grid):
    """The piecewise linear curve through (0, 0) and the steps, at the times of grid."""
    t = np.concatenate(([0.0], history["t"]))
    p = np.concatenate(([0.0], history["pressure_mean"]))
    return np.interp(grid, t, p)


def l1(grid, f):
    """int |f| dt over grid, f linear between the nodes (exact where f changes sign too)."""
    h = np.diff(grid)
    a, b = f[:-1], f[1:]
    same = a * b >= 0
    whole = h * (np.abs(a) + np.abs(b)) / 2
    denominator = np.where(same, 1.0, np.abs(a) + np.abs(b))
    crossing = h * (a * a + b * b) / (2 * denominator)
    return float(np.sum(np.where(same, whole, crossing)))


def austenite_time(history):
    """The time from which the run is austenite for good (the end of its transient)."""
    fa = history["fraction_austenite"]
    not_austenite = np.nonzero(fa < 1)[0]
    if len(not_austenite) == 0:
        return float(history["t"][0])
    last = not_austenite[-1]
    if last + 1 >= len(fa):
        sys.exit("reference_curve: the finest run never ends its transient within the simulated time")
    return float(history["t"][last + 1])


def extrapolate(grid, curves):
    """The Richardson extrapolation of curves (levels of h halving, on one time grid) and the tests
    of its assumptions (the module docstring): a dict with reference, previous (the extrapolant
    without the finest level), order, orders, differences (relative L1 of the successive
    differences), relative (f -> L1(f) / L1(reference)), uncertainty and tests; or failure."""
    if len(curves) < 4:
        return {"failure": f"{len(curves)} levels: the tests need at least 4"}
    diffs = [b - a for a, b in zip(curves, curves[1:])]
    norms = [l1(grid, d) for d in diffs]
    orders = [math.log2(a / b) if a > 0 and b > 0 else float("nan") for a, b in zip(norms, norms[1:])]
    k = orders[-1]
    if not (k > 0):
        return {"failure": f"the curve does not converge (last observed order {k})"}
    factor = 2.0 ** k
    reference = curves[-1] + diffs[-1] / (factor - 1)
    # Without the finest level: the pair before, extrapolated with the order measured before it
    # (so that a drifting order shows; with one order and one shape the two extrapolants agree).
    previous = curves[-2] + diffs[-2] / (2.0 ** orders[-2] - 1)
    scale = l1(grid, reference)
    relative = lambda f: l1(grid, f) / scale
    finest_error = relative(curves[-1] - reference)
    stability = relative(previous - reference)
    mismatch = l1(grid, diffs[-2] - factor * diffs[-1]) / norms[-2]
    shape_effect = mismatch * norms[-1] / (factor - 1) / scale
    last3 = orders[-3:]
    tests = {
        "A1_orders_last_three": last3, "A1_spread": max(last3) - min(last3),
        "A1_ok": bool(max(last3) - min(last3) <= ORDER_SPREAD),
        "A2_shape_mismatch": mismatch, "A2_effect_on_reference": shape_effect,
        "A2_ok": bool(shape_effect < finest_error),
        "A3_reference_change_without_finest": stability, "A3_finest_level_error": finest_error,
        "A3_ok": bool(stability < finest_error),
    }
    return {"reference": reference, "previous": previous, "order": k, "orders": orders,
            "differences": [n / scale for n in norms], "relative": relative,
            "uncertainty": max(stability, shape_effect), "tests": tests}


def study(levels, model, out_root, tend=TEND, steps_per_element=STEPS_PER_ELEMENT, scale_name="reduced"):
    """Runs sleeve-radial at each level (nr, 7.5 nr steps over TEND, or the given scale's);
    returns the list of (nr, history, wall)."""
    runs = []
    for nr in levels:
        steps = int(round(steps_per_element * nr))
        label = "" if scale_name == "reduced" else f" -scale {scale_name}"
        print(f"reference_curve: sleeve-radial{label} -phasemodel {model} -nr {nr} -steps {steps} -tend {tend:g}", flush=True)
        history, wall = run("edp/scenes/sleeve-radial.edp", os.path.join(out_root, f"{model}-nr{nr}"),
                            ["-nr", nr, "-steps", steps, "-tend", tend, "-phasemodel", model], scale_name)
        runs.append((nr, history, wall))
    return runs


def fraction_reference(levels, out, tend=TEND, steps_per_element=STEPS_PER_ELEMENT, scale_name="reduced"):
    """The fraction model's levels, their curves on the finest run's transient grid [0, tA], the
    extrapolation (extrapolate's dict; exits naming its failure) and the levels' table rows:
    (levels' runs, transient grid, curves, extrapolation, rows)."""
    fraction = study(levels, "fraction", out, tend, steps_per_element, scale_name)
    finest = fraction[-1][1]
    grid = np.concatenate(([0.0], finest["t"]))
    transient = grid[grid <= austenite_time(finest) + 1e-12]
    curves = [on_grid(h, transient) for _, h, _ in fraction]
    ex = extrapolate(transient, curves)
    if "failure" in ex:
        sys.exit(f"reference_curve: {ex['failure']}")
    rows = [{"nr": nr, "steps": int(round(steps_per_element * nr)), "wall_seconds": wall,
             "error": ex["relative"](c - ex["reference"])} for (nr, h, wall), c in zip(fraction, curves)]
    for row, d in zip(rows, ex["differences"]):
        row["difference_to_next"] = d
    for row, o in zip(rows, ex["orders"]):
        row["order_of_differences"] = o
    return fraction, transient, curves, ex, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="coarse levels (nr 20-160), no document")
    parser.add_argument("--test", action="store_true",
                        help="the on/off scheme without its finest level (nr 40-1280; the fraction levels all: its "
                             "assumption A3 needs nr 1280): about 60 %% of the time, the same checks "
                             "(tests/reference_curve_test.py); the document only with --doc")
    parser.add_argument("--scale", choices=("reduced", "paper"), default="reduced",
                        help="reduced (the default: 30 s, docs/reference.md) or paper (80 s, nr 20-640, "
                             "results/reference-paper, docs/reference-paper.md)")
    parser.add_argument("--out", default=None)
    parser.add_argument("--doc", default=None)
    parser.add_argument("--no-defaults", action="store_true", help="skip the defaults' runs")
    opts = parser.parse_args()
    if opts.scale == "paper":
        import reference_paper  # (tools/bench/reference_paper.py: it imports this module's study)
        return reference_paper.main_paper(opts)
    opts.doc = opts.doc or (None if opts.test else os.path.join(ROOT, "docs", "reference.md"))
    out = opts.out or os.path.join(ROOT, "results", "reference-quick" if opts.quick else "reference")
    os.makedirs(out, exist_ok=True)
    fraction_levels = QUICK_FRACTION_LEVELS if opts.quick else FRACTION_LEVELS
    onoff_levels = QUICK_ONOFF_LEVELS if opts.quick else ONOFF_LEVELS[:-1] if opts.test else ONOFF_LEVELS

    fraction, transient, curves, ex, fraction_rows = fraction_reference(fraction_levels, out)
    finest = fraction[-1][1]
    tA = austenite_time(finest)
    reference, previous, rel, tests = ex["reference"], ex["previous"], ex["relative"], ex["tests"]
    k, uncertainty = ex["order"], ex["uncertainty"]

    onoff = study(onoff_levels, "onoff", out)
    onoff_rows = []
    for nr, h, wall in onoff:
        onoff_rows.append({"nr": nr, "steps": int(round(STEPS_PER_ELEMENT * nr)), "wall_seconds": wall,
                           "error": rel(on_grid(h, transient) - reference)})
    errors = [r["error"] for r in onoff_rows]
    for a, b in zip(onoff_rows, onoff_rows[1:]):
        a["order"] = math.log2(a["error"] / b["error"]) if a["error"] > 0 and b["error"] > 0 else None
    sizes = np.log([r["nr"] for r in onoff_rows])
    fit = np.polyfit(sizes, np.log(errors), 1)
    half = len(onoff_rows) // 2
    fit_fine = np.polyfit(sizes[half:], np.log(errors[half:]), 1) if len(onoff_rows) - half >= 2 else fit
    onoff_summary = {"levels": onoff_rows, "order_fit_all": -float(fit[0]), "order_fit_finer_half": -float(fit_fine[0]),
                     "falls_with_h": errors[-1] < errors[0] and -float(fit[0]) > 0}
    tests["onoff_falls_with_h"] = onoff_summary["falls_with_h"]

    defaults = []
    if not opts.quick and not opts.no_defaults:
        for name, script, args in DEFAULTS:
            print(f"reference_curve: {name}", flush=True)
            h, wall = run(script, os.path.join(out, "default-" + str(len(defaults))), args)
            defaults.append({"run": name, "wall_seconds": wall, "error": rel(on_grid(h, transient) - reference)})

    with open(os.path.join(out, "reference.csv"), "w") as f:
        f.write("# Richardson extrapolation of sleeve-radial's mean contact pressure (tools/bench/reference_curve.py)\n")
        f.write("t,pressure_reference_Pa,pressure_finest_Pa,pressure_without_finest_Pa\n")
        for row in zip(transient, reference, curves[-1], previous):
            f.write(",".join(f"{v:.12g}" for v in row) + "\n")
    summary = {"tend": TEND, "t_austenite": tA, "steps_per_element": STEPS_PER_ELEMENT, "order": k,
               "fraction_levels": fraction_rows, "tests": tests, "onoff": onoff_summary,
               "reference_uncertainty": uncertainty, "defaults": defaults}
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    if not opts.quick and opts.doc:
        write_doc(opts.doc, summary)
    failed = [name for name in ("A1_ok", "A2_ok", "A3_ok", "onoff_falls_with_h") if not tests[name]]
    print(json.dumps({"order": k, "reference_uncertainty": uncertainty, "tests": tests}, indent=1))
    if failed:
        sys.exit(f"reference_curve: assumption(s) failed: {', '.join(failed)} ({os.path.join(out, 'summary.json')})")


def pct(x):
    return f"{100 * x:.3f} %" if x is not None else "-"


def level_rows(levels, pct, reversion=False):
    """The table rows of the fraction model's levels: nr, steps, wall time, error against p* (and,
    with `reversion`, over the reversion window), difference to the next level, order of the
    differences ("-" where there is none); `pct` formats a relative error."""
    rows = []
    for r in levels:
        o = r.get("order_of_differences")
        cells = [f"{r['nr']}", f"{r['steps']}", f"{r['wall_seconds']:.2f}", pct(r["error"])]
        cells += [pct(r.get("error_reversion"))] if reversion else []
        cells += [pct(r.get("difference_to_next")), f"{o:.2f}" if o is not None else "-"]
        rows.append("| " + " | ".join(cells) + " |")
    return rows


def assumption_rows(s, pct):
    """The order used and the table of the assumption tests A1-A3 of summary s (pct: the percent
    format), as the document's lines."""
    t = s["tests"]
    return [
        "",
        f"Order used: k = {s['order']:.3f} (the last pair). p* = p_N + (p_N - p_N-1) / (2^k - 1).",
        "",
        "| assumption | test | measured | holds |",
        "|---|---|---|---|",
        f"| A1 asymptotic range | orders of the last three pairs within {ORDER_SPREAD} | "
        f"{', '.join(f'{o:.3f}' for o in t['A1_orders_last_three'])} (spread {t['A1_spread']:.3f}) | {'yes' if t['A1_ok'] else 'NO'} |",
        f"| A2 one error shape | its effect on p*, m L1(d_N-1) / (2^k - 1), below the finest level's error | "
        f"m = {t['A2_shape_mismatch']:.3f}: {pct(t['A2_effect_on_reference'])} against {pct(t['A3_finest_level_error'])} | {'yes' if t['A2_ok'] else 'NO'} |",
        f"| A3 stable extrapolant | the reference without the finest level moves less than the finest level's error | "
        f"{pct(t['A3_reference_change_without_finest'])} against {pct(t['A3_finest_level_error'])} | {'yes' if t['A3_ok'] else 'NO'} |",
    ]


def write_doc(path, s):
    lines = [
        "# An accuracy reference for the force curve",
        "",
        "Written by `tools/bench/reference_curve.py` (its docstring states the method); numbers from that run.",
        "Every accuracy figure of docs/benchmarks.md is measured against the fraction model's own finest",
        "radial run. This page measures against something else: the Richardson extrapolation of the",
        "radial fraction curve to h, dt -> 0, whose assumptions are tested below, and checks it with the",
        "paper's on/off scheme, another discretisation of the same problem. Error: relative L1 in time",
        f"of the mean contact pressure over the transient [0, {s['t_austenite']:.3f} s] (tools/bench/oracles/curve_error.py's",
        f"`l1_transient`); levels: nr elements, {s['steps_per_element']:g} nr steps over {s['tend']:g} s.",
        "",
        "## The fraction model's levels and the extrapolation",
        "",
        "| nr | steps | wall (s) | error against p* | difference to next | order of differences |",
        "|---|---|---|---|---|---|",
    ]
    lines += level_rows(s["fraction_levels"], pct)
    lines += assumption_rows(s, pct) + [
        "",
        f"The reference's uncertainty (the larger of A2's and A3's): {pct(s['reference_uncertainty'])}.",
        "",
        "## The paper's on/off scheme against it",
        "",
        "| nr | steps | wall (s) | error against p* | order to next |",
        "|---|---|---|---|---|",
    ]
    for r in s["onoff"]["levels"]:
        o = r.get("order")
        lines.append(f"| {r['nr']} | {r['steps']} | {r['wall_seconds']:.2f} | {pct(r['error'])} | "
                     + (f"{o:.2f} |" if o is not None else "- |"))
    lines += [
        "",
        f"Observed order of the on/off scheme (least squares on log error against log nr): "
        f"{s['onoff']['order_fit_all']:.2f} over all levels, {s['onoff']['order_fit_finer_half']:.2f} over the finer half. "
        "Its error against p* falls at every level, with no floor down to the finest: the two schemes are "
        "consistent with one limit (consistent, not proved: at order 0.4 the on/off scheme would need "
        "about 10^5 elements to reach the fraction model's default error).",
        "",
    ]
    if s["defaults"]:
        lines += ["## The defaults against the reference", "",
                  "| run | wall (s) | error against p* |", "|---|---|---|"]
        for d in s["defaults"]:
            lines.append(f"| {d['run']} | {d['wall_seconds']:.2f} | {pct(d['error'])} |")
        lines += ["", f"Each error is known to within the reference's uncertainty ({pct(s['reference_uncertainty'])}, "
                  "in the same units).", ""]
    lines += ["The same at the paper's scale, over the whole transient and the reversion window: "
              "[reference-paper.md](reference-paper.md) (`tools/bench/reference_curve.py --scale paper`).", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
