#!/usr/bin/python3
"""Figures of the sleeve-radial scene (the centred circular sleeve as a 1D problem in r), from
results/sleeve-radial/:

  force-temperature.png  contact pressure (MPa) against the inner-surface temperature (C), the
                         paper's Fig. 12, and against time (s) zoomed on the transient, the four
                         phases shaded; with further history.csv files given (a sleeve-circular
                         run, say), their curves on the same axes
  iterations.png         heat <-> phases fixed-point and DC iterations per step
  fields.png             radial profiles of sigma_rr, sigma_tt (MPa), T (C) and the phase (the
                         signed martensite fraction: M1 > 0, A, M2 < 0) at the three instants
                         (end of dilatation, during contact, end)
Usage: tools/plot/plot_sleeve-radial.py results/sleeve-radial [other/history.csv ...]
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
from sleeve_curves import fields_time, force_panels, iterations_figure, read_csv, state_values  # noqa: E402
from sma.plotting import save  # noqa: E402
from units import celsius  # noqa: E402


def force_temperature(outdir, summary, others):
    """Left: pressure against the inner-surface temperature; right: against time, zoomed on the
    transient; this run's four phases shaded (sleeve_curves.force_panels)."""
    h = read_csv(os.path.join(outdir, "history.csv"))
    curves = {f"1D, nr {summary['nr']}, {summary['n_steps']} steps": (h["T_inner_mean"], h["pressure_mean"], h["t"])}
    for path in others:
        o = read_csv(path)
        curves[os.path.relpath(os.path.dirname(path))] = (o["T_inner_mean"], o["pressure_mean"], o["t"])
    fig = plt.figure(figsize=(15, 4.8))
    legend, left, right = force_panels(fig, curves, summary, h, [0.0] + h["t"],
                                       state_values(summary, h, "T_inner_mean"), "inner-surface temperature (°C)",
                                       f"{summary['scene']}: clamping pressure against temperature and time")
    for ax in (left, right):
        ax.axhline(summary["lame_pressure"] / 1e6, color="k", ls=":", lw=0.8,
                   label="Lame shrink fit" if ax is left else None)
    handles, names = left.get_legend_handles_labels()
    keep = [(hd, n) for hd, n in zip(handles, names) if n in legend or n == "Lame shrink fit"]
    left.legend(*zip(*keep), fontsize=7, loc="lower right")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "force-temperature.png"), 120)
    print("force-temperature.png curves: " + " | ".join(legend))


def iterations(outdir, summary):
    # DC iterations are summed over the fixed-point iterations of a step, so they lie above.
    iterations_figure(outdir, summary, (("dc_iterations", "DC (all passes of the step)"),
                                        ("fixed_point_iterations", "heat <-> phases")),
                      1, "t (s)", log_counts=False)  # the clamping happens in the first 16 s of 150


def fields(outdir, summary):
    paths = sorted(glob.glob(os.path.join(outdir, "fields-*.csv")))
    if not paths:
        return
    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    for path in paths:
        when = fields_time(path)
        d = read_csv(path)
        r_mm = [r * 1e3 for r in d["r"]]
        label = f"{os.path.basename(path)[len('fields-'):-len('.csv')]} ({when})"
        line, = axes[0].plot(r_mm, [v / 1e6 for v in d["sigma_rr"]], lw=1, label=label)
        axes[0].plot(r_mm, [v / 1e6 for v in d["sigma_tt"]], lw=1, ls="--", color=line.get_color())
        axes[1].plot(r_mm, [celsius(T) for T in d["T"]], lw=1, color=line.get_color())
        axes[2].step(r_mm, d["phase"], where="mid", lw=1, color=line.get_color())
    axes[0].set_title("sigma_rr (solid), sigma_tt (dashed)", fontsize=9)
    axes[0].set_ylabel("stress (MPa)")
    axes[1].set_title("temperature", fontsize=9)
    axes[1].set_ylabel("T (°C)")
    # The radial CSV's phase is the signed martensite fraction chi: +1 all M1, 0 A, -1 all M2.
    axes[2].set_title("phase: signed martensite fraction", fontsize=9)
    axes[2].set_ylabel("phase (1): M1 > 0, A = 0, M2 < 0")
    axes[2].set_yticks([-1, -0.5, 0, 0.5, 1], ["M2", "-0.5", "A", "0.5", "M1"])
    axes[2].set_ylim(-1.1, 1.1)
    for ax in axes:
        ax.set_xlabel("r (mm)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{summary['scene']}: radial profiles at the three instants")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "fields.png"), 110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-radial"
    summary = results_io.read_summary(outdir, __file__)
    force_temperature(outdir, summary, sys.argv[2:])
    iterations(outdir, summary)
    fields(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
