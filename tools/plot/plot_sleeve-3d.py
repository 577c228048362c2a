#!/usr/bin/python3
"""Figures of the sleeve-3d scene (the sleeve as a 3D solid, a quarter of its section and half its
length), from results/sleeve-3d/: the axisymmetric scene's two figures (its outputs have the same
columns: the ring-averaged pressure per layer z in bore-*.csv), drawn by plot_sleeve-axisymmetric.py:

  force-temperature.png  the ring-averaged contact pressure at mid-length (z = 0), at the free end
                         and its mean over the bore, against the bore's mean temperature and time
  bore-pressure.png      the ring-averaged contact pressure along the bore at the three instants
  bend.png               (-bend > 0) the moment the joint resists with (kN m) and the bore's nodes
                         open and sliding against the pipe's rotation (mrad); the first sliding
                         and the first leak path marked, each shaded over the increment it lies in
  pullout.png            (-pullout > 0) the pull-out force against the pipe's displacement and
                         mu N, drawn by plot_sleeve-axisymmetric.py from the same pullout.csv columns
Usage: tools/plot/plot_sleeve-3d.py results/sleeve-3d
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))  # tools/: results_io
import results_io  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

spec = importlib.util.spec_from_file_location("plot_axisymmetric", os.path.join(HERE, "plot_sleeve-axisymmetric.py"))
axisymmetric = importlib.util.module_from_spec(spec)
spec.loader.exec_module(axisymmetric)


def bend(outdir, summary):
    path = os.path.join(outdir, "bend.csv")
    if not os.path.exists(path):
        return
    d = axisymmetric.read_csv(path)
    angle = [a * 1e3 for a in d["angle"]]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    left.plot([0] + angle, [0] + [m / 1e3 for m in d["moment"]], marker=".", lw=1.2)
    b = summary["bending"]
    for key, label, color in (("first_sliding", "first sliding", "C1"), ("leak_path", "leak path", "C3")):
        if b.get(key + "_angle") is not None:
            # the event is known to its increment: shaded from the increment before to it
            if b.get(key + "_angle_before") is not None:
                left.axvspan(b[key + "_angle_before"] * 1e3, b[key + "_angle"] * 1e3, color=color, alpha=0.15, lw=0)
            left.axvline(b[key + "_angle"] * 1e3, color=color, ls="--", lw=0.8, label=f"{label} (within the shaded increment)")
    left.set_xlabel("pipe rotation (mrad)")
    left.set_ylabel("moment the joint resists with (kN m)")
    left.grid(alpha=0.3)
    if left.get_legend_handles_labels()[0]:
        left.legend(fontsize=8)
    right.plot(angle, d["nodes_open"], marker=".", lw=1, label="open (no pressure)")
    right.plot(angle, d["nodes_sliding"], marker=".", lw=1, label="sliding on the pipe")
    right.set_xlabel("pipe rotation (mrad)")
    right.set_ylabel(f"bore nodes (of {int(d['nodes_pressing'][0] + d['nodes_open'][0])})")
    right.grid(alpha=0.3)
    right.legend(fontsize=8)
    fig.suptitle(f"{summary['scene']}: the coupling bent by its pipe ends, mu = {summary['parameters']['mu']:g}")
    fig.tight_layout()
    axisymmetric.save(fig, os.path.join(outdir, "bend.png"), 120)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-3d"
    summary = results_io.read_summary(outdir, __file__)
    axisymmetric.force_temperature(outdir, summary)
    axisymmetric.bore_pressure(outdir, summary)
    bend(outdir, summary)
    if summary.get("pullout"):
        # the axisymmetric figure's keys, from the 3D summary's pullout object and parameters
        pull = summary["pullout"]
        axisymmetric.pullout(outdir, {"scene": summary["scene"], "mu": summary["parameters"]["mu"],
                                      "pullout_force_final": pull["force_final"], "pullout_force_max": pull["force_max"]})
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
