#!/usr/bin/python3
"""Verification of the elastic pipe of sleeve-radial (-pipeE > 0: a second body in contact).

1. Compound cylinders: at the end the ring is all austenite and elastic, so the contact pressure
   must be the closed-form shrink fit of an elastic ring on an elastic pipe (tools/lame.py
   compound_pressure, written apart from the scene's LameCompoundPressure), plane strain and plane
   stress, solid shaft and hollow pipe: the relative error must fall at order 2 in nr (both bodies
   P1, the pipe's elements of the ring's size) over nr = 2 ... 32; the pipe's inner-surface
   displacement of the hollow pipe against the closed form too.
2. Rigid limit: -pipeE 1e15 reproduces the rigid pipe's run (the default run: paper scale, nr 160,
   1000 steps): the whole pressure curve within 2e-5 of its maximum, the same contact status and
   events at every step; the difference is linear in 1/E (1e13: 100 times larger, within 20 %).
3. Action = reaction: each body's nodal force at the interface from its own equilibrium (ring:
   K u - B s - f; pipe: K_p v) are opposite and equal the contact reaction, to round-off; the gap
   from the pipe's deformed surface is closed at the end and never negative, the reaction
   complementary to it at every step; the pressures on the two bodies are the one force over each
   body's own radius.
4. Bad inputs: -pipeE, -pipenu, -pipeRi out of range and an elastic pipe asked of a 2D scene fail
   with one line naming the option (docs/errors.md lists them; the bad-inputs test runs its rows).
Writes results/checks/sleeve_pipe.json.
"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools"))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows, run_scene  # noqa: E402
from lame import compound_pressure, pipe_inner_displacement  # noqa: E402

STEEL = ("200e9", "0.28")  # the pipe of checks 1 and 3: E (Pa), nu


def radial(tag, *args):
    out = run_scene("sleeve-radial", "sleeve-pipe-" + tag, "-quiet", "1", *args)
    return {"summary": json.load(open(os.path.join(out, "summary.json"))),
            "rows": rows(os.path.join(out, "history.csv")),
            "final": rows(os.path.join(out, "fields-final.csv"))}


def action_reaction(tag, run):
    """Check 3 on one run; returns the worst figures."""
    s, pipe = run["summary"], run["summary"]["pipe"]
    p = s["parameters"]
    force = pipe["reaction_per_radian"]
    balance = abs(pipe["interface_force_ring"] + pipe["interface_force_pipe"]) / force
    ring_vs_reaction = abs(pipe["interface_force_ring"] / force - 1)
    pressures = abs(pipe["pressure_ring"] * p["ring_inner_radius"] / (pipe["pressure_pipe"] * pipe["outer_radius"]) - 1)
    delta = s["interference"]
    gap_end = abs(pipe["gap_deformed"]) / delta
    h = run["rows"]
    reaction_max = max(float(r["reaction_per_radian"]) for r in h)
    gap_min = min(float(r["gap_inner"]) for r in h) / delta
    complementarity = max(abs(float(r["gap_inner"])) / delta * float(r["reaction_per_radian"]) / reaction_max for r in h)
    pipe_motion = max(abs(float(r["pipe_u_outer"]) + float(r["reaction_per_radian"]) * pipe["compliance"])
                      for r in h) / delta
    check(balance < 1e-9 and ring_vs_reaction < 1e-9 and pressures < 1e-10 and gap_end < 1e-9
          and gap_min >= -1e-9 and complementarity < 1e-9 and pipe_motion < 1e-10,
          f"{tag}: interface forces ring {pipe['interface_force_ring']:.9g} and pipe {pipe['interface_force_pipe']:.9g} "
          f"N/rad balance to {balance:.1e}, the ring's equals the reaction to {ring_vs_reaction:.1e}; pressures "
          f"{pipe['pressure_ring'] / 1e6:.6f} / {pipe['pressure_pipe'] / 1e6:.6f} MPa, one force ({pressures:.1e}); gap "
          f"from the deformed pipe at the end {gap_end:.1e}, min {gap_min:.1e}, complementarity {complementarity:.1e} "
          f"(of the interference); pipe motion = -F c to {pipe_motion:.1e}")
    return {"force_balance": balance, "ring_force_vs_reaction": ring_vs_reaction, "gap_end": gap_end,
            "gap_min": gap_min, "complementarity": complementarity}


def main():
    figures = {"compound": {}, "action_reaction": {}}

    # 1. Compound cylinders, order 2 in nr.
    for plane in ("strain", "stress"):
        for pipe_inner in (0.0, 0.04):
            case = f"{plane}-{'solid' if pipe_inner == 0 else 'hollow'}"
            errors, runs = {}, {}
            for nr in (2, 4, 8, 16, 32):
                runs[nr] = run = radial(f"{case}-nr{nr}", "-nr", str(nr), "-steps", "300", "-tend", "30", "-plane", plane,
                                        "-pipeE", STEEL[0], "-pipenu", STEEL[1], "-pipeRi", str(pipe_inner))
                s, p = run["summary"], run["summary"]["parameters"]
                a, b = p["ring_inner_radius"], p["ring_inner_radius"] + p["ring_thickness"]
                exact = compound_pressure(p["E"], p["nu"], a, b, float(STEEL[0]), float(STEEL[1]), pipe_inner,
                                          p["pipe_A"], plane)
                s_max = max(abs(float(r["s"])) for r in run["final"])
                austenite = float(run["rows"][-1]["fraction_austenite"])
                if austenite != 1 or s_max != 0:
                    check(False, f"{case} nr {nr}: all austenite ({austenite}) and elastic (max |s| {s_max}) at the end")
                errors[nr] = abs(s["final_pressure_mean"] / exact - 1)
            scene_formula = abs(runs[32]["summary"]["lame_pressure"] / exact - 1)
            orders = [math.log2(errors[n] / errors[2 * n]) for n in (2, 4, 8, 16)]
            print(f"{case}: compound pressure {exact / 1e6:.6f} MPa, errors "
                  + ", ".join(f"nr {n} {e:.2e}" for n, e in errors.items()) + "; orders "
                  + ", ".join(f"{o:.3f}" for o in orders))
            check(errors[32] < 2e-5 and all(1.9 <= o <= 2.1 for o in orders) and scene_formula < 1e-10,
                  f"{case}: final pressure at nr 32 within {errors[32]:.1e} < 2e-5 of the compound cylinders' "
                  f"{exact / 1e6:.6f} MPa, order {min(orders):.3f} to {max(orders):.3f} in nr; the scene's own "
                  f"lame_pressure agrees with tools/lame.py to {scene_formula:.1e}")
            entry = {"exact_Pa": exact, "errors": {str(n): e for n, e in errors.items()}, "orders": orders}
            if pipe_inner > 0:
                s = runs[32]["summary"]
                pipe = s["pipe"]
                exact_inner = pipe_inner_displacement(float(STEEL[0]), float(STEEL[1]), pipe_inner, pipe["outer_radius"],
                                                      pipe["pressure_pipe"], plane)
                inner_error = abs(pipe["u_inner"] / exact_inner - 1)
                check(inner_error < 1e-4, f"{case} nr 32: the pipe's inner surface moves by {pipe['u_inner'] * 1e6:.4f} um, "
                      f"{inner_error:.1e} < 1e-4 from the closed form at its pressure")
                entry["pipe_inner_displacement_error"] = inner_error
            figures["compound"][case] = entry
            figures["action_reaction"][case + "-nr32"] = action_reaction(f"{case} nr 32", runs[32])

    # 2. Rigid limit on the default run.
    paper = ("-scale", "paper")
    rigid = radial("rigid", *paper)
    stiff = {E: radial(f"E{E}", *paper, "-pipeE", E) for E in ("1e15", "1e13")}
    pmax = max(float(r["pressure_mean"]) for r in rigid["rows"])
    difference = {}
    for E, run in stiff.items():
        same_rows = len(run["rows"]) == len(rigid["rows"])
        difference[E] = max(abs(float(a["pressure_mean"]) - float(b["pressure_mean"]))
                            for a, b in zip(rigid["rows"], run["rows"])) / pmax
        status = sum(a["contact_nodes"] != b["contact_nodes"] for a, b in zip(rigid["rows"], run["rows"]))
        figures["action_reaction"]["default-E" + E] = action_reaction(f"default run, -pipeE {E}", run)
        if E == "1e15":
            events = [(k, rigid["summary"][k], run["summary"][k]) for k in ("first_contact_step", "austenite_step")]
            check(same_rows and status == 0 and all(x == y for _, x, y in events) and difference[E] <= 2e-5,
                  f"rigid limit: -pipeE 1e15 against the rigid pipe: pressure curve within {difference[E]:.2e} "
                  f"<= 2e-5 of its maximum {pmax / 1e6:.3f} MPa over {len(run['rows'])} steps, contact status equal at "
                  f"every step ({status} differ), events {events}")
    ratio = difference["1e13"] / difference["1e15"]
    check(80 <= ratio <= 120, f"rigid limit: the difference grows as 1/E: {difference['1e13']:.2e} at 1e13 against "
          f"{difference['1e15']:.2e} at 1e15 (ratio {ratio:.1f}, 100 expected)")
    figures["rigid_limit"] = {"relative_difference": difference, "ratio_1e13_over_1e15": ratio}

    # 4. Bad inputs name the option.
    bad_cases = [
        (["edp/scenes/sleeve-radial.edp", "-pipeE", "-1"], "error: sleeve-radial: -pipeE -1 must be in (0, 1e15] Pa"),
        (["edp/scenes/sleeve-radial.edp", "-pipeE", "2e15"], "error: sleeve-radial: -pipeE 2e+15 must be in (0, 1e15] Pa"),
        (["edp/scenes/sleeve-radial.edp", "-pipeE", "2e11", "-pipenu", "0.5"],
         "error: sleeve-radial: -pipenu 0.5 must be in (-1, 0.5)"),
        (["edp/scenes/sleeve-radial.edp", "-pipeE", "2e11", "-pipeRi", "0.0505"],
         "error: sleeve-radial: -pipeRi 0.0505 must be in [0, -pipeA 0.0505) m"),
        (["edp/scenes/sleeve-circular.edp", "-pipeE", "2e11"], "error: sleeve-circular: -pipeE 2e+11: the elastic pipe"),
    ]
    for args, start in bad_cases:
        bad = subprocess.run([os.path.join(ROOT, "tools", "ff"), *args, "-out", os.path.join(TEST_RESULTS, "sleeve-pipe-bad")],
                             cwd=ROOT, capture_output=True, text=True)
        said = [ln for ln in (bad.stdout + bad.stderr).splitlines() if ln.startswith("error:")]
        check(bad.returncode == 1 and len(said) == 1 and said[0].startswith(start),
              f"{' '.join(args[1:])} fails (exit {bad.returncode}) with one line naming it: {said}")

    record("sleeve_pipe", dict(figures, test="sleeve_pipe"))
    finish()


if __name__ == "__main__":
    main()
