"""make bench, sections 6 and 6b (tools/bench/bench.py): the Lame ring (edp/scenes/ring-lame.edp):
pressure error against time per mesh level; the same against GetFEM on the same meshes
(tools/bench/oracles/getfem_lame.py: agreement, time to error). figure() and doc() draw and write
their part of docs/benchmarks.md."""
import csv
import json
import os
import subprocess
import sys
import time

from common import OUT, QUICK, TOOLS, run, save

GETFEM_LAME = os.path.join(TOOLS, "bench", "oracles", "getfem_lame.py")
BENCH_TARGETS = (1e-3, 1e-4, 1e-5)
# GetFEM's runs in the bench: (label, options); P1 is ours to rounding, the P2 ones GetFEM only.
BENCH_ELEMENTS = (("P1", []), ("P2 straight", ["--order", "2"]),
                  ("P2 curved", ["--order", "2", "--geometry", "curved"]))


def measure(results):
    """ring-lame in both PSOR modes, and against GetFEM, into `results`."""
    lame_rows = []
    for mode in ("condensed", "full"):
        print(f"bench: ring-lame {mode}", flush=True)
        wall, s, failure = run("edp/scenes/ring-lame.edp", os.path.join(OUT, f"lame-{mode}"),
                               "-psormode", mode, *(["-levels", "l1 l2"] if QUICK else []),
                               allow_failure=True)
        for level in (s or {}).get("levels", []):
            lame_rows.append({"mode": mode, "level": level["name"], "nodes": level["nodes"],
                              "rel_error": level["rel_error"], "wall_seconds": level["wall_seconds"],
                              "psor_sweeps": level["psor_iterations"]})
    results["lame"] = lame_rows
    for target in (1e-3, 1e-4):
        ok = [r for r in lame_rows if r["mode"] == "condensed" and r["rel_error"] <= target]
        results[f"lame_seconds_to_{target:g}_error"] = min(r["wall_seconds"] for r in ok) if ok else None

    print("bench: ring-lame against GetFEM", flush=True)
    results["getfem_lame"] = bench(run, os.path.join(OUT, "getfem-lame"), QUICK)


def ours_pressure(out, level):
    """ring-lame's mean pressure from its pressure-<level>.csv, to the CSV's 15 digits (the
    summary's has 12): total normal force over total tributary length, as the scene computes it."""
    with open(os.path.join(out, f"pressure-{level}.csv")) as f:
        rows = list(csv.DictReader(f))
    return sum(float(r["normal_force"]) for r in rows) / sum(float(r["tributary_length"]) for r in rows)


def run_getfem(out_json, levels, options):
    """One GetFEM process over `levels`; returns (process wall seconds, its JSON)."""
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, GETFEM_LAME, "--levels", levels, "--json",
                           out_json, *options], capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit(f"bench: tools/bench/oracles/getfem_lame.py --levels '{levels}' {' '.join(options)} failed: "
                 f"{(proc.stderr or proc.stdout).strip().splitlines()[-1:]}")
    with open(out_json) as f:
        return wall, json.load(f)


def time_to_error(rows, key):
    """For each target, the `key` time of the coarsest level (rows from coarse to fine) whose error
    is within it, with that level's name (None: no level reaches it)."""
    result = {}
    for target in BENCH_TARGETS:
        first = next((r for r in rows if r["rel_error"] <= target), None)
        result[f"{target:g}"] = {"seconds": first[key], "level": first["name"]} if first else None
    return result


def bench(run, out, quick):
    """ring-lame (condensed PSOR, P1) against GetFEM on the same meshes: per level, the pressure
    agreement, the error against Lame, the solve time (least of `repeats` processes) and the
    process time (one process per level, least of `repeats`); the time to each error target.
    `run` is tools/bench/bench.py's (tools/ff script -out dir args)."""
    try:
        import getfem  # noqa: F401
    except ImportError:
        return {"skipped": "python3-getfem is not installed (tools/install-deps.sh installs it)"}
    levels = ["l1", "l2"] if quick else ["l1", "l2", "l3", "l4"]
    repeats = 1 if quick else 3
    os.makedirs(out, exist_ok=True)
    version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "python3-getfem"],
                             capture_output=True, text=True).stdout.strip()
    # Solve times: every level in one process, `repeats` processes, the least per level.
    ours = {}
    for k in range(repeats):
        ours_dir = os.path.join(out, f"ours-{k}")
        _, summary, _ = run("edp/scenes/ring-lame.edp", ours_dir, "-levels", " ".join(levels), "-quiet", 1)
        for level in summary["levels"]:
            row = ours.setdefault(level["name"], {**level, "pressure_mean": ours_pressure(ours_dir, level["name"])})
            row["solve_seconds"] = min(row["solve_seconds"], level["solve_seconds"])
    theirs = {}
    for label, options in BENCH_ELEMENTS:
        for k in range(repeats):
            _, result = run_getfem(os.path.join(out, f"getfem-{label.replace(' ', '-')}-{k}.json"),
                                   " ".join(levels), options)
            for level in result["levels"]:
                row = theirs.setdefault((label, level["name"]), level)
                row["solve_seconds"] = min(row["solve_seconds"], level["solve_seconds"])
    _, obstacle = run_getfem(os.path.join(out, "getfem-obstacle.json"), " ".join(levels), ["--contact", "obstacle"])
    obstacle = {lv["name"]: lv["pressure_mean"] for lv in obstacle["levels"]}
    # Process times: one level per process.
    for level in levels:
        walls = [run("edp/scenes/ring-lame.edp", os.path.join(out, f"ours-{level}"), "-levels", level,
                     "-quiet", 1)[0] for _ in range(repeats)]
        ours[level]["process_seconds"] = min(walls)
        walls = [run_getfem(os.path.join(out, f"getfem-{level}.json"), level, [])[0] for _ in range(repeats)]
        theirs[("P1", level)]["process_seconds"] = min(walls)
    rows = []
    for level in levels:
        o, g = ours[level], theirs[("P1", level)]
        rows.append({"name": level, "nodes": o["nodes"], "contact_nodes": o["contact_nodes"],
                     "ours_pressure": o["pressure_mean"], "getfem_pressure": g["pressure_mean"],
                     "agreement": abs(g["pressure_mean"] - o["pressure_mean"]) / o["pressure_mean"],
                     "agreement_obstacle_brick": abs(obstacle[level] - o["pressure_mean"]) / o["pressure_mean"],
                     "ours_rel_error": o["rel_error"], "getfem_rel_error": g["rel_error"],
                     "ours_solve_seconds": o["solve_seconds"], "getfem_solve_seconds": g["solve_seconds"],
                     "ours_process_seconds": o["process_seconds"], "getfem_process_seconds": g["process_seconds"],
                     "psor_sweeps": o["psor_iterations"], "newton_iterations": g["newton_iterations"]})
    ours_rows = [{"name": r["name"], "rel_error": r["ours_rel_error"], "solve": r["ours_solve_seconds"],
                  "process": r["ours_process_seconds"]} for r in rows]
    getfem_rows = {label: [{"name": lv, "nodes": theirs[(label, lv)]["nodes"],
                            "contact_nodes": theirs[(label, lv)]["contact_nodes"],
                            "rel_error": theirs[(label, lv)]["rel_error"],
                            "solve": theirs[(label, lv)]["solve_seconds"],
                            **({"process": theirs[(label, lv)]["process_seconds"]} if label == "P1" else {})}
                           for lv in levels]
                   for label, _ in BENCH_ELEMENTS}
    times = {"ours P1": {"solve": time_to_error(ours_rows, "solve"), "process": time_to_error(ours_rows, "process")}}
    for label, _ in BENCH_ELEMENTS:
        times[f"GetFEM {label}"] = {"solve": time_to_error(getfem_rows[label], "solve")}
    times["GetFEM P1"]["process"] = time_to_error(getfem_rows["P1"], "process")
    return {"getfem_version": version, "repeats": repeats, "levels": rows, "getfem_elements": getfem_rows,
            "time_to_error": times}


def doc_lines(r):
    """docs/benchmarks.md's lines of the comparison with GetFEM (bench's result `r`)."""
    w = ["### Against GetFEM (ring-lame, same meshes, same problem)", ""]
    if "skipped" in r:
        return w + [f"Not measured: {r['skipped']}.", ""]
    w += [f"GetFEM {r['getfem_version']} (python3-getfem) solves the same discrete problem "
          "(tools/bench/oracles/getfem_lame.py): the meshes meshes/ring-l*.msh, P1 plane strain, the symmetry supports "
          "on the two cuts, frictionless Signorini contact of the inner-surface nodes with the pipe along "
          "its radial normal, by its semi-smooth Newton (Alart-Curnier, MUMPS); ours is ring-lame with its "
          "defaults (condensed PSOR on the Delassus operator, active-set polish). Metric: the mean contact "
          "pressure (total normal force / length of the inner surface, ring-lame's summary "
          "`pressure_mean`), its relative error against Lame's closed form (tools/bench/oracles/lame.py). "
          "Solve time: after the mesh is read, the finite element space, assembly, factorisation, contact "
          "operator (ours: the Delassus operator, from sparse forward solves of the plugin's LDL' factor), solve and mean pressure "
          "(ring-lame's `solve_seconds`; getfem_lame.py's `solve_seconds`); process: the whole run of one "
          f"level (FreeFEM or Python start, mesh reading included); each the least of {r['repeats']} run(s).", ""]
    w += ["| level | nodes | contact nodes | error (ours) | error (GetFEM) | agreement | agreement (obstacle brick) "
          "| solve ours (ms) | solve GetFEM (ms) | ours / GetFEM | process ours (s) | process GetFEM (s) |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for x in r["levels"]:
        w.append(f"| {x['name']} | {x['nodes']} | {x['contact_nodes']} | {x['ours_rel_error']:.3e} | "
                 f"{x['getfem_rel_error']:.3e} | {x['agreement']:.1e} | {x['agreement_obstacle_brick']:.1e} | "
                 f"{1e3 * x['ours_solve_seconds']:.1f} | {1e3 * x['getfem_solve_seconds']:.1f} | "
                 f"{x['ours_solve_seconds'] / x['getfem_solve_seconds']:.1f} | {x['ours_process_seconds']:.2f} | "
                 f"{x['getfem_process_seconds']:.2f} |")
    w += ["", "Agreement: |p(GetFEM) - p(ours)| / p(ours), ours to the 15 digits of pressure-<level>.csv. "
          "GetFEM's nodal contact with rigid obstacle brick differs only by its normal (a finite difference "
          "of the signed distance, about 1e-5 rad off radial): the last column.", ""]
    w += ["Time to a pressure error: the solve time (ms) of the coarsest level whose error is within the "
          f"target (that level in brackets; -: none of {', '.join(x['name'] for x in r['levels'])} reaches it):", "",
          "| error <= | ours P1 | GetFEM P1 | ours / GetFEM | GetFEM P2 straight | GetFEM P2 curved |", "|---|---|---|---|---|---|"]
    t = r["time_to_error"]
    def cell(entry):
        return f"{1e3 * entry['seconds']:.1f} ({entry['level']})" if entry else "-"
    for target in BENCH_TARGETS:
        key = f"{target:g}"
        ours, gf1 = t["ours P1"]["solve"][key], t["GetFEM P1"]["solve"][key]
        ratio = f"{ours['seconds'] / gf1['seconds']:.1f}" if ours and gf1 else "-"
        w.append(f"| {key} | {cell(ours)} | {cell(gf1)} | {ratio} | {cell(t['GetFEM P2 straight']['solve'][key])} | "
                 f"{cell(t['GetFEM P2 curved']['solve'][key])} |")
    process = [(f"{target:g}", t["ours P1"]["process"][f"{target:g}"], t["GetFEM P1"]["process"][f"{target:g}"])
               for target in BENCH_TARGETS]
    w += ["", "The same with the whole process, one level per run (s): " + "; ".join(
        f"error <= {key}: ours {o['seconds']:.2f} ({o['level']}), GetFEM {g['seconds']:.2f} ({g['level']})"
        for key, o, g in process if o and g) + "."]
    w += ["", "P2 straight: P2 on the same straight-sided triangles (what FreeFEM offers), the mid-edge nodes' "
          "gap their vertices' (the ring's interference); its error is the polygonal boundary's, O(h^2). "
          "P2 curved: isoparametric P2 (the arcs' mid-edge nodes on the circles; GetFEM's GT_PK(2,2)), "
          "O(h^4). Errors: "
          + "; ".join(f"{label} " + ", ".join(f"{x['rel_error']:.1e}" for x in rows)
                      for label, rows in r["getfem_elements"].items()) + "."]
    # Each level halves h: P2 on a level has the nodes (and dofs) of P1 on the next one.
    p1, p2 = r["getfem_elements"]["P1"], r["getfem_elements"]["P2 straight"]
    pairs = [f"P2 {a['name']} {a['rel_error']:.1e} against P1 {b['name']} {b['rel_error']:.1e}"
             for a, b in zip(p2, p1[1:])]
    if pairs:
        w += ["", "P2 on straight triangles gains little at equal dofs (P2 on a level has the nodes of P1 on "
              "the next): " + "; ".join(pairs) + ". GetFEM's gain is the isoparametric one, curved "
              "elements, which FreeFEM's 2D meshes do not have."]
    return w + [""]




def figure(r, plt):
    """lame.png; returns {"lame": its path from docs/}."""
    pngs = {}
    # Lame.
    fig, ax = plt.subplots(figsize=(5, 4))
    for mode in ("condensed", "full"):
        rows = [x for x in r["lame"] if x["mode"] == mode]
        if rows:
            ax.loglog([x["wall_seconds"] for x in rows], [x["rel_error"] for x in rows], "o-", label=mode)
            for x in rows:
                ax.annotate(x["level"], (x["wall_seconds"], x["rel_error"]), fontsize=7)
    ax.set(xlabel="wall time (s: mesh, assembly, factorisation, solve)", ylabel="pressure error vs Lame")
    ax.legend(fontsize=8)
    pngs["lame"] = save(fig, "lame.png")
    return pngs


def doc(r, w, pngs):
    """Lame ring: time to a given pressure error, and against GetFEM."""
    w("## Lame ring: time to a given pressure error")
    w("")
    w(f"![Lame]({pngs['lame']})")
    w("")
    w("| mode | level | nodes | pressure error | wall (s) | PSOR sweeps |")
    w("|---|---|---|---|---|---|")
    for x in r["lame"]:
        w(f"| {x['mode']} | {x['level']} | {x['nodes']} | {x['rel_error']:.2e} | {x['wall_seconds']:.3f} | {x['psor_sweeps']} |")
    w("")
    for target in (1e-3, 1e-4):
        t = r.get(f"lame_seconds_to_{target:g}_error")
        w(f"- error <= {target:g}: " + (f"{t:.3f} s (condensed)" if t is not None else "not reached"))
    w("")
    for line in doc_lines(r["getfem_lame"]):
        w(line)
