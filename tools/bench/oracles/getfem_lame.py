#!/usr/bin/python3
"""The ring-lame problem (edp/scenes/ring-lame.edp) solved by GetFEM (python3-getfem), an
independent solver to compare our answers and our speed with (make bench, tools/bench/bench.py).

The same problem: the quarter rings meshes/ring-<level>.msh read from gmsh (label 1 inner surface,
3 the cut y = 0, 4 the cut x = 0), plane-strain isotropic elasticity, the symmetry supports
u2 = 0 on label 3 and u1 = 0 on label 4 at every node there (as FreeFEM's on()), and frictionless
Signorini contact of the inner-surface nodes with the rigid pipe of radius Rp: n.u + gap >= 0 at
each node, n the pipe's radial normal, gap = |x| - Rp, as edp/solvers/contact.idp. GetFEM solves
it by its semi-smooth Newton on the Alart-Curnier augmented Lagrangian (one sparse LU, MUMPS, per
iteration; here one iteration: every node is in contact).

Element (--order, --geometry):
  1 (default): P1 on the triangles of the mesh: ours, to rounding;
  2 straight: P2 on the same straight-sided triangles (what FreeFEM can do); the mid-edge nodes of
     the inner surface lie inside its circle by Ri (1 - cos(h / 2Ri)), so their gap is taken as
     their edge's vertices' (the ring's interference), not |x| - Rp (which adds that sagitta, a 7 %
     error on l1); limited by the polygonal boundary to O(h^2);
  2 curved: isoparametric P2 (GetFEM's GT_PK(2,2)): the same vertices and triangles, the mid-edge
     nodes of the inner and outer arcs moved onto their circles; the surface length is then the
     length of those curved edges.
Contact brick (--contact):
  basic (default): GetFEM's basic contact brick with the normals and gaps computed here: the same
     discrete problem as ours;
  obstacle: GetFEM's nodal contact with rigid obstacle brick on the signed distance
     sqrt(x^2 + y^2) - Rp: the same problem except that it takes the normal from a one-sided
     finite difference of that distance (step 1e-3 of the element size), about 1e-5 rad off the
     radial direction, which moves the pressure by about 1e-10 relative.
The mean pressure is ring-lame's: the sum of the nodal normal contact forces (GetFEM's contact
multipliers, N per m of depth) over the length of the inner surface (the sum of its edge lengths),
its error against Lame's closed form (tools/bench/oracles/lame.py).

Timed: solve_seconds is everything after the mesh import (and, curved, after the curved mesh is
built): the finite element space, integration method, model, assembly, supports and contact
operator, the Newton solve and the mean pressure (time.perf_counter); with --repeat N the least of
N solves in this process. The process's own wall time is measured by the caller (tools/bench/bench.py).

Usage: tools/bench/oracles/getfem_lame.py [--levels "l1 l2"] [--order 1|2] [--geometry straight|curved]
                            [--contact basic|obstacle] [--repeat N] [--json FILE]
                            [--E 85e9 --nu 0.3 --Ri 0.05 --Ro 0.06 --Rp 0.0505]
"""
import argparse
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lame import lame_pressure  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
INNER, OUTER, CUT_Y0, CUT_X0 = 1, 2, 3, 4   # the labels of meshes/ring.geo
FACES = 100  # region FACES + label: the faces of that label only (see import_ring)


def label_faces(mesh, label):
    """The (triangle, face) pairs of boundary label `label`: GetFEM's gmsh import puts the
    triangles of physical surface 1 ("ring") into region 1 too, beside the inner edges (face
    number 65535 for a whole triangle; a face of a triangle is 0, 1 or 2)."""
    region = mesh.region(label)
    return region[:, region[1] < 3]


def face_vertices(mesh, faces):
    """The two vertex numbers of each P1 face, a 2 x n array."""
    return np.array([mesh.pid_in_faces(np.array([[cv], [f]])) for cv, f in faces.T]).T


def import_ring(getfem, path, curved):
    """The mesh of `path` (curved: its isoparametric P2 version) with its regions FACES + label, its
    vertex count, the inner surface's edges' end vertices and mid-edge nodes (coordinates, 2 x n
    each), and the inner surface's length (straight: the sum of the chords; curved: of the
    quadratic arcs)."""
    if not os.path.exists(path):
        sys.exit(f"getfem_lame: mesh {path} does not exist (make meshes)")
    mesh = getfem.Mesh("import", "gmsh", path)
    for label in (INNER, OUTER, CUT_Y0, CUT_X0):
        if label not in mesh.regions() or label_faces(mesh, label).shape[1] == 0:
            sys.exit(f"getfem_lame: mesh {path} has no boundary edge of label {label}")
    pts = mesh.pts()
    edges = face_vertices(mesh, label_faces(mesh, INNER))
    a, b = pts[:, edges[0]], pts[:, edges[1]]
    middle = (a + b) / 2
    if not curved:
        for label in (INNER, CUT_Y0, CUT_X0):
            mesh.set_region(FACES + label, label_faces(mesh, label))
        return mesh, mesh.nbpts(), a, b, middle, np.hypot(*(b - a)).sum()
    # Isoparametric P2: each triangle with its mid-edge nodes, those of the inner and outer
    # arcs moved radially onto the circle of their edge's vertices.
    radius = np.hypot(*pts)
    arc = {}
    for label in (INNER, OUTER):
        for p, q in face_vertices(mesh, label_faces(mesh, label)).T:
            arc[(min(p, q), max(p, q))] = (radius[p] + radius[q]) / 2
    def mid_node(p, q):
        x = (pts[:, p] + pts[:, q]) / 2
        r = arc.get((min(p, q), max(p, q)))
        return x if r is None else x * (r / np.hypot(*x))
    curved_mesh = getfem.Mesh("empty", 2)
    quadratic = getfem.GeoTrans("GT_PK(2,2)")
    for cv in range(mesh.nbcvs()):
        p, q, r = mesh.pid_from_cvid(cv)[0]
        # GT_PK(2,2)'s node order: vertex 0, mid 01, vertex 1, mid 02, mid 12, vertex 2; the same
        # vertex order keeps the face numbers (face i opposite vertex i), so the regions carry over.
        nodes = [pts[:, p], mid_node(p, q), pts[:, q], mid_node(p, r), mid_node(q, r), pts[:, r]]
        added = curved_mesh.add_convex(quadratic, np.array(nodes).T)
        if int(np.ravel(added)[0]) != cv:
            sys.exit(f"getfem_lame: {path}: the curved mesh renumbered triangle {cv}")
    for label in (INNER, CUT_Y0, CUT_X0):
        curved_mesh.set_region(FACES + label, label_faces(mesh, label))
    middle = np.array([mid_node(p, q) for p, q in edges.T]).T
    # Length of the quadratic arc a -> middle -> b: Gauss-Legendre in t on [0, 1] (5 points: exact
    # to 1e-12 and beyond for these nearly straight arcs).
    t, w = np.polynomial.legendre.leggauss(5)
    t, w = (t + 1) / 2, w / 2
    length = 0.
    for ti, wi in zip(t, w):
        tangent = a * (4 * ti - 3) + middle * (4 - 8 * ti) + b * (4 * ti - 1)
        length += wi * np.hypot(*tangent).sum()
    return curved_mesh, mesh.nbpts(), a, b, middle, length


def contact_gaps(xy, a, b, middle, Rp):
    """The gap of each contact node (columns of xy) of straight P2: |x| - Rp at a vertex; at a
    mid-edge node, its edge's vertices' mean (the node lies inside the circle by the sagitta, which
    is the polygon's geometry, not the interference)."""
    radius = np.hypot(*xy)
    gap = radius - Rp
    vertex_gap = (np.hypot(*a) + np.hypot(*b)) / 2 - Rp
    for i in range(xy.shape[1]):
        to_middle = np.hypot(*(middle - xy[:, i:i + 1]))
        k = int(np.argmin(to_middle))
        if to_middle[k] <= 1e-9 * radius[i]:
            gap[i] = vertex_gap[k]
    return gap


def solve(getfem, mesh, a, b, middle, length, order, curved, contact, E, nu, Ri, Ro, Rp):
    """Solves the contact problem on `mesh`; returns the level's figures."""
    start = time.perf_counter()
    mf = getfem.MeshFem(mesh, 2)
    mf.set_classical_fem(order)
    # Exact for P1 (constant strains) and straight P2 (linear); curved P2's rational integrand: the
    # pressure moves by 6e-11 from degree 4 to 8 on l1.
    degree = 4 if curved else 2 * (order - 1)
    mim = getfem.MeshIm(mesh, getfem.Integ(f"IM_TRIANGLE({max(degree, 1)})"))
    # Solved with the moduli over E (displacements unchanged, forces over E; the answer is linear
    # in E): the residual of GetFEM's Newton is then in metres for every equation (see max_res).
    md = getfem.Model("real")
    md.add_fem_variable("u", mf)
    md.add_initialized_data("lambda", [nu / ((1 + nu) * (1 - 2 * nu))])  # plane strain
    md.add_initialized_data("mu", [1 / (2 * (1 + nu))])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")

    # Symmetry supports: u2 = 0 on the cut y = 0, u1 = 0 on the cut x = 0, at every dof there (the
    # dofs of a vector field are (x, y) pairs: even x, odd y).
    nd = mf.nbdof()
    fixed = sorted({int(d) for d in mf.basic_dof_on_region(FACES + CUT_Y0) if d % 2 == 1}
                   | {int(d) for d in mf.basic_dof_on_region(FACES + CUT_X0) if d % 2 == 0})
    B = getfem.Spmat("empty", len(fixed), nd)
    for row, dof in enumerate(fixed):
        B[row, dof] = 1.
    md.add_variable("support", len(fixed))
    md.add_constraint_with_multipliers("u", "support", B, np.zeros(len(fixed)))

    # Contact at the inner surface's nodes (the x dof of each pair).
    inner = np.array([int(d) for d in mf.basic_dof_on_region(FACES + INNER) if d % 2 == 0])
    xy = mf.basic_dof_nodes(inner)
    radius = np.hypot(xy[0], xy[1])
    m = len(inner)
    gap = contact_gaps(xy, a, b, middle, Rp) if order == 2 and not curved else radius - Rp
    md.add_variable("lambda_n", m)
    md.add_initialized_data("r", [1.])  # augmentation: of the order of the (scaled) E, GetFEM's advice
    if contact == "basic":
        BN = getfem.Spmat("empty", m, nd)
        for i, dof in enumerate(inner):  # B_N u <= gap: -n.u <= |x| - Rp, n = x / |x|
            BN[i, dof] = -xy[0, i] / radius[i]
            BN[i, dof + 1] = -xy[1, i] / radius[i]
        md.add_initialized_data("gap", gap)
        md.add_basic_contact_brick("u", "lambda_n", "r", BN, "gap")
    else:
        md.add_nodal_contact_with_rigid_obstacle_brick(mim, "u", "lambda_n", "r", FACES + INNER,
                                                       f"sqrt(x*x + y*y) - {Rp!r}", 1)
    # GetFEM's Newton stops on the norm of its residual over every equation: here the equilibrium's
    # (force / E, m) and the contact's ((Alart-Curnier) / r, m). A wrong active set leaves at least
    # the displacement or force / E of a node in it (about 1e-6 m on l3 at P2 straight with the
    # sagitta in the gap), the rounding of the equilibrium about eps delta per dof (1e-15 m at 10^4
    # dofs): 1e-9 delta between the two bounds what the stop can leave on the pressure at about
    # 1e-9 relative; the check below makes sure.
    iterations, converged = md.solve("max_res", 1e-9 * (Rp - Ri), "max_iter", 50, "lsolver", "mumps")
    force = -E * md.variable("lambda_n")  # N per m of depth (GetFEM: <= 0 in contact)
    pressure = force.sum() / length
    seconds = time.perf_counter() - start
    u = md.variable("u")
    # Signorini at every contact node (radial normal): n.u + gap >= 0, force >= 0, their product 0.
    normal_motion = (xy[0] * u[inner] + xy[1] * u[inner + 1]) / radius + gap
    scale, largest = Rp - Ri, np.abs(force).max()
    complementarity = max(-normal_motion.min() / scale, -force.min() / largest,
                          np.max(np.abs(normal_motion * force)) / (scale * largest))
    exact = lame_pressure(E, nu, Ri, Ro, Rp - Ri, "strain")
    return {"dofs": int(nd), "contact_nodes": m,
            "pressure_mean": float(pressure), "pressure_exact": exact,
            "rel_error": abs(pressure - exact) / exact, "newton_iterations": int(iterations),
            "converged": bool(converged), "complementarity": float(complementarity),
            "solve_seconds": seconds}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--levels", default="l1 l2 l3 l4", help="mesh levels: meshes/ring-<level>.msh")
    parser.add_argument("--order", type=int, choices=(1, 2), default=1, help="Lagrange degree of u")
    parser.add_argument("--geometry", choices=("straight", "curved"), default="straight",
                        help="P2 only: straight triangles, or the arcs' mid-edge nodes on the circles")
    parser.add_argument("--contact", choices=("basic", "obstacle"), default="basic")
    parser.add_argument("--repeat", type=int, default=1, help="solves per level, the least time reported")
    parser.add_argument("--json", help="write the levels' figures to this file")
    for name, value in (("E", 85e9), ("nu", 0.3), ("Ri", 0.05), ("Ro", 0.06), ("Rp", 0.0505)):
        parser.add_argument(f"--{name}", type=float, default=value, help=f"as ring-lame's -{name}")
    args = parser.parse_args()
    curved = args.geometry == "curved"
    if curved and args.order != 2:
        sys.exit("getfem_lame: --geometry curved needs --order 2 (P1 has no mid-edge nodes)")
    if args.repeat < 1:
        sys.exit(f"getfem_lame: --repeat {args.repeat} must be >= 1")
    if not (0 < args.Ri < args.Ro and args.Rp > args.Ri):
        sys.exit(f"getfem_lame: need 0 < Ri < Ro and Rp > Ri (got {args.Ri}, {args.Ro}, {args.Rp})")
    try:
        import getfem
    except ImportError:
        sys.exit("getfem_lame: python3-getfem is not installed (tools/install-deps.sh installs it)")
    getfem.util_trace_level(0)  # no "Trace 2 ... assembly" line per level
    element = f"P{args.order}" + (" curved" if curved else "")
    rows = []
    for level in args.levels.split():
        mesh, vertices, a, b, middle, length = import_ring(getfem, os.path.join(ROOT, "meshes", f"ring-{level}.msh"),
                                                           curved)
        radii = np.hypot(*mesh.pts())
        if abs(radii.min() - args.Ri) > 1e-9 * args.Ri or abs(radii.max() - args.Ro) > 1e-9 * args.Ro:
            sys.exit(f"getfem_lame: mesh ring-{level}.msh is the ring {radii.min()}, {radii.max()} m, "
                     f"not --Ri {args.Ri} --Ro {args.Ro}")
        runs = [solve(getfem, mesh, a, b, middle, length, args.order, curved, args.contact,
                      args.E, args.nu, args.Ri, args.Ro, args.Rp) for _ in range(args.repeat)]
        row = min(runs, key=lambda r: r["solve_seconds"])
        if not row["converged"]:
            sys.exit(f"getfem_lame: {level}: GetFEM's Newton did not converge in {row['newton_iterations']} iterations")
        if row["complementarity"] > 1e-8:
            sys.exit(f"getfem_lame: {level}: GetFEM's answer violates Signorini by {row['complementarity']:.2e} "
                     "(relative): its Newton stopped on a wrong active set")
        row = {"name": level, "element": element, "contact": args.contact, **row, "nodes": vertices}
        rows.append(row)
        print(f"getfem_lame {level} {element} ({args.contact}): {row['nodes']} nodes, {row['contact_nodes']} "
              f"contact nodes, {row['newton_iterations']} Newton iterations; mean pressure "
              f"{row['pressure_mean']:.15g} Pa, Lame {row['pressure_exact']:.15g} Pa, rel. error "
              f"{row['rel_error']:.3e}, solve {1e3 * row['solve_seconds']:.1f} ms", flush=True)
    if args.json:
        with open(args.json + ".partial", "w") as f:
            json.dump({"solver": "getfem", "levels": rows}, f, indent=2)
        os.replace(args.json + ".partial", args.json)


if __name__ == "__main__":
    main()
