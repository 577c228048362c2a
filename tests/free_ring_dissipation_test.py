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
The fraction model on the free ring with 1e6 Pa (-phasemodel fraction, 2 s steps): the newton step
solver (-stepsolver auto) solves every step, no fall-back to the nested loops; the ring turns
within the same tolerances of the closed forms, the energy balance holds, and every step of the
reverse transformation (monotone: no variant changes) dissipates k / (rho L) of its latent heat.
And on sleeve-radial (the fraction model; the paper's scale), the same law through the sleeve's
-dissipation: 0 gives every file of the run without the option (summary.json but its timing
keys); 1e5 Pa runs the newton step solver (-stepsolver auto) and the nested loops
(-stepsolver fixedpoint): both converge, their heat balance holds to 1e-9 with the dissipated
heat as a source, they agree (dissipated heat, final pressure) to 1e-7 relative (the nested loops
at -fptol 1e-12), and the
dissipated heat is at most 2 k x the ring's area per radian (every point there and back) and
above 99 % of it (the ring transforms through and back); the same on sleeve-circular (the 2D
quarter ring, coarse mesh, newton).
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
    for name, args in (("plain", []), ("zero", ["-dissipation", "0"]), ("k", ["-dissipation", "1e5"]),
                       # (the nested loops' default -fptol 1e-8, a relative change of T, leaves
                       # 1e-4 of the dissipated heat: 1e-12 takes up to 871 iterations a step)
                       ("k-fixedpoint", ["-dissipation", "1e5", "-stepsolver", "fixedpoint", "-fptol", "1e-12"])):
        outs[name] = os.path.join(TEST_RESULTS, f"sleeve-radial-dissipation-{name}")
        # (fixed steps, -tol 0: the two solvers compared on the same steps)
        # (-meshestimate 0: the companion's files hold its own timings)
        run = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-quiet", "1",
                              "-tol", "0", "-meshestimate", "0", "-out", outs[name], *args], cwd=ROOT, capture_output=True,
                             text=True)
        check(run.returncode == 0, f"sleeve-radial {' '.join(args)} ran (exit {run.returncode})")
    files = sorted(f for f in os.listdir(outs["plain"]) if f != "summary.json")
    same = all(filecmp.cmp(os.path.join(outs["plain"], f), os.path.join(outs["zero"], f), shallow=False) for f in files)
    check(same and timeless(os.path.join(outs["plain"], "summary.json")) == timeless(os.path.join(outs["zero"], "summary.json")),
          f"sleeve-radial -dissipation 0: {', '.join(files)} byte-identical, summary.json equal but its timing keys")
    s = json.load(open(os.path.join(outs["k"], "summary.json")))
    p = s["parameters"]
    ri, ro = p["ring_inner_radius"], p["ring_inner_radius"] + p["ring_thickness"]
    full = 2 * s["dissipation"] * (ro * ro - ri * ri) / 2
    fp = json.load(open(os.path.join(outs["k-fixedpoint"], "summary.json")))
    for t in (s, fp):
        check(t["heat_balance_residual_max"] <= 1e-9 and t["unconverged_steps"] == 0,
              f"sleeve-radial -dissipation 1e5: step solver {t['step_solver']}, converged, heat balance "
              f"{t['heat_balance_residual_max']:.2e} <= 1e-9")
        check(0.99 * full < t["heat_dissipated"] <= full * (1 + 1e-9),
              f"dissipated heat ({t['step_solver']}) {t['heat_dissipated']:.6g} J/m per radian, 2 k x ring area "
              f"{full:.6g} ({t['heat_dissipated'] / full - 1:+.2e})")
    check(s["step_solver"] == "newton" and s["step_fallbacks"] == 0 and fp["step_solver"] == "fixedpoint",
          f"-stepsolver auto takes newton with k > 0 ({s['step_solver']}, {s['step_fallbacks']} fall-backs)")
    for key in ("heat_dissipated", "final_pressure_mean"):
        check(abs(s[key] - fp[key]) <= 1e-7 * abs(fp[key]),
              f"newton and the nested loops agree on {key}: {s[key]:.9g} and {fp[key]:.9g} "
              f"({s[key] / fp[key] - 1:+.1e})")
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
                              "-mesh", "meshes/sleeve-coarse.msh", "-meshestimate", "0", "-out", outs[name], *args],
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
    check(s["step_solver"] == "newton" and s["step_fallbacks"] == 0 and s["unconverged_steps"] == 0
          and 0.99 * full < s["heat_dissipated"] <= full * (1 + 1e-9),
          f"sleeve-circular -dissipation 1e5: newton, converged, no fall-back; dissipated {s['heat_dissipated']:.6g} J/m, "
          f"2 k x the quarter ring's area {full:.6g} ({s['heat_dissipated'] / full - 1:+.2e}: the heat is on the "
          f"ring's true annulus, -curvedmeasure 1; below it where points are not fully through)")
    return {"heat_dissipated_J_per_m": s["heat_dissipated"], "full_cycle_J_per_m": full}


def free_ring_fraction(p):
    """The fraction model with k = 1e6 Pa at the free ring's default 2 s steps: the newton step
    solver (auto) solves every step (the nested loops stop at their limit there)."""
    out = run_scene("free-ring", "free-ring-dissipation-fraction", "-dissipation", str(K), "-phasemodel", "fraction")
    s = json.load(open(os.path.join(out, "summary.json")))
    h = history(out)
    n = len(h["t"])
    its = [int(x) for x in h["fixed_point_iterations"] if x > 0]
    check(s["step_solver"] == "newton" and s["step_fallbacks"] == 0 and s["unconverged_steps"] == 0
          and s["step_residual_max"] <= s["step_tol"],
          f"free ring, fractions, k = 1e6: newton at every step, no fall-back, residual <= {s['step_residual_max']:.2e}; "
          f"iterations per transforming step max {max(its)}, mean {sum(its) / len(its):.2f} ({len(its)} steps)")
    t_f, t_r = closed_forms(p, K)
    forward = next(i for i in range(n) if h["fraction_austenite"][i] < 1)
    reverse = next(i for i in range(forward, n) if h["fraction_austenite"][i] == 1)
    start = max(i for i in range(reverse) if h["fraction_austenite"][i] == 0)  # the last all-martensite step
    t_fwd = h["T_mean"][forward - 1]
    tol_fwd = (h["T_max"][forward - 1] - h["T_min"][forward - 1]) + abs(t_fwd - h["T_mean"][forward - 2])
    t_rev = h["T_mean"][reverse - 1]
    tol_rev = (h["T_max"][reverse - 1] - h["T_min"][reverse - 1]) + abs(t_rev - h["T_mean"][reverse - 2])
    check(abs(t_fwd - t_f) <= tol_fwd and abs(t_rev - t_r) <= tol_rev,
          f"fractions: forward starts at {t_fwd:.3f} K ({t_f:.3f} K +- {tol_fwd:.3f}), reverse ends at {t_rev:.3f} K "
          f"({t_r:.3f} K +- {tol_rev:.3f})")
    terms = ("stored_heat", "boundary_heat", "latent_heat", "dissipated_heat")
    scale = sum(abs(h[t][i]) for t in terms for i in range(n))
    worst = max(abs(h["stored_heat"][i] - h["boundary_heat"][i] - h["latent_heat"][i] - h["dissipated_heat"][i])
                for i in range(n)) / scale
    check(worst <= 1e-9, f"fractions: energy balance per step with the dissipated heat {worst:.2e} <= 1e-9")
    # The reverse transformation is monotone (every point from its martensite to austenite, no
    # variant change): each step dissipates k / (rho L) of its latent heat.
    expected = K / (p["rho"] * p["latent"])
    worst_ratio = max(abs(h["dissipated_heat"][i] / abs(h["latent_heat"][i]) - expected) / expected
                      for i in range(start + 1, reverse + 1) if h["latent_heat"][i] != 0)
    check(worst_ratio <= 1e-9, f"fractions: each reverse step dissipates k / (rho L) of its latent heat (worst {worst_ratio:.1e})")
    # The forward transformation, a front through the ring whose compressed side takes martensite
    # 2 on the way (then turns to martensite 1: its variant changes dissipate more), dissipates
    # at least k per unit fraction and at most 5 % more.
    moved = sum(abs(x) for x in h["latent_heat"][: start + 1])
    ratio = sum(h["dissipated_heat"][: start + 1]) / moved / expected
    check(1 - 1e-9 <= ratio <= 1.05, f"fractions: forward dissipation {ratio:.4f} x k per unit fraction moved")
    return {"iterations_max": max(its), "iterations_mean": sum(its) / len(its), "forward_K": t_fwd, "reverse_K": t_rev,
            "heat_dissipated_J_per_m": s["heat_dissipated"], "forward_dissipation_ratio": ratio}


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
    fraction = free_ring_fraction(p)
    radial = sleeve_radial()
    circular = sleeve_circular()
    record("free_ring_dissipation", {
        "test": "free_ring_dissipation", "k_Pa": K, "dt": p["dt"],
        "forward_K": t_fwd, "forward_closed_form_K": t_f, "forward_tolerance_K": tol_fwd,
        "reverse_K": t_rev, "reverse_closed_form_K": t_r, "reverse_tolerance_K": tol_rev,
        "width_K": width, "width_closed_form_K": width_cf,
        "heat_dissipated_J_per_m": dissipated, "latent_heat_moved_J_per_m": latent_moved,
        "energy_balance_step_residual": step_residual, "energy_balance_run_residual": run_residual,
        "free_ring_fraction_newton": fraction, "sleeve_radial": radial, "sleeve_circular": circular})
    finish()


if __name__ == "__main__":
    main()
