"""make bench, section 4 (tools/bench/bench.py): the kernels (edp/bench/kernels.edp): plugin
against pure-.edp phase projection and PSOR sweeps, and one DC iteration against one back-solve.
doc() writes their part of docs/benchmarks.md."""
from common import OUT, QUICK, run


def measure(results):
    """edp/bench/kernels.edp's figures, into `results`."""
    print("bench: kernels (plugin against pure .edp, DC iteration against back-solve)", flush=True)
    _, kernels, _ = run("edp/bench/kernels.edp", OUT, "-repeat", 5 if QUICK else 20,
                        "-sweeps", 50 if QUICK else 200, result="kernels.json")
    results["kernels"] = kernels
    results["plugin_speedup_projection"] = kernels["projection"]["speedup"]
    results["plugin_speedup_psor"] = kernels["psor"]["speedup"]
    results["dc_iteration_over_backsolve"] = kernels["dc"]["contact_over_backsolve"]
    results["dc_iteration_over_backsolve_without_contact"] = kernels["dc"]["free_over_backsolve"]


def doc(r, w):
    """Plugin against pure .edp; one DC iteration against one back-solve."""
    k = r["kernels"]
    w("## Plugin against pure .edp")
    w("")
    p, q = k["projection"], k["psor"]
    w(f"Same inputs, same results (checked in the script: the projections agree exactly, the PSOR "
      f"iterates to {q['relative_difference']:.1e} relative), default mesh ({k['nodes']} nodes).")
    w("")
    w("| kernel | size | plugin | best pure .edp | ratio |")
    w("|---|---|---|---|---|")
    w(f"| phase projection (local step) | {p['points']} points, all three phases | {1e6 * p['plugin_seconds']:.1f} us | "
      f"{1e3 * p['best_script_seconds']:.2f} ms (P0 expressions; script loop {1e3 * p['loop_seconds']:.1f} ms) | "
      f"**{p['speedup']:.0f}x** |")
    w(f"| PSOR sweeps (condensed, Tresca) | {q['unknowns']} unknowns x {q['sweeps']} sweeps | {1e3 * q['plugin_seconds']:.2f} ms | "
      f"{1e3 * q['script_seconds']:.1f} ms | **{q['speedup']:.0f}x** |")
    w("")
    w("## One DC iteration against one back-solve")
    w("")
    dc = k["dc"]
    w(f"Back-solve of the factorised stiffness ({2 * k['nodes']} dofs): FreeFEM's `K^-1` (UMFPACK) "
      f"{1e3 * dc['backsolve_seconds']:.3f} ms, the plugin's `SpdSolve` (sparse LDL') "
      f"{1e3 * dc['backsolve_plugin_seconds']:.3f} ms (same solution to {dc['backsolve_plugin_relative_difference']:.1e}). "
      f"One DC iteration as the scenes run it (edp/solvers/dc.idp DCSolve: global step, traces, local step; "
      f"no Lagrangian record): without contact {1e3 * dc['iteration_free_seconds']:.3f} ms = "
      f"**{dc['free_over_backsolve']:.2f}** back-solves; with the pipe ({dc['contact_nodes_active']} nodes "
      f"active, u_free by the plugin's back-solve, condensed PSOR warm-started from the previous reactions, "
      f"then u = K^-1 (rhs + H' r), a second plugin back-solve) "
      f"{1e3 * dc['iteration_contact_seconds']:.3f} ms = **{dc['contact_over_backsolve']:.2f}** FreeFEM back-solves "
      f"= {dc['contact_over_plugin_backsolve']:.2f} plugin back-solves.")
    w("")
