#!/usr/bin/python3
"""Figures of docs/variants.md from the variants' outputs (edp/variants/*.edp at their defaults).

  asymmetric-phases.png   beam phase zones, symmetric law against alpha_minus < alpha_plus (medium mesh)
  lobed-pressure.png      contact pressure and tangential density along the ring, circle and lobed pipe
  p2-convergence.png      beam tip deflection against degrees of freedom, P1 and P2
  deviatoric-phases.png   beam phase zones with the deviatoric transformation direction (medium mesh)
Usage: tools/plot/plot_variants.py [--only <variant>] [results/variants] [docs/variants]
  (--only: the one figure of that variant, e.g. into its results folder: make run SCENE=beam-p2)
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests"))
from checklib import rows  # noqa: E402

from sma.plotting import save as save_png  # noqa: E402

PHASE_COLOURS = {0: "0.6", 1: "black", 2: "white"}  # the paper's Fig. 9: grey, black, white


def save(fig, path):
    save_png(fig, path, 120, tight=True)
    print("wrote", path)


def draw_beam_phases(ax, table):
    """The beam's triangles coloured by phase (phase-*.csv rows) on its 10 cm x 1 cm frame."""
    polys = [[(float(r[f"x{i}"]), float(r[f"y{i}"])) for i in (1, 2, 3)] for r in table]
    ax.add_collection(PolyCollection(polys, facecolors=[PHASE_COLOURS[int(float(r["phase"]))] for r in table],
                                     edgecolors="0.35", linewidths=0.1))
    ax.set_xlim(0, 0.1)
    ax.set_ylim(0, 0.01)
    ax.set_aspect("equal")


def asymmetric(src, dst, mesh="medium"):
    summary = results_io.read_json(os.path.join(src, "summary.json"))
    runs = {(r["law"], r["mesh"]): r for r in summary["runs"]}
    fig, axes = plt.subplots(2, 1, figsize=(10, 3.6))
    for ax, law in zip(axes, ("symmetric-plugin", "asymmetric")):
        table = rows(os.path.join(src, f"phase-{law}-{mesh}.csv"))
        draw_beam_phases(ax, table)
        r = runs[(law, mesh)]
        ax.set_title(f"alpha+ = {r['alpha_plus'] / 1e6:.0f} MPa, alpha- = {r['alpha_minus'] / 1e6:.0f} MPa: "
                     f"M1 (black) {r['fraction_m1']:.3f}, M2 (white) {r['fraction_m2']:.3f}, "
                     f"tip {r['tip_deflection'] * 1e3:.2f} mm", fontsize=9)
        ax.set_yticks([])
    save(fig, os.path.join(dst, "asymmetric-phases.png"))


def lobed(src, dst):
    summary = results_io.read_json(os.path.join(src, "summary.json"))
    fig, ax = plt.subplots(figsize=(7, 4))
    styles = {"circle-plugin": ("0.5", "circle (eps = 0)"), "lobed": ("tab:blue", "lobed, mu = 0"),
              "lobed-friction": ("tab:red", f"lobed, mu = {summary['parameters']['mu']}")}
    for name, (colour, label) in styles.items():
        table = rows(os.path.join(src, f"pressure-{name}.csv"))
        angle = [float(r["angle_deg"]) for r in table]
        ax.plot(angle, [float(r["pressure"]) / 1e6 for r in table], "-o", ms=3, color=colour, label=label + ": pressure")
        if name == "lobed-friction":
            ax.plot(angle, [float(r["tangential_density"]) / 1e6 for r in table], "--", color=colour,
                    label=label + ": tangential")
    ax.axhline(summary["pressure_lame"] / 1e6, color="k", lw=0.6, ls=":", label="Lame (circle)")
    ax.set_xlabel("angle (deg): lobes at 0 and 90, valley at 45")
    ax.set_ylabel("force density (MPa)")
    ax.set_title(f"Ring on a lobed pipe r = Rp (1 + {summary['parameters']['eps']} cos 4 theta)", fontsize=10)
    ax.legend(fontsize=8)
    save(fig, os.path.join(dst, "lobed-pressure.png"))


def p2(src, dst):
    summary = results_io.read_json(os.path.join(src, "summary.json"))
    fig, ax = plt.subplots(figsize=(6, 4))
    for element, marker in (("P1", "s-"), ("P2", "o-")):
        runs = [r for r in summary["runs"] if r["element"] == element]
        ax.plot([r["dofs"] for r in runs], [r["tip_deflection"] * 1e3 for r in runs], marker, label=element)
        for r in runs:
            ax.annotate(r["mesh"], (r["dofs"], r["tip_deflection"] * 1e3), fontsize=7, xytext=(3, -9),
                        textcoords="offset points")
    ax.set_xscale("log")
    ax.set_xlabel("displacement dofs")
    ax.set_ylabel("tip deflection (mm)")
    ax.set_title("Beam (paper 3.2): P1 one point, P2 three mid-edge points", fontsize=10)
    ax.legend()
    save(fig, os.path.join(dst, "p2-convergence.png"))


def deviatoric(src, dst, mesh="medium"):
    summary = results_io.read_json(os.path.join(src, "summary.json"))
    level = next((m for m in summary["meshes"] if m["name"] == mesh), summary["meshes"][-1])
    table = rows(os.path.join(src, f"phase-{level['name']}.csv"))
    fig, ax = plt.subplots(figsize=(10, 1.9))
    draw_beam_phases(ax, table)
    ax.set_yticks([])
    ax.set_title(f"direction {summary['parameters']['direction']}: M1 (black) {level['fraction_m1']:.3f}, "
                 f"M2 (white) {level['fraction_m2']:.3f}, tip {level['tip_deflection'] * 1e3:.2f} mm "
                 f"({level['name']} mesh)", fontsize=9)
    save(fig, os.path.join(dst, "deviatoric-phases.png"))


def main():
    args = sys.argv[1:]
    only = None
    if args[:1] == ["--only"]:
        only, args = args[1], args[2:]
    src = args[0] if len(args) > 0 else "results/variants"
    dst = args[1] if len(args) > 1 else "docs/variants"
    os.makedirs(dst, exist_ok=True)
    figures = {"beam-asymmetric": asymmetric, "ring-lobed": lobed, "beam-p2": p2, "beam-deviatoric": deviatoric}
    if only is not None and only not in figures:
        sys.exit(f"error: no figure of variant {only!r} here (figures: {', '.join(figures)})")
    for name, draw in figures.items():
        if only in (None, name):
            draw(os.path.join(src, name), dst)


if __name__ == "__main__":
    results_io.guard(main)
