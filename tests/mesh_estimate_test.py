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
  - a later run in the same folder without -meshestimate leaves no companion (its summary.json
    "mesh_error_estimate": null);
  - a mesh it cannot halve (an unstructured ring) is refused before the folder is taken, naming
    -meshestimate: the folder's earlier results stay;
  - -layers 36 remakes the structured ring with 36 layers: the run equals -mesh
    meshes/sleeve-aniso36.msh's (its force curve to 1e-9, the node count);
  - -balance 1 (sleeve-radial, sleeve-circular): the layers are the pilot's, ceil(nr0 mesh / time)
    from its two estimates over the transient (clamped), the run is on them and reports its own mesh
    estimate, and no scratch folder is left in /tmp; -balance with -layers, and -layers 1, refused.
Writes results/checks/mesh_estimate.json.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, run_scene_captured, summary_of  # noqa: E402
from curve_error import curve_error  # noqa: E402


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
        _, proc = run_scene_captured(scene, f"mesh-estimate-{scene}", "-quiet", "1", *extra)
        s = summary_of(out)
        check(proc.returncode == 0 and not os.path.exists(os.path.join(out, "mesh-estimate"))
              and not os.path.exists(os.path.join(out, "mesh-estimate.log")) and s["mesh_error_estimate"] is None,
              f"{scene}: the next run without -meshestimate leaves no companion and writes mesh_error_estimate null")
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
    # reports its own mesh error; its scratch folder of /tmp is gone
    scratch = lambda: {n for n in os.listdir("/tmp") if n.startswith("sma-sleeve-")}  # noqa: E731
    before = scratch()
    for scene, extra, nodes in (("sleeve-radial", [], lambda n: n + 1),
                                ("sleeve-circular", ["-vtkevery", "0"], lambda n: (n + 1) * 19)):
        out, proc = run_scene_captured(scene, f"mesh-estimate-balance-{scene}", "-quiet", "1", "-balance", "1", *extra)
        if proc.returncode != 0:
            check(False, f"{scene} -balance 1 exit {proc.returncode} {proc.stdout[-300:]}")
            continue
        s = summary_of(out)
        b = s["balance"]
        wanted = -(-b["pilot_layers"] * b["pilot_mesh_error_estimate_transient"] // b["pilot_time_error_estimate_transient"])
        data[f"balance_{scene}"] = {**b, "nodes": s["nodes"], "mesh_error_estimate_transient": s["mesh_error_estimate_transient"],
                                    "time_error_estimate_transient": s["time_error_estimate_transient"]}
        check(b["layers"] == max(4, min(wanted, 20000 if scene == "sleeve-radial" else 400)) and s["nodes"] == nodes(b["layers"])
              and s["mesh_estimate_layers"] == b["layers"] and s["mesh_error_estimate_transient"] > 0,
              f"{scene} -balance 1: the pilot on {b['pilot_layers']} (time {b['pilot_time_error_estimate_transient']:.2e}, "
              f"mesh {b['pilot_mesh_error_estimate_transient']:.2e} over the transient) gives {b['layers']} layers "
              f"({s['nodes']} nodes); the run's own mesh estimate {s['mesh_error_estimate_transient']:.2e}, time "
              f"{s['time_error_estimate_transient']:.2e}")
    left = scratch() - before
    check(not left, f"-balance 1 leaves no scratch folder in /tmp (left: {sorted(left) or 'none'})")
    for args, word in ((["-balance", "1", "-layers", "36"], "-balance 1"), (["-layers", "1"], "-layers 1")):
        _, proc = run_scene_captured("sleeve-circular", "mesh-estimate-refused", "-quiet", "1", *args)
        message = [l for l in (proc.stdout + proc.stderr).splitlines() if l.startswith("error:")]
        check(proc.returncode == 1 and message and word in message[-1],
              f"{' '.join(args)}: exit {proc.returncode}, {message[-1] if message else '(no error line)'}")
    record("mesh_estimate", data)
    finish()


if __name__ == "__main__":
    main()
