#!/usr/bin/python3
"""The final contact state's time error with friction, against the runs' own bound of it
(-timeestimate 1: the difference to the run again at 10 times -tol) and against Richardson's
estimate from two companions (a section of make bench, docs/benchmarks/traction-time-error.md).

Cases (paper scale, mu 0.2): sleeve-3d's clamping on Coulomb's cone (-pipeB 0.0504 -length 0.02,
nr 2, nt 8: the filtered e_theta and e_z traction densities and the normal reaction), its held ends
(-ends held -Ri 0.05 -pipeA 0.0504 -pipeB 0.0505 -length 0.02: the e_theta density), and
sleeve-elliptic-friction (its default mesh: the tangential density). Each at -tol 1e-2 ... 1e-5 and
a reference (3e-6 for the cone, 1e-6 otherwise); for the runs at 1e-4 and 1e-5: the actual error
(largest nodal difference of contact-final.csv's field to the reference's, over the reference's
largest |value|), d1 and d2 (the same difference to the runs 10 and 100 times looser), the observed
order p = log10(d2 / d1) and Richardson's d1 / (10^p - 1), and the bound d1 (-timeestimate 1's).
These numbers were typed by hand into docs/measurements.md#m-traction-time-error before this
section measured them.

bench.py calls measure() and write_doc(); alone: tools/bench/bench.py --only traction-time.
"""
import math
import os

from common import OUT, ROOT, read_csv, run, write_whole
from markdown_wrap import wrap

DOC = os.path.join(ROOT, "docs", "benchmarks", "traction-time-error.md")
TOLS = ["1e-2", "1e-3", "1e-4", "1e-5"]
CONE = ["-scale", "paper", "-mu", "0.2", "-pipeB", "0.0504", "-length", "0.02"]
HELD = ["-scale", "paper", "-mu", "0.2", "-ends", "held", "-Ri", "0.05", "-pipeA", "0.0504", "-pipeB", "0.0505",
        "-length", "0.02"]
CASES = [("cone", "sleeve-3d", CONE, "3e-6", ["tangential_density_theta", "tangential_density_z", "normal_force"]),
         ("held ends", "sleeve-3d", HELD, "1e-6", ["tangential_density"]),
         ("sleeve-elliptic-friction", "sleeve-elliptic-friction", ["-scale", "paper"], "1e-6", ["tangential_density"])]


def column(out, name):
    return read_csv(os.path.join(out, "contact-final.csv"))[name]


def difference(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def measure(results):
    """Runs the cases into results/bench/traction-time/; returns the record (also results['traction_time'])."""
    print("bench: the final tractions' time error against the runs' bound (-timeestimate 1) and Richardson's", flush=True)
    rows = []
    for name, scene, args, ref_tol, fields in CASES:
        outs, steps = {}, {}
        for tol in TOLS + [ref_tol]:
            out = os.path.join(OUT, "traction-time", f"{scene}-{name.replace(' ', '-')}-{tol}")
            _, s, _ = run(f"edp/scenes/{scene}.edp", out, *args, "-tol", tol, "-quiet", "1")
            outs[tol], steps[tol] = out, s["n_steps"]
        for field in fields:
            values = {tol: column(out, field) for tol, out in outs.items()}
            scale = max(abs(v) for v in values[ref_tol])
            for i, tol in enumerate(TOLS[2:], start=2):
                looser, loosest = TOLS[i - 1], TOLS[i - 2]
                d1 = difference(values[tol], values[looser]) / scale
                d2 = difference(values[looser], values[loosest]) / scale
                actual = difference(values[tol], values[ref_tol]) / scale
                p = math.log10(d2 / d1) if d1 > 0 and d2 > 0 else None
                richardson = d1 / (10 ** min(max(p, 0.25), 4) - 1) if p is not None else None
                rows.append({"case": name, "field": field, "tol": tol, "steps": steps[tol], "companion_steps": steps[looser],
                             "actual": actual, "d1": d1, "d2": d2, "order": p, "richardson": richardson})
    record = {"rows": rows}
    results["traction_time"] = record
    return record


def write_doc(record):
    rows = record["rows"]
    low = sum(1 for r in rows if r["richardson"] is not None and r["richardson"] < r["actual"])
    below = sum(1 for r in rows if r["d1"] < r["actual"])
    ratios = [r["d1"] / r["actual"] for r in rows if r["actual"] > 0]
    lines = ["# The final tractions' time error, the runs' bound and Richardson's estimate", "",
             "Written by `tools/bench/traction_time.py` (its docstring states the method); numbers from that run. "
             "Relative to the reference's largest |value| of the field; d1, d2: the differences to the runs 10 and 100 "
             "times looser; the bound is d1, what `-timeestimate 1` reports (summary.json `time_error_bound`).", "",
             "| case | field | -tol | steps (companion) | actual | bound d1 | d1 / actual | d2 | observed order | "
             "Richardson | Richardson / actual |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        rich = f"{r['richardson']:.2e} | {r['richardson'] / r['actual']:.2f}" if r["richardson"] is not None else "- | -"
        order = f"{r['order']:.2f}" if r["order"] is not None else "-"
        lines.append(f"| {r['case']} | {r['field']} | {r['tol']} | {r['steps']} ({r['companion_steps']}) | {r['actual']:.2e} | "
                     f"{r['d1']:.2e} | {r['d1'] / r['actual']:.1f} | {r['d2']:.2e} | {order} | {rich} |")
    lines += ["", f"The bound fell below the error in {below} of {len(rows)} cases (d1 / actual from {min(ratios):.1f} to "
              f"{max(ratios):.1f}); Richardson's estimate erred low in {low} of {len(rows)}.", ""]
    write_whole(DOC, wrap("\n".join(lines)))
