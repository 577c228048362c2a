#!/usr/bin/python3
"""Figures of the sleeve-axisymmetric scene (the sleeve of finite length, half of it, rigid pipe;
with -pullout the whole length, its end face z = 0 held), from results/sleeve-axisymmetric/:

  force-temperature.png  contact pressure (MPa) at mid-length (z = 0, the symmetry plane; with
                         -pullout z = L / 2), at the free end (z = L / 2; with -pullout z = L) and
                         its mean over the bore, against the bore's mean temperature (C) and against
                         time (s), during clamping; the open-ended cylinder's and plane strain's
                         closed forms dotted
  bore-pressure.png      the contact pressure along the bore (MPa against z in mm) at the three
                         instants (end of dilatation, during contact, end; and after the pull-out)
  pullout.png            (-pullout > 0) the pull-out force (kN: the sleeve's force on the pipe, > 0
                         against the pipe's motion; docs/parameters.md) and +-mu times the total
                         normal force against the pipe's displacement (mm)
Usage: tools/plot/plot_sleeve-axisymmetric.py results/sleeve-axisymmetric
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402
import glob

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import fields_time, read_csv  # noqa: E402
from sma.plotting import save  # noqa: E402
from units import celsius  # noqa: E402


def closed_forms(ax, summary):
    ax.axhline(summary["open_cylinder_pressure"] / 1e6, color="k", ls=":", lw=0.8, label="open-ended cylinder")
    ax.axhline(summary["plane_strain_pressure"] / 1e6, color="grey", ls="--", lw=0.8, label="plane strain (Lame)")


def places(summary):
    """The words of the bore's points: {"mid": ..., "end": ..., "z": the axis label}. Half length:
    z from the symmetry plane (z = 0) to the free end (L / 2); with -pullout the whole length, z
    from the end face held axially (z = 0, the shoulder) to the free end face (z = L), the pipe
    pulled out through the held face (towards) or the free one (-pulldirection away)."""
    L = summary["parameters"]["length"] * 1e3
    if not summary.get("whole_length"):
        return {"mid": "mid-length (z = 0, the symmetry plane)", "end": f"free end (z = L / 2 = {L / 2:g} mm)",
                "z": f"z (mm): 0 the symmetry plane (mid-length), {L / 2:g} the free end"}
    away = summary.get("pull_direction", "towards") == "away"
    held = "the held end face (shoulder" + ("" if away else "; the pipe pulled out through it") + ")"
    free = "the free end face" + (" (the pipe pulled out through it)" if away else "")
    return {"mid": f"mid-length (z = L / 2 = {L / 2:g} mm)", "end": f"free end face (z = L = {L:g} mm)",
            "z": f"z (mm): 0 {held}, {L:g} {free}"}


def force_temperature(outdir, summary):
    h = read_csv(os.path.join(outdir, "history.csv"))
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.5))
    T = [celsius(v) for v in h["T_inner_mean"]]
    where = places(summary)
    for key, label in (("pressure_mid", where["mid"]), ("pressure_end", where["end"]),
                       ("pressure_mean", "mean over the bore")):
        p = [v / 1e6 for v in h[key]]
        left.plot(T, p, lw=1, label=label)
        right.plot(h["t"], p, lw=1, label=label)
    for ax in (left, right):
        closed_forms(ax, summary)
        ax.set_ylabel("contact pressure (MPa)")
        ax.grid(alpha=0.3)
    left.set_xlabel("bore's mean temperature (°C)")
    right.set_xlabel("t (s)")
    left.legend(fontsize=7, loc="lower right")
    p = summary["parameters"]
    fig.suptitle(f"{summary['scene']}: L {p['length'] * 1e3:g} mm, nr {p['nr']}, nz {p['nz']}, "
                 f"{summary['n_steps']} steps" + (" (clamping; the pull-out: pullout.png)"
                                                   if summary.get("whole_length") else ""))
    fig.tight_layout()
    save(fig, os.path.join(outdir, "force-temperature.png"), 120)


def bore_pressure(outdir, summary):
    paths = sorted(glob.glob(os.path.join(outdir, "bore-*.csv")))
    if not paths:
        return
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for path in paths:
        d = read_csv(path)
        name = os.path.basename(path)[len("bore-"):-len(".csv")]
        when = (f"after the pipe moved {summary['pullout'] * 1e3:g} mm" if name == "4-pulled"
                else fields_time(path))
        ax.plot([z * 1e3 for z in d["z"]], [v / 1e6 for v in d["pressure"]], lw=1, marker=".", ms=3,
                label=f"{name} ({when})")
    closed_forms(ax, summary)
    ax.set_xlabel(places(summary)["z"])
    ax.set_ylabel("contact pressure (MPa)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title(f"{summary['scene']}: contact pressure along the bore")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "bore-pressure.png"), 120)


def pullout(outdir, summary):
    path = os.path.join(outdir, "pullout.csv")
    if not os.path.exists(path):
        return
    d = read_csv(path)
    w = [abs(v) * 1e3 for v in d["pipe_displacement"]]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    # pullout_force: the sleeve's force on the pipe, counted along the pipe's motion reversed (> 0:
    # the joint resists the pull), whichever the direction. Towards the held face it starts < 0:
    # at the end of clamping the sleeve, its axial contraction held back by the pipe, drags the
    # pipe towards that face; it rises through 0 to the plateau +mu N.
    away = summary.get("pull_direction", "towards") == "away"
    words = "away from" if away else "towards"
    force = [v / 1e3 for v in d["pullout_force"]]
    mu_n = [summary["mu"] * v / 1e3 for v in d["normal_force_total"]]
    # on the plateau at every increment (-pulldirection away): the two curves said once
    # (docs/parameters.md, coinciding curves: within 1 % of the axis)
    plateau = max(abs(f - b) for f, b in zip(force, mu_n)) <= 0.01 * max(mu_n)
    what = "pull-out force: the sleeve's on the pipe, > 0 against its motion"
    ax.plot(w, force, lw=1.2, marker=".", ms=3, label=what + (" = mu N (sliding at every increment)" if plateau else ""))
    ax.plot(w, mu_n, lw=0.8, ls="--", color="C1",
            label=None if plateau else f"± mu N, the sliding bounds (mu = {summary['mu']:g})")
    if min(force) < 0:
        ax.plot(w, [-v for v in mu_n], lw=0.8, ls="--", color="C1")
    ax.axhline(0, color="k", lw=0.6)
    if away:  # on the plateau from the first increment: no zoom onto round-off
        ax.set_ylim(0, max(force + mu_n) * 1.08)
    ax.set_xlabel(f"pipe displacement {words} the held end face (mm)")
    ax.set_ylabel("force (kN, whole circumference)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{summary['scene']}: pull-out force, final {summary['pullout_force_final'] / 1e3:.1f} kN, "
                 f"max {summary['pullout_force_max'] / 1e3:.1f} kN")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "pullout.png"), 120)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-axisymmetric"
    summary = results_io.read_summary(outdir, __file__)
    force_temperature(outdir, summary)
    bore_pressure(outdir, summary)
    pullout(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
