#!/usr/bin/python3
"""Moving layers (-movinglayers 1, edp/problems/sleeve/moving-layers.idp): the quarter ring's layers
follow the transformation fronts through the thickness.

sleeve-circular at the paper's scale on meshes/sleeve-aniso36.msh (36 layers, 18 arc segments),
-tol 3e-4, with and without the moving layers, against sleeve-radial's 1000 fixed steps (nr 160:
the radially symmetric problem's 1D model, an independent computation 0.026 % from the extrapolated
reference over the reversion window, docs/reference-paper.md):
  - the moves carry the state: the lumped heat content and the area-weighted fractions (and latent
    fractions) the same before and after every move to 1e-13 (relative), every step's heat balance
    to round-off, the phase fractions of every row inside [0, 1] and summing to 1;
  - the moves happen (layer_moves > 0), and mesh-moves.csv has a row per move whose radii go
    strictly up from the bore's to the outer surface's;
  - they pay: the error of the force curve over the reversion window (relative L1 of the mean
    pressure) at most 0.7 of the fixed mesh's (measured 0.08 % against 0.17 %);
  - the final state is the fixed mesh's (mean pressure to 1e-4: the shrink fit's);
  - the fields at the end (fields-3-end.csv, .vtu) are the moved mesh's: every centroid and its
    displacement the mean of its triangle's nodes' (1e-8 m, 1e-12 m);
  - what they do not carry is refused with a message naming -movinglayers: -ring half, -phasemodel
    onoff.
Writes results/checks/moving_layers.json.
"""
import csv
import os
import sys

import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, rows, run_scene_captured, summary_of  # noqa: E402
from curve_error import curve_error  # noqa: E402

MESH = "meshes/sleeve-aniso36.msh"


def main():
    data = {}
    ref, proc = run_scene_captured("sleeve-radial", "moving-layers-radial", "-quiet", "1", "-tol", "0")
    check(proc.returncode == 0, f"sleeve-radial -tol 0 (the reference) exit {proc.returncode} {proc.stderr[-300:]}")
    runs = {}
    for name, extra in (("fixed", []), ("moving", ["-movinglayers", "1"])):
        out, proc = run_scene_captured("sleeve-circular", f"moving-layers-{name}", "-quiet", "1", "-vtkevery", "0",
                                       "-mesh", MESH, "-tol", "3e-4", *extra)
        check(proc.returncode == 0, f"sleeve-circular -mesh {MESH} -tol 3e-4 {' '.join(extra)} exit "
                                    f"{proc.returncode} {proc.stderr[-300:]}")
        if proc.returncode != 0:
            finish()
            return
        runs[name] = (out, summary_of(out), curve_error(os.path.join(out, "history.csv"),
                                                        os.path.join(ref, "history.csv")))
    out, s, e = runs["moving"]
    _, fixed, e_fixed = runs["fixed"]
    data = {"moves": s["layer_moves"], "heat_change_max": s["layer_move_heat_change_max"],
            "fraction_change_max": s["layer_move_fraction_change_max"], "finest_layer": s["layer_finest"],
            "l1_reversion_moving": e["l1_reversion"], "l1_reversion_fixed": e_fixed["l1_reversion"],
            "l1_transient_moving": e["l1_transient"], "l1_transient_fixed": e_fixed["l1_transient"],
            "steps_moving": s["n_steps"], "steps_fixed": fixed["n_steps"]}
    check(s["moving_layers"] is True and s["layer_moves"] > 0 and fixed["moving_layers"] is False,
          f"the layers moved {s['layer_moves']} times (and not in the fixed run)")
    check(s["layer_move_heat_change_max"] < 1e-13 and s["layer_move_fraction_change_max"] < 1e-13,
          f"per move the heat content changed {s['layer_move_heat_change_max']:.1e} and the fractions' amount "
          f"{s['layer_move_fraction_change_max']:.1e} (relative), < 1e-13")
    check(s["heat_balance_residual_max"] < 1e-9,
          f"every step's heat balance {s['heat_balance_residual_max']:.1e} < 1e-9")
    history = rows(os.path.join(out, "history.csv"))
    fractions = [[float(r[k]) for k in ("fraction_austenite", "fraction_m1", "fraction_m2")] for r in history]
    worst = max(max(abs(min(f)) if min(f) < 0 else 0, max(f) - 1, abs(sum(f) - 1)) for f in fractions)
    check(worst < 1e-12, f"the phase fractions of every row inside [0, 1] and summing to 1 (worst {worst:.1e})")
    with open(os.path.join(out, "mesh-moves.csv"), newline="") as f:
        moves = list(csv.DictReader(f))
    radii = [[float(v) for k, v in m.items() if k.startswith("r_")] for m in moves]
    increasing = all(all(b > a for a, b in zip(r, r[1:])) for r in radii)
    ends = all(abs(r[0] - radii[0][0]) < 1e-12 and abs(r[-1] - radii[0][-1]) < 1e-12 for r in radii)
    check(len(moves) == s["layer_moves"] and len(radii[0]) == 37 and increasing and ends,
          f"mesh-moves.csv: {len(moves)} rows (summary.json: {s['layer_moves']}), 37 radii each, strictly "
          f"increasing from {radii[0][0]:.6f} to {radii[0][-1]:.6f} m in every row")
    # The fields at the end, per triangle (CSV) and per node (VTU), are of the moved mesh as it is:
    # each centroid and its displacement the mean of its triangle's three nodes'.
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, "fields-3-end.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 3)
    nodes = vtk_to_numpy(grid.GetPoints().GetData())[cells].mean(axis=1)
    shift = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))[cells].mean(axis=1)
    table = rows(os.path.join(out, "fields-3-end.csv"))
    where = max(max(abs(float(r["x"]) - c[0]), abs(float(r["y"]) - c[1])) for r, c in zip(table, nodes))
    moved = max(max(abs(float(r["ux"]) - d[0]), abs(float(r["uy"]) - d[1])) for r, d in zip(table, shift))
    data.update({"end_fields_centroid_offset": where, "end_fields_displacement_offset": moved})
    check(len(table) == len(cells) and where < 1e-8 and moved < 1e-12,
          f"fields-3-end.csv and .vtu agree on the moved mesh: centroids {where:.1e} m (VTU coordinates in single "
          f"precision), displacements {moved:.1e} m from their nodes' means")
    check(e["l1_reversion"] <= 0.7 * e_fixed["l1_reversion"],
          f"over the reversion window the moving layers' error {100 * e['l1_reversion']:.3f} % <= 0.7 x the "
          f"fixed mesh's {100 * e_fixed['l1_reversion']:.3f} % (against sleeve-radial's 1000 steps)")
    check(abs(s["final_pressure_mean"] / fixed["final_pressure_mean"] - 1) < 1e-4,
          f"final pressure {s['final_pressure_mean']:.6e} = the fixed mesh's {fixed['final_pressure_mean']:.6e} to 1e-4")
    for args, what in ((["-ring", "half", "-mesh", "meshes/sleeve-half-coarse.msh"], "-ring half"),
                       (["-phasemodel", "onoff", "-tol", "0"], "-phasemodel onoff")):
        _, proc = run_scene_captured("sleeve-circular", "moving-layers-refused", "-quiet", "1", "-movinglayers", "1",
                                     *args)
        message = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("error:")]
        check(proc.returncode != 0 and message and "-movinglayers 1" in message[-1],
              f"-movinglayers 1 {what}: exit {proc.returncode}, {message[-1] if message else '(no error line)'}")
    record("moving_layers", data)
    finish()


if __name__ == "__main__":
    main()
