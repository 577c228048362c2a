#!/usr/bin/python3
"""The run's own estimate of its mesh error (-meshestimate 1, edp/problems/sleeve/mesh-estimate.idp).

sleeve-circular at its defaults (18 layers x 18 arc segments, the paper's scale, -tol 1e-3) and
sleeve-radial at nr 40 (against their companions on 9 layers, 20 elements):
  - the estimate is the formula it states, computed again here from the two histories it leaves
    (the run's and mesh-estimate/history.csv) by tools/bench/oracles/curve_error.py's exact L1:
    int |p_h - p_H| dt / int |p_h| dt / (nr / nr_H - 1), over the run, the transient and the
    reversion window, to 1e-9 (relative);
  - it estimates: against sleeve-radial's nr 640 run (20 nr steps over 80 s: 0.005 % from p* over
    the window, docs/reference-paper.md, an independent computation of the radially symmetric
    problem), its effectivity over the reversion window and the transient (estimate over the error
    measured) within [0.5, 2] for both scenes (measured: circular 1.2, radial 1.0);
  - a later run in the same folder with -meshestimate 0 leaves no companion (its summary.json
    "mesh_error_estimate": null);
  - a mesh it cannot halve (an unstructured ring) is refused before the folder is taken, naming
    -meshestimate: the folder's earlier results stay;
  - -layers 36 remakes the structured ring with 36 layers: the run equals -mesh
    meshes/sleeve-aniso36.msh's (its force curve to 1e-9, the node count);
  - -balance 1 (sleeve-radial, sleeve-circular): the layers are the pilot's, ceil(nr0 mesh / time)
    from its two estimates over the transient (clamped), the run is on them and reports its own mesh
    estimate, and no scratch folder is left in its TMPDIR (this test's own, not /tmp: the scenes
    remove their scratch folders wherever TMPDIR puts them); -balance with -layers, and -layers 1,
    refused;
  - both directions, -meshestimate 2 -meshlevels 3 (sleeve-elliptic, whose pressure varies around
    the ring, on -arcs 18: 18 x 18): the run is -mesh meshes/sleeve-aniso.msh's (18 x 18, force
    curves to 1e-9); its companions are 9 x 9 and 4 x 4; the order is the one for which
    (n3^-k - n2^-k) / (n2^-k - n^-k) is the two differences' ratio over the transient, and the
    estimates use it, all recomputed here from the three histories to 1e-9; -balance 2 -meshlevels 3
    takes ceil(18 (mesh / time)^(1 / k)) layers and as many arc segments, and reports its own
    estimate in both directions; -meshestimate 3, -meshlevels 4, -balance 2 with -arcs, and
    sleeve-radial's -balance 2 refused; a remade ring of slivers (-layers 2000 -arcs 1) or of more
    than 2e6 cells refused as a generated mesh is, its scratch folder removed at exit;
  - sleeve-axisymmetric (the (r, z) mesh, -nr and its square cells halved together) at -nr 4,
    -meshestimate 1 -meshlevels 3 (companions at 2 and 1): the estimates and the order recomputed
    from the three histories, the extrapolated curve (history-extrapolated.csv, Richardson's at the
    observed order) and its own estimate too (1e-9), its error against -nr 16 below the run's and
    below its estimate (measured 2.8e-3 against 4.8e-3 and 5.8e-3 over the transient), and its effectivity against the -nr 16 run (whose own error is about a
    tenth of nr 4's: measured 0.04 % against 0.5 % over the transient, nr 16 against 32) in [0.5, 2]
    (measured 1.25 / 1.17; against nr 32: 1.16 / 1.06); -balance 1 -meshlevels 3 -tol 3e-3 from -nr 4
    takes ceil(4 (mesh / time)^(1 / k)) elements and square cells;
  - a stage after the clamping (sleeve-3d -length 0.02 -mu 0.2 -bend 1e-2 -bendsteps 2 -nr 4 -nt 8
    -meshestimate 1 -meshlevels 3): summary.json's mesh_error_estimate_stage per column of bend.csv
    (moment, normal_force_total) is |v - v_H| / |v| / (2^k - 1) of the three runs' last rows, k the
    order their differences' ratio gives in [0.25, 4] or 1 outside (the moment's differences do not
    shrink there: order 1 taken, and said), and <column>_curve the whole curve's, max_i |v_i - v_H,i|
    / max_i |v_i| / (2^k - 1) over the increments (the same loads in both runs), recomputed here to 1e-9.
Writes results/checks/mesh_estimate.json.
"""
import atexit
import math
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, rows, run_scene_captured, summary_of  # noqa: E402
from curve_error import austenite_time, curve_error, interpolate, l1_errors, read_history  # noqa: E402


def ratio_of_differences(k, n, n2, n3):
    return (n3 ** -k - n2 ** -k) / (n2 ** -k - n ** -k)


def three_levels(out, n, n2, n3):
    """From a run with -meshlevels 3 in out: (ratio, order, [(reported, recomputed)...]) recomputed from the
    three histories (the difference ratio over the transient, the order by bisection, the estimates)."""
    s = summary_of(out)
    fine, half, quarter = (os.path.join(out, *p, "history.csv") for p in ((), ("mesh-estimate",),
                                                                           ("mesh-estimate", "mesh-estimate")))
    h, c, q = read_history(fine), read_history(half), read_history(quarter)
    t_a = min(austenite_time(h) or h["t"][-1], h["t"][-1], c["t"][-1], q["t"][-1])
    curve = lambda x: ([0.0] + x["t"], [0.0] + x["pressure_mean"])  # noqa: E731
    ratio = l1_errors(*curve(q), *curve(c), t_a)[0] / l1_errors(*curve(c), *curve(h), t_a)[0]
    lo, hi = 0.25, 4.0
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if ratio_of_differences(mid, n, n2, n3) < ratio else (lo, mid)
    k = (lo + hi) / 2
    again = curve_error(half, fine)
    factor = (n / n2) ** k - 1
    pairs = [(s["mesh_estimate_difference_ratio"], ratio), (s["mesh_estimate_order"], k),
             (s["mesh_error_estimate"], again["l1"] / factor), (s["mesh_error_estimate_transient"], again["l1_transient"] / factor),
             (s["mesh_error_estimate_window"], again["l1_reversion"] / factor)]
    return ratio, k, max(abs(a / b - 1) for a, b in pairs)


def extrapolated(out, n, n2, n3, k):
    """history-extrapolated.csv and mesh_extrapolated_error_estimate(_transient) recomputed from the three
    histories: X = p_h + (p_h - p_H) / ((n / n2)^k - 1) on the union of the two runs' times, its estimate
    int |X - X'| / int |X| / ((n / n2)^k - 1), X' the companions' extrapolant. Returns (X's times, X's
    pressures, the largest relative difference of the file and the estimates to their recomputation)."""
    s = summary_of(out)
    fine, half, quarter = (os.path.join(out, *p, "history.csv") for p in ((), ("mesh-estimate",),
                                                                           ("mesh-estimate", "mesh-estimate")))
    h, c, q = read_history(fine), read_history(half), read_history(quarter)
    curve = lambda x: ([0.0] + x["t"], [0.0] + x["pressure_mean"])  # noqa: E731

    def extrapolant(a, b, factor):
        (ta, pa), (tb, pb) = curve(a), curve(b)
        grid = sorted(set(ta + tb))
        return grid, [interpolate(ta, pa, t) + (interpolate(ta, pa, t) - interpolate(tb, pb, t)) / factor for t in grid]

    f1, f2 = (n / n2) ** k - 1, (n2 / n3) ** k - 1
    tx, px = extrapolant(h, c, f1)
    tx2, px2 = extrapolant(c, q, f2)
    written = read_history(os.path.join(out, "history-extrapolated.csv"))
    scale = max(abs(v) for v in px)
    worst = max([abs(a - b) / scale for a, b in zip(written["pressure_mean"], px[1:])]
                + [abs(a - b) / max(b, 1) for a, b in zip(written["t"], tx[1:])]
                + [0.0 if len(written["t"]) == len(tx) - 1 else 1.0])
    t_end = min(h["t"][-1], c["t"][-1], q["t"][-1])
    t_a = min(austenite_time(h) or t_end, t_end)
    for key, end in (("mesh_extrapolated_error_estimate", t_end), ("mesh_extrapolated_error_estimate_transient", t_a)):
        difference, norm = l1_errors(tx2, px2, tx, px, end)[:2]
        worst = max(worst, abs(s[key] / (difference / norm / f1) - 1))
    return tx, px, worst


def order_of(ratio, n, n2, n3):
    """The order k in [0.25, 4] whose ratio_of_differences is `ratio` (bisection), or None outside."""
    lo, hi = 0.25, 4.0
    if not ratio_of_differences(lo, n, n2, n3) <= ratio <= ratio_of_differences(hi, n, n2, n3):
        return None
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if ratio_of_differences(mid, n, n2, n3) < ratio else (lo, mid)
    return (lo + hi) / 2


def stage(data):
    """The bending's final values' mesh estimate against the three runs' bend.csv."""
    out, proc = run_scene_captured("sleeve-3d", "mesh-estimate-stage", "-quiet", "1", "-length", "0.02", "-mu", "0.2",
                                   "-bend", "1e-2", "-bendsteps", "2", "-nr", "4", "-nt", "8", "-meshestimate", "1",
                                   "-meshlevels", "3")
    check(proc.returncode == 0, f"sleeve-3d -bend 1e-2 -meshestimate 1 -meshlevels 3 exit {proc.returncode} {proc.stderr[-300:]}")
    if proc.returncode != 0:
        return
    s = summary_of(out)
    estimate = s["mesh_error_estimate_stage"]
    curves = [rows(os.path.join(out, *p, "bend.csv")) for p in ((), ("mesh-estimate",), ("mesh-estimate", "mesh-estimate"))]
    last = [c[-1] for c in curves]
    n, n2, n3 = s["mesh_estimate_layers"], s["mesh_estimate_coarse_layers"], s["mesh_estimate_coarsest_layers"]
    worst, orders, taken = 0.0, {}, []
    for name in ("moment", "normal_force_total"):
        v, v2, v3 = (float(r[name]) for r in last)
        k = order_of(abs(v2 - v3) / abs(v - v2), n, n2, n3)
        if k is None:
            k = 1.0
            taken.append(name)
        again = abs(v - v2) / abs(v) / ((n / n2) ** k - 1)
        # the whole curve: the largest difference over the increments (the same loads) over its largest value
        fine, coarse = ([float(r[name]) for r in c] for c in curves[:2])
        curve = max(abs(a - b) for a, b in zip(fine, coarse)) / max(abs(a) for a in fine) / ((n / n2) ** k - 1)
        orders[name] = k
        worst = max(worst, abs(estimate[name] / again - 1), abs(estimate[name + "_order"] / k - 1),
                    abs(estimate[name + "_curve"] / curve - 1))
    said = [name for name in orders if f"the bending's {name} shows no order" in proc.stdout]
    data["stage"] = {"estimate": estimate, "orders": orders, "order_1_taken": taken}
    check(estimate["name"] == "bending" and estimate["increments"] == 2 and (n, n2, n3) == (4, 2, 1) and worst < 1e-9
          and said == taken,
          f"the bending's mesh estimate (4, 2, 1): moment {estimate['moment']:.3e} (curve {estimate['moment_curve']:.3e}, "
          f"order {orders['moment']:.3f}), normal force {estimate['normal_force_total']:.3e} (curve "
          f"{estimate['normal_force_total_curve']:.3e}, order {orders['normal_force_total']:.3f}), recomputed from the "
          f"three bend.csv to {worst:.1e}; order 1 taken for {taken or 'none'}, said for {said or 'none'}")


def balanced(scene, folder, lo, hi, *args):
    """A -balance run: (its summary, the resolution its pilot's estimates give, ceil(n0 (mesh / time)^(1 / k))
    from the pilot's n0 clamped to [lo, hi]), or (None, None) when it failed."""
    out, proc = run_scene_captured(scene, folder, "-quiet", "1", *args)
    if proc.returncode != 0:
        check(False, f"{scene} {' '.join(args)} exit {proc.returncode} {proc.stdout[-300:]}")
        return None, None
    s = summary_of(out)
    b = s["balance"]
    wanted = math.ceil(b["pilot_layers"] * (b["pilot_mesh_error_estimate_transient"] / b["pilot_time_error_estimate_transient"])
                       ** (1 / b["pilot_mesh_estimate_order"]))
    return s, max(lo, min(hi, wanted))


def axisymmetric(data):
    """-meshestimate 1 -meshlevels 3 and -balance 1 on sleeve-axisymmetric (see the docstring)."""
    ref, pr = run_scene_captured("sleeve-axisymmetric", "mesh-estimate-axisymmetric-nr16", "-quiet", "1", "-nr", "16")
    out, proc = run_scene_captured("sleeve-axisymmetric", "mesh-estimate-axisymmetric", "-quiet", "1", "-nr", "4",
                                   "-meshestimate", "1", "-meshlevels", "3")
    if pr.returncode != 0 or proc.returncode != 0:
        check(False, f"sleeve-axisymmetric -nr 16 / -nr 4 -meshestimate 1 -meshlevels 3 exit {pr.returncode} / "
              f"{proc.returncode} {proc.stdout[-300:]}")
        return
    s = summary_of(out)
    ratio, k, worst = three_levels(out, 4, 2, 1)
    check((s["mesh_estimate_layers"], s["mesh_estimate_coarse_layers"], s["mesh_estimate_coarsest_layers"]) == (4, 2, 1)
          and 0.25 < k < 4 and worst < 1e-9, f"sleeve-axisymmetric -nr 4 -meshlevels 3: differences shrink by {ratio:.3f} "
          f"(4, 2, 1): order {k:.3f}; the estimates recomputed from the three histories to {worst:.1e}")
    e = curve_error(os.path.join(out, "history.csv"), os.path.join(ref, "history.csv"))
    window = s["mesh_error_estimate_window"] / e["l1_reversion"]
    transient = s["mesh_error_estimate_transient"] / e["l1_transient"]
    data["axisymmetric"] = {"order": k, "effectivity_window": window, "effectivity_transient": transient}
    check(0.5 <= window <= 2 and 0.5 <= transient <= 2,
          f"sleeve-axisymmetric -nr 4: effectivity against -nr 16 {window:.2f} over the window, {transient:.2f} over the "
          "transient, in [0.5, 2]")
    # the extrapolated curve: as written, and better than the run's own, within its estimate
    tx, px, worst = extrapolated(out, 4, 2, 1, k)
    r = read_history(os.path.join(ref, "history.csv"))
    difference, norm = l1_errors(tx, px, [0.0] + r["t"], [0.0] + r["pressure_mean"], austenite_time(r))[:2]
    actual, estimate = difference / norm, s["mesh_extrapolated_error_estimate_transient"]
    data["axisymmetric"].update(extrapolated_error_transient=actual, extrapolated_estimate_transient=estimate)
    check(worst < 1e-9 and actual < e["l1_transient"] and actual <= estimate,
          f"sleeve-axisymmetric -nr 4: history-extrapolated.csv and its estimates recomputed to {worst:.1e}; its error "
          f"against -nr 16 {actual:.2e} over the transient, below the run's {e['l1_transient']:.2e} and its estimate "
          f"{estimate:.2e}")
    s, n = balanced("sleeve-axisymmetric", "mesh-estimate-axisymmetric-balance", 2, 2000, "-nr", "4", "-balance", "1",
                    "-meshlevels", "3", "-tol", "3e-3")
    if s is None:
        return
    b, p = s["balance"], s["parameters"]
    check(b["pilot_layers"] == 4 and b["layers"] == n and p["nr"] == n and p["nz"] == 5 * n and s["mesh_estimate_layers"] == n,
          f"sleeve-axisymmetric -balance 1 from -nr 4 (order {b['pilot_mesh_estimate_order']:.2f}, time "
          f"{b['pilot_time_error_estimate_transient']:.2e}, mesh {b['pilot_mesh_error_estimate_transient']:.2e}): -nr {p['nr']}, "
          f"-nz {p['nz']} (square cells), its own estimate {s['mesh_error_estimate_transient']:.2e}")


def both_directions(data):
    """-meshestimate 2 -meshlevels 3, -arcs, -balance 2 on sleeve-elliptic (see the docstring)."""
    out, proc = run_scene_captured("sleeve-elliptic", "mesh-estimate-elliptic", "-quiet", "1", "-vtkevery", "0",
                                   "-arcs", "18", "-meshestimate", "2", "-meshlevels", "3")
    same, pb = run_scene_captured("sleeve-elliptic", "mesh-estimate-elliptic-aniso", "-quiet", "1", "-vtkevery", "0",
                                  "-mesh", "meshes/sleeve-aniso.msh")
    if proc.returncode != 0 or pb.returncode != 0:
        check(False, f"sleeve-elliptic -arcs 18 -meshestimate 2 -meshlevels 3 / -mesh sleeve-aniso exit {proc.returncode} "
              f"/ {pb.returncode} {proc.stdout[-300:]}")
        return
    s = summary_of(out)
    apart = curve_error(os.path.join(out, "history.csv"), os.path.join(same, "history.csv"))["l1"]
    check(s["nodes"] == summary_of(same)["nodes"] == 19 * 19 and s["arcs_chosen"] == 18 and apart < 1e-9,
          f"-arcs 18 on sleeve-quarter (18 x 90) is meshes/sleeve-aniso.msh: {s['nodes']} nodes, curves {apart:.1e} apart")
    check((s["mesh_estimate_layers"], s["mesh_estimate_arcs"], s["mesh_estimate_coarse_layers"], s["mesh_estimate_coarse_arcs"],
           s["mesh_estimate_coarsest_layers"], s["mesh_estimate_levels"]) == (18, 18, 9, 9, 4, 3),
          f"-meshestimate 2 -meshlevels 3 on 18 x 18: companions {s['mesh_estimate_coarse_layers']} x "
          f"{s['mesh_estimate_coarse_arcs']} and {s['mesh_estimate_coarsest_layers']} layers")
    ratio, k, worst = three_levels(out, 18, 9, 4)
    worst = max(worst, extrapolated(out, 18, 9, 4, k)[2])
    data["elliptic_both_directions"] = {"ratio": ratio, "order": k, "estimate_transient": s["mesh_error_estimate_transient"],
                                        "estimate_window": s["mesh_error_estimate_window"]}
    check(0.25 < k < 4 and worst < 1e-9, f"-meshlevels 3: the differences shrink by {ratio:.3f} (18, 9, 4): order {k:.3f}; "
          f"the estimates (transient {100 * s['mesh_error_estimate_transient']:.3f} %) are the two histories' L1 difference "
          f"over (2^k - 1), and history-extrapolated.csv and its estimates the three histories', to {worst:.1e}")
    s, layers = balanced("sleeve-elliptic", "mesh-estimate-elliptic-balance", 4, 400, "-vtkevery", "0", "-mesh",
                         "meshes/sleeve-aniso.msh", "-balance", "2", "-meshlevels", "3")
    if s is None:
        return
    b = s["balance"]
    data["elliptic_balance"] = {**b, "nodes": s["nodes"], "mesh_error_estimate_transient": s["mesh_error_estimate_transient"],
                                "time_error_estimate_transient": s["time_error_estimate_transient"]}
    check(b["pilot_layers"] == 18 and abs(b["pilot_mesh_estimate_order"] / k - 1) < 1e-9 and b["layers"] == layers and b["arcs"] == layers
          and s["nodes"] == (layers + 1) ** 2 and s["mesh_estimate_arcs"] == layers and s["mesh_estimate_coarse_arcs"] == layers // 2
          and s["mesh_estimate_levels"] == 3 and s["mesh_error_estimate_transient"] > 0,
          f"-balance 2: the pilot on 18 x 18 (order {b['pilot_mesh_estimate_order']:.3f}, time "
          f"{b['pilot_time_error_estimate_transient']:.2e}, mesh {b['pilot_mesh_error_estimate_transient']:.2e}) gives "
          f"{b['layers']} x {b['arcs']} ({s['nodes']} nodes); the run's own estimates: mesh "
          f"{s['mesh_error_estimate_transient']:.2e}, time {s['time_error_estimate_transient']:.2e}")


# The runs' temporary folders go under this test's own TMPDIR (the plugin's TemporaryDirectory
# follows it), so that the checks that none is left see this test's runs only: in /tmp a sleeve-3d
# run of a test beside it, its mesh's scratch folder still in use, read as one left behind.
SCRATCH = tempfile.mkdtemp(prefix="sma-mesh-estimate-test-")
os.environ["TMPDIR"] = SCRATCH
atexit.register(shutil.rmtree, SCRATCH, True)


def scratch_folders():
    """The scenes' scratch folders now in this test's TMPDIR."""
    return {n for n in os.listdir(SCRATCH) if n.startswith("sma-sleeve-")}


def main():
    data = {}
    ref, proc = run_scene_captured("sleeve-radial", "mesh-estimate-reference", "-quiet", "1", "-nr", "640", "-tend", "80",
                                   "-steps", "12800", "-tol", "0")
    check(proc.returncode == 0, f"sleeve-radial -nr 640 (the reference) exit {proc.returncode} {proc.stderr[-300:]}")
    if proc.returncode != 0:
        finish()
        return
    reference = os.path.join(ref, "history.csv")
    for scene, extra, coarse in (("sleeve-circular", ["-vtkevery", "0"], 9), ("sleeve-radial", ["-nr", "40"], 20)):
        out, proc = run_scene_captured(scene, f"mesh-estimate-{scene}", "-quiet", "1", "-meshestimate", "1", *extra)
        check(proc.returncode == 0, f"{scene} -meshestimate 1 exit {proc.returncode} {proc.stderr[-300:]}")
        if proc.returncode != 0:
            continue
        s = summary_of(out)
        fine = s["mesh_estimate_layers"]
        again = curve_error(os.path.join(out, "mesh-estimate", "history.csv"), os.path.join(out, "history.csv"))
        factor = fine / coarse - 1
        pairs = [(s["mesh_error_estimate"], again["l1"] / factor),
                 (s["mesh_error_estimate_transient"], again["l1_transient"] / factor),
                 (s["mesh_error_estimate_window"], again["l1_reversion"] / factor)]
        worst = max(abs(a / b - 1) for a, b in pairs)
        check(s["mesh_estimate_coarse_layers"] == coarse and worst < 1e-9,
              f"{scene}: the estimate against {s['mesh_estimate_coarse_layers']} (of {fine}) is the two histories' "
              f"L1 difference over (nr / nr_H - 1), over the run, transient and window, to {worst:.1e}")
        e = curve_error(os.path.join(out, "history.csv"), reference)
        window = s["mesh_error_estimate_window"] / e["l1_reversion"]
        transient = s["mesh_error_estimate_transient"] / e["l1_transient"]
        data[scene] = {"estimate_window": s["mesh_error_estimate_window"], "error_window": e["l1_reversion"],
                       "estimate_transient": s["mesh_error_estimate_transient"], "error_transient": e["l1_transient"],
                       "effectivity_window": window, "effectivity_transient": transient,
                       "time_error_estimate": s["time_error_estimate"]}
        check(0.5 <= window <= 2 and 0.5 <= transient <= 2,
              f"{scene}: effectivity {window:.2f} over the window ({100 * s['mesh_error_estimate_window']:.3f} % "
              f"against {100 * e['l1_reversion']:.3f} % measured), {transient:.2f} over the transient, in [0.5, 2]")
        # the same folder again without the option: no companion left, the summary says none was made
        _, proc = run_scene_captured(scene, f"mesh-estimate-{scene}", "-quiet", "1", "-meshestimate", "0", *extra)
        s = summary_of(out)
        check(proc.returncode == 0 and not os.path.exists(os.path.join(out, "mesh-estimate"))
              and not os.path.exists(os.path.join(out, "mesh-estimate.log")) and s["mesh_error_estimate"] is None,
              f"{scene}: the next run with -meshestimate 0 leaves no companion and writes mesh_error_estimate null")
    out, proc = run_scene_captured("sleeve-circular", "mesh-estimate-sleeve-circular", "-quiet", "1", "-meshestimate", "1",
                                   "-mesh", "meshes/ring-coarse.msh")
    message = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("error:")]
    kept = os.path.exists(os.path.join(out, "summary.json"))
    check(proc.returncode == 1 and message and "-meshestimate 1" in message[-1] and kept,
          f"an unstructured ring is refused before the folder is taken (exit {proc.returncode}, earlier results "
          f"{'kept' if kept else 'LOST'}): {message[-1] if message else '(no error line)'}")
    # -layers N: the structured ring remade with N layers equals the mesh file of N layers (to round-off:
    # the radii are read back from the loaded mesh)
    a, pa = run_scene_captured("sleeve-circular", "mesh-estimate-layers36", "-quiet", "1", "-vtkevery", "0", "-layers", "36")
    b, pb = run_scene_captured("sleeve-circular", "mesh-estimate-aniso36", "-quiet", "1", "-vtkevery", "0",
                               "-mesh", "meshes/sleeve-aniso36.msh")
    if pa.returncode == 0 and pb.returncode == 0:
        same = curve_error(os.path.join(a, "history.csv"), os.path.join(b, "history.csv"))["l1"]
        sa, sb = summary_of(a), summary_of(b)
        check(sa["nodes"] == sb["nodes"] == 37 * 19 and sa["layers_chosen"] == 36 and same < 1e-9,
              f"-layers 36 is meshes/sleeve-aniso36.msh: {sa['nodes']} nodes (37 x 19), the force curves {same:.1e} apart")
    else:
        check(False, f"-layers 36 / -mesh sleeve-aniso36 exit {pa.returncode} / {pb.returncode} {pa.stdout[-300:]}")
    # -balance 1: the layers from the pilot's two estimates, C / nr set to the time error; the run then
    # reports its own mesh error; its scratch folder is gone
    before = scratch_folders()
    for scene, extra, nodes in (("sleeve-radial", [], lambda n: n + 1),
                                ("sleeve-circular", ["-vtkevery", "0"], lambda n: (n + 1) * 19)):
        s, layers = balanced(scene, f"mesh-estimate-balance-{scene}", 4, 20000 if scene == "sleeve-radial" else 400,
                             "-balance", "1", *extra)
        if s is None:
            continue
        b = s["balance"]
        data[f"balance_{scene}"] = {**b, "nodes": s["nodes"], "mesh_error_estimate_transient": s["mesh_error_estimate_transient"],
                                    "time_error_estimate_transient": s["time_error_estimate_transient"]}
        check(b["pilot_mesh_estimate_order"] == 1 and b["layers"] == layers and s["nodes"] == nodes(b["layers"])
              and s["mesh_estimate_layers"] == b["layers"] and s["mesh_error_estimate_transient"] > 0,
              f"{scene} -balance 1: the pilot on {b['pilot_layers']} (time {b['pilot_time_error_estimate_transient']:.2e}, "
              f"mesh {b['pilot_mesh_error_estimate_transient']:.2e} over the transient) gives {b['layers']} layers "
              f"({s['nodes']} nodes); the run's own mesh estimate {s['mesh_error_estimate_transient']:.2e}, time "
              f"{s['time_error_estimate_transient']:.2e}")
    left = scratch_folders() - before
    check(not left, f"-balance 1 leaves no scratch folder in TMPDIR (left: {sorted(left) or 'none'})")
    for args, word in ((["-balance", "1", "-layers", "36"], "-balance 1"), (["-layers", "1"], "-layers 1")):
        _, proc = run_scene_captured("sleeve-circular", "mesh-estimate-refused", "-quiet", "1", *args)
        message = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("error:")]
        check(proc.returncode == 1 and message and word in message[-1],
              f"{' '.join(args)}: exit {proc.returncode}, {message[-1] if message else '(no error line)'}")
    both_directions(data)
    axisymmetric(data)
    stage(data)
    # a ring of slivers or of too many cells is refused (after the scratch folder was made: none is left)
    before = scratch_folders()
    for args, word in ((["-layers", "2000", "-arcs", "1"], "quality"), (["-layers", "1500", "-arcs", "1500"], "cells")):
        _, proc = run_scene_captured("sleeve-elliptic", "mesh-estimate-refused", "-quiet", "1", *args)
        message = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("error:")]
        left = scratch_folders() - before
        check(proc.returncode == 1 and message and word in message[-1] and not left,
              f"sleeve-elliptic {' '.join(args)}: exit {proc.returncode}, scratch folders left {sorted(left) or 'none'}, "
              f"{message[-1][:160] if message else '(no error line)'}")
    for scene, args, word in (("sleeve-elliptic", ["-meshestimate", "3"], "-meshestimate 3"),
                              ("sleeve-elliptic", ["-meshlevels", "4"], "-meshlevels 4"),
                              ("sleeve-elliptic", ["-balance", "2", "-arcs", "18"], "-balance 2"),
                              ("sleeve-radial", ["-balance", "2"], "-balance 2")):
        _, proc = run_scene_captured(scene, "mesh-estimate-refused", "-quiet", "1", *args)
        message = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("error:")]
        check(proc.returncode == 1 and message and word in message[-1],
              f"{scene} {' '.join(args)}: exit {proc.returncode}, {message[-1] if message else '(no error line)'}")
    record("mesh_estimate", data)
    finish()


if __name__ == "__main__":
    main()
