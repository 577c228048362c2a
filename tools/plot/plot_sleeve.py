#!/usr/bin/python3
"""Figures of the sleeve scenes (paper Figures 12-36), from results/<scene>/ (docs/outputs.md):

  force-temperature.png  left: the contact pressure (MPa) at the three inner-surface points
                         against each point's own temperature (°C), the paper's Fig. 12, 16, 18,
                         22, 26, 30, 34; right: the same pressures against time (s), zoomed on the
                         transient, the whole run in a narrow panel. Shaded with the curve's four
                         phases (no contact, linear in T, reversion, austenite); curves that
                         coincide share one legend entry with their measured largest difference
  displacement.png       the inner surface at the three instants: radial displacement (um)
                         against the angle with the pipe's surface, and the opening to the pipe
                         (um, 0 where touching): the offset ring's recentring, the elliptic lift-off
  iterations.png         iteration counts per step of the three nested loops and PSOR
  fields-<instant>.png   radial stress (MPa), temperature (C) and phases (A, M1, M2) at the three
                         instants (the paper's Fig. 13-14, 19-20, 23-24, 27-28, 31-32, 35-36)
The data files are in SI units (K, Pa, m, s); the pictures in degrees C, MPa, mm, um, s.
Prints each figure's curve labels (the legend) on stdout.
Usage: tools/plot/plot_sleeve.py results/<scene>
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402
import glob
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from units import celsius  # noqa: E402
from sma.plotting import save  # noqa: E402,F401  (every plot tool's PNGs: a temporary name, then renamed)

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
PHASE_NAMES = ("A", "M1", "M2")  # the phase labels 0, 1, 2 of the fields
# A point touches the pipe when its gap is at most this (m): the contact solver leaves round-off
# of about 1e-13 m; a point opens again when its gap exceeds it after the first touch.
TOUCHING = 1e-9


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

def zoom_end(summary, t_end):
    """The end of the time panels' zoom on the transient: a quarter past the time from which the
    ring is austenite for good (summary.json austenite_step x dt), or the whole run."""
    dt = summary["parameters"]["dt"]
    austenite = summary["austenite_step"]
    return min(t_end, austenite * dt * 1.25 + 5 * dt) if austenite is not None else t_end


def force_panels(fig, curves, summary, history, t_state, T_state, xlabel, title):
    """Left: pressure against temperature; middle: against time, zoomed on the transient; right
    (when the zoom cuts the run), the whole run in a narrow panel of its own (an inset covered the
    rise of a slower run). curves: {label: (T in K, p in Pa, t in s)}; history, t_state, T_state:
    the run whose phases are shaded. Returns the legend labels and the two main axes."""
    spans = phase_spans(summary, history)
    groups = coincident_groups({k: (c[0], c[1]) for k, c in curves.items()})
    t_end = t_state[-1]
    t_zoom = zoom_end(summary, t_end)
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


# ---- The inner surface: displacement and opening ----

def ellipse_gap(px, py, A, B):
    """Signed distance from (px, py) to the ellipse (x/A)^2 + (y/B)^2 = 1 (negative inside) and
    the ellipse's outward normal at the nearest point: the plugin's ObstacleGap (the contact
    condition is n.u + gap >= 0), recomputed by bisection on the nearest point's parameter."""
    x, y = abs(px), abs(py)

    def f(t):
        return (B * B - A * A) * math.sin(t) * math.cos(t) + A * x * math.sin(t) - B * y * math.cos(t)
    lo, hi = 0.0, math.pi / 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    t = 0.5 * (lo + hi)
    qx, qy = A * math.cos(t), B * math.sin(t)
    nx, ny = qx / A ** 2, qy / B ** 2
    nn = math.hypot(nx, ny)
    d = math.hypot(x - qx, y - qy)
    return (-d if (x / A) ** 2 + (y / B) ** 2 < 1 else d), math.copysign(nx / nn, px), math.copysign(ny / nn, py)


def pipe_radius_along(theta, par):
    """Distance from the ring's centre (the origin) to the pipe's surface along the ray at angle
    theta (rad): the pipe is the ellipse of semi-axes pipe_A (x), pipe_B (y) centred at (offset, 0)."""
    c, s = math.cos(theta), math.sin(theta)
    A, B, x0 = par["pipe_A"], par["pipe_B"], par["offset"]
    # ((r c - x0) / A)^2 + (r s / B)^2 = 1, the positive root
    qa = (c / A) ** 2 + (s / B) ** 2
    qb = -2 * x0 * c / A ** 2
    qc = (x0 / A) ** 2 - 1
    return (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)


def displacement_states(outdir, summary):
    """The states displacement.png draws, as (t in s, VTU file relative to outdir, instant name or
    ""): the three instants (fields-<instant>.vtu) and the periodic frames of fields.pvd within
    the time panels' zoom on the transient."""
    instants = {os.path.basename(p) for p in glob.glob(os.path.join(outdir, "fields-*.vtu"))}
    pvd = os.path.join(outdir, "fields.pvd")
    if not os.path.exists(pvd):
        return [(0.0, f, f[len("fields-"):-len(".vtu")]) for f in sorted(instants)]
    import xml.etree.ElementTree as ET
    listed = [(float(d.get("timestep")), d.get("file")) for d in ET.parse(pvd).getroot().iter("DataSet")]
    t_zoom = zoom_end(summary, max(t for t, _ in listed))
    return [(t, f, f[len("fields-"):-len(".vtu")] if f in instants else "") for t, f in listed
            if f in instants or t <= t_zoom]


def inner_surface(outdir, summary, vtu):
    """The inner-surface (contact) nodes in one VTU state, by angle: angle (deg), radial
    displacement u_r (m), the u_r that reaches the pipe along the ray (m) and the gap to the pipe
    n.u + initial gap (m, >= 0, 0 where touching), from contact-final.csv (the nodes, 12 digits)
    and the VTU file `vtu` of outdir (the nodal displacement)."""
    import vtk  # only here: the other figures need no VTK
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(outdir, vtu))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    disp = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    par = summary["parameters"]
    nodes = read_csv(os.path.join(outdir, "contact-final.csv"))
    out = []
    for x, y in zip(nodes["x"], nodes["y"]):
        i = int(((points[:, 0] - x) ** 2 + (points[:, 1] - y) ** 2).argmin())  # the VTU holds floats
        ux, uy = float(disp[i][0]), float(disp[i][1])
        r, theta = math.hypot(x, y), math.atan2(y, x)
        gap, nx, ny = ellipse_gap(x - par["offset"], y, par["pipe_A"], par["pipe_B"])
        out.append((math.degrees(theta), (x * ux + y * uy) / r, pipe_radius_along(theta, par) - r,
                    nx * ux + ny * uy + gap))
    return sorted(out)


def translation_along_x(nodes):
    """The half ring's rigid shift along x at one instant: a1 of the least-squares fit
    u_r = a0 + a1 cos(theta) over the inner-surface nodes (a translation t along x adds t cos(theta)
    to u_r; a uniform dilatation adds a constant)."""
    cs = [math.cos(math.radians(n[0])) for n in nodes]
    us = [n[1] for n in nodes]
    k = len(cs)
    mc, mu = sum(cs) / k, sum(us) / k
    return sum((c - mc) * (u - mu) for c, u in zip(cs, us)) / sum((c - mc) ** 2 for c in cs)


def reopening(t, gap):
    """(largest gap, its time) after the point first touched (gap <= TOUCHING), or None when it
    never opens again by more than TOUCHING."""
    first = next((k for k, g in enumerate(gap) if g <= TOUCHING), None)
    if first is None:
        return None
    k = max(range(first, len(gap)), key=lambda j: gap[j])
    return (gap[k], t[k]) if gap[k] > TOUCHING else None


def gap_axis(ax, top):
    """A gap axis from just below 0 to the largest gap (m), at least 0.1 um high: the round-off
    around 0 where touching (1e-13 m) stays flat on the zero line."""
    high = max(top * 1e6, 0.1) * 1.05
    ax.set_ylim(-0.04 * high, high)


def obstacle_is_summarys(outdir, summary):
    """True when the pipe of summary.json (an ellipse, pipe_A x pipe_B, centred at offset) is the
    obstacle the run used: at the last state every node in contact (contact-final.csv) has a gap
    within TOUCHING by that ellipse. A variant with its own obstacle (ObstacleAt, e.g.
    edp/variants/sleeve-superellipse.edp) fails it: its gap along the surface is not drawn."""
    final = read_csv(os.path.join(outdir, "contact-final.csv"))
    nodes = inner_surface(outdir, summary, "fields-3-end.vtu")
    touching = {round(math.degrees(math.atan2(y, x)), 9)
                for x, y, n in zip(final["x"], final["y"], final["normal_force"]) if n > 0}
    return all(abs(n[3]) <= TOUCHING for n in nodes if round(n[0], 9) in touching)


def displacement(outdir, summary):
    """displacement.png: u_r and the gap to the pipe along the inner surface at the instants, and
    the gap at the three points against time (points.csv)."""
    states = displacement_states(outdir, summary)
    if not states or not os.path.exists(os.path.join(outdir, "contact-final.csv")):
        return
    par = summary["parameters"]
    half = par.get("ring") == "half"
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(17, 5.6))
    hidden, middle_top = [], 0.0
    ellipse = obstacle_is_summarys(outdir, summary)
    for t, vtu, name in states:
        nodes = inner_surface(outdir, summary, vtu)
        angle = [n[0] for n in nodes]
        label = f"{name} (t = {t:g} s)" if name else f"t = {t:g} s"
        if half:
            label += f", shift along x {translation_along_x(nodes) * 1e6:.2f} um"
        if all(n[1] == 0 for n in nodes):
            # The initial state (u = 0; the offset ring touches in its first step): it overlaps
            # the pipe by the interference and would only squash the scales.
            hidden.append(name or f"t = {t:g} s")
            continue
        line, = left.plot(angle, [n[1] * 1e6 for n in nodes], "-o", ms=2, lw=1, label=label)
        if ellipse:
            middle.plot(angle, [n[3] * 1e6 for n in nodes], "-o", ms=2, lw=1, color=line.get_color(), label=label)
            middle_top = max(middle_top, max(n[3] for n in nodes))
    if ellipse:
        left.plot(angle, [n[2] * 1e6 for n in nodes], "k--", lw=1, label="pipe surface: the u_r that touches it")
    else:
        # A variant's own obstacle (ObstacleAt): its gap at the other instants cannot be recomputed
        # here, but the run wrote its own at the end (contact-final.csv's gap, any obstacle shape).
        final = read_csv(os.path.join(outdir, "contact-final.csv"))
        if "gap" in final:
            end = sorted((math.degrees(math.atan2(y, x)), g) for x, y, g in zip(final["x"], final["y"], final["gap"]))
            middle.plot([a for a, _ in end], [g * 1e6 for _, g in end], "-o", ms=2, lw=1, color="k",
                        label="end (contact-final.csv: the run's own obstacle)")
            middle_top = max(g for _, g in end)
        else:
            middle.text(0.5, 0.5, "the run's obstacle is not summary.json's ellipse\n(a variant's ObstacleAt):\n"
                        "the gap along the surface is not drawn; points.csv's gap (right) is the run's own",
                        ha="center", va="center", transform=middle.transAxes, fontsize=8)
    middle.axhline(0, color="k", lw=0.8)
    gap_axis(middle, middle_top)
    for ax in (left, middle):
        ax.set_xlabel("angle of the inner-surface node (deg)")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    left.set_ylabel("radial displacement u_r (um)")
    left.set_title("radial displacement about the ring's centre" +
                   (f" ({', '.join(hidden)}: the initial state u = 0, not shown)" if hidden else ""), fontsize=9)
    middle.set_ylabel("gap to the pipe, n.u + initial gap (um); 0: touching")
    middle.set_title("gap to the pipe along the surface", fontsize=9)
    # The gap at the three points against time, zoomed like the force: the order of touching, the
    # openings after it. Beside it the share of the inner nodes in contact: near one half, contact
    # alternates node to node (the P1 checkerboard the pressure recovery filters, docs/parameters.md)
    # and a point's node may open while its neighbours touch.
    p = read_csv(os.path.join(outdir, "points.csv"))
    names = [k[len("gap_"):-len("_m")] for k in p if k.startswith("gap_")]
    labels = point_labels(summary, names)
    h = read_csv(os.path.join(outdir, "history.csv"))
    shade(right, phase_spans(summary, h), [0.0] + h["t"])
    for name in names:
        gap = p[f"gap_{name}_m"]
        label = labels[name]
        opens = reopening(p["t"], gap)
        if opens:
            label += f": opens again by up to {opens[0] * 1e6:.2g} um (t = {opens[1]:.3g} s)"
        right.plot(p["t"], [g * 1e6 for g in gap], lw=1.2, label=label)
    right.axhline(0, color="k", lw=0.8)
    t_zoom = zoom_end(summary, p["t"][-1])
    right.set_xlim(0, t_zoom)
    gap_axis(right, max(max(p[f"gap_{n}_m"]) for n in names))
    right.set_xlabel("time t (s)")
    right.set_ylabel("gap to the pipe at the point's node (um)")
    right.set_title("gap at the three points against time (phases shaded)", fontsize=9)
    right.grid(alpha=0.3)
    share = right.twinx()
    share.plot(h["t"], [c / summary["contact_nodes"] for c in h["contact_nodes"]], color="0.3", lw=0.8, ls=":",
               label="share of the inner nodes in contact (right axis)")
    share.set_ylim(0, 1.05)
    share.set_ylabel("share of the inner nodes in contact")
    lines = [ln for ln in right.get_lines() + share.get_lines() if not ln.get_label().startswith("_")]
    right.legend(lines, [ln.get_label() for ln in lines], fontsize=7, loc="upper center",
                 bbox_to_anchor=(0.5, -0.13))
    pipe = (f"circular pipe, radius {par['pipe_A'] * 1e3:.4g} mm" if par["pipe_A"] == par["pipe_B"] else
            f"elliptic pipe, semi-axes {par['pipe_A'] * 1e3:.5g} (x) and {par['pipe_B'] * 1e3:.5g} (y) mm")
    extra = f"; pipe centre at x = {par['offset'] * 1e6:.3g} um" if par.get("offset", 0) else ""
    if not ellipse:
        pipe, extra = "the variant's own obstacle", ""
    fig.suptitle(f"{summary['scene']}: the inner surface (ring inner radius {par['ring_inner_radius'] * 1e3:.5g} mm, "
                 f"{pipe}{extra})", fontsize=10)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "displacement.png"), 110)
    print("displacement.png states: " + " | ".join(f"{name or 'frame'} t = {t:g} s" for t, _, name in states))


def iterations(outdir, summary):
    h = read_csv(os.path.join(outdir, "history.csv"))
    fig, ax = plt.subplots(figsize=(7, 4))
    for key, label in (("fixed_point_iterations", "heat <-> phases"),
                       ("slip_iterations", "slip threshold"), ("dc_iterations", "DC"),
                       ("psor_sweeps", "PSOR sweeps")):
        ax.plot(h["t"], h[key], lw=0.8, label=label)
    ax.set_yscale("symlog")
    ax.set_xscale("symlog", linthresh=max(1.0, 20 * summary["parameters"]["dt"]))
    ax.set_xlabel("time t (s), logarithmic beyond the first steps")
    ax.set_ylabel("iterations in the step")
    ax.set_title(f"{summary['scene']}: iterations per step")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "iterations.png"), 120)


PHASE_COLOURS = ("0.75", "tab:red", "tab:blue")  # A, M1, M2


def phase_map(ax, fig, tri, phases, flat=False):
    """The phase field in the colours of PHASE_COLOURS, its colour bar naming only the phases
    present (a bar with an M2 colour where no point is M2 misleads). flat: one colour per
    triangle of `tri` (the mesh's own), else contours over the points of `tri`."""
    present = sorted({int(round(v)) for v in phases})
    index = {p: k for k, p in enumerate(present)}
    cmap = mcolors.ListedColormap([PHASE_COLOURS[p] for p in present])
    levels = [k - 0.5 for k in range(len(present) + 1)]
    values = [index[int(round(v))] for v in phases]
    if flat:
        mappable = ax.tripcolor(tri, facecolors=values, cmap=cmap, vmin=-0.5, vmax=len(present) - 0.5)
    else:
        mappable = ax.tricontourf(tri, values, levels=levels, cmap=cmap)
    bar = fig.colorbar(mappable, ax=ax, shrink=0.8, ticks=range(len(present)))
    bar.ax.set_yticklabels([PHASE_NAMES[p] for p in present])
    bar.set_label("phase")
    return mappable


def mesh_fields(vtu):
    """The triangles of a fields VTU (matplotlib Triangulation, mm) with its per-triangle arrays
    and nodal temperature, or None when the VTU is absent."""
    if not os.path.isfile(vtu):
        return None
    import vtk  # only here: the other figures need no VTK
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    cells = [[grid.GetCell(i).GetPointId(k) for k in range(3)] for i in range(grid.GetNumberOfCells())
             if grid.GetCellType(i) == 5]  # VTK_TRIANGLE
    if not cells or len(cells) != grid.GetNumberOfCells():
        return None
    tri = mtri.Triangulation(points[:, 0] * 1e3, points[:, 1] * 1e3, cells)
    cd, pd = grid.GetCellData(), grid.GetPointData()
    return tri, {name: vtk_to_numpy(cd.GetArray(name)) for name in ("sigma_rr", "phase")}, \
        vtk_to_numpy(pd.GetArray("temperature"))


def fields(outdir, summary):
    for path in sorted(glob.glob(os.path.join(outdir, "fields-*.csv"))):
        when = fields_time(path)
        mesh = mesh_fields(path[:-4] + ".vtu")
        if mesh is not None:
            # The mesh's own triangles, one colour each for the stress and the phase (P1
            # displacements give one stress per triangle): contours through the triangles'
            # centres drew periodic blobs that were the mesh's pattern, not the solution's.
            tri, cell, T_nodes = mesh
            fig, axes = plt.subplots(1, 3, figsize=(13, 4))
            sigma = axes[0].tripcolor(tri, facecolors=cell["sigma_rr"] / 1e6)
            fig.colorbar(sigma, ax=axes[0], shrink=0.8).set_label("sigma_rr (MPa), one value per triangle")
            temp = axes[1].tricontourf(tri, [celsius(v) for v in T_nodes], levels=20)
            fig.colorbar(temp, ax=axes[1], shrink=0.8).set_label("T (°C)")
            phase_map(axes[2], fig, tri, cell["phase"], flat=True)
            decorate_fields(fig, axes, summary, path, when)
            continue
        d = read_csv(path)
        x_mm, y_mm = [v * 1e3 for v in d["x"]], [v * 1e3 for v in d["y"]]
        tri = mtri.Triangulation(x_mm, y_mm)
        # Delaunay of the centroids also fills the hole of the ring: mask those triangles.
        radius = [math.hypot(x, y) for x, y in zip(x_mm, y_mm)]
        inner = min(radius)
        tri.set_mask([math.hypot(sum(x_mm[k] for k in t) / 3, sum(y_mm[k] for k in t) / 3) < inner * 0.999
                      for t in tri.triangles])
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
        sigma = axes[0].tricontourf(tri, [v / 1e6 for v in d["sigma_rr"]], levels=20)
        fig.colorbar(sigma, ax=axes[0], shrink=0.8).set_label("sigma_rr (MPa)")
        temp = axes[1].tricontourf(tri, [celsius(v) for v in d["T"]], levels=20)
        fig.colorbar(temp, ax=axes[1], shrink=0.8).set_label("T (°C)")
        phase_map(axes[2], fig, tri, d["phase"])
        decorate_fields(fig, axes, summary, path, when)


def decorate_fields(fig, axes, summary, path, when):
    """Titles and axes of a fields figure, then fields-<instant>.png beside the CSV."""
    for ax, label in zip(axes, ("radial stress", "temperature", "phase (A austenite, M1 and M2 martensite)")):
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
    instant = os.path.basename(path)[len("fields-"):-len(".csv")]
    fig.suptitle(f"{summary['scene']}: {instant} ({when})")
    fig.tight_layout()
    save(fig, path[:-4] + ".png", 110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-circular"
    summary_path = os.path.join(outdir, "summary.json")
    if not os.path.isfile(summary_path):
        sys.exit(f"error: {summary_path} missing: the run did not finish (summary.json is written last)")
    summary = results_io.read_json(summary_path)
    if summary.get("scene") == "sleeve-radial":
        # the radial model writes no points.csv, contact-final.csv or VTU: its own plot tool
        raise results_io.ResultsError(f"{outdir} holds a run of sleeve-radial, whose figures are "
                                      "tools/plot/plot_sleeve-radial.py's (make run draws them)")
    force_temperature(outdir, summary)
    displacement(outdir, summary)
    iterations(outdir, summary)
    fields(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
