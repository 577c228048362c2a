#!/usr/bin/python3
"""The dissipative Fremond law on the free ring (docs/model.md#a-dissipative-law; issue 28, item 1).

Runs edp/scenes/free-ring.edp (on/off phases, the paper's scheme) without the option, with
-dissipation 0 and with -dissipation 1e6 (Pa), and checks
  * k = 0 is the paper's law byte for byte: history.csv, ring-final.vtu and summary.json (but its
    wall_seconds) of the run without the option and of -dissipation 0 are equal;
  * the transformation temperatures of the stress-free ring against the closed forms (plane strain,
    lambda + mu the 2D bulk modulus): forward on cooling where -c(T) = k,
    T_f = T0 (1 - k / (rho L)); reverse on heating where alpha^2 / (lambda + mu) - c = -k. The ring
    is not one material point: its temperature spreads over T_min..T_max (the exchange through its
    surfaces) and moves by the ramp over a step; the mean temperature at the end of the step before
    the ring turns is within that spread plus one step's change of the closed form, and the width
    within the sum of both ends' tolerances (the material point's exact check, to 0.01 K:
    tests/edp/dissipative_law.edp);
  * the energy bookkeeping: per step and over the run, stored heat = heat through the boundary +
    latent heat + dissipated heat, to 1e-6 relative (recomputed from history.csv); the net latent
    heat of the cycle is zero; the dissipated heat of the cycle is k per unit fraction moved each
    way, 2 k per unit volume over the cycle: dissipated / latent heat moved = k / (rho L)
    (the latent heat moved, rho L per unit volume each way, measures the ring's area), to 1e-9.
And on sleeve-radial (the fraction model; the paper's scale), the same law through the sleeve's
-dissipation: 0 gives every file of the run without the option (summary.json but its timing
keys); 1e5 Pa runs the nested loops (-stepsolver auto says so; -stepsolver newton refuses, naming
the dissipation), its heat balance holds to 1e-9 with the dissipated heat as a source, and the
dissipated heat is at most 2 k x the ring's area per radian (every point there and back) and
above 99 % of it (the ring transforms through and back); the same on sleeve-circular (the 2D
quarter ring, coarse mesh).
Writes results/checks/free_ring_dissipation.json.
"""
import filecmp
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows, run_scene  # noqa: E402

K = 1e6  # Pa


def history(out):
    h = rows(os.path.join(out, "history.csv"))
    return {key: [float(r[key]) for r in h] for key in h[0]}


def closed_forms(p, k):
    """T_f and T_r of a stress-free point (plane strain) with the dissipation k (Pa)."""
    bulk = p["E"] / (2 * (1 + p["nu"]) * (1 - 2 * p["nu"]))
    rho_l = p["rho"] * p["latent"]
    t_f = p["T0"] * (1 - k / rho_l)
    # (rho a (Tc - T))^2 / bulk - rho L / T0 (T - T0) + k = 0, x = Tc - T >= 0.
    a2, m = (p["rho"] * p["a"]) ** 2 / bulk, rho_l / p["T0"]
    x = (-m + math.sqrt(m * m + 4 * a2 * (m * (p["Tc"] - p["T0"]) - k))) / (2 * a2)
    return t_f, p["Tc"] - x


def timeless(path):
    """summary.json without its timing keys."""
    return {k: v for k, v in json.load(open(path)).items() if "seconds" not in k and not k.startswith("loop_over")}


def sleeve_radial():
    outs = {}
    for name, args in (("plain", []), ("zero", ["-dissipation", "0"]), ("k", ["-dissipation", "1e5"])):
        outs[name] = os.path.join(TEST_RESULTS, f"sleeve-radial-dissipation-{name}")
        run = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-quiet", "1",
                              "-out", outs[name], *args], cwd=ROOT, capture_output=True, text=True)
        check(run.returncode == 0, f"sleeve-radial {' '.join(args)} ran (exit {run.returncode})")
        if name == "k":
            note = "-stepsolver auto runs the paper's nested loops (fixedpoint)" in run.stdout + run.stderr
            check(note, "sleeve-radial -dissipation 1e5: the run says auto took the nested loops")
    files = sorted(f for f in os.listdir(outs["plain"]) if f != "summary.json")
    same = all(filecmp.cmp(os.path.join(outs["plain"], f), os.path.join(outs["zero"], f), shallow=False) for f in files)
    check(same and timeless(os.path.join(outs["plain"], "summary.json")) == timeless(os.path.join(outs["zero"], "summary.json")),
          f"sleeve-radial -dissipation 0: {', '.join(files)} byte-identical, summary.json equal but its timing keys")
    s = json.load(open(os.path.join(outs["k"], "summary.json")))
    p = s["parameters"]
    ri, ro = p["ring_inner_radius"], p["ring_inner_radius"] + p["ring_thickness"]
    full = 2 * s["dissipation"] * (ro * ro - ri * ri) / 2
    check(s["step_solver"] == "fixedpoint" and s["heat_balance_residual_max"] <= 1e-9,
          f"sleeve-radial -dissipation 1e5: step solver {s['step_solver']}, heat balance {s['heat_balance_residual_max']:.2e} <= 1e-9")
    check(0.99 * full < s["heat_dissipated"] <= full * (1 + 1e-9),
          f"dissipated heat {s['heat_dissipated']:.6g} J/m per radian, 2 k x ring area {full:.6g} "
          f"({s['heat_dissipated'] / full - 1:+.2e})")
    refused = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-dissipation", "1e5",
                              "-stepsolver", "newton", "-out", os.path.join(TEST_RESULTS, "sleeve-radial-dissipation-newton")],
                             cwd=ROOT, capture_output=True, text=True)
    check(refused.returncode == 1 and "-stepsolver newton cannot run here: it solves the paper's law without "
          "dissipation" in refused.stdout + refused.stderr, "-stepsolver newton refuses -dissipation > 0, naming it")
    return {"heat_dissipated_J_per_m": s["heat_dissipated"], "full_cycle_J_per_m": full,
            "heat_balance_residual_max": s["heat_balance_residual_max"], "final_pressure_mean": s["final_pressure_mean"]}


def same_tree(a, b):
    """Every file under a (but summary.json) byte-identical under b."""
    for folder, _, files in os.walk(a):
        for f in files:
            if f == "summary.json" and folder == a:
                continue
            other = os.path.join(b, os.path.relpath(os.path.join(folder, f), a))
            if not (os.path.exists(other) and filecmp.cmp(os.path.join(folder, f), other, shallow=False)):
                return False
    return True


def sleeve_circular():
    """The 2D quarter ring (coarse mesh, the paper's scale): -dissipation 0 is the default run, 1e5 Pa
    converges through the nested loops and dissipates at most 2 k x the quarter ring's area."""
    outs = {}
    for name, args in (("plain", []), ("zero", ["-dissipation", "0"]), ("k", ["-dissipation", "1e5"])):
        outs[name] = os.path.join(TEST_RESULTS, f"sleeve-circular-dissipation-{name}")
        run = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", "-quiet", "1",
                              "-mesh", "meshes/sleeve-coarse.msh", "-out", outs[name], *args],
                             cwd=ROOT, capture_output=True, text=True)
        check(run.returncode == 0, f"sleeve-circular (coarse) {' '.join(args)} ran (exit {run.returncode})")
    check(same_tree(outs["plain"], outs["zero"]) and timeless(os.path.join(outs["plain"], "summary.json"))
          == timeless(os.path.join(outs["zero"], "summary.json")),
          "sleeve-circular -dissipation 0: every file byte-identical to the default run (summary.json but its timing keys)")
    s = json.load(open(os.path.join(outs["k"], "summary.json")))
    geometry = dict(line.split()[:2] for line in open(os.path.join(ROOT, "meshes", "sleeve-geometry.txt"))
                    if len(line.split()) >= 2 and not line.startswith("#"))
    ri = s["parameters"]["ring_inner_radius"]
    ro = ri + float(geometry["Hr"])
    full = 2 * s["dissipation"] * math.pi / 4 * (ro * ro - ri * ri)
    check(s["step_solver"] == "fixedpoint" and s["unconverged_steps"] == 0 and 0.99 * full < s["heat_dissipated"] <= full,
          f"sleeve-circular -dissipation 1e5: nested loops, converged; dissipated {s['heat_dissipated']:.6g} J/m, "
          f"2 k x the quarter ring's area {full:.6g} ({s['heat_dissipated'] / full - 1:+.2e}: the polygonal mesh, "
          f"and points not fully through)")
    return {"heat_dissipated_J_per_m": s["heat_dissipated"], "full_cycle_J_per_m": full}


def main():
    plain = run_scene("free-ring", "free-ring-paper-law")
    zero = run_scene("free-ring", "free-ring-dissipation-0", "-dissipation", "0")
    same = [f for f in ("history.csv", "ring-final.vtu")
            if filecmp.cmp(os.path.join(plain, f), os.path.join(zero, f), shallow=False)]
    summaries = [json.load(open(os.path.join(d, "summary.json"))) for d in (plain, zero)]
    for s in summaries:
        s.pop("wall_seconds")
    check(len(same) == 2 and summaries[0] == summaries[1],
          f"-dissipation 0 is the paper's law: {', '.join(same)} byte-identical, summary.json equal but "
          f"its wall_seconds: {summaries[0] == summaries[1]}")

    out = run_scene("free-ring", "free-ring-dissipation", "-dissipation", str(K))
    summary = json.load(open(os.path.join(out, "summary.json")))
    p = summary["parameters"]
    check(p.get("dissipation") == K, f"summary.json records the dissipation {p.get('dissipation')} Pa")
    h = history(out)
    n = len(h["t"])
    t_f, t_r = closed_forms(p, K)

    def ends(i):
        """Mean temperature at the end of step i, and its tolerance: the ring's spread there plus
        one step's change of the mean."""
        return h["T_mean"][i], (h["T_max"][i] - h["T_min"][i]) + abs(h["T_mean"][i] - h["T_mean"][i - 1])

    forward = next(i for i in range(n) if h["fraction_austenite"][i] < 1)
    reverse = next(i for i in range(forward, n) if h["fraction_austenite"][i] == 1)
    switches = sum(1 for a, b in zip(h["fraction_austenite"], h["fraction_austenite"][1:]) if a != b)
    t_fwd, tol_fwd = ends(forward - 1)
    t_rev, tol_rev = ends(reverse - 1)
    check(abs(t_fwd - t_f) <= tol_fwd,
          f"forward (cooling) at {t_fwd:.3f} K (mean, the step before step {forward + 1}); closed form "
          f"T_f = T0 (1 - k / (rho L)) = {t_f:.3f} K; error {t_fwd - t_f:+.3f} K within {tol_fwd:.3f} K")
    check(abs(t_rev - t_r) <= tol_rev,
          f"reverse (heating) at {t_rev:.3f} K (step {reverse + 1}); closed form {t_r:.3f} K; error "
          f"{t_rev - t_r:+.3f} K within {tol_rev:.3f} K")
    width, width_cf = t_rev - t_fwd, t_r - t_f
    check(abs(width - width_cf) <= tol_fwd + tol_rev,
          f"loop width {width:.3f} K against {width_cf:.3f} K (k = 0: {closed_forms(p, 0)[1] - p['T0']:.3f} K)")
    check(switches == 2, f"the ring turns once each way ({switches} switches of its austenite fraction)")

    # Energy bookkeeping with the dissipated heat as a source.
    terms = ("stored_heat", "boundary_heat", "latent_heat", "dissipated_heat")
    scale = sum(abs(h[t][i]) for t in terms for i in range(n))
    residual = [h["stored_heat"][i] - h["boundary_heat"][i] - h["latent_heat"][i] - h["dissipated_heat"][i]
                for i in range(n)]
    step_residual = max(abs(r) for r in residual) / scale
    run_residual = abs(sum(residual)) / scale
    check(step_residual <= 1e-6 and run_residual <= 1e-6,
          f"energy balance with the dissipated heat: per step {step_residual:.2e}, run {run_residual:.2e} (<= 1e-6)")
    latent_moved = sum(abs(x) for x in h["latent_heat"])
    net_latent = abs(sum(h["latent_heat"])) / latent_moved
    check(net_latent <= 1e-9, f"net latent heat of the cycle {net_latent:.2e} of the {latent_moved:.6g} J/m moved")
    dissipated = sum(h["dissipated_heat"])
    ratio = dissipated / latent_moved
    expected = K / (p["rho"] * p["latent"])
    check(min(h["dissipated_heat"]) >= 0 and abs(ratio - expected) <= 1e-9 * expected,
          f"dissipated heat of the cycle {dissipated:.6g} J/m = 2 k x ring area: dissipated / latent moved "
          f"{ratio:.12g}, k / (rho L) = {expected:.12g}; summary heat_dissipated {summary['heat_dissipated']:.6g}")
    radial = sleeve_radial()
    circular = sleeve_circular()
    record("free_ring_dissipation", {
        "test": "free_ring_dissipation", "k_Pa": K, "dt": p["dt"],
        "forward_K": t_fwd, "forward_closed_form_K": t_f, "forward_tolerance_K": tol_fwd,
        "reverse_K": t_rev, "reverse_closed_form_K": t_r, "reverse_tolerance_K": tol_rev,
        "width_K": width, "width_closed_form_K": width_cf,
        "heat_dissipated_J_per_m": dissipated, "latent_heat_moved_J_per_m": latent_moved,
        "energy_balance_step_residual": step_residual, "energy_balance_run_residual": run_residual,
        "sleeve_radial": radial, "sleeve_circular": circular})
    finish()


if __name__ == "__main__":
    main()
