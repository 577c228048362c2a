#!/usr/bin/python3
"""The 3D sleeve's mechanics solve on FreeFEM's ffddm over MPI (tools/bench/ffddm_sleeve_3d.edp,
one-level RAS and GMRES; docs/benchmarks/ffddm-sleeve-3d.md), on the default 3D mesh's size
(nr 2, nt 8, nz 10: 891 dofs).

- Against the exact solution: the quarter ring loaded by a uniform phase stress, free of contact,
  dilates freely, u = e (x, y, z) with e = s / (3 lambda + 2 mu), which P1 holds exactly: on one
  rank (its subdomain the whole ring, one iteration) the error is round-off (1e-11); on two ranks,
  two subdomains, GMRES at 1e-8 leaves at most 1e-6 of it, after more than one iteration.
- MPI equality: the two solutions, each within that of the exact one, agree to 2e-6.
- The direct solve (UMFPACK, one rank) on the same operator: round-off (1e-11).
Writes results/checks/ffddm_3d.json.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tools", "bench"))

from checklib import check, finish, record  # noqa: E402
from ffddm_scaling import solve  # noqa: E402


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
    record("ffddm_3d", {"one_rank": one, "two_ranks": two})
    finish()


if __name__ == "__main__":
    main()
