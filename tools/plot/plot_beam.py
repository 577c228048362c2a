#!/usr/bin/python3
"""Figures of the beam scene (paper Fig. 9 and 10) from the CSVs written by edp/scenes/beam.edp.

phase-<mesh>.png: phase zones, austenite grey, martensite 1 black, martensite 2 white (as the paper);
dc-convergence.png: relative displacement change per DC iteration, log scale, all meshes.
Usage: tools/plot/plot_beam.py [results/beam]
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from sma.plotting import save  # noqa: E402

PHASE_COLOURS = {0: "0.6", 1: "black", 2: "white"}


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def phase_map(outdir, mesh):
    rows = read_rows(os.path.join(outdir, f"phase-{mesh['name']}.csv"))
    polys = [[(float(r["x1"]), float(r["y1"])), (float(r["x2"]), float(r["y2"])),
              (float(r["x3"]), float(r["y3"]))] for r in rows]
    colours = [PHASE_COLOURS[int(float(r["phase"]))] for r in rows]
    fig, ax = plt.subplots(figsize=(10, 1.9))
    ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors="0.35", linewidths=0.1))
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"beam, {mesh['name']} mesh ({mesh['nodes']} nodes, {mesh['triangles']} triangles): "
                 f"austenite grey {mesh['fraction_austenite']:.3f}, martensite 1 black "
                 f"{mesh['fraction_m1']:.3f}, martensite 2 white {mesh['fraction_m2']:.3f}",
                 fontsize=8)
    save(fig, os.path.join(outdir, f"phase-{mesh['name']}.png"), 130, tight=True)


def convergence(outdir, meshes):
    rows = read_rows(os.path.join(outdir, "dc-convergence.csv"))
    fig, ax = plt.subplots(figsize=(6, 4))
    for mesh in meshes:
        mine = [r for r in rows if r["mesh"] == mesh["name"]]
        its = [int(r["iteration"]) for r in mine]
        change = [max(float(r["relative_change"]), 1e-17) for r in mine]
        ax.semilogy(its, change, "o-", label=f"{mesh['name']} ({mesh['nodes']} nodes)")
    tol = results_io.read_json(os.path.join(outdir, "summary.json"))["parameters"]["dc_tol"]
    ax.axhline(tol, color="0.5", ls="--", lw=0.8, label=f"stopping tolerance {tol:g}")
    ax.set_xlabel("DC iteration")
    ax.set_ylabel("relative change of u (Euclidean norm)")
    ax.set_title("DC convergence on the beam (paper Fig. 10)")
    ax.legend(fontsize=8)
    save(fig, os.path.join(outdir, "dc-convergence.png"), 130, tight=True)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/beam"
    summary = results_io.read_summary(outdir, __file__)
    for mesh in summary["meshes"]:
        phase_map(outdir, mesh)
    convergence(outdir, summary["meshes"])


if __name__ == "__main__":
    results_io.guard(main)
