#!/usr/bin/python3
"""The sleeve scenes' ParaView time series (fields.pvd + VTU frames), read back with VTK.

Runs sleeve-circular on meshes/sleeve-coarse.msh, 60 steps, a frame every 10 steps, and asserts:
  - fields.pvd is a VTK Collection whose times are, in increasing order, exactly the periodic
    frames (steps 10..50) and the three instants, each at step x dt (dt and the instants' steps
    from summary.json), every listed file present;
  - every VTU has the mesh's points and triangles (summary.json: nodes, triangles) and the fields
    displacement (3 components) and temperature at the points, phase, sigma_rr, sigma_tt,
    T0_local per cell;
  - the temperature of each periodic frame at the inner-surface nodes, averaged with their
    tributary lengths (contact-final.csv), equals history.csv's T_inner_mean at that step;
  - the last frame is fields-3-end.vtu at t = 150 s and agrees with fields-3-end.csv, written by
    a different writer: per triangle phase, sigma_rr, sigma_tt, T0_local, and the CSV's centroid
    temperature and displacement (ux, uy) = the means of the triangle's three nodal values in the VTU;
  - the last frame's displacement closes the gap with the pipe at every inner node: u.n =
    pipe radius - node radius (Signorini, every node in contact at the end);
  - no *.partial file is left;
and, for files written under a temporary name and renamed: a second run (3000 steps) into a
directory holding an old summary.json is killed after 2 s: no summary.json, history.csv or
points.csv is left (only their .partial), and fields.pvd, if any, is valid and lists only whole
VTU files. Writes results/checks/paraview.json.
"""
import glob
import math
import os
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows, run_scene, sleeve_outputs  # noqa: E402

STEPS, EVERY = 60, 10
VTK_TRIANGLE = 5


def read_pvd(path):
    root = ET.parse(path).getroot()
    assert root.get("type") == "Collection", root.get("type")
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def triangles(grid):
    """Indices of the triangle cells and their point ids."""
    ids = [i for i in range(grid.GetNumberOfCells()) if grid.GetCellType(i) == VTK_TRIANGLE]
    return ids, [[grid.GetCell(i).GetPointId(k) for k in range(3)] for i in ids]


def nearest_points(grid, xy):
    """Point id of the VTU nearest to each (x, y), and the largest distance (m)."""
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    found, worst = [], 0.0
    for x, y in xy:
        d2 = (pts[:, 0] - x) ** 2 + (pts[:, 1] - y) ** 2
        k = int(d2.argmin())
        found.append(k)
        worst = max(worst, math.sqrt(d2[k]))
    return found, worst


def killed_run():
    """A long run killed once it has written a few frames, into a directory with an old summary.json."""
    out = os.path.join(TEST_RESULTS, "paraview-killed")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with open(os.path.join(out, "summary.json"), "w") as f:
        f.write('{"scene": "an earlier run"}\n')
    with open(os.path.join(out, ".sma-results"), "w") as f:  # its manifest lists it
        f.write("sma-results manifest 1\nscene sleeve-circular\nsummary.json\n")
    proc = subprocess.Popen([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", "-mesh",
                             "meshes/sleeve-coarse.msh", "-steps", "100000", "-tend", "10000", "-vtkevery", "20",
                             "-quiet", "1", "-out", out], cwd=ROOT, stdout=subprocess.DEVNULL,
                            start_new_session=True)
    # Killed once 5 frames are out (at most 60 s): the run lasts minutes, whatever the machine.
    deadline = time.time() + 60
    frames = os.path.join(out, "frames")
    while time.time() < deadline and proc.poll() is None:
        if os.path.isdir(frames) and len(os.listdir(frames)) >= 5:
            break
        time.sleep(0.05)
    still_running = proc.poll() is None
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    check(still_running, "the 100000-step run was still running when killed after its 5th frame")
    left = sorted(os.listdir(out))
    check(not any(name in left for name in ("summary.json", "history.csv", "points.csv", "contact-final.csv")),
          f"killed run: no summary.json, history.csv, points.csv, contact-final.csv (left: "
          f"{[n for n in left if n != 'frames']})")
    listed, whole = [], True
    if os.path.exists(os.path.join(out, "fields.pvd")):
        listed = read_pvd(os.path.join(out, "fields.pvd"))
        for _, name in listed:
            path = os.path.join(out, name)
            whole = whole and os.path.exists(path) and read_vtu(path).GetNumberOfPoints() > 0
    frames = len(glob.glob(os.path.join(out, "frames", "step-*.vtu")))
    check(whole, f"killed run: fields.pvd lists {len(listed)} frames, each a whole VTU "
          f"({frames} finished frames in frames/)")
    return {"killed_frames_listed": len(listed), "killed_left": left}


def main():
    out = run_scene("sleeve-circular", "paraview", "-mesh", "meshes/sleeve-coarse.msh", "-steps", str(STEPS),
                    "-vtkevery", str(EVERY), "-quiet", "1")
    run = sleeve_outputs(out)
    summary, hist, final = run["summary"], run["history"], run["final"]
    dt = summary["parameters"]["dt"]

    # ---- The index ----
    frames = read_pvd(os.path.join(out, "fields.pvd"))
    instants = {(summary["first_contact_step"] - 1) * dt: "fields-1-dilated.vtu",
                summary["during_contact_step"] * dt: "fields-2-contact.vtu", STEPS * dt: "fields-3-end.vtu"}
    expected = sorted(set(instants) | {s * dt for s in range(EVERY, STEPS, EVERY)})
    times = [t for t, _ in frames]
    check(len(times) == len(expected) and all(abs(a - b) <= 1e-9 * max(1, b) for a, b in zip(times, expected)),
          f"fields.pvd times {times} = periodic every {EVERY} steps and the three instants, x dt = {dt} s")
    check(all(b > a for a, b in zip(times, times[1:])), "fields.pvd times strictly increasing")
    check(all(name == instants[t] for t, name in frames if t in instants),
          "the three instants are listed with their fields-<instant>.vtu")
    check(all(os.path.exists(os.path.join(out, name)) for _, name in frames), "every listed file exists")

    # ---- Every frame: mesh and field names ----
    grids = {name: read_vtu(os.path.join(out, name)) for _, name in frames}
    shapes_ok, names_ok = True, True
    for name, g in grids.items():
        tri_ids, _ = triangles(g)
        shapes_ok = shapes_ok and g.GetNumberOfPoints() == summary["nodes"] and len(tri_ids) == summary["triangles"]
        pd, cd = g.GetPointData(), g.GetCellData()
        names_ok = (names_ok and pd.GetArray("displacement") is not None
                    and pd.GetArray("displacement").GetNumberOfComponents() == 3
                    and pd.GetArray("temperature") is not None
                    and all(cd.GetArray(n) is not None for n in ("phase", "sigma_rr", "sigma_tt", "T0_local")))
    check(shapes_ok, f"every VTU has {summary['nodes']} points and {summary['triangles']} triangles (summary.json)")
    check(names_ok, "every VTU has displacement (3 components), temperature (points), phase, sigma_rr, sigma_tt, "
          "T0_local (cells)")

    # ---- Periodic frames against history.csv ----
    inner_xy = [(float(r["x"]), float(r["y"])) for r in final]
    lengths = [float(r["tributary_length"]) for r in final]
    worst_T, worst_match = 0.0, 0.0
    for t, name in frames:
        if not name.startswith("frames/"):
            continue
        step = round(t / dt)
        g = grids[name]
        ids, match = nearest_points(g, inner_xy)
        worst_match = max(worst_match, match)
        temp = vtk_to_numpy(g.GetPointData().GetArray("temperature"))
        mean = sum(temp[k] * w for k, w in zip(ids, lengths)) / sum(lengths)
        worst_T = max(worst_T, abs(mean - float(hist[step - 1]["T_inner_mean"])))
    check(worst_match < 1e-7, f"inner nodes found in the VTU points within {worst_match:.1e} m")
    check(worst_T < 1e-8, f"periodic frames: tributary mean of the VTU temperature at the inner nodes = "
          f"history.csv T_inner_mean at that step, worst difference {worst_T:.2e} K")

    # ---- The last frame against fields-3-end.csv ----
    last_t, last_name = frames[-1]
    check(last_name == "fields-3-end.vtu" and abs(last_t - STEPS * dt) < 1e-9,
          f"last frame {last_name} at t = {last_t} s (end: {STEPS * dt} s)")
    g = grids["fields-3-end.vtu"]
    csv = rows(os.path.join(out, "fields-3-end.csv"))
    tri_ids, tri_pts = triangles(g)
    check(len(tri_ids) == g.GetNumberOfCells() == len(csv),
          f"fields-3-end.vtu's cells are the {len(csv)} triangles only ({g.GetNumberOfCells()} cells, "
          f"{len(tri_ids)} triangles): no boundary line cells among them")
    cd, pd = g.GetCellData(), g.GetPointData()
    worst = {}
    for field in ("phase", "sigma_rr", "sigma_tt", "T0_local"):
        values = vtk_to_numpy(cd.GetArray(field))
        scale = max(1.0, max(abs(float(r[field])) for r in csv))
        worst[field] = max(abs(values[i] - float(r[field])) for i, r in zip(tri_ids, csv)) / scale
    temp = vtk_to_numpy(pd.GetArray("temperature"))
    worst["T_centroid"] = max(abs(sum(temp[k] for k in p) / 3 - float(r["T"])) for p, r in zip(tri_pts, csv)) \
        / max(float(r["T"]) for r in csv)
    # The CSV's displacement is the P1 field at the centroid: the mean of the three nodes' (VTU).
    disp = vtk_to_numpy(pd.GetArray("displacement"))
    for c, key in enumerate(("ux", "uy")):
        worst[f"{key}_centroid"] = max(abs(sum(disp[k][c] for k in p) / 3 - float(r[key])) for p, r in zip(tri_pts, csv)) \
            / max(abs(float(r[key])) for r in csv)
    pts = vtk_to_numpy(g.GetPoints().GetData())
    worst_centroid = max(math.hypot(sum(pts[k][0] for k in p) / 3 - float(r["x"]),
                                    sum(pts[k][1] for k in p) / 3 - float(r["y"])) for p, r in zip(tri_pts, csv))
    check(len(csv) == len(tri_ids) and worst_centroid < 1e-7,
          f"fields-3-end.csv rows = VTU triangles ({len(csv)}), same order (centroids within {worst_centroid:.1e} m)")
    check(max(worst.values()) < 1e-9, "fields-3-end.vtu = fields-3-end.csv (10 digits) per triangle, relative "
          "differences "
          + ", ".join(f"{k} {v:.1e}" for k, v in worst.items()))

    # ---- Displacement: the gap closed at every inner node ----
    ids, _ = nearest_points(g, inner_xy)
    disp = vtk_to_numpy(pd.GetArray("displacement"))
    pipe = summary["parameters"]["pipe_A"]
    gap_error = max(abs((disp[k][0] * x + disp[k][1] * y) / math.hypot(x, y) - (pipe - math.hypot(x, y)))
                    for k, (x, y) in zip(ids, inner_xy))
    check(summary["final_nodes_in_contact"] == len(final) and gap_error < 1e-10,
          f"end: every inner node in contact, u.n = pipe radius - node radius within {gap_error:.1e} m "
          f"(interference {1e6 * (pipe - summary['parameters']['ring_inner_radius']):.1f} um)")

    partial = [p for p in glob.glob(os.path.join(out, "**", "*.partial*"), recursive=True)]
    check(not partial, f"no *.partial file left after the run ({len(partial)})")

    killed = killed_run()
    record("paraview", dict(killed, test="paraview", mesh="meshes/sleeve-coarse.msh", steps=STEPS,
                            vtkevery=EVERY, frames=len(frames), times=times,
                            periodic_T_inner_worst_K=worst_T, end_vs_csv_worst=worst,
                            end_gap_error_m=gap_error,
                            vtu_bytes=os.path.getsize(os.path.join(out, "fields-3-end.vtu"))))
    finish()


if __name__ == "__main__":
    main()
