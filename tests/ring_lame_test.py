#!/usr/bin/python3
"""Verification of the contact solver on the ring-lame scene against Lamé's exact pressure.

Asserts: mean contact pressure within 5e-4 (relative) of Lamé's on the default mesh (l3, 1377
nodes); error falling as h^2 over the four levels (each observed order >= 1.8, h halving from level
to level); recovered pressure uniform within 1 % at about 1200 nodes (l3), and the raw nodal
pressures' checkerboard (which the recovery removes) reported beside it.
Writes results/checks/ring_lame.json.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, rows, run_scene  # noqa: E402


def main():
    out = run_scene("ring-lame", "ring-lame")
    levels = json.load(open(os.path.join(out, "summary.json")))["levels"]
    by_name = {lv["name"]: lv for lv in levels}
    default = by_name["l3"]
    check(default["rel_error"] <= 5e-4,
          f"default mesh ({default['nodes']} nodes): mean pressure {default['pressure_mean']:.6e} Pa vs "
          f"Lamé {default['pressure_exact']:.6e} Pa, relative error {default['rel_error']:.2e} <= 5e-4")
    orders = [math.log(a["rel_error"] / b["rel_error"], 2) for a, b in zip(levels, levels[1:])]
    print("observed orders of the mean-pressure error:", ", ".join(f"{o:.3f}" for o in orders))
    check(min(orders) >= 1.8, f"error falls as h^2: orders {[round(o, 3) for o in orders]} each >= 1.8")
    check(default["non_uniformity"] <= 0.01,
          f"recovered pressure uniform within 1 % at {default['nodes']} nodes: (max-min)/mean "
          f"{default['non_uniformity']:.4f}")
    raw = [float(r["pressure_nodal"]) for r in rows(os.path.join(out, "pressure-l3.csv"))]
    raw_spread = (max(raw) - min(raw)) / default["pressure_mean"]
    print(f"raw nodal pressures (force / tributary length) at l3: (max-min)/mean {raw_spread:.4f}")
    record("ring_lame", {"test": "ring_lame", "levels": levels, "orders": orders,
                         "raw_nodal_non_uniformity_l3": raw_spread})
    finish()


if __name__ == "__main__":
    main()
