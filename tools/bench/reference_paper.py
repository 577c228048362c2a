#!/usr/bin/python3
"""The accuracy reference at the paper's scale: tools/bench/reference_curve.py --scale paper (that
module's docstring states the method); this module holds its paper-scale study and document,
docs/reference-paper.md, on reference_curve.py's levels, extrapolation and assumption tests."""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_curve import ROOT, TEND, STEPS_PER_ELEMENT, run, l1, austenite_time, fraction_reference, assumption_rows, level_rows  # noqa: E402

# --scale paper (the module docstring): 20 nr steps over 80 s, the reduced scale's dt = 4 / nr s.
PAPER_TEND = 80.0
PAPER_STEPS_PER_ELEMENT = STEPS_PER_ELEMENT * PAPER_TEND / TEND
PAPER_FRACTION_LEVELS = [20, 40, 80, 160, 320, 640]
QUICK_PAPER_FRACTION_LEVELS = [20, 40, 80, 160]
PAPER_DEFAULTS = [
    ("sleeve-radial (default: nr 160, steps chosen by -tol 1e-3)", "edp/scenes/sleeve-radial.edp", []),
    ("sleeve-radial (nr 160, 1000 fixed steps over 150 s: -tol 0)", "edp/scenes/sleeve-radial.edp", ["-tol", 0]),
    ("sleeve-circular (default mesh, steps chosen by -tol 1e-3)", "edp/scenes/sleeve-circular.edp", ["-vtkevery", 0]),
    ("sleeve-circular (default mesh, the paper's 1500 fixed steps: -tol 0)", "edp/scenes/sleeve-circular.edp",
     ["-vtkevery", 0, "-tol", 0]),
    ("sleeve-circular (108 layers x 18 arc segments, -tol 3e-4)", "edp/scenes/sleeve-circular.edp",
     ["-vtkevery", 0, "-mesh", "meshes/sleeve-aniso108.msh", "-tol", 3e-4]),
    ("sleeve-circular (36 layers x 18 arc segments, -tol 3e-4)", "edp/scenes/sleeve-circular.edp",
     ["-vtkevery", 0, "-mesh", "meshes/sleeve-aniso36.msh", "-tol", 3e-4]),
    ("sleeve-circular (36 moving layers x 18 arc segments, -tol 3e-4: -movinglayers 1)", "edp/scenes/sleeve-circular.edp",
     ["-vtkevery", 0, "-mesh", "meshes/sleeve-aniso36.msh", "-tol", 3e-4, "-movinglayers", 1]),
]

def main_paper(opts):
    """--scale paper (the module docstring): the fraction study at the paper's scale over PAPER_TEND,
    the assumption tests, and the paper-scale defaults over the transient and the reversion window."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "oracles"))
    import curve_error  # noqa: E402 (tools/bench/oracles: l1_transient, l1_reversion)
    out = opts.out or os.path.join(ROOT, "results", "reference-paper-quick" if opts.quick else "reference-paper")
    doc = opts.doc or os.path.join(ROOT, "docs", "reference-paper.md")
    os.makedirs(out, exist_ok=True)
    levels = QUICK_PAPER_FRACTION_LEVELS if opts.quick else PAPER_FRACTION_LEVELS
    spe = PAPER_STEPS_PER_ELEMENT

    fraction, transient, curves, ex, fraction_rows = fraction_reference(levels, out, PAPER_TEND, spe, "paper")
    finest = fraction[-1][1]
    tA = austenite_time(finest)
    reference, previous, tests = ex["reference"], ex["previous"], ex["tests"]
    k, uncertainty = ex["order"], ex["uncertainty"]

    # The reference as a history (p* on the finest grid up to tA, the finest run's fraction and
    # contact columns): curve_error.py takes its transient [0, tA] and reversion window [tR, tA] from it.
    n = len(transient) - 1  # transient[1:] are the finest run's first n steps
    ref_history = os.path.join(out, "reference-history.csv")
    with open(ref_history, "w") as f:
        f.write("# p* of tools/bench/reference_curve.py --scale paper on the finest run's steps up to t_A, "
                "with that run's fraction_austenite and contact_nodes\n")
        f.write("t,pressure_mean,fraction_austenite,contact_nodes\n")
        for i in range(n):
            f.write(f"{transient[i + 1]:.12g},{reference[i + 1]:.12g},{finest['fraction_austenite'][i]:.12g},"
                    f"{finest['contact_nodes'][i]:.12g}\n")
    as_lists = {key: list(map(float, finest[key][:n])) for key in ("t", "fraction_austenite", "contact_nodes")}
    tR = curve_error.reversion_time(as_lists)
    # The reference's uncertainty and the levels' errors in the window's norm (the same A2, A3
    # quantities, integrals over [tR, tA]): informative, not tests.
    window = {"t_reversion": tR}
    if tR is not None:
        w = transient >= tR - 1e-12
        gw = transient[w]
        scale_w = l1(gw, reference[w])
        rel_w = lambda f: l1(gw, f[w]) / scale_w
        d1, d2 = curves[-1] - curves[-2], curves[-2] - curves[-3]
        factor = 2.0 ** k
        mismatch_w = l1(gw, (d2 - factor * d1)[w]) / l1(gw, d2[w])
        window.update({
            "A2_shape_mismatch": mismatch_w, "A2_effect_on_reference": mismatch_w * rel_w(d1) / (factor - 1),
            "A3_reference_change_without_finest": rel_w(previous - reference),
            "finest_level_error": rel_w(curves[-1] - reference),
            "level_errors": [rel_w(c - reference) for c in curves]})
        window["uncertainty"] = max(window["A2_effect_on_reference"], window["A3_reference_change_without_finest"])
        for row, e in zip(fraction_rows, window["level_errors"]):
            row["error_reversion"] = e

    defaults = []
    if not opts.quick and not opts.no_defaults:
        for name, script, args in PAPER_DEFAULTS:
            print(f"reference_curve: {name}", flush=True)
            run_out = os.path.join(out, "default-" + str(len(defaults)))
            h, wall = run(script, run_out, args, "paper")
            e = curve_error.curve_error(os.path.join(run_out, "history.csv"), ref_history)
            defaults.append({"run": name, "command": " ".join(["tools/ff", script, "-quiet", "1", *map(str, args)]),
                             "wall_seconds": wall, "error": e["l1_transient"], "error_reversion": e["l1_reversion"],
                             "transient_end": e["transient_end"], "reversion_start": e["reversion_start"],
                             "steps": len(h["t"])})

    with open(os.path.join(out, "reference.csv"), "w") as f:
        f.write("# Richardson extrapolation of sleeve-radial -scale paper's mean contact pressure "
                "(tools/bench/reference_curve.py --scale paper)\n")
        f.write("t,pressure_reference_Pa,pressure_finest_Pa,pressure_without_finest_Pa\n")
        for row in zip(transient, reference, curves[-1], previous):
            f.write(",".join(f"{v:.12g}" for v in row) + "\n")
    summary = {"scale": "paper", "tend": PAPER_TEND, "t_austenite": tA, "steps_per_element": spe, "order": k,
               "fraction_levels": fraction_rows, "tests": tests, "reference_uncertainty": uncertainty,
               "reversion_window": window, "defaults": defaults}
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    if not opts.quick:
        write_doc_paper(doc, summary)
    failed = [name for name in ("A1_ok", "A2_ok", "A3_ok") if not tests[name]]
    print(json.dumps({"order": k, "reference_uncertainty": uncertainty, "tests": tests,
                      "reversion_window": {key: v for key, v in window.items() if key != "level_errors"},
                      "defaults": defaults}, indent=1))
    if failed:
        sys.exit(f"reference_curve: assumption(s) failed: {', '.join(failed)} ({os.path.join(out, 'summary.json')})")

def pct3(x):
    """Three significant digits: the paper scale's errors are hundredths of a percent."""
    return f"{100 * x:.3g} %" if x is not None else "-"

def write_doc_paper(path, s):
    w = s["reversion_window"]
    lines = [
        "# An accuracy reference for the force curve at the paper's scale",
        "",
        "Written by `tools/bench/reference_curve.py --scale paper` (its docstring states the method); numbers",
        "from that run. The same Richardson extrapolation and assumption tests as docs/reference.md (the",
        "reduced scale's), at sleeve-radial's default scale (`-scale paper`: the 0.5 mm interference, a = 2625).",
        "Error: relative L1 in time of the mean contact pressure over the transient",
        f"[0, {s['t_austenite']:.3f} s] (tools/bench/oracles/curve_error.py's `l1_transient`) and over the reversion",
        f"window [{w['t_reversion']:.3f}, {s['t_austenite']:.3f} s] (`l1_reversion`: from the finest run's last step before its"
        if w.get("t_reversion") is not None else "window (`l1_reversion`: none found;",
        "ring starts to turn back to austenite, to its austenite time); levels: nr elements,",
        f"{s['steps_per_element']:g} nr steps over {s['tend']:g} s (dt = {s['tend'] / s['steps_per_element']:g} / nr s, "
        "the reduced study's dt for each nr).",
        "",
        "## The fraction model's levels and the extrapolation",
        "",
        "| nr | steps | wall (s) | error against p* | error, reversion window | difference to next | order of differences |",
        "|---|---|---|---|---|---|---|",
    ]
    lines += level_rows(s["fraction_levels"], pct3, reversion=True)
    lines += assumption_rows(s, pct3) + [
        "",
        f"The reference's uncertainty (the larger of A2's and A3's): {pct3(s['reference_uncertainty'])} over the transient.",
    ]
    if w.get("t_reversion") is not None:
        lines += [
            "In the reversion window's norm (the same quantities integrated over the window; informative, "
            f"not tests): A2's effect {pct3(w['A2_effect_on_reference'])} (m = {w['A2_shape_mismatch']:.3f}), "
            f"A3's change {pct3(w['A3_reference_change_without_finest'])}, against the finest level's "
            f"{pct3(w['finest_level_error'])}: uncertainty {pct3(w['uncertainty'])}.",
        ]
    lines.append("")
    if s["defaults"]:
        lines += ["## The paper-scale defaults against the reference", "",
                  "| run | command | wall (s) | error against p*, transient | error, reversion window |",
                  "|---|---|---|---|---|"]
        for d in s["defaults"]:
            lines.append(f"| {d['run']} | `{d['command']}` | {d['wall_seconds']:.2f} | {pct3(d['error'])} | "
                         f"{pct3(d['error_reversion'])} |")
        lines += ["", f"Each error is known to within the reference's uncertainty ({pct3(s['reference_uncertainty'])} "
                  "over the transient"
                  + (f", {pct3(w['uncertainty'])} over the reversion window" if w.get("t_reversion") is not None else "")
                  + ", in the same units).", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))

