#!/usr/bin/python3
"""Figures of the sleeve-life scene (the coupling's life on the radial model), from
results/sleeve-life/:

  pressure-temperature.png  the mean contact pressure (MPa) against the inner-surface temperature
                            (C) over the whole history, one colour per stage (cooling, storage,
                            installation, heating, service), with the pressure the joint must keep
                            (-minpressure) and the free ring's transformation temperatures
  life.png                  against time (s): the ambient and the inner-surface temperature (C),
                            the martensite fraction, and the pressure (MPa), stages shaded
  fields.png                radial profiles at the three instants (tools/plot/plot_sleeve-radial.py's)
Usage: tools/plot/plot_sleeve-life.py results/sleeve-life
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402  (first: the sma package sets numpy's threads before numpy loads)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import read_csv  # noqa: E402
from sma.plotting import save  # noqa: E402
from units import celsius  # noqa: E402

STAGES = {1: ("1 cooling", "tab:blue"), 2: ("2 storage", "tab:cyan"), 3: ("3 installation", "tab:purple"),
          4: ("4 heating", "tab:red"), 5: ("5 service", "tab:green")}


def runs_of(stages):
    """[(stage, first row, last row)] of the consecutive rows of each stage."""
    out, start = [], 0
    for i in range(1, len(stages) + 1):
        if i == len(stages) or stages[i] != stages[start]:
            out.append((int(stages[start]), start, i - 1))
            start = i
    return out


def shade_stages(axes, t, stages, labelled, origin):
    """Shades each stage's rows (times t) in its colour on every axis, names the stages in the
    legend of the axis `labelled`, and grids the axes; the first run starts at time `origin`."""
    for stage, a, b in runs_of(stages):
        name, colour = STAGES[stage]
        for ax in axes:
            ax.axvspan(t[a - 1] if a > 0 else origin, t[b], color=colour, alpha=0.12, lw=0,
                       label=name if ax is labelled else None)
    for ax in axes:
        ax.grid(alpha=0.3)


def pressure_temperature(outdir, summary, h):
    fig, ax = plt.subplots(figsize=(8, 5))
    T = [celsius(x) for x in h["T_inner_mean"]]
    p = [x / 1e6 for x in h["pressure_mean"]]
    seen = set()
    for stage, a, b in runs_of(h["stage"]):
        lo = max(0, a - 1)  # joined to the previous stage's last point
        name, colour = STAGES[stage]
        ax.plot(T[lo:b + 1], p[lo:b + 1], color=colour, lw=1.3, label=None if stage in seen else name)
        seen.add(stage)
    ax.axhline(summary["min_pressure"] / 1e6, color="k", ls="--", lw=0.8, label="-minpressure")
    for key, label, style in (("T_forward_free", "free ring: forward", ":"), ("T_reverse_free", "free ring: reverse", "-.")):
        ax.axvline(celsius(summary[key]), color="0.4", ls=style, lw=0.8, label=f"{label} {celsius(summary[key]):.1f} °C")
    ax.set_xlabel("inner-surface temperature (°C)")
    ax.set_ylabel("mean contact pressure (MPa)")
    k = float(summary.get("dissipation", 0))  # (summary.json has it only when k > 0)
    ax.set_title(f"{summary['scene']}: clamping pressure over the coupling's life (dissipation k = {k / 1e6:g} MPa)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "pressure-temperature.png"), 120)


def life(outdir, summary, h):
    fig, axes = plt.subplots(3, 1, figsize=(10, 7.5), sharex=True)
    t = h["t"]
    axes[0].plot(t, [celsius(x) for x in h["T_ambient_K"]], color="0.5", lw=0.8, label="ambient")
    axes[0].plot(t, [celsius(x) for x in h["T_inner_mean"]], color="k", lw=1.1, label="inner surface")
    axes[0].set_ylabel("temperature (°C)")
    axes[1].plot(t, [1 - x for x in h["fraction_austenite"]], color="k", lw=1.1)
    axes[1].set_ylabel("martensite fraction (1)")
    axes[2].plot(t, [x / 1e6 for x in h["pressure_mean"]], color="k", lw=1.1)
    axes[2].axhline(summary["min_pressure"] / 1e6, color="k", ls="--", lw=0.8, label="-minpressure")
    axes[2].set_ylabel("mean contact pressure (MPa)")
    axes[2].set_xlabel("time (s)")
    shade_stages(axes, t, h["stage"], axes[1], 0.0)
    axes[0].legend(fontsize=7, loc="upper right")
    axes[1].legend(fontsize=7, loc="upper right", ncol=5)
    axes[2].legend(fontsize=7, loc="upper right")
    fig.suptitle(f"{summary['scene']}: temperatures, martensite and pressure against time")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "life.png"), 110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-life"
    summary = results_io.read_summary(outdir, __file__)
    h = read_csv(os.path.join(outdir, "history.csv"))
    pressure_temperature(outdir, summary, h)
    life(outdir, summary, h)
    import importlib
    radial = importlib.import_module("plot_sleeve-radial")
    radial.fields(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
