#!/usr/bin/python3
"""The pull-out force of the sleeve of finite length against the mesh (issue 27, item 4), a
section of make bench.

sleeve-axisymmetric at the paper's scale (L = 10 cm, mu 0.2, the whole length with its end face held,
the pipe moved 1 mm after clamping in 25 increments: -mu 0.2 -pullout 1e-3 -pullsteps 25), the
scene's 1000 time steps at every level (the time step is not refined: the study measures the
mesh's share of the error), square cells (-nz 0), nr elements through the thickness:
  rigid pipe:         nr 2, 3, 4, 6, 8, 12;
  steel shaft:        nr 2, 4, 8 (-pipeE 200e9 -pipenu 0.28, the pipe meshed with the ring's cells).
The pull-out force is the sliding plateau's F, summary.json's pullout_force_final (= mu N, every
node slipping; > 0: the sleeve's force on the pipe against its motion, docs/parameters.md). Observed order
p = log2((F_h - F_h/2) / (F_h/2 - F_h/4)) from each doubling triple (rigid: 2-4-8 and 3-6-12;
steel: 2-4-8); the reference is the Richardson extrapolation of the two finest doubling levels
with the finer triple's p, and each level's error is against it. Time to 1 % (and 0.1 %): the
least wall time (the process's, FreeFEM's start and the setup included) of a level within it.

bench.py calls measure() from main(), report.py section() from write_doc(); alone:
  tools/bench/pullout.py [--quick]   (writes results/bench-pullout/summary.json and prints the section;
                                      --quick: rigid nr 2, 4, 8 only)
"""
import json
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import without_companion  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = "edp/scenes/sleeve-axisymmetric.edp"
PULL = ["-scale", "paper", "-mu", "0.2", "-pullout", "1e-3", "-pullsteps", "25"]
STEEL = ["-pipeE", "200e9", "-pipenu", "0.28"]
SERIES = {"rigid pipe": ([2, 3, 4, 6, 8, 12], []), "steel shaft": ([2, 4, 8], STEEL)}
QUICK_SERIES = {"rigid pipe": ([2, 4, 8], [])}
TARGETS = (1e-2, 1e-3)


def run_level(out, nr, extra):
    """One run; returns its row (nr, nodes, pull-out force, plateau ratio, wall seconds)."""
    os.makedirs(out, exist_ok=True)
    start = time.perf_counter()
    proc = subprocess.run([os.path.join(ROOT, "tools", "ff"), SCENE, "-out", out, "-quiet", "1", "-nr", str(nr),
                           *PULL, *extra, *without_companion(SCENE, [*PULL, *extra])], cwd=ROOT, capture_output=True,
                          text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        lines = [l for l in (proc.stdout + "\n" + proc.stderr).splitlines() if l.startswith("error:")]
        sys.exit(f"bench_pullout: {SCENE} -nr {nr} {' '.join(extra)} failed: {lines[-1] if lines else proc.returncode}")
    s = json.load(open(os.path.join(out, "summary.json")))
    return {"nr": nr, "nz": s["parameters"]["nz"], "nodes": s["nodes"] + s.get("pipe", {}).get("nodes", 0),
            "pullout_force": s["pullout_force_final"], "force_over_mu_normal": s["pullout_force_over_mu_normal"],
            "wall_seconds": wall, "loop_seconds": s["wall_seconds"]}


def study(rows):
    """Orders, the extrapolated reference, errors and times to the targets of one series."""
    force = {r["nr"]: r["pullout_force"] for r in rows}
    triples = [(n, 2 * n, 4 * n) for n in sorted(force) if 2 * n in force and 4 * n in force]
    orders = {}
    for a, b, c in triples:
        d1, d2 = force[a] - force[b], force[b] - force[c]
        orders[f"{a}-{b}-{c}"] = math.log2(d1 / d2) if d1 * d2 > 0 else None
    finest = max(triples, key=lambda t: t[2]) if triples else None
    p = orders.get("-".join(map(str, finest))) if finest else None
    rec = {"rows": rows, "orders": orders}
    if p is None:
        return rec
    fine, mid = force[finest[2]], force[finest[1]]
    reference = fine + (fine - mid) / (2 ** p - 1)
    for r in rows:
        r["error"] = abs(r["pullout_force"] - reference) / reference
    rec.update(order=p, reference=reference, reference_levels=[finest[1], finest[2]])
    for target in TARGETS:
        ok = [r for r in rows if r["error"] <= target]
        rec[f"seconds_to_{target:g}"] = min(r["wall_seconds"] for r in ok) if ok else None
        rec[f"nr_to_{target:g}"] = min(ok, key=lambda r: r["wall_seconds"])["nr"] if ok else None
    return rec


def measure(out_root, quick=False):
    """Runs every series into out_root/pullout/; returns the record for summary.json."""
    rec = {}
    for name, (levels, extra) in (QUICK_SERIES if quick else SERIES).items():
        print(f"bench: sleeve-axisymmetric pull-out, {name}, nr {levels}", flush=True)
        tag = name.replace(" ", "-")
        rows = [run_level(os.path.join(out_root, "pullout", f"{tag}-nr{nr}"), nr, extra) for nr in levels]
        rec[name] = study(rows)
    return rec


def section(rec, plt, save):
    """The Markdown lines of the section (save(fig, name) -> the PNG's path relative to docs/)."""
    lines = ["## Pull-out force of the sleeve of finite length", ""]
    w = lines.append
    w("sleeve-axisymmetric at the paper's scale, L = 10 cm, mu 0.2, the pipe moved 1 mm after clamping "
      "(`-mu 0.2 -pullout 1e-3 -pullsteps 25`), 1000 time steps at every level (only the mesh is refined), "
      "square cells; the pull-out force is the sliding plateau mu N (the sleeve's force on the pipe, > 0 "
      "against its motion). Reference: Richardson's extrapolation of "
      "the two finest doubling levels with their observed order; time: the whole process "
      "(tools/bench/pullout.py).")
    w("")
    series = [(name, s) for name, s in rec.items() if s.get("reference")]
    if series:
        fig, ax = plt.subplots(figsize=(5.5, 4))
        for name, s in series:
            rows = s["rows"]
            ax.loglog([r["wall_seconds"] for r in rows], [max(r["error"], 1e-12) for r in rows], "o-", label=name)
            for r in rows:
                ax.annotate(f"nr {r['nr']}", (r["wall_seconds"], max(r["error"], 1e-12)), fontsize=7)
        for target in TARGETS:
            ax.axhline(target, color="grey", lw=0.6, ls=":")
        ax.set(xlabel="wall time (s)", ylabel="pull-out force error (relative)")
        ax.legend(fontsize=8)
        w(f"![pull-out force error against time]({save(fig, 'pullout.png')})")
        w("")
    for name, s in rec.items():
        orders = ", ".join(f"{k}: {v:.2f}" if v is not None else f"{k}: n/a" for k, v in s["orders"].items())
        if s.get("reference"):
            to = "; ".join(f"to {100 * t:g} %: " + (f"{s[f'seconds_to_{t:g}']:.1f} s (nr {s[f'nr_to_{t:g}']})"
                                                    if s[f"seconds_to_{t:g}"] is not None else "not reached")
                           for t in TARGETS)
            w(f"**{name}**: observed order {orders}; reference {s['reference'] / 1e3:.3f} kN (nr "
              f"{s['reference_levels'][0]}, {s['reference_levels'][1]}); time {to}.")
        else:
            w(f"**{name}**: observed order {orders}; no reference (no doubling triple with a monotone difference).")
        w("")
        w("| nr | nodes | pull-out force (kN) | error | plateau / mu N | wall (s) |")
        w("|---|---|---|---|---|---|")
        for r in s["rows"]:
            err = f"{r['error']:.2e}" if "error" in r else "-"
            w(f"| {r['nr']} | {r['nodes']} | {r['pullout_force'] / 1e3:.3f} | {err} | {r['force_over_mu_normal']:.12f} | "
              f"{r['wall_seconds']:.1f} |")
        w("")
    return lines


if __name__ == "__main__":
    from common import run_alone
    run_alone("pullout", measure, section)
