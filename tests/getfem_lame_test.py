#!/usr/bin/python3
"""ring-lame against an independent solver: GetFEM (tools/bench/oracles/getfem_lame.py) on the same meshes.

Asserts: on l1 and l2, GetFEM's mean contact pressure (semi-smooth Newton on the same discrete P1
problem) equals ring-lame's (condensed PSOR, active-set polish) within 1e-9 relative, ours read to
the 15 digits of pressure-<level>.csv; and GetFEM's isoparametric P2 on the same triangles
converges to Lame's closed form at order >= 3.5 from l1 to l2 (h halved), which checks the
script's problem (supports, contact, mean pressure) against the exact answer, not only against us.
Writes results/checks/getfem_lame.json.
"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, run_scene  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tools", "bench"))
from ring_lame import ours_pressure  # noqa: E402

LEVELS = ["l1", "l2"]


def getfem(name, *options):
    path = os.path.join(TEST_RESULTS, f"getfem-lame-{name}.json")
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "bench", "oracles", "getfem_lame.py"), "--levels", " ".join(LEVELS),
                    "--json", path, *options], cwd=ROOT, check=True)
    with open(path) as f:
        return {lv["name"]: lv for lv in json.load(f)["levels"]}


def main():
    out = run_scene("ring-lame", "getfem-lame-ours", "-levels", " ".join(LEVELS))
    p1 = getfem("p1")
    agreement = {}
    for level in LEVELS:
        ours = ours_pressure(out, level)
        theirs = p1[level]["pressure_mean"]
        agreement[level] = abs(theirs - ours) / ours
        check(agreement[level] <= 1e-9, f"{level}: mean pressure ours {ours:.15g} Pa, GetFEM {theirs:.15g} Pa, "
              f"relative difference {agreement[level]:.1e} <= 1e-9")
    curved = getfem("p2-curved", "--order", "2", "--geometry", "curved")
    errors = [curved[level]["rel_error"] for level in LEVELS]
    order = math.log(errors[0] / errors[1], 2)
    check(order >= 3.5, f"GetFEM isoparametric P2 against Lame: errors {errors[0]:.2e}, {errors[1]:.2e}, "
          f"observed order {order:.2f} >= 3.5")
    record("getfem_lame", {"test": "getfem_lame", "agreement_p1": agreement, "p2_curved_errors": errors,
                           "p2_curved_order": order})
    finish()


if __name__ == "__main__":
    main()
