#!/usr/bin/python3
"""Figure of the free-ring scene: temperatures and phase fractions against time.

Usage: tools/plot/plot_free-ring.py [results/free-ring] [other-run-dir label ...]
Extra (directory, label) pairs overlay the mean temperature of other runs (e.g. -latent 0).
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

from sma.plotting import save  # noqa: E402
from units import celsius  # noqa: E402


def read(outdir):
    with open(os.path.join(outdir, "history.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/free-ring"
    h = read(outdir)
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax.plot(h["t"], [celsius(T) for T in h["T_outside"]], "k--", lw=0.8, label="outside")
    ax.plot(h["t"], [celsius(T) for T in h["T_mean"]], label="ring, mean")
    ax.plot(h["t"], [celsius(T) for T in h["T_inner"]], lw=0.8, label="inner surface point")
    extra = sys.argv[2:]
    for d, label in zip(extra[::2], extra[1::2]):
        ax.plot(read(d)["t"], [celsius(T) for T in read(d)["T_mean"]], ":", label=label)
    T0 = results_io.read_json(os.path.join(outdir, "summary.json"))["parameters"]["T0"]
    ax.axhline(celsius(T0), color="0.6", lw=0.6, label=f"T0 = {celsius(T0):.2f} °C")
    ax.set_ylabel("T (°C)")
    ax.legend(fontsize=8)
    ax.set_title(f"free ring cooled and heated through T0 = {celsius(T0):.2f} °C ({T0:g} K)")
    bx.plot(h["t"], h["fraction_austenite"], label="austenite")
    bx.plot(h["t"], h["fraction_m1"], label="martensite 1")
    bx.plot(h["t"], h["fraction_m2"], label="martensite 2")
    bx.set_xlabel("t (s)")
    bx.set_ylabel("area fraction (1)")
    bx.legend(fontsize=8)
    save(fig, os.path.join(outdir, "temperature.png"), 120, tight=True)


if __name__ == "__main__":
    results_io.guard(main)
