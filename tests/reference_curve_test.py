#!/usr/bin/python3
"""The accuracy reference of tools/bench/reference_curve.py: its extrapolation on curves whose limit is
known, its assumption tests failing where their assumption does not hold, then the real study.

  - curves p* + C(t) h^k (k = 1.3, a C with kinks): the extrapolant is p* to round-off, the order
    k, every assumption holds;
  - p* + C1 h + c C2 h^2 in the asymptotic range: where the assumptions hold, the stated
    uncertainty bounds the reference's true error; before it (differences changing sign, an h^2
    term dominating the coarse levels only): an assumption fails;
  - p* + C(t; h) h with the error's shape moving between levels: A2 fails;
  - the radial sleeve (fraction levels nr 40-1280, on/off 40-1280: `--test`, make reference's study
    but the on/off's finest level, 2560, 40 % of its time; the defaults): the tool passes
    its own tests, the fraction model's error against the reference falls at every level at an
    order near its differences', the on/off scheme's error falls at every level, and every
    default's error is above the reference's uncertainty (so measuring it against the reference
    means something).
Writes results/checks/reference_curve.json.
"""
import json
import os
import subprocess
import sys

import numpy as np

from checklib import ROOT, check, finish, record

sys.path.insert(0, os.path.join(ROOT, "tools", "bench"))
import reference_curve as rc  # noqa: E402

grid = np.linspace(0.0, 16.0, 3201)
exact = np.where(grid < 4, 0.0, np.minimum(grid - 4, 8.0)) * 1e6  # zero, linear, constant (kinks)
shape = np.sin(grid) * 1e5 + np.where(grid > 9, 5e4, 0.0)
hs = [1.0 / 2 ** l for l in range(5)]

ex = rc.extrapolate(grid, [exact + shape * h ** 1.3 for h in hs])
error = rc.l1(grid, ex["reference"] - exact) / rc.l1(grid, exact)
check(abs(ex["order"] - 1.3) < 1e-9 and error < 1e-12,
      f"exact model p* + C h^1.3: order {ex['order']:.12f}, reference error {error:.2e}")
check(all(ex["tests"][k] for k in ("A1_ok", "A2_ok", "A3_ok")), f"exact model: assumptions hold {ex['tests']}")

shape2 = np.cos(2 * grid) * 1e5


def extrapolated(curves):
    e = rc.extrapolate(grid, curves)
    return e, rc.l1(grid, e["reference"] - exact) / rc.l1(grid, exact)


# Two orders (h and h^2, of one shape or of two), in the asymptotic range: the assumptions may
# hold, and then the stated uncertainty must bound the reference's true error.
for c2, second in ((1, shape), (4, shape), (16, shape), (1, shape2), (16, shape2)):
    e, true_error = extrapolated([exact + shape * h + c2 * second * h ** 2 for h in hs])
    holds = all(e["tests"][k] for k in ("A1_ok", "A2_ok", "A3_ok"))
    check(not holds or e["uncertainty"] >= true_error,
          f"p* + C1 h + {c2} C2 h^2 ({'one shape' if second is shape else 'two shapes'}): assumptions "
          f"{'hold' if holds else 'fail'}, uncertainty {e['uncertainty']:.2e} >= true error {true_error:.2e}")
# Pre-asymptotic: the h^2 term changes the differences' sign or dominates the coarse levels only.
for c2, second in ((-0.8, shape), (4, shape2)):
    e, true_error = extrapolated([exact + shape * h + c2 * second * h ** 2 for h in hs])
    check(not all(e["tests"][k] for k in ("A1_ok", "A2_ok", "A3_ok")),
          f"p* + C1 h + {c2} C2 h^2, orders {[round(o, 2) for o in e['orders']]}: an assumption fails "
          f"(A1 {e['tests']['A1_ok']}, A2 {e['tests']['A2_ok']}, A3 {e['tests']['A3_ok']})")
moving, _ = extrapolated([exact + np.sin(grid + 10 * h) * 1e5 * h for h in hs])
check(not moving["tests"]["A2_ok"], f"an error shape moving with h: A2 fails (mismatch "
      f"{moving['tests']['A2_shape_mismatch']:.3f}, effect {moving['tests']['A2_effect_on_reference']:.2e} "
      f"against the finest error {moving['tests']['A3_finest_level_error']:.2e})")

out = os.path.join(ROOT, "results", "reference-test")
proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools", "bench", "reference_curve.py"), "--test", "--out", out,
                       "--doc", os.path.join(out, "reference.md")], cwd=ROOT, capture_output=True, text=True)
check(proc.returncode == 0, "tools/bench/reference_curve.py passes its assumption tests"
      + ("" if proc.returncode == 0 else f" (exit {proc.returncode}: {proc.stderr.strip() or proc.stdout.strip()})"))
summary = json.load(open(os.path.join(out, "summary.json")))
fr = summary["fraction_levels"]
errors = [r["error"] for r in fr]
check(all(a > b for a, b in zip(errors, errors[1:])), f"fraction model: error against p* falls at every level {errors}")
fitted = -np.polyfit(np.log([r["nr"] for r in fr[-4:]]), np.log(errors[-4:]), 1)[0]
check(abs(fitted - summary["order"]) < 0.2, f"fraction model: order of its errors against p* {fitted:.3f} "
      f"near the order of its differences {summary['order']:.3f}")
oo = [r["error"] for r in summary["onoff"]["levels"]]
check(all(a > b for a, b in zip(oo, oo[1:])), f"on/off scheme: error against p* falls at every level {oo}")
check(0.2 < summary["onoff"]["order_fit_all"] < 1.0, f"on/off scheme: observed order {summary['onoff']['order_fit_all']:.3f}")
u = summary["reference_uncertainty"]
for d in summary["defaults"]:
    check(d["error"] > 2 * u, f"{d['run']}: error {100 * d['error']:.3f} % above twice the reference's "
          f"uncertainty {100 * u:.3f} %")
record("reference_curve", {"order": summary["order"], "uncertainty": u, "fraction": fr,
                           "onoff": summary["onoff"], "defaults": summary["defaults"]})
finish()
