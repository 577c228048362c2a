#!/usr/bin/python3
"""Figures of the sleeve-3d scene (the sleeve as a 3D solid, a quarter of its section and half its
length), from results/sleeve-3d/: the axisymmetric scene's two figures (its outputs have the same
columns: the ring-averaged pressure per layer z in bore-*.csv), drawn by plot_sleeve-axisymmetric.py:

  force-temperature.png  the ring-averaged contact pressure at mid-length (z = 0), at the free end
                         and its mean over the bore, against the bore's mean temperature and time
  bore-pressure.png      the ring-averaged contact pressure along the bore at the three instants
Usage: tools/plot/plot_sleeve-3d.py results/sleeve-3d
"""
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))  # tools/: results_io
import results_io  # noqa: E402

spec = importlib.util.spec_from_file_location("plot_axisymmetric", os.path.join(HERE, "plot_sleeve-axisymmetric.py"))
axisymmetric = importlib.util.module_from_spec(spec)
spec.loader.exec_module(axisymmetric)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-3d"
    summary = results_io.read_json(os.path.join(outdir, "summary.json"))
    axisymmetric.force_temperature(outdir, summary)
    axisymmetric.bore_pressure(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
