"""make bench, section 2 (tools/bench/bench.py): the work-precision grid: sleeve-circular on 5
structured meshes x 4 step counts, the error of the force-temperature curve against the radial
reference (tools/bench/oracles/curve_error.py, relative L1 in time) and of the final pressure against
Lame's closed form, versus wall time; the same curve from sleeve-radial; the cost per step against
the nodes. figures() and doc() draw and write their part of docs/benchmarks.md."""
import os

from common import FINE_FPMAXIT, OUT, QUICK, fit_exponent, run, save
from curve_error import curve_error
from lame import lame_pressure

# Structured quarter rings of meshes/ring.geo: nr layers through the thickness, 5 nr along the arc.
MESH_LEVELS = [(6, "meshes/sleeve-coarse.msh"), (9, "meshes/sleeve-nr9.msh"),
               (12, "meshes/sleeve-nr12.msh"), (18, "meshes/sleeve-quarter.msh"),
               (27, "meshes/sleeve-nr27.msh")]
STEP_COUNTS = [375, 750, 1500, 3000]
# The radial model (sleeve-radial): elements in r x steps. Below about two elements of heat
# diffusion per step the reverting layer flips phase every step (docs/parameters.md, sleeve-radial).
RADIAL_NR = [10, 20, 40, 80, 160]
RADIAL_STEPS = [1500, 3000, 6000]
if QUICK:
    MESH_LEVELS = MESH_LEVELS[:2]
    STEP_COUNTS = [150, 300]
    RADIAL_NR = [10, 20]
    RADIAL_STEPS = [750, 1500]


def measure(results, reference):
    """The grid, the radial model's and the cost per step, into `results`."""
    grid = []
    for nr, mesh in MESH_LEVELS:
        for steps in STEP_COUNTS:
            print(f"bench: sleeve-circular nr {nr} steps {steps}", flush=True)
            out = os.path.join(OUT, f"circular-nr{nr}-steps{steps}")
            wall, s, _ = run("edp/scenes/sleeve-circular.edp", out, "-mesh", mesh, "-steps", steps,
                             "-quiet", 1)
            err = curve_error(os.path.join(out, "history.csv"), reference)
            p = s["parameters"]
            lame = lame_pressure(p["E"], p["nu"], p["ring_inner_radius"], p["ring_inner_radius"] + 0.01,
                                 p["pipe_A"] - p["ring_inner_radius"], p["plane"])
            grid.append({"nr": nr, "mesh": mesh, "nodes": s["nodes"], "steps": steps,
                         "wall_seconds": wall, "loop_seconds": s["wall_seconds"],
                         "seconds_per_step": s["wall_seconds"] / steps,
                         "curve_error": err["l1_transient"], "curve_error_whole": err["l1"],
                         "curve_error_linf": err["linf"],
                         "final_vs_reference": err["final"],
                         "final_vs_lame": abs(s["final_pressure_mean"] - lame) / lame,
                         "lame_pressure": lame, "final_pressure_mean": s["final_pressure_mean"],
                         "first_contact_dT": err.get("first_contact_dT"),
                         "iterations_mean": {"fixed_point": s["fixed_point_iterations_mean"],
                                             "slip_threshold": s["slip_threshold_iterations_mean"],
                                             "dc": s["dc_iterations_mean"],
                                             "psor": s["psor_sweeps_mean"]}})
    results["work_precision"] = grid
    within = [g for g in grid if g["curve_error"] <= 0.01]
    fastest = min(within, key=lambda g: g["wall_seconds"]) if within else None
    results["wall_seconds_to_1pct_curve_error"] = fastest["wall_seconds"] if fastest else None
    results["fastest_within_1pct"] = fastest
    results["most_accurate"] = min(grid, key=lambda g: g["curve_error"])
    within = [g for g in grid if g["curve_error_whole"] <= 0.01]
    fastest_whole = min(within, key=lambda g: g["wall_seconds"]) if within else None
    results["wall_seconds_to_1pct_curve_error_whole_process"] = (fastest_whole["wall_seconds"]
                                                                 if fastest_whole else None)
    results["fastest_within_1pct_whole_process"] = fastest_whole

    # The same curve from the radial model (what the centred circular sleeve needs: a 1D problem).
    radial = []
    for nr in RADIAL_NR:
        for steps in RADIAL_STEPS:
            print(f"bench: sleeve-radial nr {nr} steps {steps}", flush=True)
            out = os.path.join(OUT, f"radial-nr{nr}-steps{steps}")
            wall, s, _ = run("edp/scenes/sleeve-radial.edp", out, "-nr", nr, "-steps", steps, "-quiet", 1,
                             *FINE_FPMAXIT)
            err = curve_error(os.path.join(out, "history.csv"), reference)
            radial.append({"nr": nr, "steps": steps, "wall_seconds": wall, "curve_error": err["l1_transient"],
                           "curve_error_whole": err["l1"], "final_vs_reference": err["final"]})
    results["work_precision_radial"] = radial
    within = [g for g in radial if g["curve_error"] <= 0.01]
    results["radial_fastest_within_1pct"] = min(within, key=lambda g: g["wall_seconds"]) if within else None
    results["radial_wall_seconds_to_1pct_curve_error"] = (results["radial_fastest_within_1pct"]["wall_seconds"]
                                                          if within else None)

    # Cost per step against nodes (the longest step count: setup amortised; loop time only).
    longest = max(STEP_COUNTS)
    per_step = [(g["nodes"], g["seconds_per_step"]) for g in grid if g["steps"] == longest]
    results["cost_per_step"] = [{"nodes": n, "seconds": c} for n, c in per_step]
    results["cost_exponent_per_step"] = fit_exponent(*zip(*per_step)) if len(per_step) >= 2 else None


def figures(r, plt):
    """work-precision.png and cost-per-step.png; returns {"wp": path, "cost": path} (from docs/)."""
    grid = r["work_precision"]
    pngs = {}
    # Work-precision diagram.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for nr in sorted({g["nr"] for g in grid}):
        rows = sorted((g for g in grid if g["nr"] == nr), key=lambda g: g["steps"])
        label = f"nr {nr} ({rows[0]['nodes']} nodes)"
        axes[0].loglog([g["wall_seconds"] for g in rows], [g["curve_error"] for g in rows], "o-", label=label)
        axes[1].loglog([g["wall_seconds"] for g in rows], [g["final_vs_lame"] for g in rows], "o-", label=label)
    for steps in sorted({g["steps"] for g in grid}):
        rows = sorted((g for g in grid if g["steps"] == steps), key=lambda g: g["nr"])
        axes[0].loglog([g["wall_seconds"] for g in rows], [g["curve_error"] for g in rows], ":",
                       color="grey", lw=0.8)
        axes[0].annotate(f"{steps} steps", (rows[-1]["wall_seconds"], rows[-1]["curve_error"]),
                         fontsize=7, color="grey")
    rad = r["work_precision_radial"]
    for steps in sorted({g["steps"] for g in rad}):
        rows = sorted((g for g in rad if g["steps"] == steps), key=lambda g: g["nr"])
        axes[0].loglog([g["wall_seconds"] for g in rows], [g["curve_error"] for g in rows], "s--", ms=4,
                       label=f"radial 1D, {steps} steps")
    axes[0].axhline(0.01, color="k", lw=0.6, ls="--")
    axes[0].set(xlabel="wall time (s, whole run)", ylabel="curve error (relative L1, transient)",
                title="force-temperature curve vs radial reference")
    axes[1].set(xlabel="wall time (s, whole run)", ylabel="|p_final - p_Lame| / p_Lame",
                title="final pressure vs Lame")
    axes[0].legend(fontsize=7)
    pngs["wp"] = save(fig, "work-precision.png")
    # Cost per step against nodes.
    cps = r["cost_per_step"]
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.loglog([c["nodes"] for c in cps], [c["seconds"] * 1e3 for c in cps], "o-")
    ax.set(xlabel="nodes", ylabel="ms per time step (loop only)",
           title=f"cost per step, fitted exponent {r['cost_exponent_per_step']:.2f}")
    pngs["cost"] = save(fig, "cost-per-step.png")
    return pngs


def doc(r, w, pngs):
    """The work-precision and cost-per-step parts of docs/benchmarks.md."""
    grid = r["work_precision"]
    fast = r["fastest_within_1pct"]
    default = [g for g in grid if g["nr"] == 18 and g["steps"] == 1500]
    w("")
    w("## Work-precision")
    w("")
    w(f"![work-precision]({pngs['wp']})")
    w("")
    w("| nr | nodes | steps | wall (s) | loop ms/step | curve error (transient) | over 150 s | final vs Lame | mean iterations fp / DC / PSOR |")
    w("|---|---|---|---|---|---|---|---|---|")
    for g in grid:
        i = g["iterations_mean"]
        w(f"| {g['nr']} | {g['nodes']} | {g['steps']} | {g['wall_seconds']:.2f} | {1e3 * g['seconds_per_step']:.2f} | "
          f"{100 * g['curve_error']:.2f} % | {100 * g['curve_error_whole']:.3f} % | {100 * g['final_vs_lame']:.4f} % | "
          f"{i['fixed_point']:.2f} / {i['dc']:.2f} / {i['psor']:.1f} |")
    w("")
    w("The radial model of the same sleeve (edp/scenes/sleeve-radial.edp), same metric:")
    w("")
    w("| elements in r | steps | wall (s) | curve error (transient) | over 150 s |")
    w("|---|---|---|---|---|")
    for g in r["work_precision_radial"]:
        w(f"| {g['nr']} | {g['steps']} | {g['wall_seconds']:.2f} | {100 * g['curve_error']:.2f} % | "
          f"{100 * g['curve_error_whole']:.3f} % |")
    w("")
    if fast:
        w(f"Fastest configuration within 1 %: nr {fast['nr']} ({fast['nodes']} nodes), {fast['steps']} steps, "
          f"{fast['wall_seconds']:.2f} s, curve error {100 * fast['curve_error']:.2f} %.")
    if default:
        d = default[0]
        w(f"The structured 18-layer mesh (the old default), 1500 steps: {d['wall_seconds']:.2f} s, curve error {100 * d['curve_error']:.2f} % "
          f"(over the whole 150 s: {100 * d['curve_error_whole']:.3f} %).")
    w("")
    w("## Cost per time step against the number of nodes")
    w("")
    w(f"![cost per step]({pngs['cost']})")
    w("")
    w(f"Loop time per step at {max(STEP_COUNTS)} steps; least-squares exponent of ms/step against nodes: "
      f"**{r['cost_exponent_per_step']:.2f}**.")
    w("")
    w("| nodes | ms per step |")
    w("|---|---|")
    for c in r["cost_per_step"]:
        w(f"| {c['nodes']} | {1e3 * c['seconds']:.3f} |")
    w("")
