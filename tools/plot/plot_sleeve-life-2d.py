#!/usr/bin/python3
"""Figures of the sleeve-life-2d scene (the coupling's life on the 2D model, a pipe of any shape),
from results/sleeve-life-2d/:

  pressure-temperature.png  the mean contact pressure (MPa) against the inner-surface temperature
                            (C) over the whole history, one colour per stage (plot_sleeve-life.py's)
  life.png                  against time (s): ambient and inner-surface temperature, martensite
                            fraction, mean pressure, stages shaded (plot_sleeve-life.py's)
  pressure-points.png       from the installation on: the contact pressure (MPa) at the inner
                            surface's points on the x axis, the diagonal and the y axis
                            (points.csv), and the smallest and largest nodal pressure (history.csv),
                            against time; below, the non-uniformity (max - min) / mean
  fields-<instant>.png      stress, temperature and phases at the three instants (plot_sleeve.py's)
Usage: tools/plot/plot_sleeve-life-2d.py results/sleeve-life-2d
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import importlib
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402  (first: the sma package sets numpy's threads before numpy loads)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import read_csv  # noqa: E402
from sleeve_fields import fields  # noqa: E402
from sma.plotting import save  # noqa: E402

life_radial = importlib.import_module("plot_sleeve-life")


def pressure_points(outdir, summary, h, pts):
    # From the installation (stage 3) on: before it the pipe is away and the pressures are 0.
    first = next((i for i, s in enumerate(h["stage"]) if s >= 3), 0)
    t = h["t"][first:]
    fig, axes = plt.subplots(2, 1, figsize=(10, 6.5), sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    ax = axes[0]
    names = [k[len("pressure_"):-len("_Pa")] for k in pts if k.startswith("pressure_") and k.endswith("_Pa")]
    for name, style in zip(names, ("-", "--", ":")):
        ax.plot(pts["t"][first:], [p / 1e6 for p in pts[f"pressure_{name}_Pa"][first:]], ls=style, lw=1.1,
                label=f"point on the {name.replace('_', ' ')}")
    ax.fill_between(t, [p / 1e6 for p in h["pressure_min"][first:]], [p / 1e6 for p in h["pressure_max"][first:]],
                    color="0.8", alpha=0.6, lw=0, label="smallest to largest nodal pressure")
    ax.axhline(summary["min_pressure"] / 1e6, color="k", ls="--", lw=0.8, label="-minpressure")
    ax.set_ylabel("contact pressure (MPa)")
    ax.legend(fontsize=7, loc="lower right")
    axes[1].plot(t, h["pressure_non_uniformity"][first:], color="k", lw=1.0)
    axes[1].set_yscale("symlog", linthresh=1e-3)  # 1e-3 on the ellipse, tens at first contact
    axes[1].set_ylabel("(max - min) / mean")
    axes[1].set_xlabel("time (s)")
    life_radial.shade_stages(axes, t, h["stage"][first:], axes[1], t[0])
    axes[1].legend(fontsize=7, loc="upper right", ncol=3)
    pipe = summary["parameters"]
    fig.suptitle(f"{summary['scene']}: pressure around the contact (pipe semi-axes {pipe['pipe_A'] * 1e3:g} x "
                 f"{pipe['pipe_B'] * 1e3:g} mm), smallest in service {summary['service_pressure_node_min'] / 1e6:.2f}"
                 f" MPa at {summary['service_pressure_node_min_angle_deg']:.0f}°"
                 if summary.get("service_pressure_node_min") is not None else
                 f"{summary['scene']}: pressure around the contact")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "pressure-points.png"), 110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-life-2d"
    summary = results_io.read_summary(outdir, __file__)
    h = read_csv(os.path.join(outdir, "history.csv"))
    pts = read_csv(os.path.join(outdir, "points.csv"))
    life_radial.pressure_temperature(outdir, summary, h)
    life_radial.life(outdir, summary, h)
    pressure_points(outdir, summary, h, pts)
    fields(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
