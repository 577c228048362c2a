#!/usr/bin/python3
"""Verification of the sleeve-axisymmetric scene (the sleeve of finite length, half of it, rigid
frictionless pipe), at the paper's scale (0.5 mm interference, a = 2625).

1. Mid-length against the closed form: at the end the ring is all austenite and elastic, and far
   from its free ends a long sleeve is an open-ended thick cylinder (generalized plane strain:
   e_zz constant, zero axial force, so sigma_zz = 0 and the in-plane stresses are plane stress's):
   p = E delta (b^2 - a^2) / (a ((1 - nu) a^2 + (1 + nu) b^2)), computed here from E, nu and the
   radii. L = 0.4 m (L / thickness 40: the ends' influence at mid-length about exp(-11)):
   the contact pressure at z = 0 must converge to it at order >= 1.8 (nr 2, 4; square cells),
   within 5e-4 at nr 4. The closed form is itself checked against an independent computation:
   sleeve-radial with -plane stress (the same in-plane problem) at nr 64, to 1e-4; and it must
   differ from the plane-strain Lame pressure (the radial model's default) by more than 5 %.
2. The pressure profile along the bore converges under refinement: L = 0.1 m (end effects over a
   quarter of the half length), nr 2, 4, 8: the largest difference between successive levels at
   the coarse nodes must fall by a factor >= 1.6 (order >= 0.7: the free end's corner is O(h)).
3. Friction and pull-out (the whole length, its end face z = 0 held axially, mu 0.2, the pipe moved
   1 mm towards the held face after clamping): at the end every node in contact slips and the
   pull-out force equals mu times the total normal force to 1e-8 (the sliding plateau), which is
   the curve's maximum; the pull-out force converges (nr 2, 4, 8: successive differences at least
   halve). Its sign convention (docs/parameters.md, pull-out force: the sleeve's force on the pipe,
   > 0 against the pipe's motion), on these runs and at nr 2 with -pulldirection away and with a
   pull of 0.1 mm (short of the plateau, the force rising from < 0): summary.json's
   pullout_force_final is pullout.csv's last row and pullout_force_max the column's maximum, both
   with their sign; the force is > 0 at the end and the sleeve's force on the pipe does negative
   work on the pipe's displacement; and it equals, to 1e-5, the force computed independently from
   fields-4-pulled.vtu: the bore's shear stress sigma_rz over the first layer of cells, -2 pi / hr
   sum_T sigma_rz,T int_T r dA (the weak form of the sleeve's equilibrium along z with the test
   function 1 on the bore, 0 one cell in: exactly the sum of the nodal friction forces, f = 0).
   The gross slip (every pressing node slipping) located inside its increment (a 64th of it) at
   nr 2, checked by runs pulled to the bracket's ends in one increment: not all slipping at the
   lower, all at the upper (the pull-out's path does not depend on its increments).
4. Invariants on every run: no penetration (gap >= -1e-12 m), pressures >= 0, all austenite at the
   end, the discrete heat balance at round-off (1e-8); bad input fails naming the option (-length 0,
   -plane stress).
5. The scene's header quotes its defaults' run (-tol 0, its fixed steps) as it comes out: the nodes,
   the first contact's step and temperature, the free end's peak and its time, austenite's step
   and temperature, the final pressures at mid-length and at the free end (checklib.header_quotes).
Writes results/checks/sleeve_axisymmetric.json.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from checklib import ROOT, check, finish, header_quotes, record, rows, run_scene  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "python"))
from sma.vtu import read_vtu  # noqa: E402

PAPER = ["-scale", "paper", "-quiet", "1", "-steps", "500", "-tend", "100"]


def axi(tag, *args):
    out = run_scene("sleeve-axisymmetric", "sleeve-axisymmetric-" + tag, *PAPER, *args)
    return {"summary": json.load(open(os.path.join(out, "summary.json"))),
            "history": rows(os.path.join(out, "history.csv")),
            "bore": rows(os.path.join(out, "bore-final.csv"))}


def invariants(tag, run):
    s = run["summary"]
    gap_min = min(float(r["gap"]) for r in run["bore"])
    p_min = min(float(r["pressure"]) for r in run["bore"])
    final = run["history"][-1]
    check(gap_min >= -1e-12 and p_min >= 0, f"{tag}: no penetration (gap min {gap_min:.3g} m), pressure >= 0 "
          f"(min {p_min:.6g} Pa)")
    check(float(final["fraction_austenite"]) == 1.0, f"{tag}: all austenite at the end "
          f"({final['fraction_austenite']})")
    check(s["heat_balance_residual_max"] < 1e-8, f"{tag}: heat balance residual {s['heat_balance_residual_max']:.3g}")


data = {}
# ---- 1. Mid-length against the open-ended cylinder ----
E, nu = 85e9, 0.3
mid = {}
for nr in (2, 4):
    run = axi(f"long-nr{nr}", "-length", "0.4", "-nr", str(nr))
    invariants(f"L 0.4 nr {nr}", run)
    s = run["summary"]
    a_, b_ = s["parameters"]["ring_inner_radius"], s["parameters"]["ring_inner_radius"] + s["parameters"]["ring_thickness"]
    delta = s["parameters"]["pipe_A"] - a_
    closed = E * delta * (b_**2 - a_**2) / (a_ * ((1 - nu) * a_**2 + (1 + nu) * b_**2))
    check(abs(s["open_cylinder_pressure"] - closed) <= 1e-10 * closed,
          f"scene's closed form {s['open_cylinder_pressure']:.9g} Pa = this test's {closed:.9g} Pa")
    mid[nr] = abs(s["final_pressure_mid"] - closed) / closed
    data[f"mid_error_nr{nr}"] = mid[nr]
order = math.log2(mid[2] / mid[4])
data["mid_order"] = order
check(order >= 1.8, f"mid-length pressure -> open cylinder at order {order:.2f} (errors {mid[2]:.3g}, {mid[4]:.3g})")
check(mid[4] < 5e-4, f"nr 4: mid-length error {mid[4]:.3g} < 5e-4")
planestrain = s["plane_strain_pressure"]
check(abs(planestrain - closed) / closed > 0.05, f"plane strain {planestrain / 1e6:.3f} MPa differs from the "
      f"open cylinder {closed / 1e6:.3f} MPa by {abs(planestrain - closed) / closed:.3f} > 5 %")
rad = run_scene("sleeve-radial", "sleeve-axisymmetric-radial-stress", "-scale", "paper", "-quiet", "1",
                "-plane", "stress", "-nr", "64", "-steps", "500", "-tend", "100")
radial = json.load(open(os.path.join(rad, "summary.json")))["final_pressure_mean"]
data["radial_plane_stress_pressure"] = radial
check(abs(radial - closed) / closed < 1e-4, f"sleeve-radial -plane stress {radial / 1e6:.5f} MPa = open "
      f"cylinder {closed / 1e6:.5f} MPa (relative {abs(radial - closed) / closed:.2g})")

# ---- 2. The profile along the bore converges ----
profiles = {}
for nr in (2, 4, 8):
    run = axi(f"short-nr{nr}", "-length", "0.1", "-nr", str(nr))
    invariants(f"L 0.1 nr {nr}", run)
    profiles[nr] = {round(float(r["z"]), 9): float(r["pressure"]) for r in run["bore"]}
diffs = []
for c, f in ((2, 4), (4, 8)):
    zs = [z for z in profiles[c] if z in profiles[f]]
    check(len(zs) == len(profiles[c]), f"nr {c}: every node of the coarse bore is one of nr {f}'s")
    diffs.append(max(abs(profiles[c][z] - profiles[f][z]) for z in zs) / closed)
data["profile_differences"] = diffs
check(diffs[0] / diffs[1] >= 1.6, f"profile differences {diffs[0]:.3g} (nr 2-4), {diffs[1]:.3g} (4-8): "
      f"ratio {diffs[0] / diffs[1]:.2f} >= 1.6")

# ---- 3. Friction and pull-out: the whole length, its end face z = 0 held (the shoulder), mu 0.2,
# the pipe moved 1 mm towards it after clamping ----
def bore_shear_force(tag, out, summary):
    """The axial force (N, along +z, the whole circumference) on the sleeve's bore after the
    pull-out, from fields-4-pulled.vtu alone: the weak form of the sleeve's axial equilibrium with
    the P1 test function v = phi e_z, phi = 1 on the bore nodes and 0 on the next column (the
    first layer of cells; phi depends on r only there), gives sum over the bore nodes of the
    contact's r_t = int sigma_rz dphi/dr r dA = -(1 / hr) sum_T sigma_rz,T int_T r dA (sigma_rz
    constant per P1 triangle; no load f, and the phase stress is isotropic: no rz part)."""
    p = summary["parameters"]
    R, hr = p["ring_inner_radius"], p["ring_thickness"] / p["nr"]
    fields = read_vtu(os.path.join(out, "fields-4-pulled.vtu"))
    xy = fields.points[fields.triangles]  # (cells, 3 vertices, r z)
    tol = 1e-6 * hr
    layer = np.all(xy[:, :, 0] <= R + hr + tol, axis=1)
    r = xy[layer][:, :, 0]
    check(bool(np.all(np.isclose(r, R, atol=tol) | np.isclose(r, R + hr, atol=tol))),
          f"{tag}: the first layer of cells has its vertices on r = R or R + hr only")
    e1, e2 = xy[layer][:, 1] - xy[layer][:, 0], xy[layer][:, 2] - xy[layer][:, 0]
    area = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
    return -2 * math.pi / hr * float(np.sum(fields.cell_data["sigma_rz"][layer] * area * r.mean(axis=1)))


def sign_convention(tag, out, summary, curve):
    """The pull-out force's one sign convention, held by summary.json, pullout.csv and the fields."""
    forces = [float(r["pullout_force"]) for r in curve]
    final, top = summary["pullout_force_final"], summary["pullout_force_max"]
    check(abs(final - forces[-1]) <= 1e-9 * abs(forces[-1]) and abs(top - max(forces)) <= 1e-9 * max(abs(f) for f in forces),
          f"{tag}: summary's final {final:.9g} N and max {top:.9g} N are pullout.csv's last row "
          f"{forces[-1]:.9g} N and its maximum {max(forces):.9g} N, with their signs")
    w = float(curve[-1]["pipe_displacement"])
    on_sleeve = bore_shear_force(tag, out, summary)
    on_pipe = -on_sleeve
    check(final > 0 and on_pipe * w < 0,
          f"{tag}: the pull-out force {final:.6g} N > 0, and the sleeve's force on the pipe {on_pipe:.6g} N "
          f"(along z, from the bore's shear stress) opposes the pipe's displacement {w:.3g} m")
    independent = math.copysign(1, w) * on_sleeve
    check(abs(independent - final) <= 1e-5 * abs(final),
          f"{tag}: the pull-out force {final:.9g} N = sign(w) x the bore's shear stress integrated from the "
          f"VTU {independent:.9g} N (relative {abs(independent - final) / abs(final):.2g} <= 1e-5, float32 fields)")
    data[f"sign_{tag}_vtu_relative"] = abs(independent - final) / abs(final)


pull = {}
for nr in (2, 4, 8):
    out = run_scene("sleeve-axisymmetric", f"sleeve-axisymmetric-pull-nr{nr}", *PAPER, "-length", "0.1",
                    "-nr", str(nr), "-mu", "0.2", "-pullout", "1e-3", "-pullsteps", "25")
    s = json.load(open(os.path.join(out, "summary.json")))
    curve = rows(os.path.join(out, "pullout.csv"))
    sign_convention(f"pull nr {nr}", out, s, curve)
    last = curve[-1]
    F, N = float(last["pullout_force"]), float(last["normal_force_total"])
    plateau = abs(F - 0.2 * N) / (0.2 * N)
    check(plateau < 1e-8, f"pull nr {nr}: sliding plateau F {F:.9g} N = mu N {0.2 * N:.9g} N "
          f"(relative {plateau:.2g} < 1e-8)")
    check(int(last["nodes_slipping"]) == int(last["nodes_in_contact"]) > 0,
          f"pull nr {nr}: every node in contact slips at the end ({last['nodes_slipping']}/{last['nodes_in_contact']})")
    forces = [float(r["pullout_force"]) for r in curve]
    check(max(forces) <= F * (1 + 1e-9), f"pull nr {nr}: the plateau is the curve's maximum "
          f"({max(forces):.9g} N)")
    pull[nr] = F
    data[f"pullout_force_nr{nr}"] = F
    data[f"plateau_relative_nr{nr}"] = plateau
    if nr == 2:
        # the gross slip located inside its increment by bisection; the path does not depend on the
        # increments (every node's slip only grows): pulled in one increment to the bracket's ends,
        # not all slipping at the lower, all at the upper
        lo, hi = s["pullout_all_slip_located"] or [None, None]
        dw, k = 1e-3 / 25, s["pullout_all_slip_from"]
        check(lo is not None and (k - 1) * dw - 1e-15 <= lo < hi <= k * dw + 1e-15
              and abs(hi - lo - dw / 2 ** s["pullout_located_probes"]) <= 1e-15,
              f"pull nr 2: the gross slip in increment {k}, located in ({lo}, {hi}] m")
        if lo is not None:
            ends = {}
            for name, end in (("lo", lo), ("hi", hi)):
                o = run_scene("sleeve-axisymmetric", f"sleeve-axisymmetric-pull-{name}", *PAPER, "-length", "0.1", "-nr", "2",
                              "-mu", "0.2", "-pullout", repr(end), "-pullsteps", "1")
                r = rows(os.path.join(o, "pullout.csv"))[-1]
                ends[name] = int(r["nodes_slipping"]) == int(r["nodes_in_contact"])
            check(not ends["lo"] and ends["hi"], f"pull nr 2 in one increment: all slipping at {lo} m {ends['lo']}, "
                  f"at {hi} m {ends['hi']}")
# the other direction, and a pull short of the plateau (the force still rising from its start < 0)
for tag, extra in (("away", ["-pullout", "1e-3", "-pulldirection", "away"]), ("short", ["-pullout", "1e-4"])):
    out = run_scene("sleeve-axisymmetric", f"sleeve-axisymmetric-pull-{tag}", *PAPER, "-length", "0.1",
                    "-nr", "2", "-mu", "0.2", "-pullsteps", "25", *extra)
    curve = rows(os.path.join(out, "pullout.csv"))
    sign_convention(f"pull {tag} nr 2", out, json.load(open(os.path.join(out, "summary.json"))), curve)
    if tag == "short":
        first = float(curve[0]["pullout_force"])
        check(first < 0, f"pull short nr 2: the force starts < 0 ({first:.6g} N: the clamped sleeve drags the "
              "pipe towards the held face)")
d1, d2 = abs(pull[2] - pull[4]), abs(pull[4] - pull[8])
check(d2 < d1 / 2, f"pull-out force converges: {pull[2]:.7g}, {pull[4]:.7g}, {pull[8]:.7g} N "
      f"(differences {d1:.4g}, {d2:.4g}: order {math.log2(d1 / d2):.2f})")

# ---- 5. The scene's header quotes its defaults' run (-tol 0: the step numbers it quotes are the
# fixed steps') as it comes out, to the digits it prints ----
out = run_scene("sleeve-axisymmetric", "sleeve-axisymmetric-defaults", "-scale", "paper", "-quiet", "1", "-tol", "0")
s = json.load(open(os.path.join(out, "summary.json")))
peak = max(rows(os.path.join(out, "history.csv")), key=lambda r: float(r["pressure_end"]))
quoted = [f"nr 6 x nz 30 Union Jack cells, {s['nodes']} nodes",
          f"touches it at step {s['first_contact_step']} (bore {s['T_inner_first_contact'] - 273.15:.1f} C)",
          f"the free end's pressure peaks at {float(peak['pressure_end']) / 1e6:.0f} MPa (t = {float(peak['t']):.0f} s)",
          f"austenite for good from step {s['austenite_step']} ({s['T_inner_austenite'] - 273.15:.1f} C)",
          f"Final pressure at mid-length {s['final_pressure_mid'] / 1e6:.3f} MPa",
          f"{s['final_pressure_end'] / 1e6:.3f} MPa at the free end"]
data["header_quoted"] = quoted
header_quotes("edp/scenes/sleeve-axisymmetric.edp", quoted)

# ---- 4. Bad input ----
for args, culprit in ((["-length", "0"], "-length"), (["-plane", "stress"], "-plane"),
                      (["-pullout", "1e-3"], "-pullout")):
    p = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-axisymmetric.edp", *args,
                        "-out", os.path.join(ROOT, "build", "test-results", "sleeve-axisymmetric-bad")],
                       cwd=ROOT, capture_output=True, text=True)
    check(p.returncode != 0 and culprit in p.stdout + p.stderr, f"{' '.join(args)}: fails naming {culprit}")

record("sleeve_axisymmetric", data)
finish()
