#!/usr/bin/python3
"""A mesh written in millimetres ($MeshUnit 0.001, docs/parameters.md#mesh-units) gives the run the
same mesh, in metres, gives.

FreeFEM's gmshload refuses any triangle of area below 1e-8 in the file's units, so a fine mesh
(the sleeve's ring from about 100 layers on) is written in millimetres, with a $MeshUnit section,
and edp/lib/mesh.idp LoadMesh scales it back. Asserted here:
  - the structured ring of 9 layers (meshes/sleeve-nr9.msh, in metres) and the same ring written
    in millimetres as the Makefile writes MILLIMETRE_MESHES (gmsh -setnumber Mesh.ScalingFactor
    1000, the section after $EndMeshFormat; its coordinates 1000 times the metre file's): 40 steps
    of sleeve-circular through the transient on each give the same node, triangle and contact
    counts, the same iteration counts per step, and the same numbers to 1e-9 relative (history.csv,
    the final mean pressure, the triangles' centroids, temperatures and displacements at the end):
    the unit changes the coordinates by an ulp, nothing else. The stresses to 1e-7 (8e-9 measured):
    the contact reactions converge to PSOR's relative tolerance of 1e-10 from slightly different
    starts, and a stress is a derivative. A wrong unit would be a factor 1000;
  - a really degenerate mesh is still refused in millimetres (meshes/sliver.geo with eps 1e-8: its
    triangle of 1e-5 mm^2 passes gmshload's floor there, the quality check names it);
  - the message for a triangle below the floor suggests millimetres only for a well-shaped one (a
    ring of 108 layers in metres), not for the degenerate sliver in metres;
  - a ring the scene remakes below the floor (-layers 90 -arcs 450: triangles of 9.7e-9 m^2; so
    -balance 2 remade sleeve-elliptic's default ring at 92 x 460, and the run stopped with only
    FreeFEM's "bug : mes < 1e-8 !") is written in millimetres and runs: 4 steps through the first
    contact give the same history.csv as the same ring written here in millimetres and given as
    -mesh.
Writes results/checks/mesh_unit.json.
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record, sleeve_geometry  # noqa: E402

STEPS = ["-steps", "40", "-tend", "20", "-quiet", "1", "-vtkevery", "0"]


def gmsh(geo, target, *options, millimetres=False):
    """gmsh -2 -format msh22 as the Makefile runs it; with `millimetres`, its MILLIMETRE_MESHES
    recipe: coordinates scaled by 1000 and the $MeshUnit section inserted after $EndMeshFormat."""
    g = sleeve_geometry()
    command = ["gmsh", "-2", "-format", "msh22", "-setnumber", "Ri", str(g["Ri"]), "-setnumber", "Hr",
               str(g["Hr"]), *options, *(["-setnumber", "Mesh.ScalingFactor", "1000"] if millimetres else []),
               os.path.join(ROOT, "meshes", geo), "-o", target]
    run = subprocess.run(command, capture_output=True, text=True)
    check(run.returncode == 0, f"gmsh {' '.join(options)} -> {os.path.basename(target)} (exit {run.returncode})")
    if millimetres:
        text = open(target).read()
        text = text.replace("$EndMeshFormat\n", "$EndMeshFormat\n$MeshUnit\n0.001\n$EndMeshUnit\n", 1)
        with open(target, "w") as f:
            f.write(text)


def first_node(path):
    """The first node's x in the file (its own units)."""
    lines = open(path).read().split("$Nodes\n", 1)[1].splitlines()
    return float(lines[1].split()[1])


def scene(out, mesh, *extra):
    run = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", "-mesh", mesh,
                          "-out", out, *STEPS, *extra], cwd=ROOT, capture_output=True, text=True)
    errors = [ln for ln in (run.stdout + run.stderr).splitlines() if ln.startswith("error:")]
    return run.returncode, errors[0] if errors else ""


def table(path):
    with open(path) as f:
        return list(csv.DictReader(ln for ln in f if not ln.startswith("#")))


def worst_relative(rows_a, rows_b):
    """Largest |a - b| over the columns' largest |a|, over every numeric column; and the iteration
    columns' mismatches."""
    worst, column = 0.0, ""
    for key in rows_a[0]:
        a = [float(r[key]) for r in rows_a]
        b = [float(r[key]) for r in rows_b]
        scale = max(abs(v) for v in a) or 1.0
        diff = max(abs(x - y) for x, y in zip(a, b)) / scale
        if diff > worst:
            worst, column = diff, key
    return worst, column


def main():
    result = {"test": "mesh_unit"}
    with tempfile.TemporaryDirectory(prefix="mesh-unit-") as tmp:
        metres = os.path.join(ROOT, "meshes", "sleeve-nr9.msh")
        mm = os.path.join(tmp, "sleeve-nr9-mm.msh")
        gmsh("ring.geo", mm, "-setnumber", "nr", "9", millimetres=True)
        ratio = first_node(mm) / first_node(metres)
        check(abs(ratio - 1000) < 1e-9, f"the millimetre file's coordinates are 1000 x the metre file's ({ratio:.12g})")
        runs = {}
        for name, mesh in (("m", metres), ("mm", mm)):
            out = os.path.join(tmp, f"run-{name}")
            code, error = scene(out, mesh)
            check(code == 0, f"sleeve-circular on the {name} mesh ran (exit {code}) {error}")
            runs[name] = out
        if all(os.path.exists(os.path.join(o, "summary.json")) for o in runs.values()):
            sm, smm = (json.load(open(os.path.join(runs[k], "summary.json"))) for k in ("m", "mm"))
            same = {k: (sm[k], smm[k]) for k in ("nodes", "triangles", "contact_nodes", "first_contact_step",
                                                 "dc_iterations_max", "fixed_point_iterations_max")}
            check(all(a == b for a, b in same.values()), f"same counts: {same}")
            hm, hmm = table(os.path.join(runs["m"], "history.csv")), table(os.path.join(runs["mm"], "history.csv"))
            iterations = [(a["fixed_point_iterations"], a["dc_iterations"]) == (b["fixed_point_iterations"],
                                                                               b["dc_iterations"])
                          for a, b in zip(hm, hmm)]
            check(len(hm) == len(hmm) == 40 and all(iterations),
                  f"same fixed-point and DC iteration counts at each of the {len(hm)} steps")
            history_diff, history_col = worst_relative(hm, hmm)
            check(history_diff <= 1e-9, f"history.csv: worst relative difference {history_diff:.1e} "
                  f"({history_col}) <= 1e-9")
            fm = table(os.path.join(runs["m"], "fields-3-end.csv"))
            fmm = table(os.path.join(runs["mm"], "fields-3-end.csv"))
            exact = ("x", "y", "T", "phase", "martensite_fraction", "ux", "uy")
            fields_diff, fields_col = worst_relative([{k: r[k] for k in exact} for r in fm],
                                                     [{k: r[k] for k in exact} for r in fmm])
            stress_diff, stress_col = worst_relative([{k: r[k] for k in ("sigma_rr", "sigma_tt")} for r in fm],
                                                     [{k: r[k] for k in ("sigma_rr", "sigma_tt")} for r in fmm])
            check(len(fm) == len(fmm) and fields_diff <= 1e-9 and stress_diff <= 1e-7,
                  f"fields at the end ({len(fm)} triangles): centroids, T, phases, u: worst relative "
                  f"difference {fields_diff:.1e} ({fields_col}) <= 1e-9; stresses {stress_diff:.1e} "
                  f"({stress_col}) <= 1e-7")
            p = abs(sm["final_pressure_mean"] / smm["final_pressure_mean"] - 1)
            check(p <= 1e-9, f"final mean pressure {sm['final_pressure_mean'] / 1e6:.6f} MPa in both, "
                  f"relative difference {p:.1e} <= 1e-9")
            result.update(nodes=sm["nodes"], history_difference=history_diff, fields_difference=fields_diff,
                          stress_difference=stress_diff,
                          final_pressure_difference=p)

        sliver_mm = os.path.join(tmp, "sliver-degenerate-mm.msh")
        gmsh("sliver.geo", sliver_mm, "-setnumber", "eps", "1e-8", millimetres=True)
        code, error = scene(os.path.join(tmp, "run-sliver-mm"), sliver_mm)
        m = re.search(r"has quality (\S+) < 0.001", error)
        check(code != 0 and m is not None and float(m.group(1)) < 1e-4,
              f"the degenerate sliver in millimetres is refused (exit {code}): {error}")
        result["degenerate_mm_message"] = error

        code, error = scene(os.path.join(tmp, "run-sliver-m"), os.path.join(ROOT, "meshes", "sliver-degenerate.msh"))
        check(code != 0 and "< 1e-8" in error and "millimetres" not in error,
              f"the degenerate sliver in metres: the floor named, no unit advice (exit {code}): {error}")
        fine = os.path.join(tmp, "sleeve-nr108-m.msh")
        gmsh("ring.geo", fine, "-setnumber", "nr", "108")
        code, error = scene(os.path.join(tmp, "run-fine-m"), fine)
        m = re.search(r"has area (\S+) < 1e-8 \(mean \S+, quality (\S+)\).*well shaped.*write it in millimetres", error)
        check(code != 0 and m is not None and float(m.group(2)) > 0.5,
              f"108 layers in metres: the floor named with the advice to write millimetres (exit {code}): {error}")
        result["fine_metres_message"] = error
        # A ring remade below the floor by the scene itself (-layers, -arcs; -balance and the mesh
        # estimate's companion write theirs the same way: sleeve-2d.idp RingMeshWrite)
        remade_steps = ["-steps", "4", "-tend", "4", "-tol", "0", "-meshestimate", "0", "-quiet", "1", "-vtkevery", "0"]
        ring90 = os.path.join(tmp, "ring-90x450-mm.msh")
        gmsh("ring.geo", ring90, "-setnumber", "nr", "90", "-setnumber", "nt", "450", millimetres=True)
        histories = []
        for name, options in (("remade", ["-layers", "90", "-arcs", "450"]), ("given", ["-mesh", ring90])):
            out = os.path.join(tmp, f"run-{name}-90")
            run = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", *options,
                                  *remade_steps, "-out", out], cwd=ROOT, capture_output=True, text=True)
            check(run.returncode == 0, f"sleeve-circular {' '.join(options)} below gmshload's floor in metres runs "
                  f"(exit {run.returncode}) {(run.stdout + run.stderr)[-300:]}")
            histories.append(open(os.path.join(out, "history.csv")).read() if run.returncode == 0 else None)
        if all(histories):
            rows = [list(csv.DictReader(h.splitlines())) for h in histories]
            contact = max(float(r["pressure_mean"]) for r in rows[0])
            # (the scene passes gmsh the radii it read, an ulp from the .geo's own: 1e-9 as above)
            remade_diff, remade_col = worst_relative(*rows)
            check(len(rows[0]) == len(rows[1]) == 4 and remade_diff <= 1e-9 and contact > 0,
                  f"-layers 90 -arcs 450 (remade in millimetres) and the same ring given in millimetres: the same "
                  f"history.csv ({len(rows[0])} steps, mean pressure up to {contact / 1e6:.3f} MPa; worst relative "
                  f"difference {remade_diff:.1e} ({remade_col}) <= 1e-9)")
            result["remade_ring_max_pressure"] = contact
    record("mesh_unit", result)
    finish()


if __name__ == "__main__":
    main()
