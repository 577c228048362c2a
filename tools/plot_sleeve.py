#!/usr/bin/python3
"""Figures of the sleeve scenes (paper Figures 12-36), from results/<scene>/:

  force-temperature.png  clamping force density (GPa) against the temperature (C) at the three
                         inner-surface points (the paper's Fig. 12, 16, 18, 22, 26, 30, 34)
  iterations.png         iteration counts per step of the three nested loops and PSOR
  fields-<instant>.png   radial stress, temperature and phases at the three instants
                         (the paper's Fig. 13-14, 19-20, 23-24, 27-28, 31-32, 35-36)
Usage: tools/plot_sleeve.py results/<scene>
"""
import csv
import glob
import json
import os
import sys
from units import KELVIN_AT_0C

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402


def read_csv(path, skip_comment=True):
    with open(path, newline="") as f:
        lines = [ln for ln in f if not (skip_comment and ln.startswith("#"))]
    rows = list(csv.DictReader(lines))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def save(fig, path, dpi):
    """Writes the PNG under a temporary name, then renames it: never a half-drawn file."""
    partial = path[:-len(".png")] + ".partial.png"
    fig.savefig(partial, dpi=dpi)
    plt.close(fig)
    os.replace(partial, path)


def force_temperature(outdir, scene):
    p = read_csv(os.path.join(outdir, "points.csv"))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    labels = {"x_axis": "on the x axis", "diagonal": "at 45 degrees", "y_axis": "on the y axis",
              "near": "0 degrees (side the pipe is shifted to)", "top": "90 degrees", "far": "180 degrees"}
    names = [k[len("pressure_"):-len("_GPa")] for k in p if k.startswith("pressure_")]
    for name in names:
        ax.plot(p[f"T_{name}_C"], p[f"pressure_{name}_GPa"], lw=1, label=labels.get(name, name))
    ax.set_xlabel("temperature at the point (C)")
    ax.set_ylabel("clamping force density (GPa)")
    ax.set_title(f"{scene}: clamping force against temperature")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "force-temperature.png"), 120)


def iterations(outdir, scene):
    h = read_csv(os.path.join(outdir, "history.csv"))
    fig, ax = plt.subplots(figsize=(7, 4))
    for key, label in (("fixed_point_iterations", "heat <-> phases"),
                       ("slip_iterations", "slip threshold"), ("dc_iterations", "DC"),
                       ("psor_sweeps", "PSOR sweeps")):
        ax.plot(h["step"], h[key], lw=0.8, label=label)
    ax.set_yscale("symlog")
    ax.set_xlabel("step")
    ax.set_ylabel("iterations in the step")
    ax.set_title(f"{scene}: iterations per step")
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "iterations.png"), 120)


def fields(outdir, scene):
    for path in sorted(glob.glob(os.path.join(outdir, "fields-*.csv"))):
        with open(path) as f:
            when = f.readline().strip("# \n")
        d = read_csv(path)
        tri = mtri.Triangulation(d["x"], d["y"])
        # Delaunay of the centroids also fills the hole of the ring: mask those triangles.
        radius = [(x * x + y * y) ** 0.5 for x, y in zip(d["x"], d["y"])]
        inner = min(radius)
        tri.set_mask([sum(radius[k] for k in t) / 3 < inner * 0.999 or
                      ((sum(d["x"][k] for k in t) / 3) ** 2 + (sum(d["y"][k] for k in t) / 3) ** 2) ** 0.5
                      < inner * 0.999 for t in tri.triangles])
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
        for ax, key, label, scale in ((axes[0], "sigma_rr", "radial stress (MPa)", 1e-6),
                                      (axes[1], "T", "temperature (C)", None),
                                      (axes[2], "phase", "phase (0 A, 1 M1, 2 M2)", 1)):
            values = [v - KELVIN_AT_0C for v in d[key]] if key == "T" else [v * scale for v in d[key]]
            c = ax.tricontourf(tri, values, levels=20 if key != "phase" else [-0.5, 0.5, 1.5, 2.5])
            fig.colorbar(c, ax=ax, shrink=0.8)
            ax.set_aspect("equal")
            ax.set_title(label, fontsize=9)
            ax.set_xticks([]), ax.set_yticks([])
        instant = os.path.basename(path)[len("fields-"):-len(".csv")]
        fig.suptitle(f"{scene}: {instant} ({when})")
        fig.tight_layout()
        save(fig, path[:-4] + ".png", 110)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-circular"
    scene = json.load(open(os.path.join(outdir, "summary.json")))["scene"]
    force_temperature(outdir, scene)
    iterations(outdir, scene)
    fields(outdir, scene)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    main()
