#!/usr/bin/python3
"""The 3D sleeve's mechanics solve on ffddm over MPI: strong and weak scaling on this machine
(tools/bench/ffddm_sleeve_3d.edp; docs/benchmarks/ffddm-sleeve-3d.md).

One level and two (GenEO). Strong: one mesh on 1 and 2 ranks (and the one-rank direct solve).
Weak: the layers along z doubled with the ranks (the same cells per rank). Then 4 and 8 ranks on
the 2 cores, both ways, for their iteration counts only. Each run's error against the exact free
dilatation, its GMRES iterations and its times; the speed-ups are ratios of runs made here one after the other. Writes
results/bench/ffddm-sleeve-3d.json and docs/benchmarks/ffddm-sleeve-3d.md (a few minutes); then, on
one rank, the contact's solves condensed against dual and the heat's steady state under refinement;
then sleeve-3d itself at its defaults, sequentially and on 1 and 2 ranks (edp/mpi/sleeve-3d.edp).

    tools/bench/ffddm_scaling.py [--nr 4 --nt 16 --nz 60]
"""
import argparse
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from markdown_wrap import wrap  # noqa: E402
from results_io import read_csv  # noqa: E402
sys.path.insert(0, os.path.join(ROOT, "tools", "bench"))
from common import without_companion  # noqa: E402
SCRIPT = os.path.join(ROOT, "tools", "bench", "ffddm_sleeve_3d.edp")
CONTACT_SCRIPT = os.path.join(ROOT, "tools", "bench", "ffddm_contact_3d.edp")
HEAT_SCRIPT = os.path.join(ROOT, "tools", "bench", "ffddm_heat_3d.edp")
BENCH_DIR = os.path.join(ROOT, "tools", "bench")
PLUGIN_DIR = os.path.join(ROOT, "plugin", "build")
STUB_DIR = os.path.join(PLUGIN_DIR, "ffddm")


def ffddm_environment():
    """FreeFEM's paths for FreeFem++-mpi: the stand-in MUMPS_mpi first (plugin/ffddm/MUMPS_mpi.cpp),
    the project's plugin (ffddm_contact_3d.edp's PsorCondensed), then Debian's MPI plugins and its
    others; the tools' shared ring (ffddm_ring_3d.idp) and the scene's distributed solve
    (edp/solvers/ddm-global-solve.idp); OpenMPI's consent to run as root (a container)."""
    for built in (os.path.join(STUB_DIR, "MUMPS_mpi.so"), os.path.join(PLUGIN_DIR, "sma.so")):
        if not os.path.exists(built):
            sys.exit(f"error: ffddm_scaling: {os.path.relpath(built, ROOT)} is not built: run make plugin")
    for tool in ("mpiexec", "FreeFem++-mpi"):
        if shutil.which(tool) is None:
            sys.exit(f"error: ffddm_scaling: {tool} not found (make deps installs openmpi and FreeFEM)")
    env = dict(os.environ)
    env["FF_LOADPATH"] = f"{STUB_DIR};{PLUGIN_DIR};/usr/lib/freefem++/mpi;/usr/lib/freefem++;./"
    env["FF_INCLUDEPATH"] = f"/usr/include/freefem++/idp;{BENCH_DIR};{os.path.join(ROOT, 'edp', 'solvers')};./"
    env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    env["OMPI_MCA_mpi_yield_when_idle"] = "1"
    return env


def run_ranks(ranks, script, options, timeout, cwd=None):
    """`script` under mpiexec on `ranks` ranks with `options` (run_in_session): (exit code or None
    when stopped, its output, the session's id)."""
    cmd = ["mpiexec", "--oversubscribe", "-np", str(ranks), "FreeFem++-mpi", "-nw", "-ne", script, "-v", "0",
           "-ffddm_verbosity", "0", *options]
    return run_in_session(cmd, timeout, cwd=cwd, env=ffddm_environment())


def run_in_session(cmd, timeout, cwd=None, env=None):
    """`cmd` (an MPI launcher) and its children in a session of their own, stopped together when the
    run outlives `timeout` s (killing mpiexec alone could leave ranks running): (exit code or None
    when stopped, its output, the session's id)."""
    run = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, start_new_session=True)
    try:
        output, _ = run.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(run.pid, signal.SIGKILL)
        output, _ = run.communicate()
        return None, output, run.pid
    except BaseException:
        os.killpg(run.pid, signal.SIGKILL)
        raise
    return run.returncode, output, run.pid


def solve(ranks, nr, nt, nz, direct=False, tol=1e-8, timeout=900, geneo=False, extra=(), script=SCRIPT):
    """One run of ffddm_sleeve_3d.edp (or `script`: ffddm_contact_3d.edp, ffddm_heat_3d.edp) on
    `ranks` ranks (two levels with `geneo`; `extra`: more of its options): its JSON record."""
    with tempfile.TemporaryDirectory(prefix="sma-ffddm-") as scratch:
        out = os.path.join(scratch, "run.json")
        options = ["-nr", str(nr), "-nt", str(nt), "-nz", str(nz), "-tol", str(tol), "-direct", "1" if direct else "0",
                   "-geneo", "1" if geneo else "0", "-out", out, *extra]
        code, output, _ = run_ranks(ranks, script, options, timeout, cwd=scratch)
        what = f"{os.path.relpath(script, ROOT)} on {ranks} ranks {' '.join(options)}"
        if code is None:
            sys.exit(f"error: ffddm_scaling: {what} still running after {timeout} s: stopped")
        if code != 0 or not os.path.exists(out):
            sys.exit(f"error: ffddm_scaling: {what} failed (exit {code}):\n" + output[-3000:])
        with open(out) as f:
            return json.load(f)


# (name, two levels, ffddm's -ffddm_geneo_nu or None for its default, the sequences run)
METHODS = (("one level", False, None, ("strong", "weak", "oversubscribed", "oversubscribed_weak")),
           ("GenEO", True, None, ("strong", "weak", "oversubscribed", "oversubscribed_weak")),
           ("GenEO, 40 vectors", True, 40, ("weak", "oversubscribed_weak")))


def measure(nr=4, nt=16, nz=60, ranks=(1, 2), oversubscribed=(4, 8)):
    """For each of METHODS: strong scaling on `ranks` (with the one-rank direct solve), weak scaling
    (nz times the ranks), and the iteration counts on more ranks than cores (`oversubscribed`, the
    same mesh and the weak sequence: their times mean nothing here, their iterations are the
    method's)."""
    results = {"cores": os.cpu_count(), "date": time.strftime("%Y-%m-%d %H:%M"), "methods": {}}
    for name, geneo, nu, sequences in METHODS:
        extra = ("-ffddm_geneo_nu", str(nu)) if nu else ()
        plans = {"strong": [(p, nz) for p in ranks], "weak": [(p, nz * p // ranks[0]) for p in ranks],
                 "oversubscribed": [(p, nz) for p in oversubscribed],
                 "oversubscribed_weak": [(p, nz * p // ranks[0]) for p in oversubscribed]}
        results["methods"][name] = {
            key: [solve(p, nr, nt, layers, direct=key == "strong" and p == ranks[0] and not geneo, geneo=geneo, extra=extra)
                  for p, layers in plans[key]] for key in sequences}
    results["contact_heat"] = measure_contact_heat()
    results["scene"] = measure_scene()
    save(results)
    return results


def save(results):
    """results/bench/ffddm-sleeve-3d.json"""
    os.makedirs(os.path.join(ROOT, "results", "bench"), exist_ok=True)
    with open(os.path.join(ROOT, "results", "bench", "ffddm-sleeve-3d.json"), "w") as f:
        json.dump(results, f, indent=1)


# The contact's bores (nr, nt, nz) and the heat's meshes: the section refined alone, then with the layers
CONTACT_MESHES = ((2, 8, 2), (2, 8, 10), (2, 8, 20), (3, 12, 20))
HEAT_MESHES = {"section": ((2, 8, 2), (4, 16, 2), (8, 32, 2)), "section and layers": ((2, 8, 2), (4, 16, 4), (8, 32, 8))}


def measure_contact_heat():
    """On one rank: the contact's solves, condensed (one a bore node) against the dual solve, with the
    largest difference of their reactions; the heat's steady state against the radial closed form,
    refining the section alone and with the layers (one time step: only the steady state is read)."""
    contact = []
    for nr, nt, nz in CONTACT_MESHES:
        condensed = solve(1, nr, nt, nz, tol=1e-10, script=CONTACT_SCRIPT)
        dual = solve(1, nr, nt, nz, tol=1e-10, script=CONTACT_SCRIPT, extra=("-dual", "1"))
        difference = max(abs(a - b) for a, b in zip(condensed["reactions"], dual["reactions"])) / max(condensed["reactions"])
        contact.append({"nr": nr, "nt": nt, "nz": nz, "bore_nodes": condensed["bore_nodes"],
                        "condensed_solves": condensed["contact_solves"], "dual_solves": dual["contact_solves"],
                        "difference": difference})
    heat = {name: [dict(solve(1, nr, nt, nz, tol=1e-10, script=HEAT_SCRIPT, extra=("-steps", "1")), nr=nr, nt=nt, nz=nz)
                   for nr, nt, nz in meshes] for name, meshes in HEAT_MESHES.items()}
    return {"contact": contact, "heat": heat}


# sleeve-3d itself at its defaults: sequentially and on MPI ranks (edp/mpi/sleeve-3d.edp through
# tools/ff-mpi), with the newton step solver (the default; on the ranks its solves called back from
# the plugin) and with the paper's nested loops; on 2 ranks the default -ddmgeneo -1 (auto) takes GenEO's
# coarse space there (567 dofs a subdomain), and one level is asked for the comparison
FIXEDPOINT = ("-stepsolver", "fixedpoint")
SCENE_RUNS = (("sequential, newton", None, ()), ("sequential, nested loops", None, FIXEDPOINT),
              ("1 rank, newton", 1, ()), ("2 ranks, newton, one level", 2, ("-ddmgeneo", "0")),
              ("2 ranks, newton, GenEO (the default)", 2, ()), ("2 ranks, nested loops, GenEO (the default)", 2, FIXEDPOINT))


def history_curve(folder):
    """(t, pressure_mean) of a run's history.csv (the plot tools' reader)."""
    columns = read_csv(os.path.join(folder, "history.csv"))
    return list(zip(columns["t"], columns["pressure_mean"]))


def interpolated(curve, t):
    for (t0, p0), (t1, p1) in zip(curve, curve[1:]):
        if t0 <= t <= t1:
            return p0 + (p1 - p0) * (t - t0) / (t1 - t0) if t1 > t0 else p1
    return curve[-1][1] if t > curve[-1][0] else curve[0][1]


def measure_scene():
    """SCENE_RUNS one after the other: each run's loop time, steps, solves and GMRES iterations, and its
    curve's largest difference to the sequential run's of the same step solver (interpolated at its
    instants, over the largest mean pressure)."""
    runs = []
    with tempfile.TemporaryDirectory(prefix="sma-ffddm-scene-") as scratch:
        for k, (name, ranks, extra) in enumerate(SCENE_RUNS):
            out = os.path.join(scratch, str(k))
            if ranks is None:
                # (the timings are the run's, not its default companion's; the ranks make none by default)
                cmd = [os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-3d.edp",
                       *without_companion("edp/scenes/sleeve-3d.edp", extra)]
            else:
                cmd = [os.path.join(ROOT, "tools", "ff-mpi"), str(ranks), "edp/mpi/sleeve-3d.edp"]
            done = subprocess.run(cmd + ["-out", out, "-quiet", "1", *extra], cwd=ROOT, capture_output=True, text=True)
            if done.returncode != 0:
                sys.exit(f"error: ffddm_scaling: sleeve-3d, {name}: exit {done.returncode}: {(done.stdout + done.stderr)[-600:]}")
            with open(os.path.join(out, "summary.json")) as f:
                summary = json.load(f)
            runs.append({"name": name, "solver": summary["step_solver"], "seconds": summary["wall_seconds"], "steps": summary["n_steps"],
                         "pressure_mid": summary["final_pressure_mid"], "distributed": summary.get("distributed"),
                         "curve": history_curve(out)})
    sequential = {r["solver"]: r["curve"] for r, (_, ranks, _) in zip(runs, SCENE_RUNS) if ranks is None}
    for r in runs:
        base = sequential[r["solver"]]
        scale = max(p for _, p in base)
        r["curve_difference"] = max(abs(interpolated(r["curve"], t) - p) for t, p in base) / scale
    for r in runs:
        del r["curve"]
    return runs


def scene_lines(runs):
    """The page's section on measure_scene()'s results."""
    base = runs[0]["seconds"]
    lines = ["", "sleeve-3d itself at its defaults (297 nodes, 891 dofs; `make run SCENE=sleeve-3d NP=2`, "
             "docs/model.md#the-scene-on-ffddm), run one after the other: the loop's time, over the sequential newton "
             "run's, and the curve's largest difference to the sequential run's of the same step solver (the runs' step "
             "control may take other steps):", "",
             "| run | steps | loop (s) | time ratio | stiffness solves | GMRES iterations a solve | curve difference |",
             "|---|---|---|---|---|---|---|"]
    for r in runs:
        d = r["distributed"]
        solves = f"{d['stiffness_solves']} | {d['stiffness_iterations'] / d['stiffness_solves']:.1f}" if d else "- | -"
        lines.append(f"| {r['name']} | {r['steps']} | {r['seconds']:.1f} | {r['seconds'] / base:.2f} | {solves} | "
                     f"{r['curve_difference']:.1e} |")
    return lines


def contact_heat_lines(study):
    """The page's section on measure_contact_heat()'s results."""
    lines = ["", "The contact condensed onto the bore (tools/bench/ffddm_contact_3d.edp, one rank): distributed solves "
             "of the condensation (one a bore node) against the dual solve (`-dual 1`, MPRGP: one a product W p), and "
             "the largest difference of their reactions:", "",
             "| nr x nt x nz | bore nodes | condensed: solves | dual: solves | difference |", "|---|---|---|---|---|"]
    for c in study["contact"]:
        lines.append(f"| {c['nr']} x {c['nt']} x {c['nz']} | {c['bore_nodes']} | {c['condensed_solves']} | "
                     f"{c['dual_solves']} | {c['difference']:.1e} |")
    lines += ["", "The heat equation's steady state (tools/bench/ffddm_heat_3d.edp, one rank) against the radial closed "
              "form, relative to Text - Tpipe, with the observed order between levels:", "",
              "| refined | nr x nt x nz | error | order |", "|---|---|---|---|"]
    for name, runs in study["heat"].items():
        for k, r in enumerate(runs):
            order = f"{math.log2(runs[k - 1]['steady_relative_error'] / r['steady_relative_error']):.2f}" if k else "-"
            lines.append(f"| {name} | {r['nr']} x {r['nt']} x {r['nz']} | {r['steady_relative_error']:.2e} | {order} |")
    return lines


def predict(runs, single, cores=64):
    """The weak sequence's iterations extrapolated to `cores` subdomains, and the time a rank would
    take there: each rank's work as in the two-rank run (its operator setup, and its solve's time per
    iteration times the iterations), communication and the coarse solve left out; the efficiency
    against `single`, one rank's time on one subdomain (one level's: no coarse space). One level: the
    iterations' growth per doubling of the subdomains (geometric, from the last two counts); two
    levels: a line in log2 of the subdomains through every count beyond one rank (least squares)."""
    chain = [r for r in runs["weak"] + runs["oversubscribed_weak"] if r["ranks"] > 1]
    xs = [math.log2(r["ranks"]) for r in chain]
    its = [r["iterations"] for r in chain]
    if chain[0]["geneo"]:
        mean_x, mean_y = sum(xs) / len(xs), sum(its) / len(its)
        slope = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, its)) / sum((x - mean_x) ** 2 for x in xs)
        iterations = mean_y + slope * (math.log2(cores) - mean_x)
        law = f"about {slope:.0f} more a doubling"
    else:
        growth = its[-1] / its[-2]
        iterations = its[-1] * growth ** (math.log2(cores) - xs[-1])
        law = f"x {growth:.2f} a doubling"
    two = chain[0]
    seconds = two["seconds_decomposition"] + two["seconds_operator"] + two["seconds_solve"] / two["iterations"] * iterations
    return {"iterations": iterations, "law": law, "seconds": seconds,
            "efficiency": single / seconds}


def write_doc(results):
    """docs/benchmarks/ffddm-sleeve-3d.md from measure()'s results."""
    methods = results["methods"]
    base = methods["one level"]["strong"][0]
    lines = ["# The 3D sleeve's mechanics on ffddm (MPI)", "",
             f"Written by tools/bench/ffddm_scaling.py (make bench) on {results['date']}, {results['cores']} cores. The "
             "quarter ring of sleeve-3d loaded by a uniform phase stress without contact (tools/bench/ffddm_sleeve_3d.edp): "
             "its exact solution is the free dilatation, which P1 holds, so the error is the solver's. FreeFEM's ffddm, "
             "overlapping Schwarz (RAS, overlap 1) and GMRES at a relative residual of 1e-8, the local factorisations "
             "UMFPACK; with one level, and with two: GenEO's coarse space (ffddm's defaults: up to 20 eigenvectors a "
             "subdomain, those under the threshold 0.5; also 40). GenEO's coarse problem is factorised on one rank by the "
             "solver ffddm names \"MUMPS\", which Debian's FreeFEM 4.11 does not ship: plugin/ffddm/MUMPS_mpi.cpp stands "
             "in with UMFPACK on that one rank (ffddm's default, -ffddm_master_p 1) and refuses a coarse problem spread "
             "over more.",
             "", f"Strong scaling ({base['dofs']} dofs, nr {base['nr']} x nt {base['nt']} x nz {base['nz']}):", "",
             "| method | ranks | coarse space | GMRES iterations | error | operator (s) | solve (s) | total (s) | speed-up |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name, runs in methods.items():
        if "strong" not in runs:
            continue
        first = runs["strong"][0]
        for r in runs["strong"]:
            lines.append(f"| {name} | {r['ranks']} | {r['coarse_space']} | {r['iterations']} | {r['relative_error']:.1e} | "
                         f"{r['seconds_operator']:.2f} | {r['seconds_solve']:.2f} | {r['seconds_total']:.2f} | "
                         f"{first['seconds_total'] / r['seconds_total']:.2f} |")
    lines += ["", f"The sequential direct solve of the same operator (UMFPACK, one rank): {base['seconds_direct']:.2f} s, "
              f"error {base['direct_relative_error']:.1e}. GenEO's operator time holds its local eigenproblems: on one "
              "rank they are wasted (one subdomain needs no coarse space).", "",
              "Weak scaling (the layers along z with the ranks: a chain of subdomains along the sleeve; the efficiency "
              "against one rank's one-level run, a single subdomain needing no coarse space):", "",
              "| method | ranks | dofs | coarse space | GMRES iterations | error | total (s) | efficiency |",
              "|---|---|---|---|---|---|---|---|"]
    for name, runs in methods.items():
        for r in runs["weak"]:
            lines.append(f"| {name} | {r['ranks']} | {r['dofs']} | {r['coarse_space']} | {r['iterations']} | "
                         f"{r['relative_error']:.1e} | {r['seconds_total']:.2f} | "
                         f"{methods['one level']['weak'][0]['seconds_total'] / r['seconds_total']:.2f} |")

    def counts(runs):
        return ", ".join(f"{r['iterations']} on {r['ranks']}" for r in runs if r["ranks"] > 1)

    every = [r for runs in methods.values() for key in runs for r in runs[key]]
    more = ["", "More subdomains than cores (their iterations are the method's, their times mean nothing here), GMRES "
            "iterations on the same mesh:"]
    more += [f"{name} {counts(runs['strong'] + runs['oversubscribed'])};" for name, runs in methods.items()
             if "strong" in runs]
    more += ["on the weak sequence (nz times the ranks):"]
    for name, runs in methods.items():
        last = runs["oversubscribed_weak"][-1]
        saturated = last["geneo"] and last["coarse_space"] == last["geneo_nu"] * last["ranks"]
        more.append(f"{name} {counts(runs['weak'] + runs['oversubscribed_weak'])}"
                    + (f" (coarse space {last['coarse_space']} at {last['ranks']}"
                       + (f": every subdomain gave its {last['geneo_nu']} vectors, all under the threshold" if saturated else "")
                       + ")" if last["geneo"] else "") + ";")
    more.append(f"every error at most {max(r['relative_error'] for r in every):.1e}.")
    lines += ["", " ".join(more[1:])]
    single = methods["one level"]["weak"][0]["seconds_total"]
    forecasts = {name: predict(runs, single) for name, runs in methods.items()}
    lines += ["", "What this predicts for 64 cores (tools/bench/ffddm_scaling.py `predict`: the weak sequence's "
              "iterations extrapolated, each rank's work as in the two-rank run, communication and the coarse solve left "
              "out; a model, not a measurement beyond 2 cores):", "",
              "| method | iterations' growth | iterations at 64 | time at 64 (s) | weak efficiency at 64 |", "|---|---|---|---|---|"]
    for name, f in forecasts.items():
        lines.append(f"| {name} | {f['law']} | {f['iterations']:.0f} | {f['seconds']:.1f} | {f['efficiency']:.2f} |")
    lines += ["", "One level does not scale: its iterations multiply with every doubling. GenEO's grow by a fixed number a "
              "doubling on this chain of thin slabs (a thin-walled ring has many soft modes a subdomain, and the "
              "default 20 vectors a subdomain are all used), so it scales with a falling efficiency; more vectors a "
              "subdomain lower the count at a higher setup cost. The sleeve's own models fit one process (sleeve-3d's "
              "bound, 2e5 cells)."]
    if "contact_heat" in results:
        lines += contact_heat_lines(results["contact_heat"])
    if "scene" in results:
        lines += scene_lines(results["scene"])
    lines.append("")
    path = os.path.join(ROOT, "docs", "benchmarks", "ffddm-sleeve-3d.md")
    with open(path, "w") as f:
        f.write(wrap("\n".join(lines)))
    print(f"wrote {os.path.relpath(path, ROOT)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nr", type=int, default=4)
    parser.add_argument("--nt", type=int, default=16)
    parser.add_argument("--nz", type=int, default=60)
    parser.add_argument("--doc-only", action="store_true",
                        help="rewrite the page from the last results/bench/ffddm-sleeve-3d.json, running nothing")
    parser.add_argument("--contact-heat-only", action="store_true",
                        help="run only the contact's and the heat's study into the last results, then the page")
    parser.add_argument("--scene-only", action="store_true",
                        help="run only sleeve-3d sequentially and on ranks into the last results, then the page")
    opts = parser.parse_args()
    if opts.doc_only or opts.contact_heat_only or opts.scene_only:
        with open(os.path.join(ROOT, "results", "bench", "ffddm-sleeve-3d.json")) as f:
            results = json.load(f)
        if opts.contact_heat_only:
            results["contact_heat"] = measure_contact_heat()
        if opts.scene_only:
            results["scene"] = measure_scene()
        if opts.contact_heat_only or opts.scene_only:
            save(results)
        write_doc(results)
    else:
        write_doc(measure(opts.nr, opts.nt, opts.nz))


if __name__ == "__main__":
    main()
