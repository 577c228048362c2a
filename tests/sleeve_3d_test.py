#!/usr/bin/python3
"""Verification of the sleeve-3d scene (the sleeve as a 3D solid, P1 tetrahedra, a quarter of the
section and half the length, rigid round pipe), at the paper's scale, against the axisymmetric
model, which solves the same problem (issue 49, its first check).

1. Frictionless, -length 0.1: the ring-averaged pressure at mid-length and the mean pressure over
   the bore at the end (all austenite, elastic) against sleeve-axisymmetric at nr 8 (whose own
   error, about 0.01 MPa, is a thirtieth of the 3D model's at nr 3), for the 3D meshes
   (nr, nt) = (2, 8) and (3, 12): the difference falls at an observed order in [1.6, 2.4] (P1's 2)
   for both, and is below 0.3 % at (3, 12). The first contact's and the reversion's end
   temperatures of the bore within 1.5 K of the axisymmetric run's.
2. Invariants on every run: equilibrium of the sleeve (K u - B s = H' r on the free dofs, 1e-9),
   no penetration, complementarity and the cone at every bore node (1e-9), the discrete heat
   balance at round-off, all austenite at the end.
3. Friction along z and the pull-out (-length 0.05 -mu 0.2 -pullout 1.2e-4 -pullsteps 3: the whole
   length, its end face z = 0 held axially, the pipe moved towards it), against sleeve-axisymmetric
   with the same options at nr 2: the clamping's invariants with friction (the cone at every node,
   the held face's axial force balancing the pipe's friction, 1e-9 of the normal force, the
   slip-threshold loop at work) and its mid-length pressure within 0.5 % of the axisymmetric one;
   the pull-out on the 3D cone (both tangential reactions free): the plateau F = mu N to 1e-8 with
   every pressing node slipping (so no circumferential friction is left at any node), F within
   0.5 % of the axisymmetric one, and at every increment the sleeve's axial balance (1e-9), the
   cone, complementarity and no penetration.
4. Bad input fails naming the option: -nt 1, -pipeE 2e11, -plane stress, -pullout without -mu,
   -pullout with -bend, -cone 1 without friction.
5. Bending (the half section, the pipe turned about y), frictionless, one run to 0.01 rad in 40
   increments of 2.5e-4 rad: over its first four (to 1e-3 rad) no node opens and the moment's
   increments are equal to 1e-8 (a linear problem); the half section's clamping within 1e-3 of the
   quarter's; at every increment the moment balance of the sleeve (its support on z = 0 against the
   contact forces, 1e-9), the cone, complementarity and no penetration. Run with -progressevery 0:
   a progress line for each step of the clamping and each increment of the bending, in order, the
   time left never negative and 0 at the last.
6. Bending with friction (mu 0.2, 0.01 rad): nodes open and sliding, the same invariants, the
   statuses decided with a margin (sealing nodes above 100 seal_tol of the largest reaction, open
   ones off by 100 seal_tol of the interference), and a moment above the frictionless one at the
   same angle, both resisting the rotation; the first sliding located at once (within a 64th of
   the increment: nodes on the cone at the end of the clamping). A leak path opening in a
   frictionless bending (-pipeB 0.04965) located inside its increment (a 64th of it), checked by
   runs bent to the bracket's ends in one increment (the state does not depend on the path without
   friction): no path at the lower end, one at the upper.
7. The plane hypothesis (-ends held: both end faces held axially and insulated; -length 0.02, the
   solution does not depend on z): every layer's pressure equal to 1e-6; on the round pipe the
   pressure converges to the plane-strain closed form (Lame) at an order in [1.6, 2.4] for
   (nr, nt) = (2, 8), (3, 12); on the elliptic pipe (-pipeA 0.0504 -pipeB 0.0505, the paper's) the
   mid-length ring average and the pressures weighted towards the x and the y axes converge to
   sleeve-elliptic's (plane strain, its default mesh, whose own error is about 0.006 MPa) at an order
   in [1.6, 2.4], within 0.4 % at (3, 12), higher towards the major axis y as in 2D.
8. Its own mesh error (-meshestimate 1 on the (2, 8) run: a companion on (1, 4)): the estimate is
   the two histories' L1 difference (tools/bench/oracles/curve_error.py) over (2 / 1 - 1), over the
   run, the transient and the reversion window, to 1e-9; against the curve's error measured from
   the axisymmetric nr 8 run (the round pipe's exact reduction) it errs high, as order 1 assumed
   against the curve's observed 1.7-1.8 makes it: effectivity over the transient in [1, 3].
9. The plane hypothesis with friction (-ends held -mu 0.2: the bore's rows (n, e_theta), u_z held by the
   ends) on the elliptic pipe, on the 2D's history (its a, held ends' default: the law's a is the 2D
   scene's there and the axisymmetric scene's with free ends; and the same 750 fixed steps): the
   invariants of 2., the ring-averaged pressure at mid-length converging to sleeve-elliptic-friction's
   at an order in [1.6, 2.4] (within 0.4 % at (3, 12)); the traction density node by node converging
   to the 2D's at an order >= 1.5 (its largest misfit); the ring-averaged tangential
   traction under 1 % of the pressure, and on the round pipe 0 (1e-9 of the pressure: the mesh's cuts
   are mirror-symmetric about every grid line theta_j, so a radial load moves no bore node around the
   ring; solid-3d.idp Solid3dMeshBuild). The pull-out's circumferential reactions likewise (1e-8),
   also while part of the bore sticks (its first increment: the nodes on the plane x = 0 exactly on it).
10. The clamping on Coulomb's cone (rows (n, e_theta, e_z), the step solver's cone: -length 0.02, nr 2,
   nt 8, -mu 0.2). On the round pipe (-cone 1), with the same 150 fixed steps, it is the clamping of
   the rows (n, e_z): the reactions within 1e-9 of the largest, the circumferential ones 0 to 1e-9. On
   the elliptic pipe with free ends (which takes the cone): the invariants of 2. on the step solver
   without a fall-back, friction around the section and along z at once (both filtered traction
   densities of contact-final.csv nonzero), the traction never above mu p (node by node: |r_t| <= mu r_n
   is 2.'s cone); the step control watches the cone's tractions at every step (a sliding node's
   direction has a history of its own): the e_theta density at 34 deg at mid-length within 10 % of
   -tol 1e-4's and its largest within 2 % (without the watch: 34 % and 5.6 %).
11. The scene's header quotes these runs' numbers as they come out (to the digits it prints; a
   number left behind when the solvers moved fails here, as README's in readme_numbers_test): the
   defaults' nodes and tetrahedra, the frictionless bending's moment and open nodes, the plane
   hypothesis's mid-length pressure, the short cone's steps and largest tractions.
Writes results/checks/sleeve_3d.json.
"""
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench", "oracles"))

from checklib import check, doc_quotes, finish, header_quotes, record, rows, run_scene, run_scene_captured, summary_of  # noqa: E402
from curve_error import curve_error  # noqa: E402
from plane_section import density_misfit, density_profile, towards_x, towards_y, weighted_pressure  # noqa: E402

COMMON = ["-quiet", "1"]


def run(scene, tag, *args, progress=False):
    """The scene's run; with progress, every progress line (-progressevery 0), its output kept."""
    if progress:
        out, done = run_scene_captured(scene, "sleeve-3d-" + tag, "-progressevery", "0", *args)
        check(done.returncode == 0, f"{scene} {' '.join(args)}: exit {done.returncode}: {done.stderr[-300:]}")
    else:
        out = run_scene(scene, "sleeve-3d-" + tag, *COMMON, *args)
    run_ = {"summary": summary_of(out), "history": rows(os.path.join(out, "history.csv")), "out": out}
    if progress:
        run_["stdout"] = done.stdout
    if os.path.exists(os.path.join(out, "pullout.csv")):
        run_["pullout"] = rows(os.path.join(out, "pullout.csv"))
    return run_


def invariants(label, run_):
    s = run_["summary"]
    check(s["equilibrium_residual"] <= 1e-9, f"{label}: equilibrium residual {s['equilibrium_residual']:.2e} <= 1e-9")
    check(s["contact_gap_min"] >= -1e-9, f"{label}: no penetration (smallest gap {s['contact_gap_min']:.2e} of the interference)")
    check(s["contact_complementarity_max"] <= 1e-9,
          f"{label}: r_n gap = 0 at every bore node ({s['contact_complementarity_max']:.2e})")
    check(s["contact_cone_excess_max"] <= 1e-9, f"{label}: |r_t| <= mu r_n at every bore node ({s['contact_cone_excess_max']:.2e})")
    check(s["axial_balance_residual"] <= 1e-9, f"{label}: axial balance {s['axial_balance_residual']:.2e} <= 1e-9")
    check(s["heat_balance_residual_max"] <= 1e-8, f"{label}: heat balance {s['heat_balance_residual_max']:.2e}")
    last = run_["history"][-1]
    check(float(last["fraction_austenite"]) == 1.0, f"{label}: all austenite at the end ({last['fraction_austenite']})")


def stage_invariants(label, b):
    """The contact laws at every increment of a stage after the clamping (summary's bending or pullout)."""
    key = "moment_balance_max" if "moment_balance_max" in b else "axial_balance_max"
    check(b[key] <= 1e-9, f"{label}: {key} (supports against contact) {b[key]:.2e}")
    check(b["cone_excess_max"] <= 1e-9, f"{label}: |r_t| <= mu r_n at every node and increment ({b['cone_excess_max']:.2e})")
    check(b["complementarity_max"] <= 1e-9, f"{label}: r_n gap = 0 ({b['complementarity_max']:.2e})")
    check(b["gap_min"] >= -1e-9, f"{label}: no penetration ({b['gap_min']:.2e} of the interference)")


def main():
    figures = {}
    axi = run("sleeve-axisymmetric", "axi8", "-nr", "8")["summary"]
    meshes = [(2, 8), (3, 12)]
    solid = {nr: run("sleeve-3d", f"nr{nr}", "-nr", str(nr), "-nt", str(nt), *(["-meshestimate", "1"] if nr == 2 else []))
             for nr, nt in meshes}
    for nr, _ in meshes:
        invariants(f"sleeve-3d nr {nr}", solid[nr])
    for key in ("final_pressure_mid", "final_pressure_mean"):
        d = [solid[nr]["summary"][key] - axi[key] for nr, _ in meshes]
        order = math.log(abs(d[0] / d[1])) / math.log(1.5) if d[1] != 0 else float("inf")
        figures[key] = {"axisymmetric_nr8": axi[key], "differences": d, "order": order}
        check(1.6 <= order <= 2.4, f"{key}: 3D - axisymmetric {d[0] / 1e6:.4f}, {d[1] / 1e6:.4f} MPa at nr 2, 3: "
              f"order {order:.2f} in [1.6, 2.4]")
        check(abs(d[1]) <= 3e-3 * axi[key], f"{key}: {abs(d[1]) / axi[key]:.2e} of it at nr 3 <= 3e-3")
    # contact-final.csv: the model's normal reactions sum to the summary's force on the whole bore
    # (times the model's copies), and an open node has no tangential density
    for nr, _ in meshes:
        nodes = rows(os.path.join(solid[nr]["out"], "contact-final.csv"))
        total = 8 * sum(float(r["normal_force"]) for r in nodes)
        reported = solid[nr]["summary"]["final_normal_force_total"]
        check(len(nodes) == solid[nr]["summary"]["contact_nodes"] and abs(total / reported - 1) <= 1e-9
              and all(float(r["tangential_density"]) == 0 for r in nodes if float(r["normal_force"]) == 0),
              f"sleeve-3d nr {nr}: contact-final.csv's {len(nodes)} nodes, 8 x their normal reactions {total:.6g} N = "
              f"the summary's {reported:.6g} N")
    # the filtered nodal pressure: on the round pipe every node reads its ring's mean (the uniform
    # pressure), where one node's reaction over its area spreads by a fifth around the ring
    for nr, _ in meshes:
        bore = rows(os.path.join(solid[nr]["out"], "bore-final.csv"))
        spread = max(max(abs(float(r[k]) / float(r["pressure"]) - 1) for k in ("pressure_min", "pressure_max")) for r in bore)
        raw = solid[nr]["summary"]["final_pressure_node_max"] / solid[nr]["summary"]["final_pressure_node_min"] - 1
        figures[f"filtered_nodal_spread_nr{nr}"] = {"filtered": spread, "unfiltered_max_over_min": raw}
        check(spread <= 1e-9 and raw >= 0.1,
              f"sleeve-3d nr {nr}, round pipe: the filtered nodal pressures equal their ring's mean to {spread:.1e} "
              f"(unfiltered, the nodes' max over min {1 + raw:.3f})")
    for key in ("T_inner_first_contact", "T_inner_austenite"):
        gap = abs(solid[3]["summary"][key] - axi[key])
        figures[key] = {"axisymmetric_nr8": axi[key], "solid_nr3": solid[3]["summary"][key]}
        check(gap <= 1.5, f"{key}: 3D nr 3 {solid[3]['summary'][key]:.2f} K, axisymmetric {axi[key]:.2f} K (within 1.5 K)")

    # 8. the run's own mesh error: the companion's curve, and the error measured against the axisymmetric one
    s, out = solid[2]["summary"], solid[2]["out"]
    again = curve_error(os.path.join(out, "mesh-estimate", "history.csv"), os.path.join(out, "history.csv"))
    pairs = [(s["mesh_error_estimate"], again["l1"]), (s["mesh_error_estimate_transient"], again["l1_transient"]),
             (s["mesh_error_estimate_window"], again["l1_reversion"])]
    worst = max(abs(a / b - 1) for a, b in pairs)
    check((s["mesh_estimate_layers"], s["mesh_estimate_coarse_layers"], s["mesh_estimate_order"]) == (2, 1, 1) and worst < 1e-9,
          f"-meshestimate 1 on (2, 8): the estimate against (1, 4) is the two histories' L1 difference over the run, "
          f"transient and window, to {worst:.1e}")
    measured = curve_error(os.path.join(out, "history.csv"), os.path.join(os.path.dirname(out), "sleeve-3d-axi8", "history.csv"))
    effectivity = s["mesh_error_estimate_transient"] / measured["l1_transient"]
    figures["mesh_estimate"] = {"estimate_transient": s["mesh_error_estimate_transient"],
                                "error_transient_against_axisymmetric_nr8": measured["l1_transient"],
                                "effectivity_transient": effectivity}
    check(1 <= effectivity <= 3, f"-meshestimate 1: {100 * s['mesh_error_estimate_transient']:.3f} % over the transient "
          f"against {100 * measured['l1_transient']:.3f} % measured from the axisymmetric nr 8: effectivity "
          f"{effectivity:.2f} in [1, 3] (order 1 assumed, errs high)")

    # 3. friction along z, then the pull-out: the whole length on its shoulder, against the axisymmetric model
    # (4e-5 m increments: part of the bore sticks at the first, all of it slides at the third)
    pull_args = ("-length", "0.05", "-mu", "0.2", "-pullout", "1.2e-4", "-pullsteps", "3")
    fr = run("sleeve-3d", "pull", *pull_args)
    invariants("sleeve-3d " + " ".join(pull_args), fr)
    axi_fr = run("sleeve-axisymmetric", "axi2-pull", "-nr", "2", *pull_args)
    s = fr["summary"]
    check(s["slip_threshold_iterations_max"] > 1, f"-mu 0.2: the slip-threshold loop iterates ({s['slip_threshold_iterations_max']})")
    rel = (s["final_pressure_mid"] - axi_fr["summary"]["final_pressure_mid"]) / axi_fr["summary"]["final_pressure_mid"]
    last, axi_last = fr["pullout"][-1], axi_fr["pullout"][-1]
    F, N, F_axi = float(last["pullout_force"]), float(last["normal_force_total"]), float(axi_last["pullout_force"])
    figures["pullout"] = {"mid_3d": s["final_pressure_mid"], "mid_axisymmetric_nr2": axi_fr["summary"]["final_pressure_mid"],
                          "mid_relative": rel, "force_3d": F, "force_axisymmetric_nr2": F_axi,
                          "force_relative": (F - F_axi) / F_axi, "force_over_mu_normal": [float(r["force_over_mu_normal"]) for r in fr["pullout"]],
                          "circumferential_over_normal": [float(r["circumferential_over_normal"]) for r in fr["pullout"]]}
    check(abs(rel) <= 5e-3, f"clamped with friction, the whole length: mid-length {s['final_pressure_mid'] / 1e6:.3f} MPa, "
          f"axisymmetric nr 2 {axi_fr['summary']['final_pressure_mid'] / 1e6:.3f} MPa ({rel:+.2%}, within 0.5 %)")
    plateau = abs(F - 0.2 * N) / (0.2 * N)
    check(plateau <= 1e-8 and int(last["nodes_slipping"]) == int(last["nodes_in_contact"]) > 0,
          f"pull-out plateau: F {F / 1e3:.3f} kN = mu N ({plateau:.1e} <= 1e-8), {last['nodes_slipping']}/"
          f"{last['nodes_in_contact']} pressing nodes slipping")
    check(abs(F - F_axi) <= 5e-3 * F_axi, f"pull-out force {F / 1e3:.3f} kN, axisymmetric nr 2 {F_axi / 1e3:.3f} kN "
          f"({(F - F_axi) / F_axi:+.2%}, within 0.5 %)")
    stage_invariants("-pullout 1.2e-4", s["pullout"])
    # the circumferential reactions, 0 by symmetry, also while part of the bore sticks: the sticking nodes on the
    # plane x = 0 once had a circumferential direction 6e-17 off their held u_x (cos(pi / 2)), which the cone took
    # for a free motion (9 %; psor_cone now refuses such a compliance)
    first = fr["pullout"][0]
    check(int(first["nodes_slipping"]) < int(first["nodes_in_contact"])
          and s["pullout"]["circumferential_over_normal_max"] <= 1e-8,
          f"-pullout 1.2e-4: {first['nodes_slipping']} of {first['nodes_in_contact']} nodes slipping at the first increment; "
          f"the circumferential reactions at most {s['pullout']['circumferential_over_normal_max']:.2e} of the largest "
          f"(0 by symmetry) at every increment")
    # The gross slip (every pressing node slipping) located inside its increment by bisection; the
    # pull-out's path does not depend on its increments (every node's slip only grows), so runs
    # pulled to the bracket's ends in one increment must find the bore not all slipping at the
    # lower end (unless it is the stage's start) and all slipping at the upper.
    p3 = s["pullout"]
    lo_s, hi_s = p3["all_slip_located"] or [None, None]
    dw = 1.2e-4 / 3
    k = p3["all_slip_from"]
    check(lo_s is not None and (k - 1) * dw - 1e-15 <= lo_s < hi_s <= k * dw + 1e-15
          and abs(hi_s - lo_s - dw / 2 ** p3["located_probes"]) <= 1e-15,
          f"-pullout 1.2e-4: the gross slip in increment {k}, located in ({lo_s}, {hi_s}] m")
    if lo_s is not None:
        ends = {name: run("sleeve-3d", f"pull-{name}", *pull_args[:4], "-pullout", repr(end), "-pullsteps", "1")["pullout"][-1]
                for name, end in (("lo", lo_s), ("hi", hi_s)) if end > 0}
        all_at = {name: int(r["nodes_slipping"]) == int(r["nodes_in_contact"]) for name, r in ends.items()}
        check(all_at.get("lo", False) is False and all_at["hi"],
              f"pulled in one increment: all slipping at {lo_s} m {all_at.get('lo')}, at {hi_s} m {all_at['hi']}")

    # A pull-out below the solves' resolution (1e-14 m): no node slips (the solves' round-off moved
    # every node by more than 1e-6 of it: all 99 read as "slipping" at 0.87 of mu N before the slip floor,
    # contact.idp ContactSlipFloor; checked by setting it to 0)
    tiny = run("sleeve-3d", "pull-tiny", *pull_args[:4], "-pullout", "1e-14", "-pullsteps", "3")
    check(all(int(r["nodes_slipping"]) == 0 and float(r["force_over_mu_normal"]) < 1 for r in tiny["pullout"])
          and tiny["summary"]["pullout"]["all_slip_from"] is None,
          f"-pullout 1e-14: no node slipping at any increment ({[r['nodes_slipping'] for r in tiny['pullout']]}), "
          f"F / (mu N) {[round(float(r['force_over_mu_normal']), 4) for r in tiny['pullout']]}, no gross slip")

    # 5. bending, frictionless, before any node opens (to 1e-3 rad): the problem is linear, so the
    # moment grows by the same amount at every increment (the clamped state carries no moment of its
    # own: the half section's cuts are mirror-symmetric about x = 0). One run to 1e-2 rad in 40
    # increments: its first four (2.5e-4 rad each, to 1e-3) are a -bend 1e-3 -bendsteps 4 run's, byte
    # for byte; its end is 6.'s frictionless moment (frictionless contact: the state at an angle does
    # not depend on the increments that led there; 10 increments gave the same moment).
    # With every progress line (-progressevery 0): one for each step of the clamping, then one for
    # each increment of the bending, in order, the time left never negative and 0 at the last.
    b0 = run("sleeve-3d", "bend0", "-bend", "1e-2", "-bendsteps", "40", progress=True)
    lines = b0["stdout"].splitlines()
    shown = [int(m.group(1)) for m in (re.match(r"sleeve-3d: step (\d+), t ", ln) for ln in lines) if m]
    increments = [m for m in (re.match(r"sleeve-3d: bending increment (\d+)/40, about (\S+) s left$", ln) for ln in lines) if m]
    left = [float(m.group(2)) for m in increments]
    check(shown == list(range(1, b0["summary"]["n_steps"] + 1)),
          f"-progressevery 0: a progress line for each of the {b0['summary']['n_steps']} steps, in order ({len(shown)} lines)")
    check([int(m.group(1)) for m in increments] == list(range(1, 41)) and min(left) >= 0 and left[-1] == 0,
          f"-progressevery 0: a line for each of the bending's 40 increments, in order ({len(increments)} lines), "
          f"the time left >= 0 and 0 at the last ({left[-1] if left else None})")
    bend0 = [r for r in rows(os.path.join(b0["out"], "bend.csv")) if float(r["angle"]) <= 1e-3 * (1 + 1e-9)]
    steps = [float(r["moment"]) for r in bend0]
    d = [b - a for a, b in zip(steps, steps[1:])]
    figures["bending_frictionless"] = {"moments": steps}
    check(len(bend0) == 4 and all(int(r["nodes_open"]) == 0 for r in bend0),
          f"-bend 1e-2 -bendsteps 40: no bore node opens over the {len(bend0)} increments to 1e-3 rad (4)")
    check(len(d) == 3 and max(abs(x - d[0]) for x in d) <= 1e-8 * abs(d[0]),
          f"frictionless, to 1e-3 rad: the moment's increments {', '.join(f'{x:.6f}' for x in d)} N m equal (linear) to 1e-8")
    half = b0["summary"]["final_pressure_mid"]
    quarter = solid[2]["summary"]["final_pressure_mid"]
    check(abs(half - quarter) <= 1e-3 * quarter, f"the half section's clamping: mid-length {half / 1e6:.4f} MPa, the "
          f"quarter's {quarter / 1e6:.4f} MPa (within 1e-3)")

    # 6. bending with friction (mu 0.2, 0.01 rad in one increment) against the frictionless one
    bent = run("sleeve-3d", "bend-mu", "-mu", "0.2", "-bend", "1e-2", "-bendsteps", "1")
    b1 = bent["summary"]["bending"]
    nodes = rows(os.path.join(bent["out"], "bore-5-bent.csv"))
    open_nodes = [r for r in nodes if float(r["pressure"]) == 0]
    check(open_nodes and all(float(r["pressure_filtered"]) == 0 for r in open_nodes)
          and all(float(r["pressure_filtered"]) > 0 for r in nodes if float(r["pressure"]) > 0),
          f"-mu 0.2 -bend 1e-2: the filtered pressure is 0 at the {len(open_nodes)} open nodes, > 0 at the pressing ones")
    f0 = b0["summary"]["bending"]  # 5.'s run: frictionless, 1e-2 rad
    stage_invariants("-mu 0.2 -bend 1e-2", b1)
    stage_invariants("-bend 1e-2 -bendsteps 40 (frictionless)", f0)
    figures["bending_friction"] = {"moment_mu": b1["moment_final"], "moment_frictionless": f0["moment_final"],
                                   "open_mu": b1["nodes_open_final"], "sliding_mu": b1["nodes_sliding_final"]}
    check(b1["nodes_open_final"] > 0 and b1["nodes_sliding_final"] > 0,
          f"-mu 0.2 -bend 1e-2: nodes open ({b1['nodes_open_final']}) and sliding ({b1['nodes_sliding_final']})")
    # The statuses decided by the load, not by the solvers: every sealing node presses with more
    # than 100 seal_tol of the largest reaction, every open one stands off by more than 100
    # seal_tol of the interference (a node at the threshold went either way between two solvers).
    check(b1["margin_sealing"] >= 100 * b1["seal_tol"] and b1["margin_open"] >= 100 * b1["seal_tol"],
          f"-mu 0.2 -bend 1e-2: the statuses' margins, sealing {b1['margin_sealing']:.2e} of the largest reaction and "
          f"open {b1['margin_open']:.2e} of the interference, >= 100 x seal_tol {b1['seal_tol']:.0e}")
    check(b1["moment_final"] > f0["moment_final"] > 0,
          f"-bend 1e-2: the moment with friction {b1['moment_final'] / 1e3:.3f} kN m above the frictionless "
          f"{f0['moment_final'] / 1e3:.3f} kN m, both > 0 (against the rotation)")
    # The first sliding, located inside its increment by bisection (a 64th of it): at once, since
    # the free ends' clamping leaves nodes on the cone (their |r_t| = mu r_n).
    located = b1["first_sliding_located"]
    check(b1["nodes_on_cone_at_clamping"] > 0 and located == [0, 1e-2 / 2 ** b1["located_probes"]]
          and abs(b1["first_sliding_located_moments"][0]) <= 1e-9 * b1["moment_final"]
          and 0 < b1["first_sliding_located_moments"][1] < b1["moment_final"],
          f"-mu 0.2 -bend 1e-2: the first sliding at once, located in ({located[0]}, {located[1]}] rad "
          f"({b1['first_sliding_located_moments'][1]:.4g} N m at its end), {b1['nodes_on_cone_at_clamping']} nodes on the "
          f"cone at the end of the clamping")

    # 6b. a leak path opening in the bending, located in its increment (frictionless: the state at an
    # angle does not depend on the path, so a run bent to each end of the located bracket in one
    # increment must find no path at the lower end and one at the upper)
    leaky = ("-pipeB", "0.04965", "-bend")
    lk = run("sleeve-3d", "bend-leak", *leaky, "1e-2", "-bendsteps", "40")["summary"]["bending"]
    lo, hi = lk["leak_path_located"] or [None, None]
    width = 1e-2 / 40 / 2 ** lk["located_probes"]
    check(lo is not None and lk["leak_path_angle_before"] <= lo < hi <= lk["leak_path_angle"]
          and abs(hi - lo - width) <= 1e-12 and not lk["leak_path_at_clamping"],
          f"-pipeB 0.04965 -bend 1e-2: a leak path in the increment ({lk['leak_path_angle_before']}, "
          f"{lk['leak_path_angle']}] rad, located in ({lo}, {hi}] (width {width:.3g})")
    if lo is not None:
        at = {end: run("sleeve-3d", f"bend-leak-{name}", *leaky, repr(end), "-bendsteps", "1")["summary"]["bending"]
              for name, end in (("lo", lo), ("hi", hi))}
        check(at[lo]["leak_path_angle"] is None and at[hi]["leak_path_angle"] == hi,
              f"bent in one increment: no leak path at {lo} rad ({at[lo]['nodes_open_final']} nodes open), one at {hi} "
              f"({at[hi]['nodes_open_final']})")

    # 7. the plane hypothesis: held ends, the round pipe against Lame, the elliptic one against sleeve-elliptic
    plane = ("-ends", "held", "-length", "0.02", "-Ri", "0.05", "-pipeA", "0.0504")
    held = {(pb, nr): run("sleeve-3d", f"held-{pb}-nr{nr}", *plane, "-pipeB", pb, "-nr", str(nr), "-nt", str(nt))["summary"]
            for pb in ("0", "0.0505") for nr, nt in meshes}
    for (pb, nr), s in held.items():
        check(abs(s["final_pressure_end"] - s["final_pressure_mid"]) <= 1e-6 * s["final_pressure_mid"],
              f"-ends held -pipeB {pb} nr {nr}: the end layer's pressure {s['final_pressure_end'] / 1e6:.6f} MPa = mid-length's "
              f"{s['final_pressure_mid'] / 1e6:.6f} (every section alike)")
    lame = held["0", 2]["plane_strain_pressure"]
    d = [held["0", nr]["final_pressure_mid"] - lame for nr, _ in meshes]
    order = math.log(abs(d[0] / d[1])) / math.log(1.5)
    figures["plane_strain_round"] = {"lame": lame, "differences": d, "order": order}
    check(1.6 <= order <= 2.4, f"-ends held, round pipe: 3D - Lame {d[0] / 1e6:.4f}, {d[1] / 1e6:.4f} MPa at nr 2, 3: order "
          f"{order:.2f} in [1.6, 2.4]")
    ell = run_scene("sleeve-elliptic", "sleeve-3d-elliptic-2d", *COMMON, "-scale", "paper", "-tol", "1e-2")
    nodes = rows(os.path.join(ell, "contact-final.csv"))
    plane2d = {"final_pressure_mid": weighted_pressure(nodes, lambda x, y: 1.0),
               "final_pressure_mid_x": weighted_pressure(nodes, towards_x),
               "final_pressure_mid_y": weighted_pressure(nodes, towards_y)}
    figures["plane_strain_elliptic"] = {"sleeve_elliptic": plane2d}
    for key, ref in plane2d.items():
        d = [held["0.0505", nr][key] - ref for nr, _ in meshes]
        order = math.log(abs(d[0] / d[1])) / math.log(1.5) if d[1] != 0 else float("inf")
        figures["plane_strain_elliptic"][key] = {"differences": d, "order": order}
        check(1.6 <= order <= 2.4 and abs(d[1]) <= 4e-3 * ref,
              f"-ends held, elliptic pipe, {key}: 3D - sleeve-elliptic {d[0] / 1e6:.4f}, {d[1] / 1e6:.4f} MPa at nr 2, 3 "
              f"(of {ref / 1e6:.3f}): order {order:.2f} in [1.6, 2.4], within 0.4 % at nr 3")
    s3 = held["0.0505", 3]
    check(s3["final_pressure_mid_y"] > s3["final_pressure_mid_x"] and plane2d["final_pressure_mid_y"] > plane2d["final_pressure_mid_x"],
          f"elliptic: higher towards the major axis y, 3D nr 3 {s3['final_pressure_mid_y'] / 1e6:.3f} > "
          f"{s3['final_pressure_mid_x'] / 1e6:.3f} MPa, 2D {plane2d['final_pressure_mid_y'] / 1e6:.3f} > "
          f"{plane2d['final_pressure_mid_x'] / 1e6:.3f} MPa")

    # 9. the plane hypothesis with friction (-mu 0.2: the rows (n, e_theta), u_z held by the ends), the elliptic
    #    pipe against sleeve-elliptic-friction, on one history: the 2D's law (held ends are plane strain and take
    #    the 2D's a by default, where free ends' 1.3 a would open the ring 1.3 times as far) and the same 750 fixed
    #    steps (friction's final state is its path's: with their own adaptive steps and a the two tractions
    #    disagreed in sign)
    history = ("-tol", "0", "-steps", "750")
    fr = {nr: run("sleeve-3d", f"held-mu-nr{nr}", *plane, "-pipeB", "0.0505", "-mu", "0.2", "-nr", str(nr), "-nt", str(nt),
                  *history) for nr, nt in meshes}
    for nr, _ in meshes:
        invariants(f"-ends held -pipeB 0.0505 -mu 0.2 nr {nr}", fr[nr])
        check(fr[nr]["summary"]["contact_tangent"] == "e_theta", f"-ends held -mu 0.2 nr {nr}: the bore's tangent e_theta "
              f"({fr[nr]['summary']['contact_tangent']})")
    ell_fr = run_scene("sleeve-elliptic-friction", "sleeve-3d-elliptic-friction-2d", *COMMON, "-scale", "paper", *history)
    nodes_fr = rows(os.path.join(ell_fr, "contact-final.csv"))
    a2d, a_free, a_axi = (summary_of(ell_fr)["parameters"]["a"], solid[2]["summary"]["parameters"]["a"],
                          axi["parameters"]["a"])
    a_held = [fr[nr]["summary"]["parameters"]["a"] for nr, _ in meshes]
    check(all(a == a2d for a in a_held) and a_free == a_axi != a2d,
          f"the law's a by default: -ends held {a_held} = sleeve-elliptic-friction's {a2d} (plane strain), free ends "
          f"{a_free} = sleeve-axisymmetric's {a_axi}")
    ref = weighted_pressure(nodes_fr, lambda x, y: 1.0)
    traction2d = weighted_pressure(nodes_fr, lambda x, y: 1.0, "tangential_force")
    d = [fr[nr]["summary"]["final_pressure_mid"] - ref for nr, _ in meshes]
    order = math.log(abs(d[0] / d[1])) / math.log(1.5) if d[1] != 0 else float("inf")
    figures["plane_strain_elliptic_friction"] = {"sleeve_elliptic_friction": ref, "differences": d, "order": order}
    check(1.6 <= order <= 2.4 and abs(d[1]) <= 4e-3 * ref,
          f"-ends held -mu 0.2, elliptic pipe: ring-averaged pressure, 3D - sleeve-elliptic-friction {d[0] / 1e6:.4f}, "
          f"{d[1] / 1e6:.4f} MPa at nr 2, 3 (of {ref / 1e6:.3f}): order {order:.2f} in [1.6, 2.4], within 0.4 % at nr 3")
    # the tangential traction: on the round pipe 0 by symmetry, which the mesh keeps (its cuts mirror-symmetric
    # about every grid line theta_j: no circumferential motion of a bore node under a radial load)
    round_fr = run("sleeve-3d", "held-mu-round", *plane, "-mu", "0.2", "-nr", "2", "-nt", "8")["summary"]
    traction = [fr[nr]["summary"]["final_traction_mid"] for nr, _ in meshes]
    figures["plane_strain_elliptic_friction"].update({"traction_mid": traction, "traction_2d": traction2d,
                                                      "traction_round": round_fr["final_traction_mid"]})
    # the filtered traction node by node (contact-final.csv's tangential_density, mid-length) against 2D's,
    # interpolated along its 91 nodes at the 3D nodes' angles: on one history it converges at P1's order
    profile2d = density_profile(nodes_fr)
    misfit = []
    for nr, _ in meshes:
        mid = rows(os.path.join(fr[nr]["out"], "contact-final.csv"))
        figures["plane_strain_elliptic_friction"][f"traction_density_mid_nr{nr}"] = density_profile(mid, mid_length=True)
        misfit.append(density_misfit(nodes_fr, mid))
    figures["plane_strain_elliptic_friction"]["traction_density_2d"] = profile2d
    figures["plane_strain_elliptic_friction"]["traction_density_misfit"] = misfit
    largest2d = max(abs(t) for _, t in profile2d)
    traction_order = math.log(misfit[0] / misfit[1]) / math.log(1.5) if misfit[1] > 0 else float("inf")
    check(traction_order >= 1.5 and misfit[1] < largest2d,
          f"-ends held -mu 0.2, one history: the traction density node by node, 3D - 2D at most {misfit[0] / 1e6:.3f}, "
          f"{misfit[1] / 1e6:.3f} MPa at nr 2, 3: order {traction_order:.2f} >= 1.5, below the 2D's largest "
          f"{largest2d / 1e6:.3f} MPa")
    check(round_fr["final_traction_mid"] <= 1e-9 * round_fr["final_pressure_mid"],
          f"-ends held -mu 0.2, round pipe: the ring-averaged |traction| {round_fr['final_traction_mid']:.2e} Pa <= 1e-9 of "
          f"the pressure (0 by symmetry; the mesh's cuts once left 13 MPa)")
    check(all(0 < t <= 0.01 * ref for t in traction), f"-ends held -mu 0.2, elliptic pipe: |traction| {traction[0] / 1e6:.3f}, "
          f"{traction[1] / 1e6:.3f} MPa at nr 2, 3, under 1 % of the pressure (2D: {traction2d / 1e6:.3f} MPa)")

    # 10. the clamping on Coulomb's cone
    cone_args = ("-length", "0.02", "-nr", "2", "-nt", "8", "-mu", "0.2")
    two_rows = run("sleeve-3d", "cone-off", *cone_args, "-tol", "0", "-steps", "150")
    cone_round = run("sleeve-3d", "cone-round", *cone_args, "-cone", "1", "-tol", "0", "-steps", "150")
    cone_ellipse = run("sleeve-3d", "cone-ellipse", *cone_args, "-pipeB", "0.0504")
    cone_fine = run("sleeve-3d", "cone-ellipse-fine", *cone_args, "-pipeB", "0.0504", "-tol", "1e-4")
    a = rows(os.path.join(cone_round["out"], "contact-final.csv"))
    b = rows(os.path.join(two_rows["out"], "contact-final.csv"))
    largest = max(float(r["normal_force"]) for r in b)
    dn = max(abs(float(x["normal_force"]) - float(y["normal_force"])) for x, y in zip(a, b)) / largest
    dz = max(abs(float(x["tangential_force_z"]) - float(y["tangential_force"])) for x, y in zip(a, b)) / largest
    dt = max(abs(float(x["tangential_force_theta"])) for x in a) / largest
    figures["cone"] = {"round_normal_difference": dn, "round_axial_difference": dz, "round_theta_largest": dt}
    check(cone_round["summary"]["contact_tangent"] == "cone" and two_rows["summary"]["contact_tangent"] == "e_z"
          and len(a) == len(b) and dn <= 1e-9 and dz <= 1e-9 and dt <= 1e-9,
          f"-mu 0.2, round pipe, 150 fixed steps: the cone's clamping (-cone 1) is the rows (n, e_z)'s: reactions "
          f"within {dn:.1e} (normal) and {dz:.1e} (axial) of the largest, circumferential {dt:.1e} (each <= 1e-9)")
    invariants("-mu 0.2 -pipeB 0.0504, free ends (the cone)", cone_ellipse)
    se = cone_ellipse["summary"]
    nodes = rows(os.path.join(cone_ellipse["out"], "contact-final.csv"))
    theta = max(abs(float(r["tangential_density_theta"])) for r in nodes)
    axial = max(abs(float(r["tangential_density_z"])) for r in nodes)
    pressure = max(float(r["pressure_filtered"]) for r in nodes)
    figures["cone"].update({"ellipse_traction_theta_max": theta, "ellipse_traction_z_max": axial,
                            "ellipse_pressure_max": pressure, "ellipse_steps": se["n_steps"],
                            "ellipse_pressure_mid": se["final_pressure_mid"]})
    check(se["contact_tangent"] == "cone" and se["step_solver"] == "newton" and se["step_fallbacks"] == 0
          and 0 < theta and 0 < axial <= 0.2 * pressure * (1 + 1e-9),
          f"-mu 0.2 -pipeB 0.0504, free ends: the clamping on the cone by the step solver ({se['step_solver']}, "
          f"{se['step_fallbacks']} fall-backs), friction around the section and along z at once: filtered traction "
          f"densities up to {theta / 1e6:.3f} MPa (e_theta) and {axial / 1e6:.2f} MPa (e_z, <= mu p = "
          f"{0.2 * pressure / 1e6:.2f} MPa)")
    fine = rows(os.path.join(cone_fine["out"], "contact-final.csv"))
    def theta_at(table, angle):
        return next(float(r["tangential_density_theta"]) for r in table if float(r["z"]) == 0
                    and abs(float(r["angle_deg"]) - angle) < 1e-6)
    mid, mid_fine = theta_at(nodes, 33.75), theta_at(fine, 33.75)
    theta_fine = max(abs(float(r["tangential_density_theta"])) for r in fine)
    figures["cone"].update({"ellipse_theta_34deg": mid, "ellipse_theta_34deg_tol1e-4": mid_fine,
                            "ellipse_traction_theta_max_tol1e-4": theta_fine,
                            "ellipse_steps_tol1e-4": cone_fine["summary"]["n_steps"]})
    check(se["step_contact_watched_steps"] >= se["n_steps"] - 3 and abs(mid - mid_fine) <= 0.1 * abs(mid_fine)
          and abs(theta - theta_fine) <= 0.02 * theta_fine,
          f"-mu 0.2 -pipeB 0.0504: the step control watches the cone's tractions ({se['step_contact_watched_steps']} of "
          f"{se['n_steps']} steps): the e_theta density at 34 deg, mid-length, {mid / 1e6:.4f} MPa against -tol 1e-4's "
          f"{mid_fine / 1e6:.4f} (within 10 %), its largest {theta / 1e6:.4f} against {theta_fine / 1e6:.4f} (within 2 %)")

    # 11. the header's numbers are these runs'
    defaults, f0 = solid[2]["summary"], b0["summary"]["bending"]
    quoted = [f"{defaults['nodes']} nodes, {defaults['tetrahedra']} tetrahedra",
              f"{f0['moment_final'] / 1e3:.2f} kN m frictionless ({f0['nodes_open_final']} of "
              f"{b0['summary']['contact_nodes']} bore nodes open)",
              f"{held['0.0505', 2]['final_pressure_mid'] / 1e6:.2f} MPa ring-averaged at mid-length",
              f"-length 0.02 -nr 2 -nt 8: {se['n_steps']} steps",
              f"from the start: {b1['nodes_on_cone_at_clamping']} nodes end the clamping on the cone", f"tractions up to {theta / 1e6:.2f} MPa around the section and "
              f"{axial / 1e6:.1f} MPa along z (mu p {0.2 * pressure / 1e6:.1f} MPa)"]
    figures["header_quoted"] = quoted
    header_quotes("edp/scenes/sleeve-3d.edp", quoted)
    # and README's, of the same runs
    fine = solid[3]["summary"]
    readme = [f"final ring-averaged pressure at mid-length {defaults['final_pressure_mid'] / 1e6:.2f} MPa at its default "
              f"2 x 8 x 10 cells ({defaults['nodes']} nodes", f"{fine['final_pressure_mid'] / 1e6:.2f} at 3 x 12 x 15",
              f"{f0['moment_final'] / 1e3:.2f} kN m frictionless",
              f"{f0['nodes_open_final']} of {b0['summary']['contact_nodes']} bore nodes open"
              + (", no leak path" if f0.get("leak_path_angle") is None else "")]
    figures["readme_quoted"] = readme
    doc_quotes("README.md", readme)

    # 4. bad input
    for args, culprit in ((["-nt", "1"], "-nt"), (["-pipeE", "2e11"], "-pipeE"), (["-plane", "stress"], "-plane"),
                          (["-pullout", "1e-4"], "-mu"), (["-mu", "0.2", "-pullout", "1e-4", "-bend", "1e-3"], "-bend"),
                          (["-cone", "1"], "-cone"), (["-cone", "2", "-mu", "0.2"], "-cone"),
                          (["-ends", "held", "-bend", "1e-3"], "-ends")):
        _, done = run_scene_captured("sleeve-3d", "sleeve-3d-bad", *COMMON, *args)
        check(done.returncode != 0 and culprit in done.stderr + done.stdout,
              f"{' '.join(args)} refused naming {culprit} (exit {done.returncode})")
    record("sleeve_3d", figures)
    finish()


if __name__ == "__main__":
    main()
