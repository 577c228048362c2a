#!/usr/bin/python3
"""Verification of sleeve-offset's elastic pipe (the half ring, -pipeE > 0: the pipe a half made to
follow the ring's mesh, rollers on its cut, its translation along x held at its centre), on the
coarse half ring, 600 steps, -scale reduced.

1. Symmetry reduction: the half ring on a centred solid steel shaft (2.1e11) gives the quarter
   ring's final pressure on the same shaft (within 1e-6), and the compound cylinders' closed form
   (tools/bench/oracles/lame.py compound_pressure, plane strain) to the coarse mesh's error (< 1e-3).
2. The offset ring (5.5 um) on the steel shaft recentres (point A moves by the offset within 5 %)
   and ends at the centred level (within 1e-4), also on a hollow steel pipe (-pipeRi 0.045) against
   its closed form (< 1.5e-3).
3. Action = reaction: each body's interface forces against the reactions it is loaded by (ring and
   pipe balances < 1e-10); along x the pipe's interface force is the ring's, opposite, to 1e-9 of
   the largest y resultant, and both equal the anchor's spring force (the ring's x equilibrium:
   what the pipe's held centre carries); no penetration of the deformed pipe (gap >= -1e-12 m).
4. Rigid limit: -pipeE 1e15 reproduces the rigid offset run (pressure mean, min, max within 1e-4
   of their peaks at every step, the same contact node count); 1e13 differs 50 to 200 times more.
Writes results/checks/sleeve_offset_pipe.json.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools"))

from checklib import check, finish, record, run_scene, sleeve_outputs  # noqa: E402
from lame import compound_pressure  # noqa: E402

HALF = ["-mesh", "meshes/sleeve-half-coarse.msh", "-steps", "600", "-quiet", "1"]
STEEL = ["-pipeE", "2.1e11"]


def offset_run(tag, *args):
    return sleeve_outputs(run_scene("sleeve-offset", "sleeve-offset-pipe-" + tag, *HALF, *args))


def closed(s, inner):
    p = s["parameters"]
    a = p["ring_inner_radius"]
    return compound_pressure(p["E"], p["nu"], a, a + 0.01, 2.1e11, 0.3, inner, p["pipe_A"])


def pipe_invariants(tag, run):
    s, pipe = run["summary"], run["summary"]["pipe"]
    check(pipe["mesh"].startswith("(following the ring"), f"{tag}: the half pipe follows the ring's mesh ({pipe['mesh']})")
    check(max(pipe["ring_balance"], pipe["pipe_balance"]) < 1e-10,
          f"{tag}: ring balance {pipe['ring_balance']:.2g}, pipe balance {pipe['pipe_balance']:.2g} < 1e-10")
    fr, fp = pipe["interface_force_ring"], pipe["interface_force_pipe"]
    scale = abs(fr[1])
    check(abs(fr[0] + fp[0]) <= 1e-9 * scale and abs(fr[0] - s["anchor_force"]) <= 1e-9 * scale,
          f"{tag}: along x the ring's interface force {fr[0]:.9g} = -the pipe's {fp[0]:.9g} = the anchor's "
          f"{s['anchor_force']:.9g} N/m (to 1e-9 of {scale:.4g})")
    check(pipe["gap_deformed_min"] >= -1e-12, f"{tag}: no penetration of the deformed pipe "
          f"(gap min {pipe['gap_deformed_min']:.2g} m)")
    return {"ring_balance": pipe["ring_balance"], "pipe_balance": pipe["pipe_balance"],
            "x_mismatch": abs(fr[0] + fp[0]) / scale}


data = {}
# ---- 1. Symmetry reduction and the closed form ----
quarter = sleeve_outputs(run_scene("sleeve-circular", "sleeve-offset-pipe-quarter", "-mesh", "meshes/sleeve-coarse.msh",
                                   "-steps", "600", "-quiet", "1", *STEEL))
centred = offset_run("centred", "-offset", "0", *STEEL)
data["centred"] = pipe_invariants("centred steel shaft", centred)
q, c = quarter["summary"]["final_pressure_mean"], centred["summary"]["final_pressure_mean"]
exact = closed(centred["summary"], 0.0)
data.update(quarter=q, centred_level=c, compound=exact)
check(abs(c / q - 1) < 1e-6, f"half ring, centred steel shaft = quarter ring: {c / 1e6:.6f} vs {q / 1e6:.6f} MPa "
      f"({abs(c / q - 1):.2g})")
check(abs(c / exact - 1) < 1e-3, f"centred: compound cylinders {exact / 1e6:.6f} MPa, error {c / exact - 1:.2e} < 1e-3")

# ---- 2. The offset ring recentres on the elastic pipe ----
steel = offset_run("steel", *STEEL)
data["steel"] = pipe_invariants("offset steel shaft", steel)
s = steel["summary"]
d, shift = s["parameters"]["offset"], s["anchor_displacement_x"]
check(abs(shift / d - 1) < 0.05, f"steel shaft: the ring recentres: u_x(A) = {shift * 1e6:.3f} um for an offset of {d * 1e6:.3f} um")
level = s["final_pressure_mean"]
check(abs(level / c - 1) < 1e-4, f"steel shaft: offset final {level / 1e6:.6f} MPa = centred {c / 1e6:.6f} MPa "
      f"({abs(level / c - 1):.2g} < 1e-4)")
wall = offset_run("wall", *STEEL, "-pipeRi", "0.045")
data["wall"] = pipe_invariants("offset steel wall", wall)
exact_wall = closed(wall["summary"], 0.045)
err_wall = wall["summary"]["final_pressure_mean"] / exact_wall - 1
data["wall_error"] = err_wall
check(abs(err_wall) < 1.5e-3, f"hollow steel pipe: final {wall['summary']['final_pressure_mean'] / 1e6:.5f} MPa against "
      f"{exact_wall / 1e6:.5f} MPa ({err_wall:.2e})")

# ---- 4. Rigid limit ----
rigid = offset_run("rigid")
diffs = {}
for e in ("1e15", "1e13"):
    run = offset_run("e" + e, "-pipeE", e)
    pipe_invariants("pipeE " + e, run)
    worst = 0.0
    for col in ("pressure_mean", "pressure_min", "pressure_max"):
        peak = max(abs(float(r[col])) for r in rigid["history"])
        worst = max(worst, max(abs(float(a[col]) - float(b[col])) for a, b in zip(rigid["history"], run["history"])) / peak)
    diffs[e] = worst
    if e == "1e15":
        check(all(a["contact_nodes"] == b["contact_nodes"] for a, b in zip(rigid["history"], run["history"])),
              "pipeE 1e15: the same contact node count at every step as the rigid pipe")
data["rigid_limit"] = diffs
check(diffs["1e15"] < 1e-4, f"pipeE 1e15: pressure curves within {diffs['1e15']:.2g} < 1e-4 of the rigid pipe's peak")
check(50 <= diffs["1e13"] / diffs["1e15"] <= 200, f"rigid limit scales as 1/E: 1e13 / 1e15 = {diffs['1e13'] / diffs['1e15']:.1f}")

record("sleeve_offset_pipe", data)
finish()
