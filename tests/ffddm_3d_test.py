#!/usr/bin/python3
"""The 3D sleeve's mechanics solve on FreeFEM's ffddm over MPI (tools/bench/ffddm_sleeve_3d.edp,
RAS and GMRES, with one level and with GenEO's coarse space; docs/benchmarks/ffddm-sleeve-3d.md),
on the default 3D mesh's size (nr 2, nt 8, nz 10: 891 dofs).

- Against the exact solution: the quarter ring loaded by a uniform phase stress, free of contact,
  dilates freely, u = e (x, y, z) with e = s / (3 lambda + 2 mu), which P1 holds exactly: on one
  rank (its subdomain the whole ring, one iteration) the error is round-off (1e-11); on two ranks,
  two subdomains, GMRES at 1e-8 leaves at most 1e-6 of it, after more than one iteration.
- MPI equality: the two solutions, each within that of the exact one, agree to 2e-6.
- The direct solve (UMFPACK, one rank) on the same operator: round-off (1e-11).
- GenEO (two levels; its coarse problem on plugin/ffddm/MUMPS_mpi.cpp's stand-in, UMFPACK on one
  rank): on two ranks a coarse space of some vectors, the same error bound and MPI equality, in
  fewer iterations than one level (the coarse space is used, not only built: 8 against 24).
- The contact condensed onto the bore through ffddm (tools/bench/ffddm_contact_3d.edp: the ring in
  austenite, ends held, on the rigid round pipe, W = H K^-1 H' from one distributed solve a bore
  node, PSOR on W): every bore node pressing, the laws at every node (gap >= -1e-8 of the
  interference, r gap <= 1e-8), the mean pressure within 1 % of Lame's plane-strain ring (0.4 % at
  nr 2, nt 8), and the reactions on 2 ranks equal to 1 rank's and to the sequential direct
  solve's to 1e-6 of the largest (GMRES at 1e-10). The dual solve (-dual 1: MPRGP, each product
  W p one distributed solve, no W built) on 2 ranks gives the same reactions to 1e-6; so it does
  in partial contact (an oval pipe, -ovality 8e-4: 21 of 27 nodes pressing), where the condensed
  PSOR equals the direct solve as well. Two layers (243 dofs): one level, since
  ARPACK fails in GenEO's eigenproblems on subdomains this small (measured: NO_SHIFTS_APPLIED).
- The heat equation's time loop through ffddm (tools/bench/ffddm_heat_3d.edp: Crank-Nicolson, 20
  steps of 60 s, a cold ring warming between the pipe and the air): the bore's mean temperature
  curve on 2 ranks equal to 1 rank's and to the direct solve's to 1e-8 of its rise; the steady
  state within 5e-3 of Text - Tpipe of the radial closed form (1.9e-3 at nr 2, nt 8).
- The stand-in refuses a coarse problem spread over two ranks (-ffddm_master_p 2): exit non-zero
  within 60 s, every rank stopped (MPI_Abort: a rank's FreeFEM error alone left the others
  waiting), the message naming the stand-in and the way out. GenEO on subdomains too small for its
  eigenproblems (ARPACK fails on one rank): the tool's catch stops every rank, within 60 s.
Writes results/checks/ffddm_3d.json.
"""
import time
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench"))

from checklib import check, finish, ranks_alive, record  # noqa: E402
from ffddm_scaling import CONTACT_SCRIPT, HEAT_SCRIPT, SCRIPT, run_ranks, solve  # noqa: E402


def stopped_run(script, options, message):
    """`script` on 2 ranks with `options`, a run that must fail on some rank: the exit code, the
    seconds, the error lines starting with `message` and whether a rank outlived mpiexec."""
    start = time.monotonic()
    code, output, session = run_ranks(2, script, options, timeout=60)
    seconds = time.monotonic() - start
    if code is None:
        return {"exit": None, "seconds": seconds, "errors": [], "left_running": True}
    errors = [line for line in output.splitlines() if line.startswith(message)]
    return {"exit": code, "seconds": seconds, "errors": errors, "left_running": ranks_alive(session)}


def main():
    one = solve(1, 2, 8, 10, direct=True, timeout=300)
    two = solve(2, 2, 8, 10, timeout=300)
    check(one["dofs"] == two["dofs"] == 891, f"the same mesh on 1 and 2 ranks: {one['dofs']}, {two['dofs']} dofs")
    check(one["relative_error"] <= 1e-11 and one["iterations"] == 1,
          f"one rank: error {one['relative_error']:.1e} of the exact dilatation (<= 1e-11) in {one['iterations']} iteration")
    check(two["relative_error"] <= 1e-6 and two["iterations"] > 1,
          f"two ranks: error {two['relative_error']:.1e} (<= 1e-6, GMRES at 1e-8) in {two['iterations']} iterations")
    check(one["relative_error"] + two["relative_error"] <= 2e-6,
          f"MPI equality: 1 and 2 ranks within {one['relative_error'] + two['relative_error']:.1e} of each other (<= 2e-6)")
    check(0 <= one["direct_relative_error"] <= 1e-11, f"the direct solve: error {one['direct_relative_error']:.1e} (<= 1e-11)")
    geneo_one = solve(1, 2, 8, 10, geneo=True, timeout=300)
    geneo_two = solve(2, 2, 8, 10, geneo=True, timeout=300)
    check(geneo_one["relative_error"] <= 1e-11 and geneo_one["iterations"] == 1,
          f"GenEO, one rank: error {geneo_one['relative_error']:.1e} (<= 1e-11) in {geneo_one['iterations']} iteration")
    check(geneo_two["coarse_space"] > 0 and geneo_two["relative_error"] <= 1e-6,
          f"GenEO, two ranks: coarse space {geneo_two['coarse_space']} (> 0), error {geneo_two['relative_error']:.1e} "
          "(<= 1e-6)")
    check(geneo_one["relative_error"] + geneo_two["relative_error"] <= 2e-6,
          f"GenEO's MPI equality: 1 and 2 ranks within {geneo_one['relative_error'] + geneo_two['relative_error']:.1e} "
          "of each other (<= 2e-6)")
    check(1 < geneo_two["iterations"] < two["iterations"],
          f"GenEO's coarse space at work: {geneo_two['iterations']} iterations on two ranks against one level's "
          f"{two['iterations']}")
    contact_one = solve(1, 2, 8, 2, direct=True, tol=1e-10, timeout=300, script=CONTACT_SCRIPT)
    contact_two = solve(2, 2, 8, 2, direct=True, tol=1e-10, timeout=300, script=CONTACT_SCRIPT)
    for name, run in (("1 rank", contact_one), ("2 ranks", contact_two)):
        check(run["pressing"] == run["bore_nodes"] > 0 and run["gap_min"] >= -1e-8 and run["complementarity_max"] <= 1e-8,
              f"contact through ffddm, {name}: {run['pressing']} of {run['bore_nodes']} bore nodes pressing, gap min "
              f"{run['gap_min']:.1e} of the interference (>= -1e-8), r gap {run['complementarity_max']:.1e} (<= 1e-8)")
        check(abs(run["pressure_mean"] / run["pressure_lame"] - 1) <= 0.01,
              f"contact through ffddm, {name}: mean pressure {run['pressure_mean'] / 1e6:.4f} MPa against Lame's "
              f"{run['pressure_lame'] / 1e6:.4f} (within 1 %)")
        check(0 <= run["direct_difference"] <= 1e-6,
              f"contact through ffddm, {name}: the reactions as the direct solve's to {run['direct_difference']:.1e} "
              "of the largest (<= 1e-6)")
    dual_two = solve(2, 2, 8, 2, tol=1e-10, timeout=300, script=CONTACT_SCRIPT, extra=("-dual", "1"))
    dual_difference = max(abs(a - b) for a, b in zip(contact_one["reactions"], dual_two["reactions"])) / max(
        contact_one["reactions"])
    check(dual_two["dual"] == 1 and dual_two["pressing"] == dual_two["bore_nodes"] and dual_difference <= 1e-6
          and dual_two["complementarity_max"] <= 1e-8 and dual_two["gap_min"] >= -1e-8,
          f"the dual solve (MPRGP, no W built) on 2 ranks: {dual_two['contact_solves']} solves, the reactions as the "
          f"condensed PSOR's on 1 rank to {dual_difference:.1e} of the largest (<= 1e-6), the laws to "
          f"{max(dual_two['complementarity_max'], -dual_two['gap_min']):.1e}")
    # partial contact: an oval pipe (-ovality 8e-4 m, 8 times the interference) leaves part of the bore open
    oval = solve(2, 2, 8, 2, direct=True, tol=1e-10, timeout=300, script=CONTACT_SCRIPT, extra=("-ovality", "8e-4"))
    oval_dual = solve(2, 2, 8, 2, tol=1e-10, timeout=300, script=CONTACT_SCRIPT, extra=("-ovality", "8e-4", "-dual", "1"))
    oval_difference = max(abs(a - b) for a, b in zip(oval["reactions"], oval_dual["reactions"])) / max(oval["reactions"])
    check(0 < oval["pressing"] < oval["bore_nodes"] and oval_dual["pressing"] == oval["pressing"],
          f"the oval pipe opens part of the bore: {oval['pressing']} of {oval['bore_nodes']} pressing (the dual solve: "
          f"{oval_dual['pressing']})")
    check(oval_difference <= 1e-6 and 0 <= oval["direct_difference"] <= 1e-6
          and max(oval["complementarity_max"], oval_dual["complementarity_max"]) <= 1e-8
          and min(oval["gap_min"], oval_dual["gap_min"]) >= -1e-8,
          f"partial contact on 2 ranks: the dual solve as the condensed PSOR to {oval_difference:.1e}, the condensed as "
          f"the direct solve to {oval['direct_difference']:.1e} (<= 1e-6), the laws at every node")
    ranks_difference = max(abs(a - b) for a, b in zip(contact_one["reactions"], contact_two["reactions"])) / max(
        contact_one["reactions"])
    check(len(contact_one["reactions"]) == len(contact_two["reactions"]) and ranks_difference <= 1e-6,
          f"contact's MPI equality: the reactions on 1 and 2 ranks within {ranks_difference:.1e} of the largest (<= 1e-6)")
    heat_one = solve(1, 2, 8, 2, direct=True, tol=1e-10, timeout=300, script=HEAT_SCRIPT)
    heat_two = solve(2, 2, 8, 2, direct=True, tol=1e-10, timeout=300, script=HEAT_SCRIPT)
    rise = heat_one["curve"][-1] - heat_one["curve"][0]
    heat_difference = max(abs(a - b) for a, b in zip(heat_one["curve"], heat_two["curve"])) / rise
    check(len(heat_one["curve"]) == len(heat_two["curve"]) == 21 and rise > 10 and heat_difference <= 1e-8,
          f"the heat time loop through ffddm: the bore's mean {heat_one['curve'][0]:.2f} -> {heat_one['curve'][-1]:.3f} K in "
          f"20 steps, the curve on 2 ranks as on 1 to {heat_difference:.1e} of its rise (<= 1e-8)")
    check(all(0 <= run["direct_difference"] <= 1e-8 for run in (heat_one, heat_two)),
          f"the heat time loop as the direct solve's: {heat_one['direct_difference']:.1e}, {heat_two['direct_difference']:.1e} "
          "of the rise (<= 1e-8)")
    check(heat_two["steady_relative_error"] <= 5e-3,
          f"the heat's steady state against the radial closed form: {heat_two['steady_relative_error']:.1e} of Text - Tpipe "
          "(<= 5e-3 at nr 2, nt 8)")
    refused = stopped_run(SCRIPT, ["-nr", "2", "-nt", "8", "-nz", "10", "-geneo", "1", "-ffddm_master_p", "2"],
                          "error: MUMPS stand-in")
    check(refused["exit"] not in (None, 0) and refused["errors"] and not refused["left_running"],
          f"a coarse problem on 2 ranks (-ffddm_master_p 2) refused: exit {refused['exit']} in {refused['seconds']:.1f} s "
          f"(limit 60), {len(refused['errors'])} stand-in error lines, ranks left running: {refused['left_running']}")
    check(all("-ffddm_master_p 1" in line for line in refused["errors"]),
          "the refusal names the way out (-ffddm_master_p 1)")
    # GenEO on subdomains too small for its eigenproblems (243 dofs on 2 ranks, 20 vectors): ARPACK
    # fails on one rank; the tool catches it and stops every rank
    failed = stopped_run(CONTACT_SCRIPT, ["-nz", "2", "-geneo", "1"], "error: ffddm_contact_3d: GenEO's coarse space failed")
    check(failed["exit"] not in (None, 0) and failed["errors"] and not failed["left_running"],
          f"GenEO failing on one rank stops them all: exit {failed['exit']} in {failed['seconds']:.1f} s (limit 60), "
          f"{len(failed['errors'])} error lines, ranks left running: {failed['left_running']}")
    record("ffddm_3d", {"one_rank": one, "two_ranks": two, "geneo_one_rank": geneo_one, "geneo_two_ranks": geneo_two,
                        "contact_one_rank": contact_one, "contact_two_ranks": contact_two,
                        "contact_ranks_difference": ranks_difference, "dual_two_ranks": dual_two, "dual_difference": dual_difference, "oval": oval, "oval_dual": oval_dual,
                        "oval_difference": oval_difference, "heat_one_rank": heat_one, "heat_two_ranks": heat_two, "heat_difference": heat_difference,
                        "refused_coarse_problem": refused, "geneo_failure": failed})
    finish()


if __name__ == "__main__":
    main()
