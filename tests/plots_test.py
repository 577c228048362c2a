#!/usr/bin/python3
"""The sleeve scenes' points.csv in SI units and the figures drawn from it (tools/plot/plot_sleeve.py,
tools/plot/plot_sleeve-radial.py; docs/outputs.md).

Runs sleeve-circular on its default mesh (meshes/sleeve-aniso.msh), 300 steps, a VTU frame every
10 steps, and asserts:
  - points.csv's header carries the units (T_<point>_K, pressure_<point>_Pa, gap_<point>_m) and
    fields-*.csv's first line the time and "SI units: m, K, Pa";
  - at the last step each point's pressure (Pa) equals contact-final.csv's pressure at the
    contact node of that angle (0, 45, 90 degrees), to the 12 digits both print;
  - in every VTU frame (a different writer), each point's temperature (K) equals the VTU's
    nodal temperature at that node, and its gap (m) equals u.n + gap recomputed from the VTU's
    displacement and the pipe of summary.json (a centred circle: n radial);
  - tools/plot/plot_sleeve.py exits 0 and writes force-temperature.png, displacement.png,
    iterations.png and fields-<instant>.png for the three instants (PNG files written by this
    run); its legend groups the three points as coinciding, with the largest difference it
    prints equal to the one measured here from points.csv (per step, each of T and pressure as a
    fraction of its span over the three curves);
  - on a copy where one point's pressure is raised by 5 % after the first contact (synthetic:
    those curves do not coincide) the tool still exits 0 and no legend entry says "coincide";
    with only that point raised, the other two are still grouped;
  - tools/plot/plot_sleeve-radial.py exits 0 and writes its three PNGs on a sleeve-radial run
    (nr 20, 300 steps).
Writes results/checks/plots.json.
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, run_scene, sleeve_outputs  # noqa: E402

STEPS, EVERY = 300, 10
POINTS = {"x_axis": 0.0, "diagonal": 45.0, "y_axis": 90.0}
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"



def write_rows(path, table):
    """Writes rows (dicts) as a CSV with their keys as the header."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)

def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def plot(tool, out, *extra):
    """Runs tools/<tool> on out; returns (exit code, stdout + stderr)."""
    done = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools", "plot", tool), out, *extra],
                          cwd=ROOT, capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


def fresh_pngs(out, names, since):
    """The PNGs among `names` missing in out, or not written after `since`, or not PNG files."""
    bad = []
    for name in names:
        path = os.path.join(out, name)
        if not os.path.exists(path) or os.path.getmtime(path) < since:
            bad.append(name)
            continue
        with open(path, "rb") as f:
            if f.read(8) != PNG_SIGNATURE:
                bad.append(name)
    return bad


def legend_labels(output):
    """The force-temperature legend the plot tool prints."""
    line = next((ln for ln in output.splitlines() if ln.startswith("force-temperature.png curves: ")), "")
    return line[len("force-temperature.png curves: "):].split(" | ") if line else []


def largest_relative_difference(points, names):
    """Largest difference over the steps between any two of the named points' curves, T and
    pressure each as a fraction of its span over the three curves (what the legend reports)."""
    T = {n: [float(r[f"T_{n}_K"]) for r in points] for n in names}
    p = {n: [float(r[f"pressure_{n}_Pa"]) for r in points] for n in names}
    T_span = max(max(v) for v in T.values()) - min(min(v) for v in T.values())
    p_span = max(max(v) for v in p.values()) - min(min(v) for v in p.values())
    worst = 0.0
    for a in names:
        for b in names:
            worst = max(worst, max(abs(u - v) for u, v in zip(T[a], T[b])) / T_span,
                        max(abs(u - v) for u, v in zip(p[a], p[b])) / p_span)
    return worst


def main():
    out = run_scene("sleeve-circular", "plots", "-steps", str(STEPS), "-vtkevery", str(EVERY), "-quiet", "1")
    run = sleeve_outputs(out)
    summary, points, final = run["summary"], run["points"], run["final"]
    dt = summary["parameters"]["dt"]

    # ---- Units in the headers ----
    units = (("T", "K"), ("pressure", "Pa"), ("gap", "m"))
    expected = ["step", "t"] + [f"{q}_{n}_{u}" for n in POINTS for q, u in units]
    check(list(points[0]) == expected, f"points.csv columns carry their units: {','.join(points[0])}")
    firsts = {}
    for instant in ("1-dilated", "2-contact", "3-end"):
        with open(os.path.join(out, f"fields-{instant}.csv")) as f:
            firsts[instant] = f.readline().strip()
    check(all(re.fullmatch(r"# t = [0-9.e+-]+ s; SI units: m, K, Pa", v) for v in firsts.values()),
          f"fields-*.csv first lines: {list(firsts.values())}")

    # ---- The last step against contact-final.csv ----
    worst_p = 0.0
    node_of = {}
    for name, angle in POINTS.items():
        node = min(final, key=lambda r: abs(float(r["angle_deg"]) - angle))
        node_of[name] = (float(node["x"]), float(node["y"]))
        p_final, p_point = float(node["pressure"]), float(points[-1][f"pressure_{name}_Pa"])
        worst_p = max(worst_p, abs(p_point - p_final) / p_final)
    check(worst_p < 1e-11, f"last step: points.csv pressure (Pa) = contact-final.csv's at the node of each "
          f"angle, relative difference {worst_p:.1e} (final {float(points[-1]['pressure_x_axis_Pa']) / 1e6:.4f} MPa)")

    # ---- Every frame: temperature and gap against the VTU ----
    pipe = summary["parameters"]["pipe_A"]
    worst_T, worst_gap, frames = 0.0, 0.0, 0
    for step in range(EVERY, STEPS, EVERY):
        grid = read_vtu(os.path.join(out, "frames", f"step-{step:06d}.vtu"))
        xyz = vtk_to_numpy(grid.GetPoints().GetData())
        temp = vtk_to_numpy(grid.GetPointData().GetArray("temperature"))
        disp = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
        row = points[step - 1]
        for name, (x, y) in node_of.items():
            k = int(((xyz[:, 0] - x) ** 2 + (xyz[:, 1] - y) ** 2).argmin())
            r = math.hypot(x, y)
            worst_T = max(worst_T, abs(float(row[f"T_{name}_K"]) - temp[k]))
            gap = (disp[k][0] * x + disp[k][1] * y) / r - (pipe - r)
            worst_gap = max(worst_gap, abs(float(row[f"gap_{name}_m"]) - gap))
        frames += 1
    check(worst_T < 1e-8, f"{frames} frames: points.csv temperature (K) = the VTU's at the node, worst {worst_T:.1e} K")
    check(worst_gap < 1e-12, f"{frames} frames: points.csv gap (m) = u.n + gap from the VTU's displacement, "
          f"worst {worst_gap:.1e} m")

    # ---- The plot tool on the run ----
    pngs = ["force-temperature.png", "displacement.png", "iterations.png",
            "fields-1-dilated.png", "fields-2-contact.png", "fields-3-end.png"]
    since = os.path.getmtime(os.path.join(out, "summary.json"))
    code, output = plot("plot_sleeve.py", out)
    bad = fresh_pngs(out, pngs, since)
    check(code == 0 and not bad, f"plot_sleeve.py exit {code}, wrote {len(pngs) - len(bad)} of the {len(pngs)} "
          f"PNGs (missing or stale: {bad})" + ("" if code == 0 else "\n" + output))
    labels = circular_legend = legend_labels(output)
    measured = largest_relative_difference(points, list(POINTS))
    printed = re.search(r"coincide within ([0-9.e+-]+) %", labels[0]) if len(labels) == 1 else None
    check(printed is not None and abs(float(printed.group(1)) / (100 * measured) - 1) < 0.05,
          f"the three points coincide (largest difference {100 * measured:.3g} % of full scale, measured here): "
          f"one legend entry {labels}")

    # ---- Synthetic: one point 5 % higher after the first contact ----
    fake = os.path.join(TEST_RESULTS, "plots-not-coinciding")
    shutil.rmtree(fake, ignore_errors=True)
    shutil.copytree(out, fake)
    with open(os.path.join(out, "points.csv"), newline="") as f:
        table = list(csv.DictReader(f))
    for r in table:
        r["pressure_diagonal_Pa"] = repr(1.05 * float(r["pressure_diagonal_Pa"]))
    write_rows(os.path.join(fake, "points.csv"), table)
    code, output = plot("plot_sleeve.py", fake)
    labels = legend_labels(output)
    check(code == 0 and len(labels) == 2 and "coincide" not in labels[1] and labels[1] == "45 deg"
          and labels[0].startswith("x axis (0 deg), y axis (90 deg) (coincide within "),
          f"diagonal raised by 5 %: exit {code}, legend {labels} (x and y axes still one entry, 45 deg alone)")
    for r in table:
        r["pressure_y_axis_Pa"] = repr(1.1 * float(r["pressure_y_axis_Pa"]))
    write_rows(os.path.join(fake, "points.csv"), table)
    code, output = plot("plot_sleeve.py", fake)
    labels = legend_labels(output)
    check(code == 0 and len(labels) == 3 and not any("coincide" in label for label in labels),
          f"diagonal +5 %, y axis +10 %: exit {code}, three legend entries, none says coincide: {labels}")

    # ---- The radial model's figures ----
    radial = run_scene("sleeve-radial", "plots-radial", "-nr", "20", "-steps", str(STEPS), "-quiet", "1")
    since = os.path.getmtime(os.path.join(radial, "summary.json"))
    code, output = plot("plot_sleeve-radial.py", radial, os.path.join(out, "history.csv"))
    radial_pngs = ["force-temperature.png", "iterations.png", "fields.png"]
    bad = fresh_pngs(radial, radial_pngs, since)
    check(code == 0 and not bad, f"plot_sleeve-radial.py exit {code}, wrote {len(radial_pngs) - len(bad)} of "
          f"{len(radial_pngs)} PNGs (missing or stale: {bad})" + ("" if code == 0 else "\n" + output))
    # The 2D model's tool on a radial run names the radial one instead of a missing points.csv.
    code, output = plot("plot_sleeve.py", radial)
    errors = [ln for ln in output.splitlines() if ln.startswith("error:")]
    check(code == 1 and len(errors) == 1 and "plot_sleeve-radial.py" in errors[0] and "Traceback" not in output,
          f"plot_sleeve.py on a sleeve-radial run: exit {code}, {errors[:1]}")
    # and the other way round (it failed on a key sleeve-circular does not write: "KeyError: 'nr'")
    code, output = plot("plot_sleeve-radial.py", out)
    errors = [ln for ln in output.splitlines() if ln.startswith("error:")]
    check(code == 1 and len(errors) == 1 and "holds a run of sleeve-circular" in errors[0]
          and "plot_sleeve.py" in errors[0], f"plot_sleeve-radial.py on a sleeve-circular run: exit {code}, {errors[:1]}")

    # ---- Damaged results: one error line naming the file, exit 1, never a traceback ----
    damaged = os.path.join(TEST_RESULTS, "plots-damaged")
    for name, damage in (("summary.json", lambda text: text[:len(text) // 2]),
                         ("history.csv", lambda text: text[:len(text) // 2].rsplit(",", 3)[0]),
                         ("points.csv", lambda text: text.replace("\n2,", "\n2,abc,", 1))):
        shutil.rmtree(damaged, ignore_errors=True)
        shutil.copytree(out, damaged)
        path = os.path.join(damaged, name)
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(damage(text))
        code, output = plot("plot_sleeve.py", damaged)
        errors = [ln for ln in output.splitlines() if ln.startswith("error:")]
        check(code == 1 and len(errors) == 1 and path in errors[0] and "Traceback" not in output,
              f"a damaged {name}: plot_sleeve.py exit {code}, {errors[0] if errors else output[-200:]}")
    shutil.rmtree(damaged, ignore_errors=True)

    record("plots", {"test": "plots", "mesh": summary["parameters"]["mesh"], "steps": STEPS, "dt_s": dt,
                     "last_step_pressure_relative_difference": worst_p, "frames": frames,
                     "frame_temperature_worst_K": worst_T, "frame_gap_worst_m": worst_gap,
                     "points_largest_difference_fraction": measured, "legend": circular_legend})
    finish()


if __name__ == "__main__":
    main()
