#!/usr/bin/python3
"""make bench: speed against error, everything measured in this one run.

Runs, from the repository root (tools/ff), and writes results/bench/ (every run's outputs,
summary.json with the headline figures) and docs/benchmarks.md with its PNGs in docs/benchmarks/
(report.py); one module of this folder a section:
  1. the radial reference (edp/scenes/sleeve-radial.edp, nr 640, 4800 steps over the first 30 s:
     the finest 1D run affordable, itself about 0.03 % from its limit)           study.py
  1b. the refinement study of the force curve (issue 13): sleeve-radial and sleeve-circular with
     dt and h refined together, against the reference and against each other, observed orders,
     the paper's on/off model beside the fraction model, the defaults, and the exchange
     coefficient from 125 to 4000 W/(m^2 K) (reversal steps, pressure zigzags)     study.py
  2. the work-precision grid: sleeve-circular on 5 structured meshes x 4 step counts; error of the
     force-temperature curve against the radial reference (oracles/curve_error.py, relative L1 in
     time) and of the final pressure against Lame's closed form, versus wall time  work_precision.py
  3. the default scene (1500 steps, default mesh) three times: wall time and iteration counts
                                                                                   default_run.py
  4. the kernels (edp/bench/kernels.edp): plugin against pure-.edp phase projection and PSOR
     sweeps, and one DC iteration against one back-solve                           kernels.py
  5. PSOR modes full / condensed (plain, with active-set polish) for omega in 1.0 .. 1.95, and
     the polish interval                                                           psor.py
  6. the Lame ring (edp/scenes/ring-lame.edp): pressure error against time per mesh level;
  6b. the same against GetFEM on the same meshes (oracles/getfem_lame.py: agreement, time to
     error)                                                                        ring_lame.py
  7. the cost against the mesh size (issue 16): sleeve-circular from 1 729 to 98 841 nodes, ms per
     step and per DC iteration, peak memory, setup, their exponents                scaling.py
  7b. sleeve-axisymmetric's pull-out force under refinement: order, time to 1 %       pullout.py
  8. sleeve-radial against numpy: the scene against oracles/radial_numpy.py (the same scheme
     written again in vectorised numpy)                                           against_numpy.py
  9. time steps chosen by the error (-tol) against fixed steps at the paper's scale: steps, loop
     time, the time error and each run's own estimate (docs/benchmarks/time-steps.md) time_steps.py
 10. moving layers against fixed meshes at the paper's scale, against p*: error over the reversion
     window, whole-process time, orders in the layers (docs/benchmarks/mesh-adaptation.md)
                                                                               mesh_adaptation.py
 11. the elliptic scenes at the paper's scale: their default mesh's 1500 steps against rings of n x n
     with steps by -tol and -balance 2, against their 144 x 144 runs; the circular goals scaled
     (docs/benchmarks/elliptic-adaptation.md)                                 elliptic_adaptation.py
 12. the 3D sleeve's mechanics on ffddm over MPI, one level and GenEO: strong and weak scaling,
     iterations on more ranks (docs/benchmarks/ffddm-sleeve-3d.md)             ffddm_scaling.py
 13. sleeve-3d's clamping on Coulomb's cone: its cost against the round pipe's, and the time error of
     its circumferential traction with and without the step control's watch
     (docs/benchmarks/sleeve-3d-cone.md)                                       cone_3d.py
 14. sleeve-3d's plane hypothesis (-ends held) against the plane-strain closed form and the 2D
     scenes, frictionless and with friction on one history (docs/benchmarks/sleeve-3d-plane.md)
                                                                               plane_3d.py
 15. the final tractions' time error with friction against the runs' bound (-timeestimate 1) and
     Richardson's estimate (docs/benchmarks/traction-time-error.md)            traction_time.py
 16. the loads after the clamping (bending, pull-out): their increments' error, -timeestimate 1's
     bound of it, their cost at the defaults (docs/benchmarks/stage-increments.md)  stages_3d.py
The oracles (tools/bench/oracles: closed forms, the curve metric, the scheme in numpy, GetFEM) are
independent of the code they check: they import nothing of python/sma.
"""
import argparse
import os
import sys
import time

import against_numpy
import cone_3d
import default_run
import elliptic_adaptation
import ffddm_scaling
import kernels
import mesh_adaptation
import plane_3d
import psor
import pullout
import report
import ring_lame
import scaling
import stages_3d
import study
import time_steps
import traction_time
import work_precision
from common import OUT, QUICK, machine, write_json

# The sections that need no reference curve, each alone (--only): results/bench/only-<name>.json.
ALONE = {"kernels": kernels.measure, "psor": psor.measure, "ring-lame": ring_lame.measure,
         "scaling": lambda results: results.update(scaling=scaling.scaling(OUT, QUICK)),
         "pullout": lambda results: results.update(pullout=pullout.measure(OUT, QUICK)),
         "numpy": lambda results: results.update(radial_numpy=against_numpy.radial_against_numpy()),
         "time-steps": lambda results: time_steps.write_doc(time_steps.measure(results)),
         "mesh-adaptation": lambda results: mesh_adaptation.write_doc(mesh_adaptation.measure(results, quick=QUICK)),
         "elliptic-adaptation": lambda results: elliptic_adaptation.write_doc(elliptic_adaptation.measure(results, quick=QUICK)),
         "ffddm": lambda results: results.update(ffddm=ffddm_scaling.write_doc(ffddm_scaling.measure())),
         "cone-3d": lambda results: cone_3d.write_doc(cone_3d.measure(results)),
         "plane-3d": lambda results: plane_3d.write_doc(plane_3d.measure(results)),
         "traction-time": lambda results: traction_time.write_doc(traction_time.measure(results)),
         "stages-3d": lambda results: stages_3d.write_doc(stages_3d.measure(results))}


def main():
    parser = argparse.ArgumentParser(prog="tools/bench/bench.py", description=__doc__.split("\n\n")[0],
                                     epilog="Without --only: every section, results/bench/summary.json and "
                                     "docs/benchmarks.md (make bench).")
    parser.add_argument("--quick", action="store_true", help="a small grid, for checking the script itself")
    parser.add_argument("--only", choices=sorted(ALONE), help="one section alone: its figures in "
                        "results/bench/only-<name>.json (summary.json and docs/benchmarks.md untouched)")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(OUT, exist_ok=True)
    bench_start = time.perf_counter()
    results = {"machine": machine(), "quick": QUICK}
    if args.only:
        ALONE[args.only](results)
        path = os.path.join(OUT, f"only-{args.only}.json")
        write_json(path, results)
        print(f"bench: {args.only} done in {time.perf_counter() - bench_start:.0f} s: {os.path.relpath(path)}")
        return
    reference = study.radial_reference(results)
    results["study"] = study.refinement_study(reference)
    work_precision.measure(results, reference)
    default_run.measure(results, reference)
    kernels.measure(results)
    psor.measure(results)
    ring_lame.measure(results)
    results["scaling"] = scaling.scaling(OUT, QUICK)
    results["pullout"] = pullout.measure(OUT, QUICK)
    results["radial_numpy"] = against_numpy.radial_against_numpy()
    time_steps.write_doc(time_steps.measure(results))
    mesh_adaptation.write_doc(mesh_adaptation.measure(results, quick=QUICK), plt)
    elliptic_adaptation.write_doc(elliptic_adaptation.measure(results, quick=QUICK))
    ffddm_scaling.write_doc(ffddm_scaling.measure())
    cone_3d.write_doc(cone_3d.measure(results))
    plane_3d.write_doc(plane_3d.measure(results))
    traction_time.write_doc(traction_time.measure(results))
    stages_3d.write_doc(stages_3d.measure(results))

    results["bench_wall_seconds"] = time.perf_counter() - bench_start
    write_json(os.path.join(OUT, "summary.json"), results)
    report.write_doc(results, plt)
    print(f"bench: done in {results['bench_wall_seconds']:.0f} s: results/bench/summary.json, docs/benchmarks.md")


if __name__ == "__main__":
    sys.exit(main())
