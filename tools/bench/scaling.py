#!/usr/bin/python3
"""The cost of sleeve-circular against the mesh size (issue 16), a section of make bench.

sleeve-circular on the structured quarter rings of meshes/ring.geo (nr layers, 5 nr arc segments:
the default scene's kind of mesh) from 1 729 to 98 841 nodes. For each size, two processes:
  A. 150 steps of 1 s (-steps 150 -tend 150) with a checkpoint after step 30, stopped there
     (-checkpoint 30 -stopafter 30: exit 4): the transient (austenite for good from step 17);
  B. the same run resumed (-resume 1 -checkpoint 0: no more checkpoints written, they are not part
     of the loop measured), REPEATS times from the same checkpoint in rounds over the sizes (a drift
     of the machine's speed then falls on every size alike), medians taken: steps 31-150, the
     transient-free part, where every step
     takes 1 fixed-point iteration, 1 DC iteration and 1 PSOR sweep whatever the mesh. B is timed:
     its loop (summary.json wall_seconds) per step and per DC iteration, its peak memory (max RSS,
     /usr/bin/time -f %M), its setup (process wall time minus loop: FreeFEM start, mesh, assembly,
     factorisations, the Delassus operator, the checkpoint read).
The iteration counts of the timed steps are read from history.csv and reported per size; the
transient's DC iterations and its approximate loop time (A's process time minus B's setup) too.
Least-squares exponents (log-log) of ms/step, ms per DC iteration, memory (max RSS, and max RSS
above FreeFEM's own: the scene's -help run, which loads the plugin and parses every script but
builds nothing) and setup time against the node count.

Sizes above NODE_LIMIT are listed as skipped. (Before the contact solver dropped its dense
G = K^-1 Hn', N x m doubles, 1.1 GB at nr 140, the limit was 40 000 nodes.)

bench.py calls scaling() from main() and section() / goals() from write_doc(); alone:
  tools/bench/scaling.py [--quick]    (writes results/bench-scaling/summary.json and prints the table)
"""
import csv
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

from common import run_alone, without_companion

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = "edp/scenes/sleeve-circular.edp"

# (layers, mesh): the structured quarter rings, 5 nr arc segments, (nr + 1) (5 nr + 1) nodes.
# nr 72, 108 and 140 are written in millimetres (docs/parameters.md#mesh-units); make bench makes them.
SERIES = [(18, "meshes/sleeve-quarter.msh"), (36, "meshes/sleeve-nr36.msh"), (72, "meshes/sleeve-nr72.msh"),
          (108, "meshes/sleeve-nr108.msh"), (140, "meshes/sleeve-nr140.msh")]
QUICK_SERIES = [(6, "meshes/sleeve-coarse.msh"), (9, "meshes/sleeve-nr9.msh")]
# Largest mesh run (the range: up to 100k nodes).
NODE_LIMIT = 100_000
STEPS = 150          # of 1 s each: the default run's 150 s at 10 times its step
CHECKPOINT = 30      # the transient is over by step 17 at every size measured (dt = 1 s)
QUICK_STEPS = 60
# B is run this many times from the same checkpoint, in rounds over the sizes, and the medians taken:
# a single 120-step loop at 1.7k nodes lasts about 0.1 s, and one run per size, size after size,
# gave fitted exponents from 0.96 to 1.14 on three make bench runs of the same code (the machine's
# speed drifts over minutes: 0.88 to 1.97 ms/step at nr 18).
REPEATS = 5
# -fpmaxit: the transient's heat <-> phase fixed point took at most 31, 60, 111 iterations at 18, 36,
# 72 layers (dt = 1 s), about 200 (the default limit) expected at 140; a limit only, nothing changes
# where the loop converges below it.
OPTIONS = ["-tend", "150", "-quiet", "1", "-vtkevery", "0", "-fpmaxit", "1000"]


def ring_nodes(nr):
    """Nodes of meshes/ring.geo's structured quarter ring of nr layers and 5 nr arc segments."""
    return (nr + 1) * (5 * nr + 1)


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def timed(args):
    """Runs tools/ff args under /usr/bin/time; returns (exit code, wall seconds, max RSS in MB, the
    error line or the output's last line)."""
    stats = os.path.join(ROOT, "results", ".bench-scaling-time")
    os.makedirs(os.path.dirname(stats), exist_ok=True)
    start = time.perf_counter()
    args = list(map(str, args))
    if any("/sleeve-" in a for a in args[:1]) and "-scale" not in args:
        args.append("-scale")  # the bench's reduced scale (docs/benchmarks.md)
        args.append("reduced")
    proc = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", stats, os.path.join(ROOT, "tools", "ff"),
                           *args, *without_companion(SCENE, args)], cwd=ROOT, capture_output=True, text=True)
    wall = time.perf_counter() - start
    rss_kb = int(open(stats).read().split()[-1])
    os.remove(stats)
    lines = (proc.stdout + "\n" + proc.stderr).splitlines()
    errors = [ln for ln in lines if ln.startswith("error:")]
    message = errors[-1] if errors else next((ln for ln in reversed(lines) if ln.strip()), "")
    return proc.returncode, wall, rss_kb / 1024, message


def history(path):
    with open(path) as f:
        return list(csv.DictReader(ln for ln in f if not ln.startswith("#")))


def iteration_stats(rows):
    """Sums, means and maxima of the loops' iteration counts over history.csv rows."""
    out = {}
    for key, name in (("fixed_point_iterations", "fixed_point"), ("dc_iterations", "dc"), ("psor_sweeps", "psor")):
        values = [float(r[key]) for r in rows]
        out[name] = {"sum": sum(values), "mean": sum(values) / len(values), "max": max(values)}
    return out


def run_transient(nr, mesh, out, steps):
    """Process A of the module docstring; returns (its record, the B arguments) or a failure row.
    A's folder is kept aside (out + ".after-transient"): a finished run removes its checkpoint, so
    each B starts from a copy."""
    args = [SCENE, "-mesh", mesh, "-steps", steps, *OPTIONS, "-out", out]
    code, wall_a, rss_a, msg = timed([*args, "-checkpoint", CHECKPOINT, "-stopafter", CHECKPOINT])
    if code != 4:
        return {"nr": nr, "mesh": mesh, "failure": f"transient run: exit {code}: {msg}"}
    saved = out + ".after-transient"
    shutil.rmtree(saved, ignore_errors=True)
    shutil.copytree(out, saved)
    # B resumes with -checkpoint 0: the checkpoints A needed are not part of the loop timed here
    # (at every 30th step they wrote the whole state: a quarter of the loop at nr 18).
    return {"nr": nr, "mesh": mesh, "out": out, "saved": saved, "wall_a": wall_a, "rss_a": rss_a,
            "args_b": [*args, "-checkpoint", 0, "-resume", 1], "runs": []}


def run_resumed(a):
    """One process B from A's checkpoint; appends (wall, max RSS, summary) to a["runs"]; returns the
    failure message or ""."""
    shutil.rmtree(a["out"])
    shutil.copytree(a["saved"], a["out"])
    code, wall_b, rss_b, msg = timed(a["args_b"])
    if code != 0:
        return f"resumed run: exit {code}: {msg}"
    a["runs"].append((wall_b, rss_b, json.load(open(os.path.join(a["out"], "summary.json")))))
    return ""


def row(a):
    """The table row of one size from its A and its B runs (medians of the B runs)."""
    nr, mesh, out, runs = a["nr"], a["mesh"], a["out"], a["runs"]
    loops = [r[2]["wall_seconds"] for r in runs]
    floors = [r[2]["backsolve_floor_seconds_per_step"] for r in runs]
    wall_a, rss_a = a["wall_a"], a["rss_a"]
    wall_b = statistics.median(r[0] for r in runs)
    rss_b = max(r[1] for r in runs)
    s = runs[-1][2]
    rows = history(os.path.join(out, "history.csv"))
    timed_rows = [r for r in rows if int(r["step"]) > CHECKPOINT]
    transient_rows = [r for r in rows if int(r["step"]) <= CHECKPOINT]
    its, its_transient = iteration_stats(timed_rows), iteration_stats(transient_rows)
    loop = statistics.median(loops)
    setup = wall_b - loop
    transient_loop = max(wall_a - setup, 0.0)
    return {"nr": nr, "mesh": mesh, "nodes": s["nodes"], "triangles": s["triangles"],
            "contact_nodes": s["contact_nodes"], "resumed_from_step": s.get("resumed_from_step"),
            "timed_steps": len(timed_rows), "loop_seconds": loop,
            "ms_per_step": 1e3 * loop / len(timed_rows), "ms_per_dc_iteration": 1e3 * loop / its["dc"]["sum"],
            "iterations": its, "peak_rss_MB": rss_b, "transient_peak_rss_MB": rss_a,
            "process_seconds": wall_b, "setup_seconds": setup,
            "transient_process_seconds": wall_a, "transient_loop_seconds_approx": transient_loop,
            "transient_iterations": its_transient,
            "transient_ms_per_dc_iteration_approx": 1e3 * transient_loop / its_transient["dc"]["sum"],
            # The whole run (issue 30: the transient included): A's loop (approx.) and B's, over all steps.
            "whole_ms_per_step": 1e3 * (transient_loop + loop) / (len(transient_rows) + len(timed_rows)),
            "whole_backsolves": its["dc"]["sum"] + its_transient["dc"]["sum"],
            "austenite_step": s["austenite_step"], "final_pressure_mean": s["final_pressure_mean"],
            # The floor: one stiffness and one heat back-solve (the scene times them after its loop).
            "floor_ms_per_step": 1e3 * statistics.median(floors),
            "loop_over_floor": loop / (len(timed_rows) * statistics.median(floors)),
            "repeats": len(runs), "loop_seconds_runs": loops}


def scaling(out_root, quick=False, node_limit=None):
    """Runs the series into out_root/scaling-nr<nr>/; returns the section's record."""
    limit = NODE_LIMIT if node_limit is None else node_limit
    series = QUICK_SERIES if quick else SERIES
    steps = QUICK_STEPS if quick else STEPS
    code, _, baseline, msg = timed([SCENE, "-help"])
    if code != 0:
        sys.exit(f"bench: {SCENE} -help failed: {msg}")
    rows = []
    for nr, mesh in series:
        nodes = ring_nodes(nr)
        if nodes > limit:
            print(f"bench: scaling, nr {nr} ({nodes} nodes): skipped, above the node limit {limit}", flush=True)
            rows.append({"nr": nr, "mesh": mesh, "nodes": nodes, "skipped": f"above the node limit {limit}"})
            continue
        print(f"bench: scaling, sleeve-circular nr {nr} ({nodes} nodes): the transient, steps 1-{CHECKPOINT}",
              flush=True)
        rows.append(run_transient(nr, mesh, os.path.join(out_root, f"scaling-nr{nr}"), steps))
        if "failure" in rows[-1]:
            print(f"bench: scaling, nr {nr}: {rows[-1]['failure']}", flush=True)
    # The timed runs in rounds over the sizes (each round runs every size once), so that a drift of
    # the machine's speed over the minutes of the series falls on every size alike.
    for k in range(REPEATS):
        print(f"bench: scaling, round {k + 1}/{REPEATS}: steps {CHECKPOINT + 1}-{steps} timed at every size",
              flush=True)
        for i, a in enumerate(rows):
            if "runs" in a:
                failure = run_resumed(a)
                if failure:
                    print(f"bench: scaling, nr {a['nr']}: {failure}", flush=True)
                    shutil.rmtree(a["saved"], ignore_errors=True)
                    rows[i] = {"nr": a["nr"], "mesh": a["mesh"], "failure": failure}
    for a in rows:
        if "saved" in a:
            shutil.rmtree(a["saved"], ignore_errors=True)
    rows = [row(a) if "runs" in a else a for a in rows]
    return summarise({"steps": steps, "checkpoint": CHECKPOINT, "dt_seconds": 150 / steps, "node_limit": limit,
                      "baseline_rss_MB": baseline, "repeats": REPEATS, "rows": rows})


def summarise(record):
    """Adds the exponents to a record of scaling()'s rows."""
    done = [r for r in record["rows"] if "ms_per_step" in r]
    baseline = record["baseline_rss_MB"]
    if len(done) >= 2:
        nodes = [r["nodes"] for r in done]
        record["exponents"] = {
            "ms_per_step": fit_exponent(nodes, [r["ms_per_step"] for r in done]),
            "ms_per_dc_iteration": fit_exponent(nodes, [r["ms_per_dc_iteration"] for r in done]),
            "whole_ms_per_step": fit_exponent(nodes, [r["whole_ms_per_step"] for r in done]),
            "whole_backsolves": fit_exponent(nodes, [r["whole_backsolves"] for r in done]),
            "floor_ms_per_step": fit_exponent(nodes, [r["floor_ms_per_step"] for r in done]),
            "peak_rss": fit_exponent(nodes, [r["peak_rss_MB"] for r in done]),
            "peak_rss_above_baseline": (fit_exponent(nodes, [r["peak_rss_MB"] - baseline for r in done])
                                        if all(r["peak_rss_MB"] > baseline for r in done) else None),
            "setup_seconds": fit_exponent(nodes, [r["setup_seconds"] for r in done]),
            # (None when a transient is too short to time apart from the setup: small meshes, --quick)
            "transient_ms_per_dc_iteration": (fit_exponent(nodes, [r["transient_ms_per_dc_iteration_approx"]
                                                                   for r in done])
                                              if all(r["transient_ms_per_dc_iteration_approx"] > 0 for r in done)
                                              else None)}
        # Between successive sizes: where the growth bends.
        record["successive_exponents"] = [
            {"nodes": [a["nodes"], b["nodes"]],
             "ms_per_step": math.log(b["ms_per_step"] / a["ms_per_step"]) / math.log(b["nodes"] / a["nodes"]),
             "peak_rss_above_baseline": (math.log((b["peak_rss_MB"] - baseline) / (a["peak_rss_MB"] - baseline))
                                         / math.log(b["nodes"] / a["nodes"])
                                         if min(a["peak_rss_MB"], b["peak_rss_MB"]) > baseline else None)}
            for a, b in zip(done, done[1:])]
        first = done[0]["iterations"]
        record["timed_iterations_equal"] = all(
            all(r["iterations"][k]["mean"] == first[k]["mean"] and r["iterations"][k]["max"] == first[k]["max"]
                for k in first) for r in done)
    return record


def goals(rec):
    """(goal, measured, met) rows for the Goals table of docs/benchmarks.md (issue 16)."""
    done = [r for r in rec["rows"] if "ms_per_step" in r]
    e = rec.get("exponents")
    if not e:
        return []
    span = f"{done[0]['nodes']}-{done[-1]['nodes']} nodes"
    reach = done[-1]["nodes"] >= 90_000
    skipped = [r for r in rec["rows"] if "skipped" in r]
    short = f"; only up to {done[-1]['nodes']} nodes (node limit {rec['node_limit']})" if not reach else ""
    mem = e["peak_rss_above_baseline"]
    return [("sleeve-circular: ms/step exponent <= 1.1 from 1.7k to 100k nodes",
             f"{e['ms_per_step']:.2f} over {span}" + short + (f", {len(skipped)} size(s) skipped" if skipped else "")
             + f" (its floor, one stiffness and one heat back-solve: {e['floor_ms_per_step']:.2f}; loop over floor "
             f"{done[0]['loop_over_floor']:.1f} to {done[-1]['loop_over_floor']:.1f}; between the two largest sizes "
             f"{rec['successive_exponents'][-1]['ms_per_step']:.2f})",
             reach and e["ms_per_step"] <= 1.1),
            ("sleeve-circular: ms/step exponent of the whole run (the transient included) <= 1.15 from 1.7k to "
             "100k nodes",
             f"{e['whole_ms_per_step']:.2f} over {span}" + short + " (the step solver's back-solves over the run grow "
             f"as N^{e['whole_backsolves']:.2f}: {done[0]['whole_backsolves']:.0f} to {done[-1]['whole_backsolves']:.0f}; "
             f"each back-solve as N^{e['floor_ms_per_step']:.2f})",
             reach and e["whole_ms_per_step"] <= 1.15),
            ("sleeve-circular: memory linear in the node count (exponent <= 1.1, above FreeFEM's own)",
             (f"{mem:.2f}" if mem is not None else "n/a") + f" over {span} (peak RSS {done[-1]['peak_rss_MB']:.0f} MB "
             f"at {done[-1]['nodes']} nodes; total RSS exponent {e['peak_rss']:.2f})" + short,
             reach and mem is not None and mem <= 1.1)]


def section(rec, plt, save):
    """The Markdown lines of the section (save(fig, name) -> the PNG's path relative to docs/)."""
    done = [r for r in rec["rows"] if "ms_per_step" in r]
    lines = ["## Scaling with the mesh size", ""]
    w = lines.append
    if len(done) >= 2:
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        n = [r["nodes"] for r in done]
        axes[0].loglog(n, [r["ms_per_step"] for r in done], "o-", label="ms per step (transient-free)")
        axes[0].loglog(n, [r["whole_ms_per_step"] for r in done], "D-", label="ms per step (whole run, transient included)")
        axes[0].loglog(n, [r["floor_ms_per_step"] for r in done], "x-", label="floor: one stiffness + one heat back-solve")
        axes[0].loglog(n, [r["transient_ms_per_dc_iteration_approx"] for r in done], "s--",
                       label="ms per DC iteration (transient, approx.)")
        axes[0].loglog(n, [1e3 * r["setup_seconds"] for r in done], "^:", label="setup (ms)")
        axes[0].loglog(n, [done[0]["ms_per_step"] * x / n[0] for x in n], color="grey", lw=0.8, label="slope 1")
        axes[0].set(xlabel="nodes", ylabel="ms")
        axes[0].legend(fontsize=7)
        axes[1].loglog(n, [r["peak_rss_MB"] for r in done], "o-", label="peak RSS")
        axes[1].loglog(n, [r["peak_rss_MB"] - rec["baseline_rss_MB"] for r in done], "s--",
                       label=f"above FreeFEM's own ({rec['baseline_rss_MB']:.0f} MB)")
        axes[1].set(xlabel="nodes", ylabel="MB")
        axes[1].legend(fontsize=7)
        w(f"![scaling]({save(fig, 'scaling.png')})")
        w("")
    w(f"sleeve-circular on the structured quarter rings (nr layers x 5 nr arc segments), {rec['steps']} steps of "
      f"{rec['dt_seconds']:g} s: a run stopped with a checkpoint after step {rec['checkpoint']} (the transient), "
      f"then resumed and timed over steps {rec['checkpoint'] + 1}-{rec['steps']}, the transient-free part "
      "(tools/bench/scaling.py; docs/parameters.md#scaling-benchmark-toolsbenchscalingpy). ms/step and ms per DC "
      f"iteration: the resumed loop (summary.json wall_seconds, median of {done[0].get('repeats', 1) if done else 1} "
      "resumed runs from the same checkpoint) over its steps and its DC iterations; memory: the "
      "resumed process's max RSS (/usr/bin/time -f %M); setup: its wall time minus its loop. The transient's "
      "ms per DC iteration is approximate (the stopped process's time minus the setup).")
    w("")
    w("*Whole run*: the transient's loop (the stopped process's time minus the setup) and the resumed loop over "
      "all the steps; its back-solves: the stiffness back-solves of the whole run (the step solver's evaluations "
      "and linearised products, one each).")
    w("")
    w("| nr | nodes | ms/step | whole run: ms/step, back-solves | floor (ms) | loop / floor | ms/DC iteration | "
      "iterations per timed step fp / DC / PSOR (max) | peak RSS (MB) | setup (s) | transient: DC iterations, ms each (approx.) |")
    w("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rec["rows"]:
        if "skipped" in r:
            w(f"| {r['nr']} | {r['nodes']} | skipped: {r['skipped']} | | | | | | | | |")
        elif "failure" in r:
            w(f"| {r['nr']} | | failed: {r['failure']} | | | | | | | | |")
        else:
            i, t = r["iterations"], r["transient_iterations"]
            w(f"| {r['nr']} | {r['nodes']} | {r['ms_per_step']:.2f} | {r['whole_ms_per_step']:.2f}, "
              f"{r['whole_backsolves']:.0f} | {r['floor_ms_per_step']:.2f} | "
              f"{r['loop_over_floor']:.2f} | {r['ms_per_dc_iteration']:.2f} | "
              f"{i['fixed_point']['mean']:.2f} / {i['dc']['mean']:.2f} / {i['psor']['mean']:.1f} "
              f"({i['fixed_point']['max']:.0f} / {i['dc']['max']:.0f} / {i['psor']['max']:.0f}) | "
              f"{r['peak_rss_MB']:.0f} | {r['setup_seconds']:.2f} | {t['dc']['sum']:.0f}, "
              f"{r['transient_ms_per_dc_iteration_approx']:.2f} |")
    w("")
    e = rec.get("exponents")
    if e:
        mem = e["peak_rss_above_baseline"]
        w(f"Least-squares exponents against the node count: ms/step **{e['ms_per_step']:.2f}** (the whole run, "
          f"transient included: **{e['whole_ms_per_step']:.2f}**; its back-solves {e['whole_backsolves']:.2f}), its floor "
          f"{e['floor_ms_per_step']:.2f} (the floor is the scene's own back-solves, timed after its loop: a "
          "sparse LDL' with AMD ordering, whose factor grows as N log N on these meshes), ms per DC "
          f"iteration {e['ms_per_dc_iteration']:.2f}, peak RSS {e['peak_rss']:.2f} (above FreeFEM's own "
          f"{rec['baseline_rss_MB']:.0f} MB: **" + (f"{mem:.2f}" if mem is not None else "n/a") + "**), setup "
          f"{e['setup_seconds']:.2f}, ms per DC iteration in the transient "
          + (f"{e['transient_ms_per_dc_iteration']:.2f}" if e["transient_ms_per_dc_iteration"] is not None else "n/a")
          + ". "
          "Between successive sizes, ms/step and memory above FreeFEM's own: "
          + "; ".join(f"{x['nodes'][0]}-{x['nodes'][1]}: {x['ms_per_step']:.2f}, "
                      + (f"{x['peak_rss_above_baseline']:.2f}" if x["peak_rss_above_baseline"] is not None else "n/a")
                      for x in rec["successive_exponents"])
          + ". Iteration counts per timed step "
          + ("equal at every size." if rec["timed_iterations_equal"] else "NOT equal across sizes (see the table)."))
        w("")
        top = rec["successive_exponents"][-1]
        rest = [(r["nodes"], r["ms_per_step"] - r["floor_ms_per_step"]) for r in done
                if r["ms_per_step"] > r["floor_ms_per_step"]]
        rest_exponent = fit_exponent([n for n, _ in rest], [t for _, t in rest]) if len(rest) >= 2 else None
        w(f"Reading: the fitted ms/step exponent lies below its floor's because at the small sizes the loop is mostly "
          f"the rest of the step (the scripts, the sparse products, the contact sweeps), which grows more slowly "
          + (f"(ms/step minus floor: exponent {rest_exponent:.2f}; " if rest_exponent is not None else "(")
          + f"loop over floor {done[0]['loop_over_floor']:.1f} "
          f"at {done[0]['nodes']} nodes, {done[-1]['loop_over_floor']:.1f} at {done[-1]['nodes']}). As the back-solves "
          f"take over, the local exponent rises towards the floor's ({top['ms_per_step']:.2f} between "
          f"{top['nodes'][0]} and {top['nodes'][1]} nodes): above about 100k nodes the sparse LDL' (its "
          f"back-solve N^{e['floor_ms_per_step']:.2f} here) sets the slope, and staying linear would take a solver "
          "whose cost grows as N (multigrid-preconditioned CG, say).")
        w("")
    return lines


def main():
    rec = run_alone("scaling", scaling, section)
    for text, value, ok in goals(rec):
        print(f"goal: {text}: {value}: {'met' if ok else 'not met'}")


if __name__ == "__main__":
    main()
