#!/usr/bin/python3
"""Histogram of a sleeve-random-ensemble run (edp/ensemble/sleeve-random-ensemble.edp), from
<out>/seeds.csv and <out>/summary.json:

  histogram.png  left: the peak and the final clamping force (mean contact pressure, MPa) over the
                 seeds; right: the largest pressure peak of a single inner-surface node over its
                 final value; the 5/50/95 % quantiles of summary.json as lines
Usage: tools/plot/plot_ensemble.py results/sleeve-random-ensemble
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import read_csv  # noqa: E402
from sma.plotting import save  # noqa: E402
from units import celsius  # noqa: E402


def histogram(ax, values, label, color, bins):
    """One histogram; a sample without spread (the final force, all austenite) gets one bar of
    a visible width instead of matplotlib's zero-width bins."""
    lo, hi = min(values), max(values)
    if hi - lo <= 1e-9 * max(abs(hi), 1e-300):
        width = 1e-4 * max(abs(hi), 1e-300)
        ax.bar([lo], [len(values)], width=width, color=color, alpha=0.6,
               label=f"{label} (all {lo:.6g})")
    else:
        ax.hist(values, bins=bins, color=color, alpha=0.6, label=label)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    for name in ("seeds.csv", "summary.json"):
        if not os.path.isfile(os.path.join(out, name)):
            sys.exit(f"error: {os.path.join(out, name)} missing: run the ensemble first (make ensemble)")
    seeds = read_csv(os.path.join(out, "seeds.csv"))
    summary = results_io.read_json(os.path.join(out, "summary.json"))
    n = len(seeds["seed"])
    bins = max(5, min(30, n // 2))
    p = summary["parameters"]

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    # What the draw changes: when the clamping is complete (the ring austenite for good). The
    # force itself ends the same for every seed once all is austenite (the draw no longer acts):
    # it is said in the title rather than drawn as one bar.
    histogram(left, [celsius(v) for v in seeds["T_inner_austenite_K"]], "inner surface", "tab:red", bins)
    left.set_xlabel("temperature at which the ring is austenite for good (°C)")
    left.set_ylabel("seeds")
    final = seeds["final_pressure_mean_Pa"]
    same = max(final) - min(final) <= 1e-6 * max(abs(max(final)), 1e-300)
    left.set_title("full clamping: its temperature over the seeds\n" +
                   (f"final pressure {final[0] / 1e6:.6g} MPa for every seed (all austenite)" if same else
                    f"final pressure {min(final) / 1e6:.6g} to {max(final) / 1e6:.6g} MPa"), fontsize=9)
    left.ticklabel_format(axis="x", useOffset=False)
    left.xaxis.set_major_locator(MaxNLocator(4))
    left.legend(fontsize=8)

    histogram(right, seeds["node_peak_over_final_max"], "largest node peak / its final value",
              "tab:green", bins)
    stats = summary["node_peak_over_final_max"]
    for key, style in (("q05", ":"), ("q50", "--"), ("q95", ":")):
        right.axvline(stats[key], color="k", linestyle=style, linewidth=1)
    right.set_xlabel("node pressure peak / final (quantiles 5, 50, 95 % dashed)")
    right.set_title("local peaks (paper Fig. 33-36: about 1.5)")
    right.legend(fontsize=8)

    fig.suptitle(f"sleeve-random-threshold, {n} seeds on {summary['n_ranks']} rank(s): spread "
                 f"{p['threshold_spread_K']} K {p['threshold_law']}, {p['steps']} steps, {p['mesh']}",
                 fontsize=10)
    fig.tight_layout()
    save(fig, os.path.join(out, "histogram.png"), 120)
    print(f"wrote {os.path.join(out, 'histogram.png')}")


if __name__ == "__main__":
    results_io.guard(main)
