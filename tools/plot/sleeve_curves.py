"""The sleeve scenes' force curves (tools/plot/plot_sleeve.py, plot_sleeve-radial.py, figures):
force-temperature.png, and the helpers of every curve figure: the results' CSV reader, the four
phases of the curve and their shading, curves that coincide, the points' labels."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402,F401
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from units import celsius  # noqa: E402
from sma.plotting import save  # noqa: E402

# Curves closer than this fraction of the axis span at every step are drawn as one legend entry:
# 1 % of a 6-inch axis is about two line widths, too close to tell apart at reading size.
COINCIDE_FRACTION = 0.01
# The four phases of the force-temperature curve (docs/model.md#fig-11-14-sleeve-circular), with their
# shading colours.
PHASES = (("no contact", "0.88"), ("contact, martensite: linear in T", "#cfe2f3"),
          ("reversion to austenite", "#fce5cd"), ("austenite: constant", "#d9ead3"))
# The three inner-surface points of edp/problems/sleeve/sleeve-2d.idp (pointName).
POINT_LABELS = {"x_axis": "x axis (0 deg)", "diagonal": "45 deg", "y_axis": "y axis (90 deg)",
                "near": "0 deg (the side the pipe is shifted to)", "top": "90 deg", "far": "180 deg"}


def read_csv(path, skip_comment=True):
    """{column: [float]} (results_io.read_csv: a cut or damaged file named, not a traceback)."""
    return results_io.read_csv(path, skip_comment)


def fields_time(path):
    """The time of a fields-<instant>.csv, from its first line '# t = 12.5 s; SI units: ...'."""
    with open(path) as f:
        first = f.readline()
    return first.lstrip("# ").split(";")[0].strip()


# ---- The four phases of the curve ----

def phase_spans(summary, history):
    """The four phases as (name, colour, first state, last state), states numbered by step (0: the
    initial state, n: after step n). Each phase begins at the state before the step where it first
    shows: no contact until summary.json's first_contact_step, linear in T until the first step
    with austenite (history.csv's fraction_austenite > 0), reversion until summary.json's
    austenite_step (austenite for good), then constant. A phase the run does not reach is left out."""
    n = len(history["step"])
    first_contact, austenite = summary["first_contact_step"], summary["austenite_step"]
    reversion = next((int(s) for s, f in zip(history["step"], history["fraction_austenite"]) if f > 0), None)
    begins = [0]
    if first_contact is not None:  # null: no contact in the run
        begins.append(first_contact - 1)
        begins.append(max(first_contact, reversion) - 1 if reversion else None)
        begins.append(austenite - 1 if austenite is not None else None)
    spans = []
    for k, begin in enumerate(begins):
        if begin is None:
            break
        end = next((b for b in begins[k + 1:] if b is not None), n)
        if end > begin:
            spans.append((PHASES[k][0], PHASES[k][1], begin, end))
    return spans


def state_values(summary, history, key):
    """history.csv's column `key` per state (0: the initial state, whose temperature is Tinit)."""
    initial = summary["parameters"]["Tinit"] if key.startswith("T") else 0.0
    return [initial] + list(history[key])


def shade(ax, spans, xs):
    """Shades each phase over the x values of its first and last state."""
    for name, colour, begin, end in spans:
        ax.axvspan(min(xs[begin], xs[end]), max(xs[begin], xs[end]), color=colour, lw=0, label=name, zorder=0)


# ---- Curves that coincide ----

def largest_difference(a, b, spans):
    """Largest difference between two curves over the steps, each coordinate as a fraction of its
    axis span: a, b = (xs, ys); spans = (x span, y span). Curves of different lengths (other runs)
    are never compared: infinity."""
    if len(a[0]) != len(b[0]):
        return math.inf
    return max(max(abs(u - v) for u, v in zip(a[k], b[k])) / spans[k] for k in (0, 1))


def coincident_groups(curves):
    """Groups the curves {label: (xs, ys)} that coincide within COINCIDE_FRACTION of the axes'
    spans at every step; returns [(legend label, [member labels])], in the curves' order, a
    group's label naming its members and their largest difference in % of full scale."""
    xs = [x for c in curves.values() for x in c[0]]
    ys = [y for c in curves.values() for y in c[1]]
    spans = (max(xs) - min(xs) or 1.0, max(ys) - min(ys) or 1.0)
    groups = []
    for label, curve in curves.items():
        for group in groups:
            if all(largest_difference(curve, curves[m], spans) <= COINCIDE_FRACTION for m in group):
                group.append(label)
                break
        else:
            groups.append([label])
    result = []
    for group in groups:
        if len(group) == 1:
            result.append((group[0], group))
            continue
        worst = max(largest_difference(curves[a], curves[b], spans) for a in group for b in group if a < b)
        result.append((f"{', '.join(group)} (coincide within {100 * worst:.2g} % of full scale)", group))
    return result


def point_labels(summary, names):
    """Legend labels of points.csv's points; on an elliptic pipe, which axis is which."""
    par = summary["parameters"]
    labels = {n: POINT_LABELS.get(n, n) for n in names}
    if par.get("pipe_A", 0) != par.get("pipe_B", 0):
        minor, major = ("x_axis", "y_axis") if par["pipe_A"] < par["pipe_B"] else ("y_axis", "x_axis")
        for name, axis in ((minor, "minor"), (major, "major")):
            if name in labels:
                labels[name] = labels[name][:-1] + f", the pipe's {axis} axis)"
    return labels


# ---- Force against temperature and time ----

def zoom_end(summary, history, t_end):
    """The end of the time panels' zoom on the transient: a quarter past the time from which the
    ring is austenite for good (history.csv's t at summary.json's austenite_step: steps of any
    length, chosen by -tol or fixed) and five of that step's lengths, or the whole run."""
    austenite = summary["austenite_step"]
    if austenite is None:
        return t_end
    t, dt = history["t"][austenite - 1], history["dt"][austenite - 1]
    return min(t_end, t * 1.25 + 5 * dt)


def force_panels(fig, curves, summary, history, t_state, T_state, xlabel, title):
    """Left: pressure against temperature; middle: against time, zoomed on the transient; right
    (when the zoom cuts the run), the whole run in a narrow panel of its own (an inset covered the
    rise of a slower run). curves: {label: (T in K, p in Pa, t in s)}; history, t_state, T_state:
    the run whose phases are shaded. Returns the legend labels and the two main axes."""
    spans = phase_spans(summary, history)
    groups = coincident_groups({k: (c[0], c[1]) for k, c in curves.items()})
    t_end = t_state[-1]
    t_zoom = zoom_end(summary, history, t_end)
    if t_zoom < t_end:
        left, right, whole = fig.subplots(1, 3, gridspec_kw={"width_ratios": [1, 1, 0.4]})
    else:
        (left, right), whole = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1]}), None
    shade(left, spans, [celsius(T) for T in T_state])
    shade(right, spans, t_state)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    styles = ("-", "--", ":")
    for k, (label, members) in enumerate(groups):
        for j, m in enumerate(members):
            T, p, t = curves[m]
            left.plot([celsius(v) for v in T], [v / 1e6 for v in p], lw=1.2, ls=styles[j % 3],
                      color=colours[k % len(colours)], label=label if j == 0 else None)
            right.plot(t, [v / 1e6 for v in p], lw=1.2, ls=styles[j % 3], color=colours[k % len(colours)])
    left.set_xlabel(xlabel)
    left.set_ylabel("contact pressure = clamping force density (MPa)")
    left.set_title("against temperature (the paper's figure)", fontsize=9)
    left.grid(alpha=0.3)
    handles, names = left.get_legend_handles_labels()
    curve_handles = [(h, n) for h, n in zip(handles, names) if n not in {p[0] for p in PHASES}]
    left.legend(*zip(*curve_handles), fontsize=7, loc="lower right")
    right.set_xlim(0, t_zoom)
    right.set_xlabel("time t (s)")
    right.set_ylabel("contact pressure (MPa)")
    right.set_title(f"against time, 0-{t_zoom:.4g} s of {t_end:.4g} s", fontsize=9)
    right.grid(alpha=0.3)
    handles, names = right.get_legend_handles_labels()
    right.legend(handles, names, fontsize=7, loc="upper left", title="phases", title_fontsize=7)
    if whole is not None:
        for k, (label, members) in enumerate(groups):
            T, p, t = curves[members[0]]
            whole.plot(t, [v / 1e6 for v in p], lw=0.8, color=colours[k % len(colours)])
        whole.axvspan(0, t_zoom, color="0.85", lw=0, zorder=0)
        whole.set_title("the whole run (middle panel's span shaded)", fontsize=8)
        whole.set_xlabel("time t (s)")
        whole.grid(alpha=0.3)
    fig.suptitle(title)
    return [g[0] for g in groups], left, right


def force_temperature(outdir, summary):
    p = read_csv(os.path.join(outdir, "points.csv"))
    h = read_csv(os.path.join(outdir, "history.csv"))
    names = [k[len("pressure_"):-len("_Pa")] for k in p if k.startswith("pressure_")]
    labels = point_labels(summary, names)
    curves = {labels[n]: (p[f"T_{n}_K"], p[f"pressure_{n}_Pa"], p["t"]) for n in names}
    fig = plt.figure(figsize=(15, 4.8))
    legend, _, _ = force_panels(fig, curves, summary, h, [0.0] + h["t"], state_values(summary, h, "T_inner_mean"),
                          "temperature of the point: the inner-surface node at the curve's angle (°C)",
                          f"{summary['scene']}: contact pressure at three inner-surface points "
                          "(phase shading at the inner surface's mean temperature)")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "force-temperature.png"), 120)
    print("force-temperature.png curves: " + " | ".join(legend))


def iterations_figure(outdir, summary, loops, linthresh, xlabel, log_counts):
    """iterations.png: the iteration counts per step of `loops` ((history.csv column, label), ...)
    against time, on a time axis linear up to `linthresh` (s) and logarithmic beyond; log_counts:
    the counts on a logarithmic axis too."""
    h = read_csv(os.path.join(outdir, "history.csv"))
    fig, ax = plt.subplots(figsize=(7, 4))
    # A loop that never ran (the slip threshold without friction: all zeros) is named, not drawn.
    idle = [label for key, label in loops if not any(h[key])]
    for key, label in loops:
        if label not in idle:
            ax.plot(h["t"], h[key], lw=0.8, label=label)
    if log_counts:
        # A logarithmic count axis shows only steps that iterate (a zero has no logarithm: a
        # symlog axis drew a stretch 0 .. 1 that means nothing).
        ax.set_yscale("log")
        ax.set_ylim(bottom=0.8)
    ax.set_xscale("symlog", linthresh=linthresh)
    ax.set_xlim(left=0)  # (a symlog axis otherwise opens on negative times)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("iterations in the step")
    ax.set_title(f"{summary['scene']}: iterations per step" + (f"\n(not drawn, zero at every step: {', '.join(idle)})"
                                                                if idle else ""), fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "iterations.png"), 120)
