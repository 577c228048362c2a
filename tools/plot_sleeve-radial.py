#!/usr/bin/python3
"""Figures of the sleeve-radial scene (the centred circular sleeve as a 1D problem in r), from
results/sleeve-radial/:

  force-temperature.png  contact pressure (MPa) against the inner-surface temperature (C), the
                         paper's Fig. 12; with further history.csv files given (a sleeve-circular
                         run, say), their curves on the same axes
  iterations.png         heat <-> phases fixed-point and DC iterations per step
  fields.png             radial profiles of sigma_rr, sigma_tt, T and the phase at the three
                         instants (end of dilatation, during contact, end)
Usage: tools/plot_sleeve-radial.py results/sleeve-radial [other/history.csv ...]
"""
import glob
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_sleeve import read_csv, save  # noqa: E402
from units import KELVIN_AT_0C  # noqa: E402


def force_temperature(outdir, summary, others):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    curves = [(os.path.join(outdir, "history.csv"),
               f"1D, nr {summary['nr']}, {summary['n_steps']} steps")]
    curves += [(path, os.path.relpath(os.path.dirname(path))) for path in others]
    for path, label in curves:
        h = read_csv(path)
        ax.plot([T - KELVIN_AT_0C for T in h["T_inner_mean"]], [p / 1e6 for p in h["pressure_mean"]],
                lw=1, label=label)
    ax.axhline(summary["lame_pressure"] / 1e6, color="k", ls=":", lw=0.8, label="Lame shrink fit")
    ax.set_xlabel("inner-surface temperature (C)")
    ax.set_ylabel("contact pressure (MPa)")
    ax.set_title(f"{summary['scene']}: clamping pressure against temperature")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "force-temperature.png"), 120)


def iterations(outdir, summary):
    h = read_csv(os.path.join(outdir, "history.csv"))
    fig, ax = plt.subplots(figsize=(7, 4))
    # DC iterations are summed over the fixed-point iterations of a step, so they lie above.
    for key, label in (("dc_iterations", "DC (all passes of the step)"),
                       ("fixed_point_iterations", "heat <-> phases")):
        ax.plot(h["t"], h[key], lw=0.8, label=label)
    ax.set_xscale("symlog", linthresh=1)  # the clamping happens in the first 16 s of 150
    ax.set_xlabel("t (s)")
    ax.set_ylabel("iterations in the step")
    ax.set_title(f"{summary['scene']}: iterations per step")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "iterations.png"), 120)


def fields(outdir, summary):
    paths = sorted(glob.glob(os.path.join(outdir, "fields-*.csv")))
    if not paths:
        return
    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    for path in paths:
        with open(path) as f:
            when = f.readline().strip("# \n")
        d = read_csv(path)
        r_mm = [r * 1e3 for r in d["r"]]
        label = f"{os.path.basename(path)[len('fields-'):-len('.csv')]} ({when})"
        line, = axes[0].plot(r_mm, [v / 1e6 for v in d["sigma_rr"]], lw=1, label=label)
        axes[0].plot(r_mm, [v / 1e6 for v in d["sigma_tt"]], lw=1, ls="--", color=line.get_color())
        axes[1].plot(r_mm, [T - KELVIN_AT_0C for T in d["T"]], lw=1, color=line.get_color())
        axes[2].step(r_mm, d["phase"], where="mid", lw=1, color=line.get_color())
    axes[0].set_title("sigma_rr (solid), sigma_tt (dashed), MPa", fontsize=9)
    axes[1].set_title("temperature (C)", fontsize=9)
    axes[2].set_title("phase (0 A, 1 M1, 2 M2)", fontsize=9)
    for ax in axes:
        ax.set_xlabel("r (mm)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{summary['scene']}: radial profiles at the three instants")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "fields.png"), 110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-radial"
    summary = json.load(open(os.path.join(outdir, "summary.json")))
    force_temperature(outdir, summary, sys.argv[2:])
    iterations(outdir, summary)
    fields(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    main()
