#!/usr/bin/python3
"""Figures of the sleeve scenes (paper Figures 12-36), from results/<scene>/ (docs/outputs.md):

  force-temperature.png  left: the contact pressure (MPa) at the three inner-surface points
                         against each point's own temperature (°C), the paper's Fig. 12, 16, 18,
                         22, 26, 30, 34; right: the same pressures against time (s), zoomed on the
                         transient, the whole run in a narrow panel. Shaded with the curve's four
                         phases (no contact, linear in T, reversion, austenite); curves that
                         coincide share one legend entry with their measured largest difference
  displacement.png       the inner surface at the three instants: radial displacement (um)
                         against the angle with the pipe's surface, and the opening to the pipe
                         (um, 0 where touching): the offset ring's recentring, the elliptic lift-off
  iterations.png         iteration counts per step of the three nested loops and PSOR
  fields-<instant>.png   radial stress (MPa), temperature (C) and phases (A, M1, M2) at the three
                         instants (the paper's Fig. 13-14, 19-20, 23-24, 27-28, 31-32, 35-36)
The data files are in SI units (K, Pa, m, s); the pictures in degrees C, MPa, mm, um, s.
Prints each figure's curve labels (the legend) on stdout.
Usage: tools/plot/plot_sleeve.py results/<scene>
"""
import quiet_interrupt  # noqa: F401  (first: a Ctrl-C ends this tool without a traceback)
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402,F401

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import force_temperature, iterations_figure  # noqa: E402
from sleeve_fields import fields  # noqa: E402
from sleeve_surface import displacement  # noqa: E402


def iterations(outdir, summary):
    """The three nested loops and PSOR, per step."""
    iterations_figure(outdir, summary, (("fixed_point_iterations", "heat <-> phases"),
                                        ("slip_iterations", "slip threshold"), ("dc_iterations", "DC"),
                                        ("psor_sweeps", "PSOR sweeps")),
                      max(1.0, 20 * summary["parameters"]["dt"]), "time t (s), logarithmic beyond the first steps",
                      log_counts=True)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "results/sleeve-circular"
    summary_path = os.path.join(outdir, "summary.json")
    if not os.path.isfile(summary_path):
        sys.exit(f"error: {summary_path} missing: the run did not finish (summary.json is written last)")
    # (a scene with its own tool, sleeve-radial's without points.csv or VTU: named, not drawn)
    summary = results_io.read_summary(outdir, __file__)
    force_temperature(outdir, summary)
    displacement(outdir, summary)
    iterations(outdir, summary)
    fields(outdir, summary)
    print(f"figures in {outdir}/")


if __name__ == "__main__":
    results_io.guard(main)
