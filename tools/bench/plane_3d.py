#!/usr/bin/python3
"""sleeve-3d's plane hypothesis (-ends held: both end faces held axially and insulated, every
section deforms alike, the 2D scenes' plane strain and, by default, their law's a) against the 2D
scenes, at (nr, nt) = (2, 8), (3, 12), (4, 16) and with friction (6, 24) (a section of make bench,
docs/benchmarks/sleeve-3d-plane.md).

The paper's scale, -length 0.02 (the held solution does not depend on z), -Ri 0.05 -pipeA 0.0504:
  frictionless, the 3D at -tol 1e-3 (its final state is its steps' to every digit):
    the round pipe (radius 0.0504) against the plane-strain closed form (Lame: summary.json's
      plane_strain_pressure);
    the paper's ellipse (-pipeB 0.0505) against sleeve-elliptic at -tol 1e-2 on its default mesh
      and on meshes/sleeve-nr36.msh: the ring average at mid-length and the pressures weighted
      towards the x and the y axes (tools/bench/oracles/plane_section.py);
  with friction (-mu 0.2: the bore's rows (n, e_theta), u_z held), on one history, the same fixed
    steps in both (friction's final state is its path's): 750 steps (and 1500 at the three coarser
    meshes) against sleeve-elliptic-friction at the same steps, on its default mesh and on
    sleeve-nr36.msh: the ring average, and the filtered tangential density node by node (its largest
    misfit at the 3D's mid-length nodes, the 2D's profile interpolated at their angles).
Orders between successive meshes, log(d1 / d2) / log(nr2 / nr1). These numbers were typed by hand
into docs/measurements.md#m-sleeve-3d-plane and #m-sleeve-3d-plane-friction before this section
measured them.

bench.py calls measure() and write_doc(); alone: tools/bench/bench.py --only plane-3d.
"""
import csv
import os

from common import OUT, ROOT, observed_orders, run, write_whole
from markdown_wrap import wrap
from plane_section import density_misfit, towards_x, towards_y, weighted_pressure

SCENE3D = "edp/scenes/sleeve-3d.edp"
DOC = os.path.join(ROOT, "docs", "benchmarks", "sleeve-3d-plane.md")
PLANE = ["-scale", "paper", "-ends", "held", "-length", "0.02", "-Ri", "0.05", "-pipeA", "0.0504", "-quiet", "1"]
ELLIPSE = ["-pipeB", "0.0505"]
MESHES = [(2, 8), (3, 12), (4, 16)]
FRICTION_MESHES = MESHES + [(6, 24)]
MESHES_2D = [("default", []), ("nr36", ["-mesh", "meshes/sleeve-nr36.msh"])]


def contact_rows(out):
    with open(os.path.join(out, "contact-final.csv")) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def solid(tag, nr, nt, *args):
    out = os.path.join(OUT, "plane-3d", f"{tag}-nr{nr}")
    wall, s, _ = run(SCENE3D, out, *PLANE, "-nr", nr, "-nt", nt, *args)
    return out, s, wall


def plane(scene, tag, *args):
    out = os.path.join(OUT, "plane-3d", tag)
    wall, s, _ = run(f"edp/scenes/{scene}.edp", out, "-scale", "paper", "-quiet", "1", *args)
    return out, s, wall


def orders(nrs, differences):
    """common.observed_orders of the differences' sizes (they are signed)."""
    return observed_orders(nrs, [abs(d) for d in differences])


def section_pressures(rows):
    return {"mid": weighted_pressure(rows, lambda x, y: 1.0), "x": weighted_pressure(rows, towards_x),
            "y": weighted_pressure(rows, towards_y)}


def measure(results):
    """Runs the cases into results/bench/plane-3d/; returns the record (also results['plane_3d'])."""
    print("bench: sleeve-3d's plane hypothesis (-ends held) against the closed form and the 2D scenes", flush=True)
    record = {"meshes": MESHES, "friction_meshes": FRICTION_MESHES}
    # frictionless: the round pipe against Lame
    rows = []
    for nr, nt in MESHES:
        _, s, wall = solid("round", nr, nt, "-tol", "1e-3")
        rows.append({"nr": nr, "nt": nt, "nodes": s["nodes"], "mid": s["final_pressure_mid"], "lame": s["plane_strain_pressure"],
                     "a": s["parameters"]["a"], "wall": wall})
    record["round"] = {"rows": rows, "orders": orders([r["nr"] for r in rows], [r["mid"] - r["lame"] for r in rows])}
    # frictionless: the ellipse against sleeve-elliptic
    ref = {}
    for name, mesh in MESHES_2D:
        out, s, wall = plane("sleeve-elliptic", f"elliptic-{name}", *mesh, "-tol", "1e-2")
        ref[name] = dict(section_pressures(contact_rows(out)), nodes=s["nodes"], wall=wall)
    rows = []
    for nr, nt in MESHES:
        _, s, wall = solid("ellipse", nr, nt, *ELLIPSE, "-tol", "1e-3")
        rows.append({"nr": nr, "nt": nt, "nodes": s["nodes"], "mid": s["final_pressure_mid"], "x": s["final_pressure_mid_x"],
                     "y": s["final_pressure_mid_y"], "wall": wall})
    nrs = [r["nr"] for r in rows]
    record["ellipse"] = {"reference": ref, "rows": rows,
                         "orders": {k: orders(nrs, [r[k] - ref["nr36"][k] for r in rows]) for k in ("mid", "x", "y")}}
    # with friction, on one history per step count
    record["friction"] = {}
    for steps in (750, 1500):
        history = ["-mu", "0.2", "-tol", "0", "-steps", steps]
        ref_rows, ref = {}, {}
        for name, mesh in MESHES_2D:
            out, s, wall = plane("sleeve-elliptic-friction", f"friction-{steps}-{name}", *mesh, *history)
            ref_rows[name] = contact_rows(out)
            ref[name] = {"mid": weighted_pressure(ref_rows[name], lambda x, y: 1.0),
                         "traction": weighted_pressure(ref_rows[name], lambda x, y: 1.0, "tangential_force"),
                         "largest": max(abs(float(r["tangential_density"])) for r in ref_rows[name]),
                         "nodes": s["nodes"], "wall": wall}
        ref["nr36"]["misfit_default"] = density_misfit(ref_rows["default"], ref_rows["nr36"])
        rows = []
        for nr, nt in (FRICTION_MESHES if steps == 750 else MESHES):
            out, s, wall = solid(f"friction-{steps}", nr, nt, *ELLIPSE, *history)
            rows.append({"nr": nr, "nt": nt, "mid": s["final_pressure_mid"], "traction": s["final_traction_mid"],
                         "misfit": density_misfit(ref_rows["default"], contact_rows(out)),
                         "misfit_nr36": density_misfit(ref_rows["nr36"], contact_rows(out)), "a": s["parameters"]["a"],
                         "wall": wall})
        nrs = [r["nr"] for r in rows]
        record["friction"][steps] = {"reference": ref, "rows": rows,
                                     "orders": {"mid": orders(nrs, [r["mid"] - ref["default"]["mid"] for r in rows]),
                                                "misfit": orders(nrs, [r["misfit"] for r in rows])}}
    results["plane_3d"] = record
    return record


def order_cells(values):
    return ["-"] + [f"{o:.2f}" if o is not None else "-" for o in values]


def write_doc(record):
    mpa = 1e-6
    round_ = record["round"]
    lines = ["# sleeve-3d's plane hypothesis (-ends held) against the closed form and the 2D scenes", "",
             "Written by `tools/bench/plane_3d.py` (its docstring states the method); numbers from that run. The "
             "paper's scale, `-ends held -length 0.02 -Ri 0.05 -pipeA 0.0504`: held ends are plane strain and take the "
             f"2D scenes' law by default (a = {round_['rows'][0]['a']:g}; free ends 1.3 times it: docs/parameters.md). "
             "Orders between successive meshes.", "",
             "## Frictionless, the round pipe against the plane-strain closed form", "",
             f"Lame: {round_['rows'][0]['lame'] * mpa:.4f} MPa.", "",
             "| (nr, nt) | nodes | ring average at mid-length (MPa) | - Lame (MPa) | order | process (s) |",
             "|---|---|---|---|---|---|"]
    for r, o in zip(round_["rows"], order_cells(round_["orders"])):
        lines.append(f"| ({r['nr']}, {r['nt']}) | {r['nodes']} | {r['mid'] * mpa:.4f} | {(r['mid'] - r['lame']) * mpa:+.4f} | "
                     f"{o} | {r['wall']:.1f} |")
    ell = record["ellipse"]
    lines += ["", "## Frictionless, the paper's ellipse (-pipeB 0.0505) against sleeve-elliptic", "",
              "sleeve-elliptic at `-tol 1e-2` (its final state is its steps' to every digit): the ring average and the "
              "pressures weighted towards the x (minor) and the y (major) axes; orders against its nr 36 mesh.", "",
              "| run | nodes | ring average (MPa) | towards x | towards y | y - x | process (s) |", "|---|---|---|---|---|---|---|"]
    for r in ell["rows"]:
        lines.append(f"| 3D ({r['nr']}, {r['nt']}) | {r['nodes']} | {r['mid'] * mpa:.4f} | {r['x'] * mpa:.4f} | "
                     f"{r['y'] * mpa:.4f} | {(r['y'] - r['x']) * mpa:.3f} | {r['wall']:.1f} |")
    for name, r in ell["reference"].items():
        lines.append(f"| sleeve-elliptic {name} | {r['nodes']} | {r['mid'] * mpa:.4f} | {r['x'] * mpa:.4f} | "
                     f"{r['y'] * mpa:.4f} | {(r['y'] - r['x']) * mpa:.3f} | {r['wall']:.1f} |")
    lines += ["", "Orders of the 3D against sleeve-elliptic nr 36: "
              + "; ".join(f"{k} {', '.join(order_cells(v)[1:])}" for k, v in ell["orders"].items()) + "."]
    for steps, f in record["friction"].items():
        ref = f["reference"]
        lines += ["", f"## With friction (-mu 0.2), one history: {steps} fixed steps in both", "",
                  f"sleeve-elliptic-friction, default mesh: ring average {ref['default']['mid'] * mpa:.4f} MPa, "
                  f"|traction| {ref['default']['traction'] * mpa:.4f} MPa, largest filtered density "
                  f"{ref['default']['largest'] * mpa:.4f} MPa ({ref['default']['wall']:.1f} s); nr 36: "
                  f"{ref['nr36']['mid'] * mpa:.4f}, {ref['nr36']['traction'] * mpa:.4f}, {ref['nr36']['largest'] * mpa:.4f} MPa "
                  f"({ref['nr36']['wall']:.1f} s), its density at most {ref['nr36']['misfit_default'] * mpa:.4f} MPa from the "
                  "default mesh's. The misfit: the largest |3D - 2D| of the filtered tangential density at the 3D's "
                  "mid-length nodes (contact-final.csv's `tangential_density`). \\|traction\\|: summary.json's "
                  "`final_traction_mid`, the ring's |r_t| node by node over its area, the 2D's likewise: the nodal "
                  "reactions' spread from node to node does not cancel in |r_t|, so neither converges to the other; "
                  "the filtered density does.", "",
                  "| 3D (nr, nt) | ring average (MPa) | - 2D | order | \\|traction\\| (MPa) | misfit (MPa) | order | "
                  "misfit to nr 36 | process (s) |", "|---|---|---|---|---|---|---|---|---|"]
        for r, om, ot in zip(f["rows"], order_cells(f["orders"]["mid"]), order_cells(f["orders"]["misfit"])):
            lines.append(f"| ({r['nr']}, {r['nt']}) | {r['mid'] * mpa:.4f} | {(r['mid'] - ref['default']['mid']) * mpa:+.4f} | "
                         f"{om} | {r['traction'] * mpa:.4f} | {r['misfit'] * mpa:.4f} | {ot} | {r['misfit_nr36'] * mpa:.4f} | "
                         f"{r['wall']:.1f} |")
    lines.append("")
    write_whole(DOC, wrap("\n".join(lines)))
