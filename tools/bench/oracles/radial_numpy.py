#!/usr/bin/python3
"""The radial sleeve model (edp/scenes/sleeve-radial.edp) computed again in numpy, from its
equations: an independent implementation of the same scheme, to check sleeve-radial against and to
time it against (tools/bench/bench.py, "sleeve-radial against numpy"; tests/radial_numpy_test.py).

    tools/bench/oracles/radial_numpy.py [-nr 160] [-steps 1000] [-out DIR] [-name value ...]

Same options, defaults and meanings as the scene (the subset of the radial model: -nr -steps
-tend -dt -theta -rannacher -dctol -dcmaxit -fptol -fpmaxit -E -nu -rho -a -latent -T0 -Tc -C0 -k
-g -gcontact -gpipe -Text -Tpipe -Tinit -plane -pipeA -Ri -thickness -interference -keepgoing;
-phasemodel fraction only). Writes DIR/history.csv (one row per step: t, T_inner_mean,
T_min, T_max, fraction_austenite, fraction_m1, fraction_m2, contact_nodes, pressure_mean,
fixed_point_iterations, dc_iterations, u_inner, reaction_per_radian; full double precision) and
DIR/summary.json (the scene's key figures and loop_seconds, the time loop alone), default DIR
results/radial-numpy.

The scheme (its equations, how they are solved): radial_scheme.py.
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from radial_scheme import HISTORY_COLUMNS, run  # noqa: E402
from sleeve_geometry import sleeve_geometry  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

# The radial scene's options and defaults (edp/problems/sleeve/parameters.idp, sleeve-radial.edp).
DEFAULTS = {
    "nr": 160, "steps": 1000, "tend": 150.0, "dt": 0.0, "theta": 0.5, "rannacher": 2,
    "dctol": 1e-3, "dcmaxit": 100, "fptol": 1e-8, "fpmaxit": 200,
    "E": 85e9, "nu": 0.3, "rho": 7900.0, "a": 300.0, "latent": 3000.0, "T0": 210.0, "Tc": 280.0,
    "C0": 837.0, "k": 18.0, "g": 500.0, "gcontact": None, "gpipe": None, "Text": 293.15,
    "Tpipe": None, "Tinit": 196.0, "plane": "strain", "pipeA": None, "Ri": 0.0, "thickness": 0.0,
    "interference": 0.0, "phasemodel": "fraction", "keepgoing": 0,
    "out": os.path.join(ROOT, "results", "radial-numpy"),
}
INTEGER_COLUMNS = {"contact_nodes", "fixed_point_iterations", "dc_iterations"}
INTEGER_OPTIONS = {"nr", "steps", "rannacher", "dcmaxit", "fpmaxit", "keepgoing"}
STRING_OPTIONS = {"plane", "phasemodel", "out"}


def fail(message):
    print(f"error: radial_numpy: {message}", file=sys.stderr)
    sys.exit(2)



def parse(argv):
    """-name value pairs over DEFAULTS; an unknown name or a bad value fails naming it."""
    p = dict(DEFAULTS)
    if len(argv) % 2:
        fail(f"options come in -name value pairs: {' '.join(argv)}")
    for name, value in zip(argv[::2], argv[1::2]):
        key = name[1:] if name.startswith("-") else None
        if key not in DEFAULTS:
            fail(f"unknown option {name} (options: {' '.join('-' + k for k in DEFAULTS)})")
        try:
            p[key] = value if key in STRING_OPTIONS else int(value) if key in INTEGER_OPTIONS else float(value)
        except ValueError:
            fail(f"{name} {value!r} is not a{'n integer' if key in INTEGER_OPTIONS else ' number'}")
    geo = sleeve_geometry()
    for key, fallback in (("gcontact", p["g"]), ("gpipe", p["g"]), ("Tpipe", p["Text"]), ("pipeA", geo["pipe"])):
        if p[key] is None:
            p[key] = fallback
    if p["interference"] > 0:
        p["Ri"] = p["pipeA"] - p["interference"]
    p["Ri"] = p["Ri"] or geo["Ri"]
    p["thickness"] = p["thickness"] or geo["Hr"]
    if p["dt"] > 0:
        p["steps"] = int(round(p["tend"] / p["dt"]))
    checks = [("nr", p["nr"] >= 1, "must be >= 1"), ("steps", p["steps"] >= 1, "must be >= 1"),
              ("theta", 0 <= p["theta"] <= 1, "must be in [0, 1]"), ("rannacher", p["rannacher"] >= 0, "must be >= 0"),
              ("dctol", p["dctol"] > 0, "must be > 0"), ("dcmaxit", p["dcmaxit"] >= 1, "must be >= 1"),
              ("fptol", p["fptol"] >= 0, "must be >= 0"), ("fpmaxit", p["fpmaxit"] >= 1, "must be >= 1"),
              ("C0", p["C0"] > 0, "must be > 0"), ("k", p["k"] >= 0, "must be >= 0"),
              ("Tinit", 0 < p["Tinit"] < p["T0"], "must be in (0, T0)"),
              ("plane", p["plane"] in ("strain", "stress"), "must be strain or stress"),
              ("phasemodel", p["phasemodel"] == "fraction", "must be fraction (the only model here)"),
              ("nu", -1 < p["nu"] < 0.5, "must be in (-1, 0.5)"), ("E", p["E"] > 0, "must be > 0"),
              ("Ri", p["Ri"] > 0, "must be > 0"), ("thickness", p["thickness"] > 0, "must be > 0")]
    for key, ok, why in checks:
        if not ok:
            fail(f"-{key} {p[key]} {why}")
    return p



def write_outputs(out, cols, summary):
    """history.csv (full double precision) and summary.json, each under a temporary name first."""
    os.makedirs(out, exist_ok=True)
    steps = len(cols["t"])
    table = np.column_stack([np.arange(1, steps + 1)] + [cols[k] for k in HISTORY_COLUMNS])
    fmt = ["%d"] + ["%d" if k in INTEGER_COLUMNS else "%.17g" for k in HISTORY_COLUMNS]
    path = os.path.join(out, "history.csv")
    np.savetxt(path + ".partial", table, fmt=fmt, delimiter=",", header="step," + ",".join(HISTORY_COLUMNS),
               comments="")
    os.replace(path + ".partial", path)
    path = os.path.join(out, "summary.json")
    with open(path + ".partial", "w") as f:
        json.dump(summary, f, indent=1, allow_nan=False, default=lambda x: x.item())  # numpy scalars
    os.replace(path + ".partial", path)


def main():
    p = parse(sys.argv[1:])
    try:
        cols, summary = run(p)
    except (RuntimeError, ArithmeticError) as e:
        fail(str(e))
    write_outputs(p["out"], cols, summary)
    print(f"radial_numpy: nr {summary['nr']}, {summary['n_steps']} steps, loop {summary['loop_seconds']:.3f} s; "
          f"first contact at step {summary['first_contact_step']}, austenite from step {summary['austenite_step']}; "
          f"final pressure {summary['final_pressure_mean'] / 1e6:.6f} MPa (Lame {summary['lame_pressure'] / 1e6:.6f})")


if __name__ == "__main__":
    main()
