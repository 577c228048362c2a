#!/usr/bin/python3
"""The page of tools/bench/elliptic_mesh_study.py (its docstring states the method):
docs/benchmarks/elliptic-mesh-refinement.md and its figure, from the study's record
(results/elliptic-mesh-study/summary.json); the study's main calls write_doc(record)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import save, write_whole  # noqa: E402
from sma.plotting import pyplot  # noqa: E402
from markdown_wrap import wrap  # noqa: E402
from elliptic_mesh_study import DOC, PNG, SCENES, LADDER, NT_DEFAULT, LAYERS, TARGET, KINDS  # noqa: E402
import numpy as np  # noqa: E402


def pct(x, spec=".3f"):
    return "-" if x is None else format(100 * x, spec) + " %"


def short(scene):
    return "friction" if scene.endswith("friction") else "elliptic"


def rows_of(rec, scene, series):
    N, rs = rec["reference_n"], [r for r in rec["rows"] if r["scene"] == scene and "failure" not in r]
    if series == "joint":
        return sorted([r for r in rs if r["nr"] == r["nt"] and (r["nr"] in LADDER or r["nr"] == N)], key=lambda r: r["nr"])
    return sorted([r for r in rs if r["nt"] == NT_DEFAULT], key=lambda r: r["nr"])


def error_table(rec, scene, series):
    a, N = rec["analysis"][scene], rec["reference_n"]
    out = ["| nr x nt | h_r (um) | h_theta (deg) | nodes | CPU (s) | loop (s) | retried steps | error, whole run | "
           "transient | before t_R | reversion window | final pressure |", "|---|" + "---|" * 11]
    for r in rows_of(rec, scene, series):
        e = a["errors"][f"{r['nr']}x{r['nt']}"]
        cells = ["reference"] * 5 if (r["nr"], r["nt"]) == (N, N) else [
            pct(e["l1"], ".4f"), pct(e["l1_transient"], ".4f"), pct(e["l1_before"], ".4f"), pct(e["l1_reversion"], ".4f"),
            pct(e["final"], ".4f")]
        out.append(f"| {r['nr']} x {r['nt']} | {1e4 / r['nr']:.0f} | {90 / r['nt']:.2f} | {r['nodes']} | "
                   f"{r['cpu_seconds']:.1f} | {r['loop_seconds']:.1f} | {r['steps_retried']} | " + " | ".join(cells) + " |")
    return out


def figure_table(rec, scene, series):
    fr = scene.endswith("friction")
    head = ("| nr x nt | final mean (MPa) | bore min / max (MPa) | non-uniformity | major - minor axis | major's peak "
            "before the minor touches (MPa) | major at the step before (MPa) | loosening | minor touches (step) | "
            "austenite (step) |")
    if fr:
        head += " tangential / normal, max (total) | sticking |"
    out = [head, "|---|" + "---|" * (head.count("|") - 2)]
    for r in rows_of(rec, scene, series):
        k = r["figures"]
        line = (f"| {r['nr']} x {r['nt']} | {k['final_pressure_mean'] / 1e6:.4f} | {k['bore_pressure_min'] / 1e6:.3f} / "
                f"{k['bore_pressure_max'] / 1e6:.3f} | {pct(k['non_uniformity'])} | {pct(k['axes_over_mean'])} | "
                f"{k.get('major_peak_before_minor', 0) / 1e6:.3f} | {k.get('major_before_minor', 0) / 1e6:.3f} | "
                f"{pct(k.get('loosening'), '.1f')} | {k['minor_first_step']} | {k['austenite_step']} |")
        if fr:
            line += (f" {k['tangential_over_normal']:.5f} ({k['tangential_over_normal_total']:.5f}) | "
                     f"{k['nodes_sticking']} of {k['nodes_in_contact']} |")
        out.append(line)
    return out


def figure(rec):
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), sharey=True)
    N = rec["reference_n"]
    for ax, scene in zip(axes, SCENES):
        if scene not in rec["analysis"]:
            continue
        a = rec["analysis"][scene]
        joint = [r["nr"] for r in rows_of(rec, scene, "joint") if r["nr"] != N]
        layers = [r["nr"] for r in rows_of(rec, scene, "layers")]
        for kind, color, label in (("l1_reversion", "C0", "reversion window"), ("l1_transient", "C1", "transient")):
            es = [100 * a["errors"][f"{n}x{n}"][kind] for n in joint]
            ax.loglog([1 / n for n in joint], es, "o-", color=color, label=f"{label}, nr = nt (h = 1/nr)")
            f = a["fits"][kind]
            hs = np.array([1 / joint[-1], 1 / joint[0]])
            ax.loglog(hs, 100 * np.exp(f["log_c"]) * hs ** f["k"], ":", color=color, lw=0.8,
                      label=f"fit, order {f['k']:.2f}")
            el = [100 * a["errors"][f"{n}x{NT_DEFAULT}"][kind] for n in layers]
            ax.loglog([1 / n for n in layers], el, "s--", color=color, mfc="none",
                      label=f"{label}, layers at nt {NT_DEFAULT} (h = 1/nr)")
            rich = a["richardson"].get("finest", {}).get(kind, {}).get("error")
            if rich:
                ax.axhline(100 * rich, color=color, lw=0.7, ls="-.")
        ax.axhline(100 * TARGET, color="k", lw=0.6, ls=":")
        ax.set(xlabel="h = 1 / nr", title=f"{scene} (reference {N} x {N})")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("error against the reference (%)")
    axes[0].legend(fontsize=7)
    fig.suptitle("paper scale, 1500 fixed steps: the mean contact pressure's error (dash-dot: the reference's "
                 "own, Richardson)", fontsize=9)
    return save(fig, PNG)


def num(x, spec=".2f"):
    return "-" if x is None else format(x, spec)


def orders_text(rec, scene):
    a = rec["analysis"][scene]
    f, jf, lf = a["fits"], a["joint_difference_fit"], a.get("layer_difference_fit", {})
    w, t = "l1_reversion", "l1_transient"
    lines = [f"**{scene}.** Against the reference, the least-squares slope of log error against log h over nr = nt "
             f"{f[w]['over'][0]}-{f[w]['over'][1]}: transient {f[t]['k']:.2f}, reversion window {f[w]['k']:.2f} (whole "
             f"run {f['l1']['k']:.2f}, before t_R {f['l1_before']['k']:.2f}); over {f[w]['over_coarse'][0]}-"
             f"{f[w]['over_coarse'][1]}, at least 2.6 times coarser than the reference: transient {f[t]['k_coarse']:.2f}, "
             f"window {f[w]['k_coarse']:.2f}; steeper with the finer meshes, as expected when their errors are measured "
             f"against a curve that is itself in error (previous section). Without the reference, the "
             f"successive differences along the ladder, {LADDER[0]}-{rec['reference_n']}, "
             f"fall with order {jf[t]['k']:.2f} over the transient and {jf[w]['k']:.2f} over the window (before t_R "
             f"{jf['l1_before']['k']:.2f}); along the layers at nt {NT_DEFAULT} (differences "
             f"{', '.join(pct(d, '.4f') for d in a['layer_differences'][w])} over the window between nr "
             f"{', '.join(map(str, LAYERS))}) with order {num(lf.get(w, {}).get('k'))} over the window, "
             f"{num(lf.get(t, {}).get('k'))} over the transient.",
             "",
             f"0.1 % over the reversion window: nr = nt = {f[w]['n_target']:.0f} "
             f"({(f[w]['n_target'] + 1) ** 2:.0f} nodes) by the fit against the reference over "
             f"{f[w]['over'][0]}-{f[w]['over'][1]} ({f[w]['n_target_coarse']:.0f} by the fit over "
             f"{f[w]['over_coarse'][0]}-{f[w]['over_coarse'][1]}); by the differences' model p = p* + C n^-k, which "
             f"needs no reference, nr = nt = {jf[w]['n_target']:.0f} ({(jf[w]['n_target'] + 1) ** 2:.0f} nodes), and "
             f"along the layers at nt {NT_DEFAULT} nr = {num(lf.get(w, {}).get('n_target'), '.0f')} (the arc's part at nt "
             f"{NT_DEFAULT} left out: section (b)). The fits against the reference take it as exact; its own window "
             f"error (previous section) is of the size of the target, consistent with their asking for coarser meshes "
             f"than the model that needs no reference."]
    return lines


def richardson_table(rec):
    out = ["| scene | estimate | interval | D1 = abs(p1 - p2) | D2 = abs(p2 - p3) | order p | the reference's error |",
           "|---|---|---|---|---|---|---|"]
    names = {"l1": "whole run", "l1_transient": "transient", "l1_before": "before t_R", "l1_reversion": "reversion window"}
    for scene in SCENES:
        a = rec["analysis"].get(scene)
        if not a:
            continue
        for name, r in a["richardson"].items():
            for kind in KINDS:
                x = r[kind]
                p = "none (D1 / D2 outside the power law's range)" if x["p"] is None else f"{x['p']:.2f}"
                out.append(f"| {short(scene)} | Richardson {', '.join(map(str, r['n']))} | {names[kind]} | "
                           f"{pct(x['d1'], '.4f')} | {pct(x['d2'], '.4f')} | {p} | {pct(x['error'], '.4f')} |")
        for kind in KINDS:
            x = a["joint_difference_fit"][kind]
            out.append(f"| {short(scene)} | differences' fit {LADDER[0]}-{rec['reference_n']} | {names[kind]} | - | - | "
                       f"{x['k']:.2f} | {pct(x['reference_error'], '.4f')} |")
    return out


def reference_error_text(rec):
    N, out = rec["reference_n"], []
    for scene in SCENES:
        a = rec["analysis"].get(scene)
        if not a:
            continue
        r, d = a["richardson"].get("finest", {}), a["joint_difference_fit"]
        r2 = a["richardson"].get("ratio2", {})
        w, t = "l1_reversion", "l1_transient"
        out.append(f"{scene}: the {N} x {N} reference's error is {pct(r.get(w, {}).get('error'), '.3f')} over the "
                   f"reversion window and {pct(r.get(t, {}).get('error'), '.3f')} over the transient by Richardson on "
                   f"the three finest meshes (order {num(r.get(w, {}).get('p'))}, {num(r.get(t, {}).get('p'))}); the "
                   f"ratio-2 triple gives {pct(r2.get(w, {}).get('error'), '.3f')} and "
                   f"{pct(r2.get(t, {}).get('error'), '.3f')} (order {num(r2.get(w, {}).get('p'))}, "
                   f"{num(r2.get(t, {}).get('p'))}), the differences' fit over the whole ladder "
                   f"{pct(d[w]['reference_error'], '.3f')} and {pct(d[t]['reference_error'], '.3f')} (order "
                   f"{d[w]['k']:.2f}, {d[t]['k']:.2f}).")
    out.append("The successive differences of the window are not a clean power law (the table's orders move with the "
               "triple chosen), so the reference's window error is known to within the spread of these estimates only; "
               "the errors against the reference that are not well above it are not the meshes' true errors.")
    return out


def conclusion(rec):
    N, parts = rec["reference_n"], []
    for scene in SCENES:
        a = rec["analysis"].get(scene)
        if not a or "18" not in a["arc_differences"]:
            continue
        rows = {(r["nr"], r["nt"]): r for r in rec["rows"] if r["scene"] == scene and "failure" not in r}
        arc, lay, w = a["arc_differences"]["18"], a["layer_span"], "l1_reversion"
        f = {key: rows[key]["figures"] for key in ((18, 18), (18, NT_DEFAULT), (LAYERS[-1], NT_DEFAULT), (N, N))}
        parts.append(
            f"In {scene}, refining the arc from 18 to {NT_DEFAULT} segments at 18 layers moves the pressure curve by "
            f"{pct(arc[w])} of the reference over the reversion window, refining the layers from 18 to {LAYERS[-1]} at "
            f"{NT_DEFAULT} segments by {pct(lay[w])}; before t_R, before the reversion starts, it is the other way round "
            f"({pct(arc['l1_before'])} for the arc, {pct(lay['l1_before'])} for the layers). The ellipticity's figures "
            f"are the arc's: the non-uniformity is {pct(f[(18, 18)]['non_uniformity'])} on 18 x 18, "
            f"{pct(f[(18, NT_DEFAULT)]['non_uniformity'])} on 18 x {NT_DEFAULT}, "
            f"{pct(f[(LAYERS[-1], NT_DEFAULT)]['non_uniformity'])} on {LAYERS[-1]} x {NT_DEFAULT} and "
            f"{pct(f[(N, N)]['non_uniformity'])} on the reference; the loosening "
            f"{pct(f[(18, 18)].get('loosening'), '.1f')}, {pct(f[(18, NT_DEFAULT)].get('loosening'), '.1f')}, "
            f"{pct(f[(LAYERS[-1], NT_DEFAULT)].get('loosening'), '.1f')} and {pct(f[(N, N)].get('loosening'), '.1f')}.")
        if "tangential_over_normal" in f[(N, N)]:
            tn = [f"{f[key]['tangential_over_normal']:.5f} on {key[0]} x {key[1]}" for key in f]
            parts.append(f"Its largest tangential over normal ratio depends on both directions: {', '.join(tn)} (the "
                         f"reference): the default 18 x {NT_DEFAULT} gives "
                         f"{f[(18, NT_DEFAULT)]['tangential_over_normal'] / f[(N, N)]['tangential_over_normal']:.2f} "
                         f"times the reference's.")
    laid = [s for s in SCENES if s in rec["analysis"] and "18" in rec["analysis"][s]["arc_differences"]]
    if not laid:
        return " ".join(parts)
    by_layers = all(rec["analysis"][s]["layer_span"]["l1_reversion"] > rec["analysis"][s]["arc_differences"]["18"]["l1_reversion"]
                    for s in laid)
    lo = [rec["analysis"][s].get("layer_difference_fit", {}).get("l1_reversion", {}).get("k") for s in laid]
    jo = [rec["analysis"][s]["joint_difference_fit"]["l1_reversion"]["k"] for s in laid]
    if by_layers:
        parts.append(
            "So over the reversion window, where the force rises as the front crosses the ring, the error is the "
            "layers': a front-following mesh would pay through the thickness, with fine layers in a band that moves "
            f"with the front, the arc kept uniform and moderate (it carries the error before the reversion, the "
            f"non-uniformity and the loosening, which change little between nt = "
            f"{NT_DEFAULT} and the reference but much from 18 to {NT_DEFAULT}). As in sleeve-circular "
            "([mesh-refinement.md](mesh-refinement.md): order 1.01 in the layers against p* over the window, 1.29 by "
            "successive differences), "
            "the layers converge at about first order here: "
            + ", ".join(f"{num(k)} by the layers' differences and {num(j)} by the ladder's in {s}"
                        for s, k, j in zip(laid, lo, jo))
            + ". Unlike that study, which ran the polygon's heat measure (`-curvedmeasure 0`) and found an "
            "arc term of order 2 comparable to the layers' (0.238 % and 0.356 % of p* on 18 x 18), these runs use the "
            "default true annulus measure, and here the arc's share of the window error is the smaller.")
    else:
        parts.append("Over the reversion window the arc's refinement moves the curve at least as much as the layers': "
                     "a front-following refinement of the layers alone would not pay here.")
    return " ".join(parts)


def time_note(rec):
    """The split steps of the finest meshes against the runs' own time-error estimates."""
    rows = [r for r in rec["rows"] if "failure" not in r]
    split = [f"{short(r['scene'])} {r['nr']} x {r['nt']}: {r['steps_retried']}" for r in rows if r["steps_retried"]]
    est = [r["time_error_estimate_transient"] for r in rows]
    diffs = [min(a["joint_differences"]["l1_transient"][-2:]) for a in rec["analysis"].values()]
    return (f"Every run ended with 0 unconverged steps. Steps retried in halves: {'; '.join(split) or 'none'}; there the "
            f"time grid is finer than the other meshes' for those steps. Each run's own estimate of its time error over "
            f"the transient (summary.json `time_error_estimate_transient`) lies between {pct(min(est), '.4f')} and "
            f"{pct(max(est), '.4f')} of the curve, below the smallest difference between the finest meshes over the "
            f"transient ({pct(min(diffs), '.4f')}): the time grid's changes at those few steps are small against the "
            f"mesh's differences.")


def write_doc(rec):
    mach, N = rec["machine"], rec["reference_n"]
    png = figure(rec)
    shas = sorted({r["plugin_sha256_16"] for r in rec["rows"]})
    failures = [r for r in rec["rows"] if "failure" in r]
    fr_ref = next((f"{r['cpu_seconds']:.0f}" for r in rec["rows"] if r["scene"] == SCENES[1] and r["nr"] == r["nt"] == N
                   and "failure" not in r), "-")
    L = ["# The elliptic scenes' force curves against the ring mesh (paper scale)", "",
         f"Written by `tools/bench/elliptic_mesh_study.py` (its docstring states the method) from its runs of "
         f"{rec['started']} to {rec.get('finished', '(unfinished)')} ({mach['nproc']} cores, {mach['cpu_model']}, "
         f"commit {rec['commit']}, plugin build {', '.join(map(str, shas))} (sha256's first 16 digits, read before each "
         f"run); one run per mesh, one at a time, on a machine another engineer may have been using for builds: the "
         f"CPU time of the process is the figure to compare, less sensitive to such load than the wall time). Issue 48: sleeve-elliptic and sleeve-elliptic-friction with a refinement study of their own. Each "
         f"scene at its defaults (paper scale, true annulus heat measure `-curvedmeasure 1`), `-tol 0 -vtkevery 0`: "
         f"the paper's {rec['steps']} fixed steps of 0.1 s on every mesh, so that the time error is the same on all "
         f"of them. Meshes: tools/bench/mesh_study.py's structured quarter rings (nr layers, h_r = 10 mm / nr; nt arc "
         f"segments, h_theta = 90 deg / nt); the scenes' default is meshes/sleeve-quarter.msh, 18 x {NT_DEFAULT}.", "",
         f"Error: relative L1 in time of the mean contact pressure (history.csv `pressure_mean`) against the same "
         f"scene's {N} x {N} run (tools/bench/oracles/curve_error.py: whole run, transient [0, t_A], reversion window "
         f"[t_R, t_A], final pressure; before t_R: [0, t_R], by the same exact L1). "
         + "; ".join(f"{s}: t_R = {rec['analysis'][s]['t_R']:.1f} s, t_A = {rec['analysis'][s]['t_A']:.1f} s"
                     for s in SCENES if s in rec["analysis"]) + ". CPU: user + system of the tools/ff process; loop: "
         f"summary.json `wall_seconds`; retried steps: summary.json `steps_retried` (steps whose solve reached a loop's "
         f"limit, taken again in halves: the step solver's, not the time step's accuracy). Study: "
         f"{rec.get('study_seconds', 0) / 60:.1f} minutes of runs; the reference, {N} x {N}, is the finest mesh whose "
         f"friction run took about 10 minutes ({fr_ref} s CPU here).", "",
         time_note(rec)]
    if failures:
        L += ["", "Failed runs: " + "; ".join(f"{r['scene']} {r['nr']} x {r['nt']}: `{r['failure']}`" for r in failures) + "."]
    for scene in SCENES:
        if scene not in rec["analysis"]:
            continue
        L += ["", f"## {scene}", "", "### (a) nr = nt: both directions together", ""] + error_table(rec, scene, "joint")
        L += ["", f"### (b) Layers at the default arc, nt = {NT_DEFAULT}", ""] + error_table(rec, scene, "layers")
        L += ["", "### The ellipticity's figures along the meshes (series (a), then (b))", ""] \
            + figure_table(rec, scene, "joint") + figure_table(rec, scene, "layers")[2:]
    L += ["", "## The reference's own error", "",
          f"Richardson on the curves' distances (docstring): the three finest meshes, and the ratio-2 triple "
          f"{N // 4}, {N // 2}, {N} as a check, and the fit of the successive differences along the whole ladder "
          f"(D_i = C abs(n_i^-k - n_i+1^-k), the reference's error C {N}^-k). Relative to the reference's norm over each "
          f"interval.", ""] + richardson_table(rec) + [""] + reference_error_text(rec)
    L += ["", "## Orders", ""]
    for scene in SCENES:
        if scene in rec["analysis"]:
            L += orders_text(rec, scene) + [""]
    L += ["## Conclusion", "", conclusion(rec), "", f"![error against h]({os.path.basename(png)})", ""]
    write_whole(DOC, wrap("\n".join(L)))
