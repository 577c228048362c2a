#!/usr/bin/python3
"""The paper's claims about its figures 11-36 (every checkable statement of its section 4 and of the
figures' captions), one row each, in its own words (tools/docs/claims_quotes.py), measured on three
runs of each figure scene: at its defaults but for the paper's 1500 fixed increments (-tol 0; the
default phase model, results/<scene>/ from make figures), with the paper's on/off scheme (results/claims/onoff-<scene>/) and with the paper's algorithm replayed (its on/off law
and iteration caps, results/claims/replay-<scene>/); a verdict on each from one rule
(tools/docs/claims_rules.py) and, for each disagreement of the default, the run that tests an
explanation (results/claims/<name>/) or "open"; each agreement marked fitted or predicted.
tools/docs/figures.py puts the table at the head of docs/figures.md.

Usage: tools/docs/claims.py --run   the runs (tools/docs/claims_runs.py; make figures)
       (tools/docs/figures.py imports table())
The measures are those of tools/docs/paper_scale_metrics.py (docs/paper-scale.md) and
tools/docs/claims_measures.py, read from these runs; a statement no output shows is a row "not
measured", naming the output it needs.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from claims_measures import (angular_variation, axis_nodal_ratio, constant_after_austenite, contact_spread,  # noqa: E402
                             equal_time_comparison, equilibrium_times, five_phases, friction_by_axis,
                             martensite_at_contact, plotted_points_peak, psor_at_grazing, reversion_abruptness, single_precision_spread,
                             tangential_over_normal_max, temperature_bands, temperature_spread)
from claims_quotes import QUOTES, said  # noqa: E402
from claims_rules import counts_line, crossing_verdict, first_sustained, joined, pct, side_word, steps, verdict  # noqa: E402
from claims_runs import ROOT, RUNS, START, default, out_of, run_all  # noqa: E402
from paper_scale_metrics import (curve, ellipse_metrics, gvar_crossing, hist, offset_metrics, reversion_start,  # noqa: E402
                                 summ, tmin_position)

def replayed(name):
    return out_of("replay-" + name)


def table():
    """The Markdown lines of the claims table; [] with a note when a run is missing."""
    need = [default(s) for s in ("sleeve-circular", "sleeve-circular-gvar", "sleeve-offset", "sleeve-elliptic",
                                 "sleeve-elliptic-friction", "sleeve-random-threshold")] + [out_of(n) for n in RUNS]
    absent = [d for d in need if not os.path.exists(os.path.join(d, "summary.json"))]
    if absent:
        return ["*(claims table: runs missing: " + ", ".join(os.path.relpath(d, ROOT) for d in absent)
                + "; make figures runs them)*", ""]
    rows, verdicts, notes = [], [], []

    def row(figs, key, ours, onoff, replay, words, explanation, fitted=False):
        """key: the row's quote (claims_quotes.QUOTES); words: the verdicts on the default, on/off and
        replay runs ("" where not measured). A line over 400 characters moves its explanation to a
        numbered note below the table, then if still too long the paper's words too."""
        verdict_text = joined(*words)
        if side_word(verdict_text, 0) != "agrees" and side_word(verdict_text, 2) == "agrees" \
                and side_word(verdict_text, 1) != "agrees":
            rest = explanation[len("explained: "):] if explanation.startswith("explained: ") else explanation
            explanation = ("explained: an artefact of the paper's iteration caps (only the replay shows it)"
                           + (f"; {rest}" if rest else ""))
        mark = " (fitted)" if fitted and side_word(verdict_text, 0) == "agrees" else ""
        french, english = QUOTES[key]
        claim, cell = said(key) + mark, explanation
        line = (lambda: f"| {figs} | {claim} | {ours} | {onoff} | {replay} | {verdict_text} | {cell} |")
        if len(line()) > 400 and explanation:  # a line a reader need not scroll (tests/docs_test.py)
            notes.append(f"{len(notes) + 1}. Fig. {figs}, {said(key)}: {explanation}")
            word = explanation.split(":")[0] if explanation.startswith(("open:", "explained:")) else ""
            cell = f"{word + ', ' if word else ''}note {len(notes)} below"
        if len(line()) > 400:
            if cell == explanation:
                notes.append(f"{len(notes) + 1}. Fig. {figs}, the paper's words: «{french}»")
            claim = f"({english}{mark}; the paper's words in note {len(notes)})"
        rows.append(line())
        verdicts.append((verdict_text, explanation, [w != "" for w in words], fitted))

    def three(scene):
        return default(scene), out_of("onoff-" + scene), replayed(scene)
    c, co, cr = (curve(d) for d in three("sleeve-circular"))
    g, go, gr = (curve(d) for d in three("sleeve-circular-gvar"))
    pc, po, pr = (summ(d)["final_pressure_mean"] for d in three("sleeve-circular"))
    # ---- Fig. 11-14 (the first contact: the first of two steps in a row in contact, a single step's
    # touch is not the start of contact)
    zero = [first_sustained(hist(d)["contact_nodes"]) - 1 for d in three("sleeve-circular")]
    row("11-12", "zero", steps(zero[0]), steps(zero[1]), steps(zero[2]),
        [verdict(z > 0) for z in zero], "the coefficient a (2625) is the smallest that clears the pipe: "
        "docs/paper-scale.md", fitted=True)
    at_once = [contact_spread(d) for d in three("sleeve-circular")]
    row("11-12", "everywhere", *[f"all nodes {x['dT']:.2f} K ({steps(x['steps'])}) after a twentieth, of the "
                                 f"{x['span']:.1f} K martensite stage" for x in at_once],
        [verdict(x["dT"] < 0.05 * x["span"], x["before_onset"]) for x in at_once], "")
    mart = [martensite_at_contact(d) for d in three("sleeve-circular")]
    row("11-12", "martensite", *[f"martensite {100 * x:.1f} % of the ring at the first contact" for x in mart],
        [verdict(x > 0.99) for x in mart], "")
    row("11-12", "linear", f"{steps(c['linear_steps'])}, R^2 {c['linear_R2']:.5f}",
        f"{steps(co['linear_steps'])}, R^2 {co['linear_R2']:.5f}", f"{steps(cr['linear_steps'])}, R^2 {cr['linear_R2']:.5f}",
        [verdict(x["linear_R2"] > 0.99) for x in (c, co, cr)], "")
    row("11-12", "jerks",
        f"largest rise {100 * c['max_jump']:.1f} % of the final force, {steps(c['jumps_over_1pct'])} above 1 %",
        f"largest {100 * co['max_jump']:.1f} %, {steps(co['jumps_over_1pct'])} above 1 %",
        f"largest {100 * cr['max_jump']:.1f} %, {steps(cr['jumps_over_1pct'])} above 1 %",
        [verdict(x["jumps_over_1pct"] > 0) for x in (c, co, cr)],
        "explained: the jumps are the on/off scheme's (whole layers switching), converged or not; the default "
        "holds each fraction by the heat balance and converges (docs/reference.md)")
    start = json.load(open(os.path.join(out_of("circular-frames"), START)))["fraction_of_thickness"]
    start_ins = json.load(open(os.path.join(out_of("circular-outer-insulated"), START)))["fraction_of_thickness"]
    row("11-12", "inner",
        f"at {start:.2f} of the thickness from the inner surface (1: outer)", "", "",
        [verdict(start < 0.3), "", ""],
        f"explained: both faces exchange heat at the printed g = 500 (the paper does not say which do): with the "
        f"outer face insulated (results/claims/circular-outer-insulated) it starts at {start_ins:.2f}, the inner surface")
    sudden = [reversion_abruptness(d) for d in three("sleeve-circular")]
    row("11-12", "sudden", *[f"{100 * a:.1f} % of the ring in a step at most; 10-90 % austenite in {w:.1f} K"
                             for a, w in sudden], [verdict(a >= 0.1, w < 3) for a, w in sudden],
        "explained: as the jumps (the row above), whole layers switching in one step are the on/off scheme's")
    settled = [constant_after_austenite(d) for d in three("sleeve-circular")]
    row("11-12", "constant", *[f"{x['final_GPa']:.4f} GPa, changes {100 * y:.3f} % after" for x, y in zip((c, co, cr), settled)],
        [verdict(y < 1e-3) for y in settled], "")
    uniform = [summ(d)["final_pressure_non_uniformity"] for d in three("sleeve-circular")]
    row("13", "uniform", *[f"non-uniform {100 * u:.2f} %" for u in uniform], [verdict(u < 0.01) for u in uniform], "")
    radial = [(tangential_over_normal_max(d), tangential_over_normal_max(e))
              for d, e in zip(three("sleeve-circular"), three("sleeve-offset"))]
    row("13, 23", "radial", *[f"tangential/normal at most {a:.1e} (off-centre: {b:.1e})" for a, b in radial],
        [verdict(max(x) < 1e-6) for x in radial], "")
    bands = [temperature_bands(d) for d in three("sleeve-circular")]
    row("14", "bands", *[f"T varies {100 * b:.1f} % of its range along a ring" for b in bands],
        [verdict(b < 0.05) for b in bands], "" if bands[2] < 0.05 else "the replay's loose contact solve "
        "leaves an unsymmetric phase pattern (Fig. 15-16 below)")
    graze = [psor_at_grazing(d) for d in three("sleeve-elliptic")]
    row("4.2.1", "grazing", f"ellipse: {graze[0][0]:.0f} PSOR sweeps at most while part of it touches, median "
        f"{graze[0][1]:.0f} once all does", *[f"at most {a:.0f}, median {b:.0f}" for a, b in graze[1:]], [verdict(a >= 2 * b, a > b) for a, b in graze],
        "the converged runs' PSOR (to a relative 1e-10; 1e-3 in the replay) takes as many sweeps while part "
        "of the surface touches as once all of it does")
    # ---- Fig. 15-16
    first, spread_first, spread_end = single_precision_spread(default("sleeve-circular-single"))
    _, spread_first_r, spread_end_r = single_precision_spread(replayed("sleeve-circular-single"))
    _, spread_double, spread_double_end = single_precision_spread(default("sleeve-circular"))
    _, spread_double_r, spread_double_end_r = single_precision_spread(replayed("sleeve-circular"))
    s1 = curve(default("sleeve-circular-single"))
    row("15-16", "single-differ",
        f"{100 * spread_first:.0f} % apart at the first contact step ({first}), {spread_end:.1e} at the end", "",
        f"{100 * spread_first_r:.0f} % apart at the first contact step, {spread_end_r:.1e} at the end",
        [verdict(spread_end > 0.01, spread_first > 0.01), "", verdict(spread_end_r > 0.01, spread_first_r > 0.01)],
        "only the coordinates are rounded here (the 1998 code computed in single precision throughout): apart "
        "at the first contact step only; docs/figures.md, Fig. 15-16, for the phases, which stay symmetric")
    row("15-16", "double",
        f"{spread_double:.1e} apart at the first contact step, {spread_double_end:.1e} at the end", "",
        f"{spread_double_r:.1e}, {spread_double_end_r:.1e}",
        [verdict(max(spread_double, spread_double_end) < 1e-6), "",
         verdict(max(spread_double_r, spread_double_end_r) < 1e-6)],
        "" if max(spread_double_r, spread_double_end_r) < 1e-6 else "the replay's points differ in double "
        "precision too: its loose contact solve, not the arithmetic (the row above)")
    asym = [angular_variation(d, "2-contact", "martensite_fraction", mirror=True) for d in
            (default("sleeve-circular-single"), replayed("sleeve-circular-single"), default("sleeve-circular"),
             replayed("sleeve-circular"))]
    row("15", "single-local", f"martensite fractions {asym[0]:.2f} apart between mirror sectors (double: {asym[2]:.2f})",
        "", f"{asym[1]:.2f} (double: {asym[3]:.2f})", [verdict(asym[0] > 0.05), "", verdict(asym[1] > 0.05)],
        "at the instant 2-contact (half the ring austenite); the replay's phases are as unsymmetric in double "
        "precision: its loose contact solve, not the arithmetic")
    row("15-16", "single-process",
        f"austenite for good at step {s1['austenite_step']} against {c['austenite_step']} in double precision", "", "",
        [verdict(abs(s1["austenite_step"] - c["austenite_step"]) > 0.01 * c["austenite_step"]), "", ""],
        "open: only the coordinates are rounded here; the 1998 code computed in single precision throughout, "
        "which no run here does")
    row("15-16", "no-contact", *["not measured: a beam run with its coordinates rounded (the beam scene has no "
                                 "-float)"] + ["", ""], ["", "", ""], "")
    # ---- Fig. 17-20
    gs = summ(default("sleeve-circular-gvar"))
    cross = [gvar_crossing(*pair) for pair in zip(three("sleeve-circular"), three("sleeve-circular-gvar"))]
    lower_t, higher_t = equal_time_comparison(default("sleeve-circular"), default("sleeve-circular-gvar"))
    cross25 = gvar_crossing(out_of("circular-pipe-25C"), out_of("gvar-pipe-25C"))
    cross30 = gvar_crossing(out_of("circular-pipe-30C"), out_of("gvar-pipe-30C"))
    final25, final30 = (summ(out_of(f"gvar-pipe-{t}C"))["final_pressure_mean"]
                        / summ(out_of(f"circular-pipe-{t}C"))["final_pressure_mean"] - 1 for t in (25, 30))
    t25 = (curve(out_of("gvar-pipe-25C"))["t_final_s"], curve(out_of("circular-pipe-25C"))["t_final_s"])
    cross_text = (lambda x: "lower at every temperature" if math.isnan(x) else f"lower only below {x:.1f} C")
    where, frame = reversion_start(default("sleeve-circular-gvar"), g["onset_step"])
    row("17-20", "gvar-interface", f"at {where:.2f} of the thickness from the inner surface (frame of step {frame})",
        "", "", [verdict(where < 0.3), "", ""], "")
    row("17-18", "gvar-lower",
        cross_text(cross[0]), cross_text(cross[1]), cross_text(cross[2]), [crossing_verdict(x) for x in cross],
        "open: the paper bounds the statement to \"the first phase (temperature below -30 C)\" and says "
        "nothing of the force above; ours is lower there too, up to the final level. Tried: the comparison "
        f"at equal time instead of equal temperature (the default runs): gvar lower at {steps(lower_t)}, higher "
        f"from step {higher_t[0]} to {higher_t[1]} (the opposite); the on/off scheme and the paper's algorithm "
        "(columns 4, 5); the faces that exchange heat and the coefficient a (docs/paper-scale.md S4, S8d: no "
        "crossing); fits of L, T0, C0, k, Tinit with a (docs/fig17-fit.md: 23 candidates, no crossing but at "
        "contact); the pipe's temperature (results/claims/*-pipe-*): the gvar interface stalls near it while "
        f"the ring warms from outside, so the curves cross near it: pipe at -25 C, crossing at {cross25:.1f} C, "
        f"the same final level ({pct(final25)}), austenite at {t25[0]:.1f} s against {t25[1]:.1f} s; pipe at "
        f"-30 C, crossing at {cross30:.1f} C but the ring near the pipe never turns austenite for good (final "
        f"{pct(final30)})")
    row("17-18", "gvar-regular",
        f"largest rise {100 * g['max_jump']:.1f} % against {100 * c['max_jump']:.1f} %",
        f"{100 * go['max_jump']:.1f} % against {100 * co['max_jump']:.1f} %",
        f"{100 * gr['max_jump']:.1f} % against {100 * cr['max_jump']:.1f} %",
        [verdict(a["max_jump"] < b["max_jump"]) for a, b in ((g, c), (go, co), (gr, cr))],
        "explained: the default has no jumps to regularise (see Fig. 11-12)")
    gvar_final = [summ(d)["final_pressure_mean"] / p - 1 for d, p in zip(three("sleeve-circular-gvar"), (pc, po, pr))]
    row("17-20", "gvar-final",
        f"austenite at {g['t_final_s']:.1f} s against {c['t_final_s']:.1f} s; {pct(gvar_final[0])}, "
        f"non-uniform {100 * gs['final_pressure_non_uniformity']:.2f} %",
        f"{go['t_final_s']:.1f} s against {co['t_final_s']:.1f} s; {pct(gvar_final[1])}",
        f"{gr['t_final_s']:.1f} s against {cr['t_final_s']:.1f} s; {pct(gvar_final[2])}",
        [verdict(a["t_final_s"] < b["t_final_s"] and abs(x) < 0.01) for a, b, x in
         ((g, c, gvar_final[0]), (go, co, gvar_final[1]), (gr, cr, gvar_final[2]))], "")
    times = [(equilibrium_times(a), equilibrium_times(b)) for a, b in zip(three("sleeve-circular-gvar"),
                                                                           three("sleeve-circular"))]
    row("19", "gvar-maximum", *[f"at its level from {tg[0]:.1f} s, T even from {tg[1]:.1f} s (g constant: {tc[0]:.0f}, "
                                f"{tc[1]:.0f} s)" for tg, tc in times],
        [verdict(tg[0] <= tg[1] / 2, tg[0] < tg[1]) for tg, _ in times],
        "the middle of the warming: half the time the ring's T_max - T_min takes to stay below 1 K")
    row("20", "gvar-equilibrium", *[f"T_max - T_min below 1 K from {tg[1]:.1f} s against {tc[1]:.1f} s"
                                    for tg, tc in times], [verdict(tg[1] < tc[1]) for tg, tc in times], "")
    # ---- Fig. 21-24
    o, oo, orr = (offset_metrics(d, p) for d, p in zip(three("sleeve-offset"), (pc, po, pr)))
    ot = offset_metrics(out_of("offset-tangent-anchor"), pc)
    row("21-24", "offset-phases",
        f"first contact near / top / far at steps {o['first_near']} / {o['first_top']} / {o['first_far']}",
        f"{oo['first_near']} / {oo['first_top']} / {oo['first_far']}",
        f"{orr['first_near']} / {orr['first_top']} / {orr['first_far']}",
        [verdict(x["first_near"] > 1, x["first_top"] > 1) for x in (o, oo, orr)],
        "explained: the paper says the deformed ring \"coincides at one instant with the pipe, and contact "
        "occurs at that instant at every point\" (4.3): its near side had a zero-force stage. With point A "
        "where the offset ring touches the pipe (the offset equals the interference), held rigidly "
        "(results/claims/offset-tangent-anchor: -anchorpoint tangent -anchor 1e3), the ring dilates about A: "
        f"near / top first touch at steps {ot['first_near']} / {ot['first_top']} (the centred ring: "
        f"{c['zero_steps'] + 1}), final non-uniform {100 * ot['non_uniformity']:.1f} %, {pct(ot['vs_circular'])} "
        "against the centred ring. The default's A (top of the outer surface, soft) lets the ring slide "
        f"{o['slide_um']:.0f} um instead")
    at_once = [contact_spread(d) for d in three("sleeve-offset") + (out_of("offset-tangent-anchor"),)]
    row("21-24", "offset-at-once", *[f"all nodes {x['dT']:.2f} K ({steps(x['steps'])}) after a twentieth, of "
                                     f"{x['span']:.1f} K" for x in at_once[:3]],
        [verdict(x["dT"] < 0.05 * x["span"], x["before_onset"]) for x in at_once[:3]],
        f"explained: the near side touches from the first step (the offset, 0.05 cm, is the interference) and the "
        f"default's soft point A lets the ring slide; A held where the ring touches the pipe "
        f"(results/claims/offset-tangent-anchor): all nodes {at_once[3]['dT']:.2f} K after a twentieth, of "
        f"{at_once[3]['span']:.1f} K: " + verdict(at_once[3]["dT"] < 0.05 * at_once[3]["span"], at_once[3]["before_onset"]))
    row("21-23", "offset-uniform", f"non-uniform {100 * o['non_uniformity']:.1f} %, "
        f"{pct(o['vs_circular'])} against the centred ring", f"{100 * oo['non_uniformity']:.1f} %, {pct(oo['vs_circular'])}",
        f"{100 * orr['non_uniformity']:.1f} %, {pct(orr['vs_circular'])}",
        [verdict(x["non_uniformity"] < 0.05 and abs(x["vs_circular"]) < 0.05) for x in (o, oo, orr)], "")
    row("22-24", "offset-radial",
        f"the ring slides {o['slide_um']:.0f} um sideways", f"{oo['slide_um']:.0f} um", f"{orr['slide_um']:.0f} um",
        [verdict(abs(x["slide_um"]) < 50) for x in (o, oo, orr)],
        f"explained: the default's point A is soft; held rigidly where the ring touches the pipe "
        f"(results/claims/offset-tangent-anchor) it slides {ot['slide_um']:.0f} um")
    # ---- Fig. 25-28
    e, eo, er = (ellipse_metrics(d, p) for d, p in zip(three("sleeve-elliptic"), (pc, po, pr)))
    row("25-26", "ellipse-major", f"steps {e['major_first_step']} (major) < {e['minor_first_step']} (minor)",
        f"{eo['major_first_step']} < {eo['minor_first_step']}", f"{er['major_first_step']} < {er['minor_first_step']}",
        [verdict(x["major_first_step"] < x["minor_first_step"]) for x in (e, eo, er)], "")
    lifts = (lambda x: f"its pressure falls {100 * x['major_relax']:.0f} %, "
             + ("to zero" if x["major_lifts_before_minor"] else "not to zero"))
    row("25-26", "ellipse-release", lifts(e), lifts(eo), lifts(er),
        [verdict(x["major_lifts_before_minor"], x["major_relax"] > 0.1) for x in (e, eo, er)],
        "" if e["major_lifts_before_minor"] else
        "open: no run lifts off at the paper's scale (all loosen the major axis by about the same amount, the "
        "paper's algorithm replayed too); on the reduced scale's quarter mesh the on/off major axis lifts off "
        "(tests/sleeve_elliptic_test.py)")
    phases = [five_phases(d) for d in three("sleeve-elliptic") + three("sleeve-elliptic-friction")]
    five = (lambda x: f"{x['count']} of 5" + (f" (no {', '.join(x['missing'])})" if x["missing"] else "")
            + f" at the major axis: zero {steps(x['zero'])}, releases {x['releases']}, R^2 {x['R2']:.4f}")
    short = (lambda x: f"{x['count']} of 5" + (f" (no {', '.join(x['missing'])})" if x["missing"] else "")
             + f", releases {x['releases']}")
    row("25-26", "ellipse-five", five(phases[0]), *[short(x) for x in phases[1:3]],
        [verdict(x["count"] == 5, x["count"] >= 4) for x in phases[:3]],
        "a release: the major axis' pressure falls 10 % before the minor axis touches; the abrupt phase as the jumps "
        "(Fig. 11-12)")
    row("27", "ellipse-uniform", *[f"major/minor {pct(x['major_over_minor'])}" for x in (e, eo, er)],
        [verdict(0 < x["major_over_minor"] < 0.03, x["major_over_minor"] > 0) for x in (e, eo, er)], "")
    row("27", "ellipse-level", *[f"{pct(x['vs_circular'])} against circular" for x in (e, eo, er)],
        [verdict(abs(x["vs_circular"] + 0.10) < 0.03) for x in (e, eo, er)], "")
    # ---- Fig. 29-32
    f, fo, fr = (ellipse_metrics(d, p) for d, p in zip(three("sleeve-elliptic-friction"), (pc, po, pr)))
    fd = ellipse_metrics(out_of("onoff-friction-diagonal"), po)
    nodal_o, net_o, abs_o = axis_nodal_ratio(out_of("onoff-sleeve-elliptic-friction"))
    nodal_r = axis_nodal_ratio(replayed("sleeve-elliptic-friction"))[0]
    f300, fins = (ellipse_metrics(out_of(n), po) for n in ("onoff-friction-300-steps", "onoff-friction-outer-insulated"))
    row("29-30", "friction-major", *[f"steps {x['major_first_step']} (major) < {x['minor_first_step']} (minor)"
                                     for x in (f, fo, fr)],
        [verdict(x["major_first_step"] < x["minor_first_step"]) for x in (f, fo, fr)], "")
    row("29-30", "friction-five", five(phases[3]), *[short(x) for x in phases[4:]],
        [verdict(x["count"] == 5, x["count"] >= 4) for x in phases[3:]], "as without friction (Fig. 25-26)")
    row("29", "friction-lift", lifts(f), lifts(fo), lifts(fr),
        [verdict(x["major_lifts_before_minor"], x["major_relax"] > 0.1) for x in (f, fo, fr)],
        "" if f["major_lifts_before_minor"] else "open: as without friction (Fig. 25-26)")
    row("30-31", "friction-14",
        f"{pct(f['major_over_minor'])}", f"{pct(fo['major_over_minor'])}",
        f"{pct(fr['major_over_minor'])} (nodal {pct(nodal_r)})",
        [verdict(abs(x["major_over_minor"] - 0.14) < 0.04, x["major_over_minor"] > 0.03) for x in (f, fo, fr)],
        "open: with friction the final state depends on the loading path (the on/off scheme's jumps give "
        f"more, the paper's algorithm replayed more still). Tried: the paper's measure, the forces at its two "
        f"axis nodes (unfiltered nodal force over tributary length, on/off): {pct(nodal_o)}; the slip threshold "
        f"lagged, one DC solve per pass at the pass before's threshold (results/claims/onoff-friction-diagonal): "
        f"{pct(fd['major_over_minor'])}; the time step 5 times longer (onoff-friction-300-steps): "
        f"{pct(f300['major_over_minor'])}; the outer face insulated (onoff-friction-outer-insulated): "
        f"{pct(fins['major_over_minor'])}; the replay's contact solve converged further (docs/model.md, the "
        "paper's algorithm replayed: its PSOR tolerance). A hoop force changes between the axes by the shear "
        "summed along the quarter: 14 % with 8 % shear needs shear of one sign, while ours alternates (on/off: "
        f"signed sum {net_o:+.3f} of the normal force, {abs_o:.3f} in absolute)")
    axes = [friction_by_axis(d) for d in three("sleeve-elliptic-friction")]
    row("30-31", "friction-where", f"{pct(f['major_over_minor'])}; tangential/normal {axes[0][0]:.3f} near the major "
        f"axis, {axes[0][1]:.3f} near the minor", *[f"{pct(x['major_over_minor'])}; {a:.3f}, {b:.3f}"
                                                     for x, (a, b) in zip((fo, fr), axes[1:])],
        [verdict(a > b and x["major_over_minor"] > 0 and x["t_over_n_total"] > 0.01, a > b and x["major_over_minor"] > 0)
         for x, (a, b) in zip((f, fo, fr), axes)],
        "explained: as the tangential force (the row below): the default's path leaves almost no shear")
    row("30-31", "friction-8", f"{f['t_over_n_total']:.3f} in total, {f['t_over_n']:.3f} at most",
        f"{fo['t_over_n_total']:.3f}, {fo['t_over_n']:.3f}", f"{fr['t_over_n_total']:.3f}, {fr['t_over_n']:.3f}",
        [verdict(0.04 < x["t_over_n_total"] < 0.12, x["t_over_n_total"] > 0.01) for x in (f, fo, fr)],
        "explained: the on/off scheme's path leaves the tangential forces the paper reports, converged or not; "
        "the default's smooth path leaves almost none")
    row("31", "friction-stick", f"{f['sticking']} of {f['in_contact']}", f"{fo['sticking']} of {fo['in_contact']}",
        f"{fr['sticking']} of {fr['in_contact']}", [verdict(x["sticking"] == x["in_contact"]) for x in (f, fo, fr)],
        "" if fr["sticking"] == fr["in_contact"] else "the replay's lagged threshold leaves its nodes on the cone's "
        "edge (slipping by this test) where the converged runs stick")
    # ---- Fig. 33-36
    r, ro, rr = (curve(d) for d in three("sleeve-random-threshold"))
    row("34", "random-onset",
        f"zero {r['zero_steps']} steps, linear {r['linear_steps']}, reversion from {r['T_onset_C']:.1f} C",
        f"zero {ro['zero_steps']}, linear {ro['linear_steps']}, from {ro['T_onset_C']:.1f} C",
        f"zero {rr['zero_steps']}, linear {rr['linear_steps']}, from {rr['T_onset_C']:.1f} C",
        [verdict(abs(x["T_onset_C"] + 25) < 2.5) for x in (r, ro, rr)],
        "the spread (10 K) is fitted to this statement: docs/paper-scale.md", fitted=True)
    width = (lambda a, b: (a["T_austenite_C"] - a["T_onset_C"], b["T_austenite_C"] - b["T_onset_C"]))
    row("34", "random-less-abrupt",
        "reversion over {:.1f} K against {:.1f} K".format(*width(r, c)), "{:.1f} K against {:.1f} K".format(*width(ro, co)),
        "{:.1f} K against {:.1f} K".format(*width(rr, cr)), [verdict(a > b) for a, b in
                                                              (width(r, c), width(ro, co), width(rr, cr))], "")
    row("34-35", "random-chaotic",
        f"largest rise {100 * r['max_jump']:.1f} % against {100 * c['max_jump']:.1f} %",
        f"{100 * ro['max_jump']:.1f} % against {100 * co['max_jump']:.1f} %",
        f"{100 * rr['max_jump']:.1f} % against {100 * cr['max_jump']:.1f} %",
        [verdict(a["max_jump"] > b["max_jump"]) for a, b in ((r, c), (ro, co), (rr, cr))],
        "open: the random threshold spreads the reversion over 17 K (the row above): each triangle's turn moves "
        "the mean force less, whatever the algorithm")
    spreads = [(temperature_spread(a), temperature_spread(b)) for a, b in
               zip(three("sleeve-random-threshold"), three("sleeve-circular"))]
    row("35-36", "random-homogeneous",
        "T_max - T_min {:.2f} K against {:.2f} K over the reversion".format(*spreads[0]),
        "{:.2f} K against {:.2f} K".format(*spreads[1]), "{:.2f} K against {:.2f} K".format(*spreads[2]),
        [verdict(a < b) for a, b in spreads], "")
    # ---- the cost: the paper's maxima per load step, against ours
    sc, so, sr = (summ(d) for d in three("sleeve-circular"))
    row("4.2.1", "iterations",
        f"not the paper's loops: newton, {sc['fixed_point_iterations_max']} iterations ({sc['dc_iterations_max']} "
        f"stiffness back-solves), {sc['psor_sweeps_max']} PSOR sweeps", f"{so['fixed_point_iterations_max']} / "
        f"{so['dc_iterations_max']} / {so['psor_sweeps_max']}",
        f"{sr['fixed_point_iterations_max']} / {sr['dc_iterations_max']} / {sr['psor_sweeps_max']} (the caps)",
        [""] +  # (the default's newton has no heat-phase, DC and PSOR loops to count against the paper's)
        [verdict(s["fixed_point_iterations_max"] <= 5 and s["dc_iterations_max"] <= 8 and s["psor_sweeps_max"] <= 20,
                 s["fixed_point_iterations_max"] <= 5) for s in (so, sr)],
        "the paper's loops, converged (on/off) or capped (the replay): the outer iterations match; the PSOR "
        "sweeps run to a relative 1e-10 (1e-3 in the replay: the paper's tolerance is not given, and 10 sweeps "
        "as a cap contradict its Fig. 11 and 25)")
    rs = summ(default("sleeve-random-threshold"))
    ru, rc, rp = curve(out_of("random-uniform")), curve(out_of("random-coarse")), curve(out_of("random-printed-a"))
    # the paper plots one point's force: the verdict on the three points a run writes (points.csv);
    # the best of the inner-surface nodes is shown, not judged
    plotted = [plotted_points_peak(d) for d in three("sleeve-random-threshold")]
    peak = (lambda x, p: f"plotted points' peak/final {p:.2f}, mean force's {x['peak_over_final']:.2f}; the best "
            f"node's {x['node_peak_over_final']:.2f}")
    row("34-35", "random-peak", peak(r, plotted[0]), peak(ro, plotted[1]), peak(rr, plotted[2]),
        [verdict(p > 1.3, p > 1.05) for p in plotted],
        "open: a late-reverting triangle pushes the surface near it, not the whole ring; the paper plots one "
        "point's force (Fig. 34, as Fig. 12), the closer reading, which no run brings to 1.5. Tried: a uniform "
        f"law of the same standard deviation (results/claims/random-uniform): node up to {ru['node_peak_over_final']:.2f}, "
        f"mean {ru['peak_over_final']:.2f}, reversion from {ru['T_onset_C']:.1f} C; the coarse mesh "
        f"(results/claims/random-coarse): node up to {rc['node_peak_over_final']:.2f}, mean {rc['peak_over_final']:.2f}; "
        f"the printed a = 300 (-scale reduced, results/claims/random-printed-a): node up to "
        f"{rp['node_peak_over_final']:.2f}, mean {rp['peak_over_final']:.2f}, but the reversion from "
        f"{rp['T_onset_C']:.1f} C (paper: -25 C); the on/off scheme and the paper's algorithm (columns 4, 5); a "
        "larger spread (docs/paper-scale.md S9, S9b: none gives 1.5, and a larger one moves the onset away from -25 C)")
    tmin = tmin_position(default("sleeve-random-threshold"))
    row("36", "random-minima",
        f"coldest node at {tmin:.2f} of the thickness" if not math.isnan(tmin) else "no contact instant written",
        "", "", [verdict(0.2 <= tmin <= 0.8), "", ""],
        "both faces exchange heat; with one face insulated the minimum moves to the other face (docs/paper-scale.md, S9c)")
    return (["## Claims, statement by statement", "",
             "Each statement the paper makes in its section 4 about its figures 11-36, in its own words (a short quote, "
             "with an English gloss), measured on the scene at its "
             "defaults (the default phase model) but for the paper's 1500 fixed increments (`-tol 0`), with the "
             "paper's on/off scheme (`-phasemodel onoff`) and with the "
             "paper's algorithm replayed (`-algorithm paper`: its on/off law and iteration caps, "
             "docs/model.md#the-papers-algorithm-replayed), each on the scene's own mesh (results/claims/); a "
             "verdict on each from one rule (tools/docs/claims_rules.py: agrees within the row's tolerance, partly "
             "when the feature is there but its number is not, disagrees when it is absent) and, for a "
             "disagreement of the default, the run that tests an explanation or \"open\". A claim only the replay "
             "shows is an artefact of the paper's iteration caps. (fitted): a parameter was chosen to meet that "
             "statement. Measures as in docs/paper-scale.md and tools/docs/claims_measures.py; " + f"seed {rs['parameters']['seed']} for the random "
             "threshold.", "", counts_line(verdicts), "",
             "| Fig. | the paper says | default model | on/off scheme | the paper's algorithm replayed | verdict "
             "(default / on/off / replay) | explanation |",
             "|---|---|---|---|---|---|---|"] + rows + [""]
            + (["The explanations (or the paper's words) too long for their row:", ""] + notes + [""] if notes else []))


if __name__ == "__main__":
    if sys.argv[1:] == ["--run"]:
        run_all()
    else:
        print("\n".join(table()))
