"""The claims table's measures (tools/docs/claims.py) that tools/docs/paper_scale_metrics.py does not
take, read from a run's outputs (docs/outputs.md): history.csv, points.csv, contact-final.csv,
fields-<instant>.csv and summary.json. Each measures what the paper plotted or describes, and a
first event is the first of two steps in a row (claims_rules.first_sustained), not one step's."""
import csv
import os

import numpy as np

from claims_rules import first_sustained, release_episodes, settled_from
from paper_scale_metrics import curve, hist, points, summ

INSTANTS = ("1-dilated", "2-contact", "3-end")  # the paper's three instants (Fig. 13-14, 19-20, ...)


def rows_of(out, name):
    with open(os.path.join(out, name), newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def points_columns(out):
    """points.csv of a run as columns of floats."""
    rows = rows_of(out, "points.csv")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def plotted_points_peak(out):
    """The largest peak over final of the force at the three inner-surface points points.csv
    writes (the points a figure plots, as the paper plots one point's force, Fig. 12 and 34)."""
    columns = points_columns(out)
    peaks = [max(p) / p[-1] for k, p in columns.items() if k.startswith("pressure_") and p[-1] > 0]
    return max(peaks) if peaks else float("nan")


def axis_nodal_ratio(out):
    """Final nodal normal force over tributary length (unfiltered) at the major (90 deg) over the
    minor axis node (0 deg), minus 1, from contact-final.csv; and the signed and absolute sums of
    the tangential forces over the sum of the normal ones."""
    rows = rows_of(out, "contact-final.csv")
    density = {round(float(r["angle_deg"])): float(r["normal_force"]) / float(r["tributary_length"]) for r in rows}
    normal = sum(float(r["normal_force"]) for r in rows)
    tangential = [float(r["tangential_force"]) for r in rows]
    return density[90] / density[0] - 1, sum(tangential) / normal, sum(abs(t) for t in tangential) / normal


def equal_time_comparison(out_circ, out_gvar):
    """Steps (after the first contact of either) where the gvar mean pressure is below / above the
    constant-g one by more than 0.1 % of the final level, compared at the same step (same dt)."""
    pc, pg = hist(out_circ)["pressure_mean"], hist(out_gvar)["pressure_mean"]
    tol = 1e-3 * pc[-1]
    lower = sum(1 for a, b in zip(pc, pg) if b < a - tol)
    higher = [i + 1 for i, (a, b) in enumerate(zip(pc, pg)) if b > a + tol]
    return lower, (higher[0], higher[-1]) if higher else (0, 0)


def single_precision_spread(out):
    """The three inner-surface points' pressures (points.csv) apart at the first step any is in
    contact, relative to the largest there, and at the end relative to the x-axis point's."""
    single = points_columns(out)
    forces = [single[f"pressure_{k}_Pa"] for k in ("x_axis", "diagonal", "y_axis")]
    first = min(next(i for i, v in enumerate(p) if v > 0) for p in forces)
    at_first = [p[first] for p in forces]
    return first + 1, (max(at_first) - min(at_first)) / max(at_first), \
        (max(p[-1] for p in forces) - min(p[-1] for p in forces)) / forces[0][-1]


def temperature_spread(out):
    """The mean over the steps from the reversion's onset to austenite of T_max - T_min (K)."""
    h, c = hist(out), curve(out)
    i0, i1 = c["onset_step"] - 1, c["austenite_step"]
    if i0 < 0 or i1 <= i0:
        return float("nan")
    return float((h["T_max"][i0:i1] - h["T_min"][i0:i1]).mean())


def contact_spread(out):
    """How far apart the inner surface's nodes start touching (paper: "at every point" at once): the
    steps from a twentieth of them in contact (not a point A held on the pipe, its node touching from
    the start) to all of them (each the first of two steps in a row), the inner temperature's rise
    between, the martensite stage's span (that first contact to the reversion's onset, K), and
    whether all touch before the onset."""
    h, s, c = hist(out), summ(out), curve(out)
    first = first_sustained(h["contact_nodes"], s["contact_nodes"] / 20)
    every = first_sustained(h["contact_nodes"], s["contact_nodes"] - 0.5)
    T = h["T_inner_mean"]
    span = T[c["onset_step"] - 1] - T[first - 1]
    return dict(steps=every - first, dT=T[every - 1] - T[first - 1], span=span,
                before_onset=0 < every < c["onset_step"])


def martensite_at_contact(out):
    """The ring's martensite fraction (by area) at the first contact (the first of two steps)."""
    h = hist(out)
    return 1 - h["fraction_austenite"][first_sustained(h["contact_nodes"]) - 1]


def reversion_abruptness(out):
    """The largest part of the ring (by area) that turns austenite in one step, and the inner
    temperature's rise while the austenite fraction goes from 10 to 90 % (K)."""
    h = hist(out)
    fa, T = h["fraction_austenite"], h["T_inner_mean"]
    i10, i90 = int(np.argmax(fa >= 0.1)), int(np.argmax(fa >= 0.9))
    return float(np.diff(fa).max()), float(T[i90] - T[i10])


def constant_after_austenite(out):
    """The largest change of the mean force after the ring is austenite for good, over the final."""
    p, aus = hist(out)["pressure_mean"], summ(out)["austenite_step"]
    return float(np.abs(p[aus - 1:] - p[-1]).max() / p[-1])


def tangential_over_normal_max(out):
    """max over the final contact nodes of |tangential force| / normal force (contact-final.csv)."""
    return max(abs(float(r["tangential_force"])) / float(r["normal_force"])
               for r in rows_of(out, "contact-final.csv") if float(r["normal_force"]) > 0)


def fields(out, instant):
    return np.genfromtxt(os.path.join(out, f"fields-{instant}.csv"), delimiter=",", names=True, skip_header=1)


def angular_variation(out, instant, column, radial=6, angular=9, mirror=False):
    """A triangle field of fields-<instant>.csv averaged on 6 rings x 9 sectors of the quarter ring:
    the largest difference along a ring between two sectors (mirror: between a sector and its mirror
    about 45 deg, the quarter ring's symmetry), over the field's range (column T) or as it is."""
    f = fields(out, instant)
    r, th, v = np.hypot(f["x"], f["y"]), np.degrees(np.arctan2(f["y"], f["x"])), f[column]
    kr = np.minimum((radial * (r - r.min()) / (r.max() - r.min())).astype(int), radial - 1)
    ka = np.clip((angular * th / 90).astype(int), 0, angular - 1)
    m = np.full((radial, angular), np.nan)
    for i in range(radial):
        for j in range(angular):
            if ((kr == i) & (ka == j)).any():
                m[i, j] = v[(kr == i) & (ka == j)].mean()
    diff = np.abs(m - m[:, ::-1]) if mirror else np.nanmax(m, axis=1, keepdims=True) - m
    scale = (v.max() - v.min()) if column == "T" else 1.0
    return float(np.nanmax(diff) / scale) if scale > 0 else 0.0


def temperature_bands(out):
    """The temperature's largest variation along a ring (angular_variation), over the three instants."""
    return max(angular_variation(out, i, "T") for i in INSTANTS)


def psor_at_grazing(out):
    """PSOR sweeps per step while only part of the inner surface touches before the reversion (the
    contact front: nodes grazing the pipe), their maximum, and the median over the steps all nodes
    touch before the reversion's onset."""
    h, s, c = hist(out), summ(out), curve(out)
    n, sweeps = h["contact_nodes"], h["psor_sweeps"]
    before = np.arange(len(n)) < c["onset_step"] - 1
    partial = before & (n > 0) & (n < s["contact_nodes"])
    full = before & (n == s["contact_nodes"])
    return float(sweeps[partial].max()) if partial.any() else float("nan"), \
        float(np.median(sweeps[full])) if full.any() else float("nan")


def equilibrium_times(out):
    """The time (s) from which the mean force stays within 0.1 % of its final value (its maximum
    level), and the time from which the ring's temperature spread T_max - T_min stays below 1 K (the
    end of the return to a uniform temperature)."""
    h = hist(out)
    p, spread, t = h["pressure_mean"], h["T_max"] - h["T_min"], h["t"]
    level = settled_from(p, 1e-3 * p[-1])
    hot = np.nonzero(spread >= 1.0)[0]
    even = hot[-1] + 2 if len(hot) else 1
    return float(t[level - 1]), float(t[even - 1]) if even <= len(t) else float("nan")


def five_phases(out):
    """The paper's five phases at the major-axis point (points.csv y_axis; paper 4.4.1): zero force
    steps, contact-release episodes (release_episodes: falls of 10 %) before the minor axis point
    touches, R^2 of a straight line in its own temperature from then to the reversion's onset,
    whether the ring turns austenite, and its force's largest change after (over its final value)."""
    P, c = points(out), curve(out)
    py, px, Ty = P["pressure_y_axis_Pa"], P["pressure_x_axis_Pa"], P["T_y_axis_K"]
    major, minor = first_sustained(py), first_sustained(px)
    releases = release_episodes(py[major - 1:minor]) if 0 < major < minor else 0
    i0, i1 = minor, c["onset_step"] - 1
    R2 = float("nan")
    if i1 - i0 > 5:
        T, p = Ty[i0:i1], py[i0:i1]
        res = p - np.polyval(np.polyfit(T, p, 1), T)
        R2 = 1 - (res ** 2).sum() / ((p - p.mean()) ** 2).sum()
    aus = c["austenite_step"]
    after = float(np.abs(py[aus - 1:] - py[-1]).max() / py[-1]) if aus > 0 else float("nan")
    there = {"zero": major > 1, "release": releases > 0, "linear": R2 > 0.99, "reversion": aus > c["onset_step"] > 0,
             "constant": after < 1e-3}
    return dict(zero=major - 1, releases=releases, R2=R2, austenite=aus > 0, after=after,
                count=sum(there.values()), missing=[k for k, v in there.items() if not v])


def friction_by_axis(out):
    """Sum |tangential| over sum normal force over the final contact nodes within 30 deg of the major
    (y) axis and of the minor (x) axis (contact-final.csv)."""
    rows = rows_of(out, "contact-final.csv")

    def ratio(keep):
        sel = [r for r in rows if keep(float(r["angle_deg"]))]
        return sum(abs(float(r["tangential_force"])) for r in sel) / sum(float(r["normal_force"]) for r in sel)
    return ratio(lambda a: a > 60), ratio(lambda a: a < 30)
