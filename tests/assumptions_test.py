#!/usr/bin/python3
"""The sleeve models watch their own assumptions during the run (edp/problems/sleeve/assumptions.idp;
docs/parameters.md, "Model bounds"): small strain and small sliding.

1. sleeve-radial (nr 40, 200 steps) at the paper's scale: no warning, summary.json
   "assumption_warnings" empty, "assumption_checks" strain_max about the ring's 1 % opening
   (inside (0.5 %, 2 %)), no slip (1D);
2. the same with a = 6000 J/(kg K) (a transformation strain beyond the small-strain range): the run
   finishes, one console line "warning: sleeve-radial: the largest strain ..." and one sentence of
   "assumption_warnings" naming the strain, strain_max > the bound 0.02;
3. sleeve-axisymmetric on a steel pipe, 40 cm long, cells of 1 mm along z (-nr 2 -nz 200): the free
   end of the ring slides along the pipe by more than a cell while in contact (the nodes are paired
   node to node with the pipe's): one warning naming the sliding, slip_over_element_max > 1.
Writes results/checks/assumptions.json.
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402


def run(scene, out, *extra):
    p = subprocess.run([os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", "-quiet", "1", *extra,
                        "-out", out], cwd=ROOT, capture_output=True, text=True, timeout=600)
    warnings = [line for line in (p.stdout + p.stderr).splitlines()
                if line.startswith("warning:") and "summary.json: assumption_warnings" in line]
    summary = json.load(open(os.path.join(out, "summary.json"))) if p.returncode == 0 else {}
    return p.returncode, warnings, summary


def main():
    data = {}
    with tempfile.TemporaryDirectory(prefix="assumptions-") as tmp:
        code, warnings, s = run("sleeve-radial", os.path.join(tmp, "plain"), "-nr", "40", "-steps", "200")
        checks = s.get("assumption_checks", {})
        check(code == 0 and not warnings and s.get("assumption_warnings") == []
              and 0.005 < checks.get("strain_max", 0) < 0.02 and checks.get("slip_over_element_max") == 0,
              f"sleeve-radial at the paper's scale: exit {code}, no assumption warning ({warnings}), strain_max "
              f"{checks.get('strain_max')} in (0.005, 0.02), no slip")
        data["plain"] = checks

        code, warnings, s = run("sleeve-radial", os.path.join(tmp, "strained"), "-nr", "40", "-steps", "200",
                                "-a", "6000")
        checks = s.get("assumption_checks", {})
        listed = s.get("assumption_warnings", [])
        check(code == 0 and len(warnings) == 1 and "the largest strain" in warnings[0]
              and len(listed) == 1 and "strain" in listed[0] and checks.get("strain_max", 0) > 0.02,
              f"sleeve-radial -a 6000: exit {code}, one strain warning ({warnings}), listed in summary.json "
              f"({listed}), strain_max {checks.get('strain_max')} > 0.02")
        data["strained"] = {"checks": checks, "warnings": listed}

        code, warnings, s = run("sleeve-axisymmetric", os.path.join(tmp, "sliding"), "-length", "0.4", "-nr", "2",
                                "-nz", "200", "-steps", "300", "-pipeE", "2e11", "-pipenu", "0.28")
        checks = s.get("assumption_checks", {})
        listed = s.get("assumption_warnings", [])
        check(code == 0 and len(warnings) == 1 and "slid" in warnings[0] and len(listed) == 1
              and checks.get("slip_over_element_max", 0) > 1,
              f"sleeve-axisymmetric on steel, 1 mm cells: exit {code}, one sliding warning ({warnings}), listed "
              f"({listed}), slip_over_element_max {checks.get('slip_over_element_max')} > 1")
        data["sliding"] = {"checks": checks, "warnings": listed}
    record("assumptions", {"test": "assumptions", **data})


if __name__ == "__main__":
    main()
    finish()
