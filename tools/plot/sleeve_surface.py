"""displacement.png of the sleeve scenes (tools/plot/plot_sleeve.py): the inner surface at the three
instants, its radial displacement against the angle and its opening to the pipe."""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402,F401
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import coincident_groups, phase_spans, point_labels, read_csv, shade, zoom_end  # noqa: E402
from sma.plotting import save  # noqa: E402

# A point touches the pipe when its gap is at most this (m): the contact solver leaves round-off
# of about 1e-13 m; a point opens again when its gap exceeds it after the first touch.
TOUCHING = 1e-9


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
    listed = [(t, os.path.relpath(f, outdir)) for t, f in results_io.read_pvd(pvd)]
    t_zoom = zoom_end(summary, read_csv(os.path.join(outdir, "history.csv")), max(t for t, _ in listed))
    return [(t, f, f[len("fields-"):-len(".vtu")] if f in instants else "") for t, f in listed
            if f in instants or t <= t_zoom]


def inner_surface(outdir, summary, vtu):
    """The inner-surface (contact) nodes in one VTU state, by angle: angle (deg), radial
    displacement u_r (m), the u_r that reaches the pipe along the ray (m) and the gap to the pipe
    n.u + initial gap (m, >= 0, 0 where touching), from contact-final.csv (the nodes, 12 digits)
    and the VTU file `vtu` of outdir (the nodal displacement)."""
    fields = results_io.read_vtu(os.path.join(outdir, vtu))  # (a cut or damaged VTU: an error line naming it)
    points, disp = fields.points, fields.point_data["displacement"]
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
    ellipse = obstacle_is_summarys(outdir, summary)
    # Around a centred circular pipe the gap along the surface is u_r shifted by a constant: the
    # middle panel would repeat the left one (one idea per panel), so it is drawn only where the
    # gap varies along the surface (an ellipse, an offset, a variant's obstacle).
    uniform_gap = ellipse and par["pipe_A"] == par["pipe_B"] and not par.get("offset", 0)
    if uniform_gap:
        fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.6))
        middle = None
    else:
        fig, (left, middle, right) = plt.subplots(1, 3, figsize=(17, 5.6))
    hidden, middle_top, frames_drawn = [], 0.0, []
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
        # The three instants in colour, each with its legend entry; the frames between them thin and
        # grey, one legend entry for all (20 entries on one line after contact said nothing).
        style = dict(marker="o", ms=2, lw=1, label=label) if name else \
            dict(color="0.7", lw=0.6, zorder=1, label="_frame")
        if not name:
            frames_drawn.append(t)
        line, = left.plot(angle, [n[1] * 1e6 for n in nodes], **style)
        if ellipse and middle is not None:
            middle.plot(angle, [n[3] * 1e6 for n in nodes], **dict(style, color=line.get_color()))
            middle_top = max(middle_top, max(n[3] for n in nodes))
    if frames_drawn:
        label = f"frames at t = {frames_drawn[0]:g} ... {frames_drawn[-1]:g} s ({len(frames_drawn)}, grey)"
        for ax in (left, middle):
            if ax is not None:
                ax.plot([], [], color="0.7", lw=0.6, label=label)
    if ellipse:
        left.plot(angle, [n[2] * 1e6 for n in nodes], "k--", lw=1, label="pipe surface: the u_r that touches it")
    elif middle is not None:
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
    if middle is not None:
        middle.axhline(0, color="k", lw=0.8)
        gap_axis(middle, middle_top)
        middle.set_ylabel("gap to the pipe, n.u + initial gap (um); 0: touching")
        middle.set_title("gap to the pipe along the surface", fontsize=9)
    for ax in (left, middle) if middle is not None else (left,):
        ax.set_xlabel("angle of the inner-surface node (deg)")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    left.set_ylabel("radial displacement u_r (um)")
    left.set_title("radial displacement about the ring's centre" +
                   (f" ({', '.join(hidden)}: the initial state u = 0, not shown)" if hidden else ""), fontsize=9)
    # The gap at the three points against time, zoomed like the force: the order of touching, the
    # openings after it. Beside it the share of the inner nodes in contact: near one half, contact
    # alternates node to node (the P1 checkerboard the pressure recovery filters, docs/parameters.md)
    # and a point's node may open while its neighbours touch.
    p = read_csv(os.path.join(outdir, "points.csv"))
    names = [k[len("gap_"):-len("_m")] for k in p if k.startswith("gap_")]
    labels = point_labels(summary, names)
    h = read_csv(os.path.join(outdir, "history.csv"))
    shade(right, phase_spans(summary, h), [0.0] + h["t"])
    # Points whose gaps coincide are one legend entry (their curves drawn dashed and dotted under it:
    # three coinciding curves hid each other with three entries).
    gaps = {labels[n]: (p["t"], [g * 1e6 for g in p[f"gap_{n}_m"]]) for n in names}
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    by_label = {labels[n]: n for n in names}
    for k, (group_label, members) in enumerate(coincident_groups(gaps)):
        for j, member in enumerate(members):
            label = group_label
            opens = reopening(p["t"], p[f"gap_{by_label[member]}_m"])
            if opens and len(members) == 1:
                label += f": opens again by up to {opens[0] * 1e6:.2g} um (t = {opens[1]:.3g} s)"
            right.plot(*gaps[member], lw=1.2, ls=("-", "--", ":")[j % 3], color=colours[k % len(colours)],
                       label=label if j == 0 else "_member")
    right.axhline(0, color="k", lw=0.8)
    t_zoom = zoom_end(summary, h, p["t"][-1])
    # Once every point touches for good the gaps are zero to the end: the axis stops a little
    # after the last opening (an empty panel after 1 s said nothing), and the title says so.
    widest = max(max(p[f"gap_{n}_m"]) for n in names)
    last_open = max((t for n in names for t, g in zip(p["t"], p[f"gap_{n}_m"]) if g > 1e-3 * widest), default=0.0)
    closed_from = None
    if 0 < last_open < t_zoom / 4:
        closed_from = next((t for t in p["t"] if t > last_open), None)
        t_zoom = max(4 * last_open, 1e-9)
    right.set_xlim(0, t_zoom)
    gap_axis(right, max(max(p[f"gap_{n}_m"]) for n in names))
    right.set_xlabel("time t (s)")
    right.set_ylabel("gap to the pipe at the point's node (um)")
    right.set_title("gap at the three points against time (phases shaded)" +
                    (f"\nall three touching (gap below 0.1 % of its largest) from t = {closed_from:g} s to the end"
                     if closed_from else ""), fontsize=9)
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

