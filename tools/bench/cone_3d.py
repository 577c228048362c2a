#!/usr/bin/python3
"""sleeve-3d's clamping on Coulomb's cone: its cost and the time error of its circumferential
traction, with and without the step control's watch of the tractions (a section of make bench,
docs/benchmarks/sleeve-3d-cone.md).

The paper's scale, mu 0.2, nr 2, nt 8, the scene's adaptive steps:
  cost, at the scene's default length (10 cm): the round pipe on the rows (n, e_z) against the
    elliptic pipe (-pipeB 0.0504, free ends: the cone, rows (n, e_theta, e_z)) with the watch
    (-stepcontact 1, the default: the three traction components at every step) and without it;
    steps, rejected steps, the loop's wall seconds (summary.json wall_seconds);
  accuracy, at -length 0.02: the filtered e_theta traction density of contact-final.csv at the
    mid-length node nearest 34 deg and its largest over the bore, at -tol 1e-3 and 1e-4, watched and
    unwatched, against the watched -tol 1e-5 run.
These numbers were typed by hand into docs/model.md#the-clamping-on-coulombs-cone before this
section measured them.

bench.py calls measure() and write_doc(); alone: tools/bench/bench.py --only cone-3d.
"""
import csv
import os

from common import OUT, ROOT, run, write_whole

SCENE = "edp/scenes/sleeve-3d.edp"
DOC = os.path.join(ROOT, "docs", "benchmarks", "sleeve-3d-cone.md")
BASE = ["-scale", "paper", "-mu", "0.2", "-quiet", "1"]
ELLIPSE = ["-pipeB", "0.0504"]
SHORT = ["-length", "0.02"]
ANGLE = 34.0  # (deg: where the unwatched run's circumferential traction was 37 % off)


def traction(out):
    """The filtered e_theta density at the mid-length node nearest ANGLE and its largest |value|."""
    with open(os.path.join(out, "contact-final.csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    mid = [r for r in rows if float(r["z"]) == 0.0]
    near = min(mid, key=lambda r: abs(float(r["angle_deg"]) - ANGLE))
    return (float(near["angle_deg"]), float(near["tangential_density_theta"]),
            max(abs(float(r["tangential_density_theta"])) for r in rows))


def one(tag, *args):
    out = os.path.join(OUT, "cone-3d", tag)
    wall, s, _ = run(SCENE, out, *BASE, *args)
    return out, {"case": tag, "steps": s["n_steps"], "rejected": s["steps_rejected"], "loop_seconds": s["wall_seconds"],
                 "process_seconds": wall, "contact_tangent": s.get("contact_tangent"), "watch": 1 if s["step_contact_watch"] else 0}


def measure(results):
    """Runs the cases into results/bench/cone-3d/; returns the record (also results['cone_3d'])."""
    print("bench: sleeve-3d's clamping on Coulomb's cone (cost at 10 cm; the traction's time error at 2 cm)", flush=True)
    cost = [one("round-rows-n-ez", "-tol", "1e-3")[1],
            one("ellipse-cone-watched", *ELLIPSE, "-tol", "1e-3")[1],
            one("ellipse-cone-unwatched", *ELLIPSE, "-tol", "1e-3", "-stepcontact", "0")[1]]
    out, ref = one("short-reference-1e-5", *ELLIPSE, *SHORT, "-tol", "1e-5")
    ref["angle"], ref["density"], ref["largest"] = traction(out)
    accuracy = []
    for watch in ("1", "0"):
        for tol in ("1e-3", "1e-4"):
            out, row = one(f"short-{'watched' if watch == '1' else 'unwatched'}-{tol}", *ELLIPSE, *SHORT, "-tol", tol,
                           "-stepcontact", watch)
            row["tol"] = tol
            row["angle"], row["density"], row["largest"] = traction(out)
            row["error"] = abs(row["density"] - ref["density"]) / abs(ref["density"])
            row["error_largest"] = abs(row["largest"] - ref["largest"]) / ref["largest"]
            accuracy.append(row)
    record = {"cost": cost, "reference": ref, "accuracy": accuracy}
    results["cone_3d"] = record
    return record


def write_doc(record):
    ref = record["reference"]
    lines = ["# sleeve-3d's clamping on Coulomb's cone: cost and the traction's time error", "",
             "Written by `tools/bench/cone_3d.py` (its docstring states the method); numbers from that run. The "
             "paper's scale, mu 0.2, nr 2, nt 8, adaptive steps; the watch is the step control's of the three traction "
             "components at every step (`-stepcontact 1`, the default; docs/model.md#the-clamping-on-coulombs-cone).", "",
             "## Cost at the default length (10 cm)", "",
             "| case | bore tangent | -stepcontact | steps | rejected | loop (s) | process (s) |", "|---|---|---|---|---|---|---|"]
    for r in record["cost"]:
        lines.append(f"| {r['case']} | {r['contact_tangent']} | {r['watch']} | {r['steps']} | {r['rejected']} | "
                     f"{r['loop_seconds']:.2f} | {r['process_seconds']:.2f} |")
    lines += ["", f"## The circumferential traction's time error (-length 0.02)", "",
              f"Reference: the watched run at `-tol 1e-5` ({ref['steps']} steps): filtered e_theta density "
              f"{ref['density'] / 1e6:.4f} MPa at {ref['angle']:.2f} deg (mid-length), largest "
              f"{ref['largest'] / 1e6:.4f} MPa.", "",
              "| case | -tol | steps | loop (s) | density at the node (MPa) | error | largest (MPa) | error |",
              "|---|---|---|---|---|---|---|---|"]
    for r in record["accuracy"]:
        lines.append(f"| {r['case']} | {r['tol']} | {r['steps']} | {r['loop_seconds']:.2f} | {r['density'] / 1e6:.4f} | "
                     f"{100 * r['error']:.1f} % | {r['largest'] / 1e6:.4f} | {100 * r['error_largest']:.1f} % |")
    lines.append("")
    write_whole(DOC, "\n".join(lines))
