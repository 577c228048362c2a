#!/usr/bin/python3
"""Hard cases of the sleeve program (issue 6, item 4; docs/stability.md): each converges to a
checked answer or fails loudly naming the loop or the culprit. Coarse mesh (6 layers), 300 steps
unless said otherwise; about 40 s.

1. Grazing contact: pipe radius equal to the ring's inner radius (interference 0), and +-0.1 um.
   Interference 0: final pressure 0 (Lame with delta = 0) to 1e-9 of the 55 um fit, no
   penetration, complementarity, no change of the contact set once the ring is austenite for good;
   +0.1 um: the final pressure is the 55 um one scaled by 0.1/55 (the final state is linear
   elastic) to 1e-6; -0.1 um: never touches. sleeve-3d at interference 0 (nr 1, nt 4, L 4 cm):
   runs through, final pressure 0, its laws; bent 1e-3 rad in 2 increments, the leak path is the
   clamping's (nothing sealed: the leak detection's positive case, said as before any bending). A 0.4 mm clearance (sleeve-radial,
   -axisymmetric, -3d): no contact, the closed forms 0 (not the formulas' negative pressures), no
   relative error claimed, nor a time or mesh error of the force that is not there (no companion run).
2. Friction mu = 0.5 and 1.0 beside 0 and 0.2 (sleeve-elliptic-friction): every node inside the
   Coulomb cone |t| <= mu n (1 + 1e-8), Signorini from the end displacement (no penetration,
   gap 0 where the normal force is > 0), a node that slipped over the last step is on the cone
   with its force opposing the slip; the mean pressure of mu = 0.2, 0.5, 1.0 is mu = 0's (within
   1e-4: the fit's axisymmetric mode is set by the mean interference, friction only redistributes).
3. Large steps: 1500, 150 and 15 steps each end all austenite (so the final state is linear
   elastic) within 1e-3 of Lame's shrink-fit pressure (coarse mesh); 150 and 15 steps against
   1500: the same final pressure to 1e-9; iteration counts and what the curve loses are recorded.
4. Single precision: tests/sleeve_single_precision_test.py (final pressure check added there).
5. Random threshold, spread 20 K: the default fraction model runs through with no reversal and no
   pressure zigzag and ends at the homogeneous final pressure. The paper's on/off model
   (-phasemodel onoff) fails loudly (the heat-phase fixed point, its iteration count and residual
   named, and the -fprelax hint); with -fprelax 1 every cycle is resolved to the fixed-point
   tolerance and the run ends at the homogeneous final pressure; without a cycle -fprelax 1
   changes no byte.
6. Slivers (meshes/sliver.geo): a layer of quality 0.011 converges to Lame within 2e-3; a layer of
   quality 9e-6 (area 7e-6 of the mean) is rejected up front naming the triangle; raising
   -meshminquality above 0.011 rejects the first one too.
7. A friction coefficient of 1e-300 (sleeve-3d pull-out): the run writes its subnormal forces (its
   summary's writer divided by zero on them).
docs/stability.md holds the tables of cases 1-3 as this test formats them (stability_rows).
Writes results/checks/hard_cases.json.
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools", "bench", "oracles"))

from checklib import KELVIN_AT_0C, REDUCED, ROOT, SLEEVE_SCENES, TEST_RESULTS, celsius, check, doc_quotes, finish, own_error_line, read_json, record, run_scene, run_scene_captured, sci, sleeve_outputs, sleeve_geometry  # noqa: E402
from lame import lame_pressure  # noqa: E402

COARSE = ["-mesh", "meshes/sleeve-coarse.msh", "-quiet", "1"]
RING_INNER = sleeve_geometry()["Ri"]  # m: meshes/sleeve-geometry.txt, the meshes' ring
THICKNESS = sleeve_geometry()["Hr"]  # m
INTERFERENCE = sleeve_geometry()["pipe"] - RING_INNER  # m, the sleeve scenes' default (55 um)


def run_failing(scene, out_name, *args):
    """Runs a scene that may fail; returns (exit code, stderr)."""
    out = os.path.join(TEST_RESULTS, out_name)
    scale = REDUCED if scene in SLEEVE_SCENES and "-scale" not in args else []
    done = subprocess.run([os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", "-out", out, *scale, *args],
                          cwd=ROOT, capture_output=True, text=True)
    return done.returncode, done.stderr + done.stdout


def ellipse_gap(px, py, A, B):
    """Signed distance from (px, py) to the ellipse (x/A)^2 + (y/B)^2 = 1 (negative inside) and the
    ellipse's outward normal at the nearest point; the plugin's ObstacleGap, recomputed by bisection."""
    x, y = abs(px), abs(py)
    f = lambda t: (B * B - A * A) * math.sin(t) * math.cos(t) + A * x * math.sin(t) - B * y * math.cos(t)
    lo, hi = 0.0, math.pi / 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    t = 0.5 * (lo + hi)
    qx, qy = A * math.cos(t), B * math.sin(t)
    nx, ny = qx / A ** 2, qy / B ** 2
    nn = math.hypot(nx, ny)
    inside = (x / A) ** 2 + (y / B) ** 2 - 1
    d = math.hypot(x - qx, y - qy)
    return (-d if inside < 0 else d), math.copysign(nx / nn, px), math.copysign(ny / nn, py)


def contact_state(out, run):
    """Per contact node at the end: normal force and w_n = n.u + gap (>= 0: admissible, 0: touching),
    from fields-3-end.vtu's displacement and the pipe of summary.json."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, "fields-3-end.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    disp = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    par = run["summary"]["parameters"]
    result = []
    for r in run["final"]:
        x, y = float(r["x"]), float(r["y"])
        i = int(((points[:, 0] - x) ** 2 + (points[:, 1] - y) ** 2).argmin())  # the VTU holds floats
        gap, nx, ny = ellipse_gap(x, y, par["pipe_A"], par["pipe_B"])
        result.append((float(r["normal_force"]), nx * disp[i][0] + ny * disp[i][1] + gap))
    return result


def signorini(label, state, tol):
    """No penetration anywhere (w_n >= -tol) and touching (|w_n| <= tol) where the normal force is > 0."""
    worst_pen = min(w for _, w in state)
    worst_gap = max((abs(w) for n, w in state if n > 0), default=0.0)
    check(worst_pen >= -tol, f"{label}: no penetration, min n.u + gap = {worst_pen:.2e} m >= -{tol:.0e}")
    check(worst_gap <= tol, f"{label}: complementarity, |n.u + gap| <= {worst_gap:.2e} m <= {tol:.0e} "
          f"where the normal force is > 0 ({sum(n > 0 for n, _ in state)} of {len(state)} nodes)")
    return {"min_gap_m": worst_pen, "max_gap_in_contact_m": worst_gap}


def iteration_stats(hist):
    cols = ("fixed_point_iterations", "slip_iterations", "dc_iterations", "psor_sweeps")
    return {c: {"max": max(float(r[c]) for r in hist), "mean": sum(float(r[c]) for r in hist) / len(hist)}
            for c in cols}


def grazing(reference):
    print("== 1. grazing contact")
    p55 = reference["summary"]["final_pressure_mean"]
    runs = {}
    for name, delta in (("zero", 0.0), ("plus", 1e-7), ("minus", -1e-7)):
        pipe = f"{RING_INNER + delta:.10f}"
        out = run_scene("sleeve-circular", f"hard-grazing-{name}", *COARSE, "-steps", "300",
                        "-pipeA", pipe, "-pipeB", pipe)
        runs[name] = (out, sleeve_outputs(out))
    out, zero = runs["zero"]
    s = zero["summary"]
    pmax = max(abs(float(r["pressure"])) for r in zero["final"])
    check(pmax <= 1e-9 * p55, f"interference 0: final pressure {pmax:.2e} Pa <= 1e-9 x the 55 um fit's "
          f"{p55 / 1e6:.4f} MPa (Lame with delta = 0: 0)")
    tol = 1e-6 * INTERFERENCE
    sig = signorini("interference 0", contact_state(out, zero), tol)
    # (docs/stability.md states these as round-off: the bounds it prints)
    check(pmax < 1e-4 and sig["min_gap_m"] > -1e-13 and sig["max_gap_in_contact_m"] < 1e-13,
          f"interference 0: round-off as docs/stability.md states it: pressure {pmax:.1e} < 1e-4 Pa, n.u + gap "
          f"{sig['min_gap_m']:.1e} > -1e-13 m, {sig['max_gap_in_contact_m']:.1e} < 1e-13 m where in contact")
    counts = [int(r["contact_nodes"]) for r in zero["history"]]
    changes = [i + 2 for i, (a, b) in enumerate(zip(counts, counts[1:])) if a != b]
    settled = s["austenite_step"]
    check(settled > 0 and all(c <= settled for c in changes),
          f"interference 0: the contact set changes {len(changes)} times (steps {changes}), never after the "
          f"ring is austenite for good (step {settled}); loops converged: fixed point <= "
          f"{s['fixed_point_iterations_max']}, DC <= {s['dc_iterations_max']}, PSOR <= {s['psor_sweeps_max']:.0f}")
    plus = runs["plus"][1]["summary"]["final_pressure_mean"]
    scale = plus / p55 / (1e-7 / INTERFERENCE) - 1
    check(abs(scale) <= 1e-6, f"+0.1 um: final pressure {plus:.2f} Pa = the 55 um fit x 0.1/55 to "
          f"{scale:.1e} (linear elastic final state)")
    minus = runs["minus"][1]
    never = max(float(r["pressure_max"]) for r in minus["history"])
    check(minus["summary"]["first_contact_step"] is None and never == 0,
          f"-0.1 um clearance: never touches (largest pressure over the run {never} Pa)")
    # A clearance of 0.4 mm (pipe inside the bore): the closed forms are the free ring's 0, not the
    # formulas' negative pressures (-116 MPa was printed, with "relative difference 0"), and no
    # relative error is claimed.
    clear = {}
    for scene, extra in (("sleeve-radial", []), ("sleeve-axisymmetric", []),
                         ("sleeve-3d", ["-nr", "1", "-nt", "4", "-length", "0.04"])):
        out_c, done_c = run_scene_captured(scene, f"hard-clearance-{scene}", "-Ri", "0.05", "-pipeA", "0.0496",
                                           "-quiet", "1", *extra)
        sc = read_json(os.path.join(out_c, "summary.json")) if done_c.returncode == 0 else {}
        forms = {k: sc.get(k) for k in ("lame_pressure", "open_cylinder_pressure", "plane_strain_pressure") if k in sc}
        said = "a clearance of 400 um: no pressure" in done_c.stdout or scene == "sleeve-radial"
        check(done_c.returncode == 0 and sc.get("first_contact_step") is None and sc.get("final_pressure_mean") == 0
              and forms and all(v == 0 for v in forms.values()) and sc.get("mid_pressure_relative_error", None) is None
              and said,
              f"{scene} with a 0.4 mm clearance: exit {done_c.returncode}, no contact, closed forms {forms} (0: the free "
              f"ring), relative error {sc.get('mid_pressure_relative_error')} (none), said: {said}")
        # Nor a run's own error of a force that is not there (step-control.idp StepForceRoundOff): no
        # time or mesh estimate, no companion run, the reason in the summary and on the last line.
        why = sc.get("time_error_estimate_unknown") or ""
        line = own_error_line(done_c)
        check(sc.get("time_error_estimate_transient", 0) is None and sc.get("mesh_error_estimate_transient") is None
              and why.startswith("no force")
              # (the 3D run's -nr 1 does not halve: its companion is skipped for that first)
              and (sc.get("mesh_estimate_skipped") or "").startswith("no force" if scene != "sleeve-3d" else "its companion")
              and sc.get("run_error_estimate_transient", 0) is None and not os.path.exists(os.path.join(out_c, "mesh-estimate"))
              and "not estimated, no force" in line,
              f"{scene} with a 0.4 mm clearance: no error estimated of no force (time {sc.get('time_error_estimate_transient')}, "
              f"mesh {sc.get('mesh_error_estimate_transient')}, why {why[:60]!r}, companion run: "
              f"{os.path.exists(os.path.join(out_c, 'mesh-estimate'))})")
        clear[scene] = forms
    # The 3D scene at interference 0 (a small mesh), clamped, then bent: its laws' gaps are measured
    # against a millionth of the bore's radius (it divided by the interference 0 and stopped after
    # the run); the clamping seals nothing (its reactions are round-off: every node open), so the
    # leak path is there before any bending, said so (it was reported as opening "after 0 rad" in
    # the first increment); the bending then presses some nodes (the pipe presses the bore at the
    # mid-plane on one side and at the free end on the other) and the rest stay open.
    out3d, done = run_scene_captured("sleeve-3d", "hard-grazing-3d", "-interference", "0", "-nr", "1", "-nt", "4",
                                     "-length", "0.04", "-bend", "1e-3", "-bendsteps", "2", "-quiet", "1")
    s3 = read_json(os.path.join(out3d, "summary.json")) if done.returncode == 0 else {}
    bend = s3.get("bending", {})
    check(done.returncode == 0 and abs(s3["final_pressure_node_max"]) <= 1e-9 * p55
          and s3["contact_gap_min"] >= -1e-6 and s3["contact_complementarity_max"] <= 1e-6,
          f"sleeve-3d at interference 0: exit {done.returncode}, final pressure {s3.get('final_pressure_node_max')} Pa, "
          f"gap {s3.get('contact_gap_min')} and r_n |gap| {s3.get('contact_complementarity_max')} (over 1e-6 Ri) "
          f"{done.stdout.strip()[-200:] if done.returncode else ''}")
    check(bend.get("leak_path_angle") == 0 and bend.get("leak_path_at_clamping") is True
          and bend.get("nodes_open_at_clamping") == 27 and 0 < bend.get("nodes_open_final", 0) < 27
          and bend.get("gap_min", -1) >= -1e-6
          and bend.get("complementarity_max", 1) <= 1e-6 and bend.get("cone_excess_max", 1) <= 1e-8
          and bend.get("moment_balance_max", 1) <= 1e-9,
          f"sleeve-3d at interference 0 bent 1e-3 rad: a leak path before any bending "
          f"({bend.get('leak_path_angle')} rad, at clamping {bend.get('leak_path_at_clamping')}, "
          f"{bend.get('nodes_open_at_clamping')} of 27 nodes open; {bend.get('nodes_open_final')} at the end), laws and moment balance "
          f"({bend.get('gap_min')}, {bend.get('complementarity_max')}, {bend.get('cone_excess_max')}, "
          f"{bend.get('moment_balance_max')})")
    return {"interference_0": dict(sig, final_pressure_max_Pa=pmax, contact_set_changes_at_steps=changes,
                                   austenite_step=settled, first_contact_step=s["first_contact_step"],
                                   iterations=iteration_stats(zero["history"])),
            "plus_0p1um_final_pressure_Pa": plus, "plus_0p1um_scaling_error": scale,
            "reference_55um_final_pressure_Pa": p55, "clearance_closed_forms": clear, "sleeve_3d_interference_0": {
                "final_pressure_node_max_Pa": s3.get("final_pressure_node_max"),
                "leak_path_angle": bend.get("leak_path_angle"), "nodes_open_final": bend.get("nodes_open_final")}}


def friction():
    print("== 2. high friction (elliptic pipe)")
    runs = {mu: sleeve_outputs(run_scene("sleeve-elliptic-friction", f"hard-friction-{mu}", *COARSE,
                                         "-steps", "300", "-mu", mu))
            for mu in ("0", "0.2", "0.5", "1.0")}
    result = {}
    base = runs["0"]["summary"]["final_pressure_mean"]
    for mu_text, run in runs.items():
        mu, s = float(mu_text), run["summary"]
        out = os.path.join(TEST_RESULTS, f"hard-friction-{mu_text}")
        entry = {"final_pressure_mean_Pa": s["final_pressure_mean"],
                 "non_uniformity": s["final_pressure_non_uniformity"],
                 "tangential_over_normal_max": s["final_tangential_over_normal"],
                 "iterations": iteration_stats(run["history"])}
        entry.update(signorini(f"mu {mu_text}", contact_state(out, run), 1e-6 * INTERFERENCE))
        if mu > 0:
            n = [float(r["normal_force"]) for r in run["final"]]
            t = [float(r["tangential_force"]) for r in run["final"]]
            slip = [float(r["slip_last_step"]) for r in run["final"]]
            ratio = max(abs(b) / (mu * a) if a > 0 else (math.inf if b != 0 else 0) for a, b in zip(n, t))
            check(ratio <= 1 + 1e-8, f"mu {mu_text}: Coulomb cone, max |t|/(mu n) = {ratio:.6f} <= 1 + 1e-8")
            slipping = [i for i, d in enumerate(slip) if abs(d) > 1e-12]
            consistent = all(abs(t[i]) >= (1 - 1e-6) * mu * n[i] and t[i] * slip[i] < 0 for i in slipping)
            check(consistent, f"mu {mu_text}: {len(n) - len(slipping)} nodes stick, {len(slipping)} slipped over "
                  f"the last step, each of those on the cone with its force opposing the slip")
            entry.update(max_cone_ratio=ratio, nodes_sticking=len(n) - len(slipping), nodes=len(n))
        loops = (f"non-uniformity {100 * s['final_pressure_non_uniformity']:.1f} %, slip-threshold iterations "
                 f"<= {s['slip_threshold_iterations_max']}, DC <= {s['dc_iterations_max']}")
        if mu > 0:  # mu = 0 is the reference of this comparison
            change = s["final_pressure_mean"] / base - 1
            check(abs(change) <= 1e-4, f"mu {mu_text}: mean pressure {s['final_pressure_mean'] / 1e6:.5f} MPa, "
                  f"{change:+.1e} from mu = 0; {loops}")
            entry["mean_pressure_change_from_mu_0"] = change
        else:
            print(f"info mu 0: mean pressure {s['final_pressure_mean'] / 1e6:.5f} MPa (the reference); {loops}")
        result[mu_text] = entry
    return result


def large_steps(fine, E, nu):
    print("== 3. large time steps")
    runs = {"1500": fine}
    for n in ("150", "15"):
        runs[n] = sleeve_outputs(run_scene("sleeve-circular", f"hard-steps-{n}", *COARSE, "-steps", n))
    lame = lame_pressure(E, nu, RING_INNER, RING_INNER + THICKNESS, INTERFERENCE)
    ref = fine["summary"]["final_pressure_mean"]
    result = {"lame_Pa": lame}
    for n, run in runs.items():
        s = run["summary"]
        dt = s["parameters"]["dt"]
        hist = run["history"]
        # Lame's pressure is the answer only if the ring ends all austenite (then linear elastic).
        austenite = float(hist[-1]["fraction_austenite"])
        check(s["austenite_step"] > 0 and austenite >= 1 - 1e-12,
              f"{n} steps (dt {dt} s): ends all austenite (fraction {austenite!r}, for good from step "
              f"{s['austenite_step']})")
        err = s["final_pressure_mean"] / lame - 1
        check(abs(err) <= 1e-3, f"{n} steps: final pressure {s['final_pressure_mean'] / 1e6:.6f} MPa, {err:.2e} "
              f"from Lame's {lame / 1e6:.6f} MPa (<= 1e-3, coarse mesh)")
        diff = None
        if run is not fine:  # the 1500-step run is the reference of this comparison
            diff = s["final_pressure_mean"] / ref - 1
            check(abs(diff) <= 1e-9, f"{n} steps: final pressure {diff:.2e} from 1500 steps' "
                  f"{ref / 1e6:.6f} MPa (<= 1e-9)")
        reversion = next((i + 1 for i, r in enumerate(hist) if float(r["fraction_austenite"]) > 0), -1)
        first = s["first_contact_step"]
        entry = {"dt_s": dt, "final_pressure_Pa": s["final_pressure_mean"], "lame_error": err,
                 "final_fraction_austenite": austenite, "diff_from_1500_steps": diff,
                 "first_contact_step": first, "first_contact_time_s": first * dt,
                 "T_inner_first_contact_K": s["T_inner_first_contact"],
                 "reversion_step": reversion, "austenite_step": s["austenite_step"],
                 "T_inner_austenite_K": s["T_inner_austenite"],
                 "linear_phase_steps": reversion - first, "peak_pressure_Pa": s["peak_pressure_mean"],
                 "iterations": iteration_stats(hist)}
        print(f"info {n} steps: contact at {first * dt:.1f} s ({entry['T_inner_first_contact_K'] - KELVIN_AT_0C:.2f} C inner), "
              f"{entry['linear_phase_steps']} steps of linear phase, austenite for good at "
              f"{s['austenite_step'] * dt:.1f} s ({entry['T_inner_austenite_K'] - KELVIN_AT_0C:.2f} C); per step at most "
              f"{s['fixed_point_iterations_max']} fixed-point, {s['dc_iterations_max']} DC, "
              f"{s['psor_sweeps_max']:.0f} PSOR sweeps")
        result[n] = entry
    return result


NOTE = re.compile(r"note: DCT fixed point cycled \(period 2, (\d+) triangles flip\); their latent fraction held "
                  r"at lambda (\S+) to (\S+) after (\d+) bisections, relative change of T (\S+)")


def random_threshold(reference):
    print("== 5. random threshold, spread 20 K")
    base = ["-mesh", "meshes/sleeve-coarse.msh", "-quiet", "1", "-steps", "300", "-cspread", "20"]
    frac = sleeve_outputs(run_scene("sleeve-random-threshold", "hard-random-20-fraction", *base))["summary"]
    homogeneous = reference["summary"]["final_pressure_mean"]
    check(frac["reversal_steps"] == 0 and frac["pressure_zigzag_steps"] == 0
          and abs(frac["final_pressure_mean"] / homogeneous - 1) <= 1e-9,
          f"fraction model (default): runs through, {frac['reversal_steps']} reversal steps, "
          f"{frac['pressure_zigzag_steps']} pressure zigzags, at most {frac['fixed_point_iterations_max']} "
          f"fixed-point iterations, final {frac['final_pressure_mean'] / 1e6:.6f} vs {homogeneous / 1e6:.6f} MPa")
    # The paper's on/off model, with its old iteration limit (the loud failure's count is asserted).
    args = base + ["-phasemodel", "onoff", "-fpmaxit", "30"]
    code, err = run_failing("sleeve-random-threshold", "hard-random-20", *args)
    m = re.search(r"error: time step (\d+): DCT fixed point \(heat <-> phases\) did not converge: (\d+) "
                  r"iterations, relative change of T (\S+) > tol ([0-9.eE+-]+)", err)
    check(code != 0 and m is not None and 1 <= int(m.group(1)) <= 300 and int(m.group(2)) == 30
          and float(m.group(3)) > float(m.group(4)) and "-fprelax 1" in err,
          f"without -fprelax: fails loudly, naming its time step and -fprelax 1 (exit {code}): "
          + (m.group(0) if m else "no 'DCT fixed point ... did not converge' message"))
    result = {"fraction_model": {k: frac[k] for k in ("reversal_steps", "pressure_zigzag_steps",
                                                      "fixed_point_iterations_max", "final_pressure_mean")},
              "loud_failure": m.group(0) if m else None, "exit_code": code}
    code, err = run_failing("sleeve-random-threshold", "hard-random-20-relax", *args, "-fprelax", "1")
    notes = [(int(a), float(b), float(c), int(d), float(e)) for a, b, c, d, e in NOTE.findall(err)]
    check(code == 0 and len(notes) > 0, f"with -fprelax 1: exit {code}, {len(notes)} cycles resolved")
    if code == 0 and notes:
        run = sleeve_outputs(os.path.join(TEST_RESULTS, "hard-random-20-relax"))
        worst = max(n[4] for n in notes)
        check(worst <= 1e-8, f"each cycle resolved to the fixed-point tolerance: relative change of T <= "
              f"{worst:.1e}; flipping triangles per cycle {sorted(set(n[0] for n in notes))}, bisections "
              f"{min(n[3] for n in notes)}-{max(n[3] for n in notes)}, lambda {min(n[1] for n in notes):.4f}-"
              f"{max(n[2] for n in notes):.4f}")
        final = run["summary"]["final_pressure_mean"]
        check(run["summary"]["austenite_step"] > 0 and abs(final / homogeneous - 1) <= 1e-9,
              f"ends all austenite at the homogeneous ring's pressure: {final / 1e6:.6f} vs "
              f"{homogeneous / 1e6:.6f} MPa")
        result.update(cycles=len(notes), max_residual=worst, final_pressure_Pa=final,
                      bisections=[n[3] for n in notes], lambdas=[n[1] for n in notes],
                      T_inner_austenite_K=run["summary"]["T_inner_austenite"])
    onoff = [*COARSE, "-steps", "300", "-phasemodel", "onoff"]
    ref_out = run_scene("sleeve-circular", "hard-reference-300-onoff", *onoff)
    same_out = run_scene("sleeve-circular", "hard-relax-no-cycle", *onoff, "-fprelax", "1")
    same = [f for f in ("history.csv", "points.csv", "contact-final.csv", "fields-3-end.csv")
            if open(os.path.join(same_out, f), "rb").read() == open(os.path.join(ref_out, f), "rb").read()]
    check(len(same) == 4, f"sleeve-circular (no cycle) with -fprelax 1: {len(same)} of 4 files byte-identical")
    result["byte_identical_without_cycle"] = same
    return result


def slivers(E, nu):
    print("== 6. nearly degenerate triangles")
    lame = lame_pressure(E, nu, RING_INNER, RING_INNER + THICKNESS, INTERFERENCE)
    out = run_scene("sleeve-circular", "hard-sliver-thin", "-mesh", "meshes/sliver-thin.msh", "-quiet", "1",
                    "-steps", "300")
    run = sleeve_outputs(out)
    s = run["summary"]
    err = s["final_pressure_mean"] / lame - 1
    check(abs(err) <= 2e-3, f"layer of quality 0.011: final pressure {s['final_pressure_mean'] / 1e6:.4f} MPa, "
          f"{err:.2e} from Lame (<= 2e-3); non-uniformity {100 * s['final_pressure_non_uniformity']:.2f} %")
    sig = signorini("sliver-thin", contact_state(out, run), 1e-6 * INTERFERENCE)
    code, msg = run_failing("sleeve-circular", "hard-sliver-degenerate", "-mesh", "meshes/sliver-degenerate.msh",
                            "-quiet", "1", "-steps", "3")
    m = re.search(r"error: mesh meshes/sliver-degenerate.msh \(option -mesh\): triangle (\d+) \(centroid (\S+) (\S+)\) has area (\S+) "
                  r"< 1e-8 \(mean (\S+), quality (\S+)\)", msg)
    check(code != 0 and m is not None, f"layer of quality 9e-6 rejected up front (exit {code}): "
          + (m.group(0) if m else "no message naming the triangle"))
    code2, msg2 = run_failing("sleeve-circular", "hard-sliver-strict", "-mesh", "meshes/sliver-thin.msh",
                              "-quiet", "1", "-steps", "3", "-meshminquality", "0.05")
    m2 = re.search(r"error: mesh meshes/sliver-thin.msh \(option -mesh\): triangle (\d+) .* has quality (\S+) < 0.05", msg2)
    check(code2 != 0 and m2 is not None and float(m2.group(2)) < 0.05,
          f"-meshminquality 0.05 rejects the thin layer (exit {code2}): " + (m2.group(0) if m2 else "no message"))
    return dict(sig, lame_Pa=lame, final_pressure_Pa=s["final_pressure_mean"], lame_error=err,
                non_uniformity=s["final_pressure_non_uniformity"], nodes=s["nodes"], triangles=s["triangles"],
                iterations=iteration_stats(run["history"]),
                degenerate_message=m.group(0) if m else None, strict_message=m2.group(0) if m2 else None)


def stability_rows(results):
    """docs/stability.md's tables of cases 1-3, formatted from the results as the page prints them:
    the page must hold each (checklib.doc_quotes), so that its figures stay this test's."""
    def its(entry):
        i = entry["iterations"]
        return (f"{i['fixed_point_iterations']['max']:.0f}", f"{i['dc_iterations']['max']:.0f}",
                f"{i['psor_sweeps']['max']:.0f}")
    g = results["grazing"]
    zero = g["interference_0"]
    fp, dc, psor = its(zero)
    changes = zero["contact_set_changes_at_steps"]
    rows_ = [f"| contact set | touches at step {zero['first_contact_step']}, the step the ring is austenite for good "
             f"(the contact set changes {len(changes)} time{'s' if len(changes) != 1 else ''}: at step"
             f"{'s' if len(changes) != 1 else ''} {', '.join(map(str, changes))}); no change after |",
             f"| loops | at most {fp} fixed-point, {dc} DC iterations, {psor} PSOR sweeps per step |",
             f"| +0.1 um | {g['plus_0p1um_final_pressure_Pa']:,.2f} Pa = the 55 um fit x 0.1/55 to ".replace(",", " ")
             + ("round-off (below 1e-10)" if abs(g["plus_0p1um_scaling_error"]) < 1e-10
                else sci(abs(g["plus_0p1um_scaling_error"]))) + " |"]
    for mu, e in results["friction"].items():
        fp, dc, psor = its(e)
        slip = f"{e['iterations']['slip_iterations']['max']:.0f}"
        change = "" if mu == "0" else sci(e["mean_pressure_change_from_mu_0"], sign=True)
        cone = "" if mu == "0" else f"{e['max_cone_ratio']:.2f}"
        rows_.append(f"| {mu} | {e['final_pressure_mean_Pa'] / 1e6:.5f} | {change} | {100 * e['non_uniformity']:.1f} % | "
                     f"{cone} | {e['tangential_over_normal_max']:.3f} | {slip} | {dc} | {psor} |")
    ls = results["large_steps"]
    for n in ("1500", "150", "15"):
        e = ls[n]
        fp, dc, psor = its(e)
        diff = "" if e["diff_from_1500_steps"] is None else sci(e["diff_from_1500_steps"])
        dt = e["dt_s"]
        rows_.append(f"| {n} | {dt:g} s | {e['final_pressure_Pa'] / 1e6:.6f} MPa | {diff} | {sci(e['lame_error'])} | "
                     f"{e['first_contact_time_s']:.1f} s (step {e['first_contact_step']}), {celsius(e['T_inner_first_contact_K']):.1f} C | "
                     f"{e['linear_phase_steps']} steps | {e['austenite_step'] * dt:.1f} s (step {e['austenite_step']}), "
                     f"{celsius(e['T_inner_austenite_K']):.1f} C | {fp}, {dc}, {psor} |")
    r = results["random_threshold_20K"]
    rows_ += [f"With the default fraction model it runs through: at most {r['fraction_model']['fixed_point_iterations_max']} "
              "fixed-point iterations in a step",
              r["loud_failure"] or "no message",
              f"Measured: {r.get('cycles')} cycles, one triangle each, {min(r.get('bisections', [0]))}-"
              f"{max(r.get('bisections', [0]))} bisections, relative change of T <= {sci(r.get('max_residual', 0))}"]
    sl = results["slivers"]
    i = sl["iterations"]
    rows_.append(f"converges: {sl['final_pressure_Pa'] / 1e6:.4f} MPa, {sci(sl['lame_error'])} from Lamé (asserted <= 2e-3; "
                 f"the structured coarse mesh {sci(results['large_steps']['1500']['lame_error'])}), non-uniformity "
                 f"{100 * sl['non_uniformity']:.1f} %, Signorini to {sci(max(-sl['min_gap_m'], sl['max_gap_in_contact_m']))} m; "
                 f"at most {i['dc_iterations']['max']:.0f} DC iterations and {i['psor_sweeps']['max']:.0f} PSOR sweeps per step |")
    return rows_


def main():
    reference = sleeve_outputs(run_scene("sleeve-circular", "hard-reference-300", *COARSE, "-steps", "300"))
    par = reference["summary"]["parameters"]
    E, nu = par["E"], par["nu"]
    fine = sleeve_outputs(run_scene("sleeve-circular", "hard-steps-1500", *COARSE, "-steps", "1500"))
    results = {"test": "hard_cases", "mesh": "meshes/sleeve-coarse.msh",
               "grazing": grazing(reference), "friction": friction(), "large_steps": large_steps(fine, E, nu),
               "random_threshold_20K": random_threshold(reference), "slivers": slivers(E, nu)}
    # A run that ends before anything happens says so: no -1 K event printed as -274.15 C.
    code, text = run_failing("sleeve-circular", "hard-nothing-happens", "-mesh", "meshes/sleeve-coarse.msh",
                             "-steps", "20", "-tend", "1", "-quiet", "1", "-vtkevery", "0")
    line = next((ln for ln in text.splitlines() if ln.startswith("sleeve-circular: 20 steps")), "")
    check(code == 0 and "no contact, never all austenite for good" in line and "-274" not in text,
          f"a run with no contact and no reversion says so: {line[:120]}")
    # A friction coefficient of 1e-300: the pull-out's forces are subnormal (1e-294 N), and writing
    # them (errors.idp RealText: 10^(e - p + 1) underflowed to 0) divided by zero after the run.
    out = run_scene("sleeve-3d", "hard-mu-subnormal", "-nr", "1", "-nt", "4", "-length", "0.04", "-pullout", "1e-4",
                    "-pullsteps", "2", "-mu", "1e-300", "-meshestimate", "0", "-scale", "paper", "-quiet", "1")
    pull = read_json(os.path.join(out, "summary.json")).get("pullout") or {}
    check(0 < pull.get("force_final", 0) < 1e-290 and 0.5 < pull.get("force_over_mu_normal", 0) <= 1 + 1e-9
          and 0 <= pull.get("circumferential_over_normal_max", 1) < 1e-300,
          f"sleeve-3d -pullout with -mu 1e-300: the run writes its subnormal forces (F {pull.get('force_final')} N, "
          f"F / (mu N) {pull.get('force_over_mu_normal')}, circumferential {pull.get('circumferential_over_normal_max')})")
    results["stability_rows"] = stability_rows(results)
    doc_quotes("docs/stability.md", results["stability_rows"])
    record("hard_cases", results)
    finish()


if __name__ == "__main__":
    main()
