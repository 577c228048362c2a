#!/usr/bin/python3
"""The figure scenes at their defaults, the paper's scale (-scale paper: the 5 cm ring on the
5.05 cm pipe, a = 2625 fitted to the paper's statements, docs/paper-scale.md), against the paper's
statements that the fit found them to agree with (section 4; docs/paper-scale.md's ids):

  - S1-S3, sleeve-circular (Fig. 12): zero force before contact, then linear in T while the ring
    is martensite, jumps while it reverts, constant once austenite (checklib.four_phases); the
    final pressure uniform and equal to Lame's shrink fit of the 0.5 mm interference (plane
    strain, the closed form of tools/bench/oracles/lame.py) within 0.2 %: of order 0.1 GPa, the paper's axis;
  - S4b, sleeve-circular-gvar (Fig. 18-19): zero force before contact, a long contact stage while
    martensite (not linear in T here: R^2 0.96, recorded), constant once austenite, the same final
    level (0.1 %), austenite for good earlier than with constant g;
  - S6, sleeve-elliptic (Fig. 26-27): contact starts on the major axis (y) steps before the minor
    axis (x) touches, and the major axis' pressure falls back (the paper's "relachement") by more
    than 10 % of its maximum before that; the final pressure nearly uniform (within 3 %), higher
    on the major axis, and below the circular case's;
  - S5, sleeve-offset (Fig. 22-23, half-ring coarse mesh): the final pressure uniform within 5 %
    and within 1 % of the circular case's level;
    and, with point A at the tangent point held rigidly (-anchorpoint tangent -anchor 1e3), the
    paper's account of it: the near side and the top touch within a step of the centred ring's
    first contact (a zero-force stage everywhere), while the soft spring on the top lets the near
    side touch at step 1;
  - S9, sleeve-random-threshold (Fig. 34): the reversion starts within 2.5 K of the paper's -25 C.
The headers of sleeve-circular (with its steel shaft, -pipeE 2.1e11), sleeve-circular-gvar,
sleeve-elliptic, sleeve-random-threshold and sleeve-offset (its default mesh: one more run) quote
these runs' numbers as printed (checklib.header_quotes), and README's table those of sleeve-elliptic,
sleeve-offset and sleeve-random-threshold. And the reduced scale is a preset: -scale reduced gives back the printed a = 300 and the meshes'
55 um interference. Records results/checks/paper_scale.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools", "bench", "oracles"))

from checklib import (KELVIN_AT_0C, celsius, check, doc_quotes, finish, four_phases, header_quotes, r_squared,  # noqa: E402
                      record, run_scene, sleeve_geometry, sleeve_outputs)
from lame import lame_pressure  # noqa: E402

# The default scale, stated so that run_scene does not pin the reduced scale, and the paper's fixed
# increments (-tol 0: the scenes' 1500, or the -steps given), on which the paper's figures are judged.
PAPER = ["-scale", "paper", "-tol", "0"]


def point_curve(run, axis):
    return ([float(r[f"T_{axis}_K"]) for r in run["points"]], [float(r[f"pressure_{axis}_Pa"]) for r in run["points"]])


def stages(label, run):
    hist = run["history"]
    T, p = point_curve(run, "x_axis")
    austenite = [float(r["fraction_austenite"]) for r in hist]
    first_contact = next(i for i, r in enumerate(hist) if int(r["contact_nodes"]) > 0)
    return four_phases(label, T, p, austenite, first_contact)


def main():
    figures = {}
    circ = sleeve_outputs(run_scene("sleeve-circular", "paper-circular", *PAPER, "-quiet", "1", "-vtkevery", "0"))
    s = circ["summary"]
    prm = s["parameters"]
    check(prm["scale"] == "paper" and prm["a"] == 2625, f"the default scale is the paper's: {prm['scale']}, a = {prm['a']}")
    figures["circular"] = stages("sleeve-circular (paper scale)", circ)
    Ri = prm["ring_inner_radius"]
    Ro = Ri + sleeve_geometry()["Hr"]  # the ring's thickness: the meshes' (stretched radially to Ri)
    lame = lame_pressure(prm["E"], prm["nu"], Ri, Ro, prm["pipe_A"] - Ri)
    final = s["final_pressure_mean"]
    check(abs(prm["pipe_A"] - Ri - 5e-4) < 1e-9 and abs(final / lame - 1) <= 2e-3
          and s["final_pressure_non_uniformity"] <= 0.01,
          f"S3: final pressure {final / 1e9:.4f} GPa, Lame's for the 0.5 mm interference {lame / 1e9:.4f} GPa "
          f"({final / lame - 1:+.2e}), uniform within {s['final_pressure_non_uniformity']:.1e}")
    figures["circular"].update(final_pressure_Pa=final, lame_Pa=lame)
    # Its header quotes this run, and the steel shaft's (-pipeE 2.1e11), as printed.
    steel = sleeve_outputs(run_scene("sleeve-circular", "paper-circular-steel", *PAPER, "-quiet", "1", "-vtkevery", "0",
                                     "-pipeE", "2.1e11"))["summary"]
    onset_row = next(r for r in circ["history"] if float(r["fraction_austenite"]) > 0)  # (the reversion's first step)
    contact_step = s["first_contact_step"]
    header_quotes("edp/scenes/sleeve-circular.edp", [
        f"zero ({contact_step - 1} steps, no contact yet); contact at step {contact_step} (inner "
        f"{s['T_inner_first_contact'] - KELVIN_AT_0C:.1f} C)", f"martensite ({int(onset_row['step']) - contact_step} steps",
        f"from {float(onset_row['T_inner_mean']) - KELVIN_AT_0C:.1f} C the steep rise",
        f"(step {s['austenite_step']}, {s['T_inner_austenite'] - KELVIN_AT_0C:.1f} C): {final / 1e9:.3f} GPa",
        f"austenite for good at step {steel['austenite_step']} ({steel['T_inner_austenite'] - KELVIN_AT_0C:.1f} C), final "
        f"pressure {steel['final_pressure_mean'] / 1e6:.3f} MPa"])

    gvar = sleeve_outputs(run_scene("sleeve-circular-gvar", "paper-gvar", *PAPER, "-quiet", "1", "-vtkevery", "0"))
    # Its stages on the mean pressure against the inner surface's mean temperature (the heat
    # exchange now differs along the surface, the x axis' point alone is not the ring's curve).
    hist = gvar["history"]
    p = [float(r["pressure_mean"]) for r in hist]
    T = [float(r["T_inner_mean"]) for r in hist]
    contact = next(i for i, v in enumerate(p) if v > 0)
    onset = next(i for i, r in enumerate(hist) if float(r["fraction_austenite"]) > 0)
    austenite = max(i for i, r in enumerate(hist) if float(r["fraction_austenite"]) < 1) + 1
    r2, _ = r_squared(T[contact:onset], p[contact:onset])
    spread = (max(p[austenite:]) - min(p[austenite:])) / p[-1]
    # (The stage between is not linear here: R^2 0.96; recorded, not asserted: docs/figures.md.)
    check(contact >= 3 and onset - contact >= 50 and spread < 1e-6,
          f"S4b: variable g: zero force over {contact} steps, contact while martensite over {onset - contact} "
          f"steps (R^2 of the mean pressure in T {r2:.3f}), constant after step {austenite + 1} (spread {spread:.1e})")
    figures["gvar"] = {"zero_steps": contact, "linear_steps": onset - contact, "linear_r2": r2,
                       "all_austenite_step": austenite + 1}
    fg = gvar["summary"]["final_pressure_mean"]
    check(abs(fg / final - 1) <= 1e-3 and figures["gvar"]["all_austenite_step"] < figures["circular"]["all_austenite_step"],
          f"S4b: variable g ends at the same level ({fg / final - 1:+.1e}) and earlier: austenite for good at step "
          f"{figures['gvar']['all_austenite_step']} against {figures['circular']['all_austenite_step']}")

    # The scene's header quotes this run (and the circular one) as printed.
    gs, cs = gvar["summary"], circ["summary"]
    counts = [int(r["contact_nodes"]) for r in hist]
    flips = [i for i in range(contact + 1, len(hist)) if counts[i] != counts[i - 1]]
    flip_counts = sorted(set(counts[contact:flips[-1] + 1])) if flips else [0]

    def t_final(run):  # the time of the first step all austenite
        return float(run["history"][run["summary"]["austenite_step"] - 1]["t"])
    header_quotes("edp/scenes/sleeve-circular-gvar.edp", [
        f"contact at step {gs['first_contact_step']} (inner {celsius(gs['T_inner_first_contact']):.1f} C",
        f"warmer than sleeve-circular's {celsius(cs['T_inner_first_contact']):.1f} C",
        f"from {float(hist[flips[0]]['t']) if flips else 0:.1f} s to {float(hist[flips[-1]]['t']) if flips else 0:.1f} s "
        f"the contact set flips between every other bore node ({flip_counts[0]}) and all {flip_counts[-1]}",
        f"from {celsius(T[onset]):.1f} C", f"reached earlier ({t_final(gvar):.1f} s instead of {t_final(circ):.1f} s, at inner "
        f"{celsius(gs['T_inner_austenite']):.1f} C), the same {fg / 1e9:.3f} GPa", f"(R^2 {r2:.2f} of the mean pressure)"])

    ell = sleeve_outputs(run_scene("sleeve-elliptic", "paper-elliptic", *PAPER, "-quiet", "1", "-vtkevery", "0"))
    _, p_minor = point_curve(ell, "x_axis")
    _, p_major = point_curve(ell, "y_axis")
    major_first = next(i for i, v in enumerate(p_major) if v > 0)
    minor_first = next(i for i, v in enumerate(p_minor) if v > 0)
    peak = max(p_major[:minor_first + 1])
    fall = (peak - p_major[minor_first]) / peak
    check(major_first + 5 < minor_first and fall > 0.10,
          f"S6: contact on the major axis at step {major_first + 1}, the minor axis at {minor_first + 1}; the major "
          f"axis' pressure falls {100 * fall:.0f} % of its maximum before (the paper's loosening)")
    es = ell["summary"]
    ratio = p_major[-1] / p_minor[-1] - 1
    check(0 < ratio < 0.03 and es["final_pressure_mean"] < final,
          f"S6b: final pressure nearly uniform, {100 * ratio:+.2f} % higher on the major axis, mean "
          f"{es['final_pressure_mean'] / 1e9:.4f} GPa below the circular {final / 1e9:.4f} GPa")
    touch = minor_first  # (the row where the minor axis touches)
    header_quotes("edp/scenes/sleeve-elliptic.edp", [
        f"major (y) axis at step {es['first_contact_step']} (inner {es['T_inner_first_contact'] - KELVIN_AT_0C:.1f} C)",
        f"rises to {max(p_major[:touch]) / 1e6:.1f} MPa and falls back to {p_major[touch] / 1e6:.1f} MPa (the paper's "
        f"loosening, {100 * (1 - p_major[touch] / max(p_major[:touch])):.0f} %) by the time the minor axis touches (step "
        f"{ell['points'][touch]['step']})", f"final {es['final_pressure_mean'] / 1e9:.4f} GPa",
        f"({p_major[-1] / 1e6:.1f} vs {p_minor[-1] / 1e6:.1f} MPa)"])
    # and README's table, of the same run
    readme = [f"contact on the major axis first (step {es['first_contact_step']}), whose pressure falls back by "
              f"{100 * (1 - p_major[touch] / max(p_major[:touch])):.0f} % before the minor axis touches (step "
              f"{ell['points'][touch]['step']}: the paper's loosening), final force "
              f"{100 * (1 - es['final_pressure_mean'] / final):.0f} % below the circular case, "
              f"{100 * (p_major[-1] / p_minor[-1] - 1):.1f} % higher on the major axis"]
    figures["elliptic"] = {"major_first_contact_step": major_first + 1, "minor_first_contact_step": minor_first + 1,
                           "major_fall": fall, "major_over_minor": ratio,
                           "final_over_circular": es["final_pressure_mean"] / final}

    off = sleeve_outputs(run_scene("sleeve-offset", "paper-offset", *PAPER, "-quiet", "1", "-vtkevery", "0",
                                   "-mesh", "meshes/sleeve-half-coarse.msh", "-steps", "750"))
    os_ = off["summary"]
    check(os_["parameters"].get("offset", 5e-4) == 5e-4 and os_["final_pressure_non_uniformity"] <= 0.05
          and abs(os_["final_pressure_mean"] / final - 1) <= 0.01,
          f"S5: off-centre by the paper's 0.05 cm, the final pressure uniform within "
          f"{100 * os_['final_pressure_non_uniformity']:.1f} % and {100 * (os_['final_pressure_mean'] / final - 1):+.2f} % "
          f"from the circular case's")
    figures["offset"] = {"non_uniformity": os_["final_pressure_non_uniformity"],
                         "final_over_circular": os_["final_pressure_mean"] / final,
                         "step_fallbacks": os_.get("step_fallbacks", 0)}

    # The scene's header quotes its defaults' run (the default mesh, the fixed steps) as printed.
    full = sleeve_outputs(run_scene("sleeve-offset", "paper-offset-default", *PAPER, "-quiet", "1", "-vtkevery", "0"))
    fs = full["summary"]
    touch_step = {point: next(int(r["step"]) for r in full["points"] if float(r[f"pressure_{point}_Pa"]) > 0)
                  for point in ("near", "top", "far")}
    header_quotes("edp/scenes/sleeve-offset.edp", [
        f"the near side touches at step {touch_step['near']} (the offset equals the interference), the top at step "
        f"{touch_step['top']}, the far side at step {touch_step['far']}; the ring slides over by "
        f"{fs['anchor_displacement_x'] * 1e3:.2f} mm", f"the final level {fs['final_pressure_mean'] / 1e9:.4f} GPa "
        f"({100 * (fs['final_pressure_mean'] / final - 1):.1f} % above the circular sleeve's), uniform within "
        f"{100 * fs['final_pressure_non_uniformity']:.1f} %"])
    readme.append(f"the ring recentres (slides {fs['anchor_displacement_x'] * 1e3:.2f} mm), final force uniform within "
                  f"{100 * fs['final_pressure_non_uniformity']:.1f} % at the centred level "
                  f"({100 * (fs['final_pressure_mean'] / final - 1):+.1f} %)")

    # Fig. 21-24, the paper's account (4.3: "the deformed ring coincides at one instant with the
    # pipe, and contact occurs then at every point"): point A where the offset ring touches the
    # pipe (the offset equals the interference), held rigidly. The ring dilates about A and meets
    # the pipe everywhere at once, when its dilatation reaches the interference: the instant the
    # centred ring touches (an independent run at the same time step).
    def first_contact(run, point):
        return next(int(r["step"]) for r in run["points"] if float(r[f"pressure_{point}_Pa"]) > 0)
    coarse = ["-quiet", "1", "-vtkevery", "0", "-steps", "750"]
    tangent = sleeve_outputs(run_scene("sleeve-offset", "paper-offset-tangent", *PAPER, *coarse, "-mesh",
                                       "meshes/sleeve-half-coarse.msh", "-anchorpoint", "tangent", "-anchor", "1e3"))
    centred = sleeve_outputs(run_scene("sleeve-circular", "paper-centred-coarse", *PAPER, *coarse, "-mesh",
                                       "meshes/sleeve-coarse.msh"))
    near, top, soft_near = first_contact(tangent, "near"), first_contact(tangent, "top"), first_contact(off, "near")
    ring = first_contact(centred, "x_axis")
    ts = tangent["summary"]
    check(near >= 3 and abs(near - ring) <= 1 and abs(top - ring) <= 1 and soft_near == 1
          and ts["final_pressure_non_uniformity"] <= 0.05 and abs(ts["final_pressure_mean"] / final - 1) <= 0.01,
          f"S5 with point A at the tangent point, fixed: the near side and the top first touch at steps {near} and "
          f"{top}, the centred ring at {ring} (a zero-force stage; with the soft spring on the top: the near side "
          f"at step {soft_near}); final uniform within {100 * ts['final_pressure_non_uniformity']:.1f} %, "
          f"{100 * (ts['final_pressure_mean'] / final - 1):+.2f} % from the circular case's")
    figures["offset_tangent_anchor"] = {"first_contact_near": near, "first_contact_top": top,
                                        "first_contact_centred": ring,
                                        "non_uniformity": ts["final_pressure_non_uniformity"]}

    rnd = sleeve_outputs(run_scene("sleeve-random-threshold", "paper-random", *PAPER, "-quiet", "1", "-vtkevery", "0"))
    hist = rnd["history"]
    onset = next(r for r in hist if float(r["fraction_austenite"]) > 0)
    onset_C = float(onset["T_inner_mean"]) - KELVIN_AT_0C
    check(abs(onset_C - (-25.0)) <= 2.5, f"S9: the random threshold's reversion starts at {onset_C:.1f} C (paper: -25 C)")
    figures["random"] = {"reversion_onset_C": onset_C, "seed": rnd["summary"].get("seed")}
    readme.append(f"the phase change from {onset_C:.0f} C (paper: -25 C)")
    doc_quotes("README.md", readme)
    header_quotes("edp/scenes/sleeve-random-threshold.edp", [
        f"phase change from {onset_C:.1f} C (paper: -25 C)",
        f"(austenite for good at {rnd['summary']['T_inner_austenite'] - KELVIN_AT_0C:.1f} C instead of "
        f"{s['T_inner_austenite'] - KELVIN_AT_0C:.1f} C)",
        f"sleeve-circular ({rnd['summary']['final_pressure_mean'] / 1e9:.3f} GPa, all austenite)"])

    red = sleeve_outputs(run_scene("sleeve-circular", "paper-reduced", "-scale", "reduced", "-quiet", "1",
                                   "-vtkevery", "0", "-steps", "150"))["summary"]["parameters"]
    interference = red["pipe_A"] - red["ring_inner_radius"]
    check(red["scale"] == "reduced" and red["a"] == 300 and abs(interference - 55e-6) < 1e-9,
          f"-scale reduced: a = {red['a']}, interference {1e6 * interference:.1f} um")
    record("paper_scale", figures)
    finish()


if __name__ == "__main__":
    main()
