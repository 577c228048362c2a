#!/usr/bin/python3
"""How sleeve-circular's force-curve error depends on the 2D ring mesh, at the paper's scale: the layers
through the thickness (nr, h_r = Hr / nr) apart from the segments along the arc (nt, h_theta = 90 deg / nt),
so that a mesh that follows the transformation front knows where resolution pays.

What it measures. Structured quarter rings of meshes/ring.geo (gmsh -setnumber nr N -setnumber nt M, Ri
and Hr from meshes/sleeve-geometry.txt as for meshes/sleeve-*.msh), written to build/mesh-study/. Two
series at the scene's 1500 fixed steps over 150 s (their time error, summary.json time_error_estimate,
shown against the mesh error; the finest meshes run again at 3000 steps as a direct check):
  (a) layers nr = 9 .. 96 at the default mesh's arc (nt 18: meshes/sleeve-aniso.msh);
  (b) arc segments nt = 18, 36, 90 at nr = 18 and at nr = 36.
For each run: the error of the mean contact pressure against p* (tools/bench/reference_curve.py --scale
paper: results/reference-paper/reference-history.csv, the extrapolated sleeve-radial curve, made first if
missing, about 30 s) by tools/bench/oracles/curve_error.py, l1_transient over [0, t_A] and l1_reversion
over the reversion window [t_R, t_A]; the nodes; the whole process's wall time (tools/ff start to exit,
median of --repeat runs), its CPU time (user + sys) and the loop's (summary.json wall_seconds).

Orders. Against p*: the least-squares slope of log error against log h over each series. Each
direction alone, without p*: the differences of successive curves along a series, D_i = |p_i - p_i+1|
(window norm), fitted to C |n_i^-k - n_i+1^-k|: the other direction's error, fixed along the
series, cancels in them. Then p(nr, nt) = p* + A(t) nr^-k + B(t) nt^-q: B(t) from the arc series,
A(t) and k from the layers' curves less B(t) nt^-q, against p*; with it, the resolution each direction
needs for 0.1 % over the window, and the uniform mesh of fewest nodes that meets it. The radial
model's levels (sleeve-radial nr 20 .. 640, 20 nr steps over 80 s, the reference tool's runs) are
drawn beside them.

    /usr/bin/python3 tools/bench/mesh_study.py --run [--repeat 3]   the runs, into results/mesh-study/
    /usr/bin/python3 tools/bench/mesh_study.py          the page again from results/mesh-study/summary.json
Writes docs/benchmarks/mesh-refinement.md and .png. --run also runs the model's uniform mesh for 0.1 %
once. Alone on the machine (the times are the measurement): about 6 minutes with --repeat 3, 2 cores.
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import ROOT, machine, run, save, write_json, write_whole  # noqa: E402
from sma.plotting import pyplot  # noqa: E402
from markdown_wrap import wrap  # noqa: E402  (tools/: the generated pages' prose wrapped as the hand-written)
from curve_error import curve_error, read_history, reversion_time, austenite_time  # noqa: E402
import numpy as np  # noqa: E402  (after common: the sma package sets numpy's threads before numpy loads)

OUT = os.path.join(ROOT, "results", "mesh-study")
MESH_DIR = os.path.join(ROOT, "build", "mesh-study")
REFERENCE_DIR = os.path.join(ROOT, "results", "reference-paper")
REFERENCE = os.path.join(REFERENCE_DIR, "reference-history.csv")
DOC = os.path.join(ROOT, "docs", "benchmarks", "mesh-refinement.md")
SCRIPT = "edp/scenes/sleeve-circular.edp"
STEPS = 1500
NT_DEFAULT = 18   # sleeve-circular's default mesh, meshes/sleeve-aniso.msh: 18 layers x 18 segments
LAYERS = [9, 12, 18, 24, 36, 48, 72, 96]
ARCS = [18, 36, 90]
ARC_AT = [18, 36]
TIME_CHECKS = [(96, 18), (36, 90)]   # run again at 2 STEPS
TARGET = 1e-3      # 0.1 % over the window
TARGET_SECONDS = 3.0


def geometry():
    """meshes/sleeve-geometry.txt: {"Ri": .., "Hr": .., "pipe": ..} (m)."""
    words = [line.split() for line in open(os.path.join(ROOT, "meshes", "sleeve-geometry.txt")) if line[0] != "#"]
    return {w[0]: float(w[1]) for w in words if len(w) == 2}


def mesh(nr, nt):
    """build/mesh-study/ring-nr<nr>-nt<nt>.msh (made once)."""
    path = os.path.join(MESH_DIR, f"ring-nr{nr}-nt{nt}.msh")
    if not os.path.exists(path):
        os.makedirs(MESH_DIR, exist_ok=True)
        g = geometry()
        numbers = [w for key, v in (("Ri", g["Ri"]), ("Hr", g["Hr"]), ("nr", nr), ("nt", nt)) for w in ("-setnumber", key, str(v))]
        done = subprocess.run(["gmsh", "-2", "-format", "msh22", *numbers, os.path.join(ROOT, "meshes", "ring.geo"),
                               "-o", path + ".part"], capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"mesh_study: gmsh failed for nr {nr}, nt {nt}: {done.stdout[-500:]}{done.stderr[-500:]}")
        os.replace(path + ".part", path)
    return path


def reference():
    """The reference history (reference_curve.py --scale paper, made here if missing)."""
    if not os.path.exists(REFERENCE):  # it exits 1 on its assumption A3 (docs/reference-paper.md: a known NO)
        print("mesh_study: making the reference (tools/bench/reference_curve.py --scale paper, about 30 s)", flush=True)
        subprocess.run([sys.executable, os.path.join(ROOT, "tools", "bench", "reference_curve.py"), "--scale", "paper",
                        "--out", REFERENCE_DIR, "--doc", os.path.join(REFERENCE_DIR, "reference-paper.md")],
                       cwd=ROOT, capture_output=True)
        if not os.path.exists(REFERENCE):
            sys.exit(f"mesh_study: {REFERENCE} was not made")


def run_case(nr, nt, steps, repeat):
    """One mesh: the scene `repeat` times (the errors of the first, the median times)."""
    path = mesh(nr, nt)
    out = os.path.join(OUT, "runs", f"nr{nr}-nt{nt}" + ("" if steps == STEPS else f"-steps{steps}"))
    walls, cpus, loops = [], [], []
    for _ in range(repeat):
        cpu = sum(resource.getrusage(resource.RUSAGE_CHILDREN)[:2])  # the children's user + system
        # (the polygonal mesh's heat measure, -curvedmeasure 0: the study that found the arc's part,
        # which the default's true annulus removes; docs/measurements.md#m-curved-measure)
        wall, s, _ = run(SCRIPT, out, "-scale", "paper", "-quiet", 1, "-vtkevery", 0, "-steps", steps, "-mesh", path,
                         "-curvedmeasure", 0)
        walls.append(wall)
        cpus.append(sum(resource.getrusage(resource.RUSAGE_CHILDREN)[:2]) - cpu)
        loops.append(s["wall_seconds"])
    e = curve_error(os.path.join(out, "history.csv"), REFERENCE)
    row = {"nr": nr, "nt": nt, "steps": steps, "process_seconds": statistics.median(walls),
           "cpu_seconds": statistics.median(cpus), "loop_seconds": statistics.median(loops), "process_seconds_all": walls,
           "l1_transient": e["l1_transient"], "l1_reversion": e["l1_reversion"],
           "history": os.path.relpath(os.path.join(out, "history.csv"), ROOT),
           **{k: s[k] for k in ("nodes", "triangles", "time_error_estimate", "time_error_estimate_transient", "steps_retried")}}
    print(f"mesh_study: nr {nr:3d} nt {nt:3d} steps {steps}: {row['nodes']} nodes, {row['process_seconds']:.2f} s, "
          f"transient {100 * row['l1_transient']:.4f} %, window {100 * row['l1_reversion']:.4f} %", flush=True)
    return row


def time_check(base):
    """The run of row `base` again at 2 STEPS: its error, and the change of the curve."""
    fine = run_case(base["nr"], base["nt"], 2 * STEPS, 1)
    d = curve_error(os.path.join(ROOT, base["history"]), os.path.join(ROOT, fine["history"]))
    return {"nr": base["nr"], "nt": base["nt"], "steps": 2 * STEPS, "l1_reversion": fine["l1_reversion"],
            "difference_transient": d["l1_transient"], "difference_reversion": d["l1_reversion"]}


def measure(repeat):
    reference()
    cases = [(nr, NT_DEFAULT) for nr in LAYERS] + [(nr, nt) for nr in ARC_AT for nt in ARCS if nt != NT_DEFAULT]
    rows = [run_case(nr, nt, STEPS, repeat) for nr, nt in cases]
    checks = [time_check(next(r for r in rows if (r["nr"], r["nt"]) == c)) for c in TIME_CHECKS]
    radial = json.load(open(os.path.join(REFERENCE_DIR, "summary.json")))["fraction_levels"]
    return {"machine": machine(), "steps": STEPS, "repeat": repeat, "geometry": geometry(), "rows": rows,
            "time_checks": checks,
            "radial": [{k: r[k] for k in ("nr", "steps", "wall_seconds", "error", "error_reversion")} for r in radial]}


def save_record(record):
    write_json(os.path.join(OUT, "summary.json"), record)


# ---- analysis: every curve and p* on one grid (the union of their steps), exact L1 norms ----
class Curves:
    """The runs' pressure curves and p* on the union grid of the transient [0, t_A], the window [t_R, t_A] and
    [0, t_R] (before the reversion); norm(kind, d) = int |d| dt / int |p*| dt over that interval."""
    def __init__(self, rows):
        ref = read_history(REFERENCE)
        self.t_R, self.t_A = reversion_time(ref), austenite_time(ref) or ref["t"][-1]
        tref, pref = np.r_[0.0, ref["t"]], np.r_[0.0, ref["pressure_mean"]]
        runs = {}
        for r in rows:
            h = read_history(os.path.join(ROOT, r["history"]))
            runs[(r["nr"], r["nt"])] = (np.r_[0.0, h["t"]], np.r_[0.0, h["pressure_mean"]])
        union = tref
        for t, _ in runs.values():
            union = np.union1d(union, t)
        self.grid, self.p, self.ref, self.scale = {}, {}, {}, {}
        for kind, (a, b) in {"transient": (0.0, self.t_A), "window": (self.t_R, self.t_A),
                             "before": (0.0, self.t_R)}.items():
            g = np.union1d(union, [a, b])
            self.grid[kind] = g = g[(g >= a) & (g <= b)]
            self.p[kind] = {key: np.interp(g, t, p) for key, (t, p) in runs.items()}
            self.ref[kind] = np.interp(g, tref, pref)
            self.scale[kind] = self.integral(kind, self.ref[kind])

    def integral(self, kind, d):
        """int |d| dt, d linear between the grid's nodes (curve_error.py's abs_integral)."""
        h, d0, d1 = np.diff(self.grid[kind]), d[:-1], d[1:]
        a0, a1 = np.abs(d0), np.abs(d1)
        cross = (d0 * d0 + d1 * d1) / (2 * np.maximum(a0 + a1, 1e-300))
        return float(np.sum(h * np.where(d0 * d1 >= 0, (a0 + a1) / 2, cross)))

    def norm(self, kind, d):
        return self.integral(kind, d) / self.scale[kind]


def difference_order(ns, ds):
    """k of the least-squares fit log D_i = log C + log (n_i^-k - n_i+1^-k)."""
    def residual(k):
        f = np.log([a ** -k - b ** -k for a, b in zip(ns, ns[1:])])
        return float(np.sum((np.log(ds) - f - np.mean(np.log(ds) - f)) ** 2))
    return float(min(np.linspace(0.2, 4.0, 3801), key=residual))


def slope(ns, es):
    """k of e = c n^-k (least squares in log-log)."""
    return -float(np.polyfit(np.log(ns), np.log(es), 1)[0])


def analyse(rec):
    """The orders, the two-term model p(nr, nt) = p* + A(t) nr^-k + B(t) nt^-q and its meshes for TARGET."""
    C, rows, fine = Curves(rec["rows"]), rec["rows"], LAYERS[2:]
    a = {"t_R": C.t_R, "t_A": C.t_A}
    for kind in ("transient", "window"):
        p, ref = C.p[kind], C.ref[kind]
        ds = [C.norm(kind, p[(n, NT_DEFAULT)] - p[(m, NT_DEFAULT)]) for n, m in zip(LAYERS, LAYERS[1:])]
        a[f"layer_differences_{kind}"] = ds
        a[f"layer_order_differences_{kind}"] = difference_order(LAYERS, ds)
        a[f"layer_order_differences_from18_{kind}"] = difference_order(fine, ds[2:])
        a[f"layer_slope_{kind}"] = slope(fine, [C.norm(kind, p[(n, NT_DEFAULT)] - ref) for n in fine])
        a[f"arcs_{kind}"] = {}
        for nr in ARC_AT:
            dsa = [C.norm(kind, p[(nr, x)] - p[(nr, y)]) for x, y in zip(ARCS, ARCS[1:])]
            a[f"arcs_{kind}"][nr] = {"differences": dsa, "order": difference_order(ARCS, dsa)}
    # B(t) from the finest arc pair at the finest nr of ARC_AT with its order q; the layers' part is the
    # curve at nt 18 less B 18^-q, against p*: its order k over nr >= 18, A(t) from the finest nr.
    q, nb = a["arcs_window"][ARC_AT[-1]]["order"], ARC_AT[-1]
    m = {"q": q}
    for kind in ("transient", "before", "window"):
        p, ref = C.p[kind], C.ref[kind]
        B = (p[(nb, ARCS[-2])] - p[(nb, ARCS[-1])]) / (ARCS[-2] ** -q - ARCS[-1] ** -q)
        radial = {n: p[(n, NT_DEFAULT)] - B * NT_DEFAULT ** -q - ref for n in LAYERS}
        m[f"radial_part_{kind}"] = {n: C.norm(kind, d) for n, d in radial.items()}
        m[f"arc_part_{kind}"] = C.norm(kind, B * NT_DEFAULT ** -q)
        if kind != "before":
            k = m[f"k_{kind}"] = slope(fine, [m[f"radial_part_{kind}"][n] for n in fine])
    A = radial[LAYERS[-1]] * LAYERS[-1] ** k   # the window's: its last kind
    m["predicted_window"] = {(r["nr"], r["nt"]): C.norm("window", A * r["nr"] ** -k + B * r["nt"] ** -q)
                             for r in rows + ([rec["target_check"]] if rec.get("target_check") else [])}
    # Each direction alone at TARGET (the other resolved), and the uniform mesh of fewest nodes that
    # meets it (the norm of the sum: the two terms partly cancel).
    m["nr_alone"], m["nt_alone"] = (C.norm("window", A) / TARGET) ** (1 / k), (C.norm("window", B) / TARGET) ** (1 / q)
    best = None
    for nr in range(12, 300):
        for nt in range(12, 300):
            if best is not None and (nr + 1) * (nt + 1) >= best[0]:
                break
            if C.norm("window", A * nr ** -k + B * nt ** -q) <= TARGET:
                best = ((nr + 1) * (nt + 1), nr, nt)
                break
    m["uniform"] = {"nodes": best[0], "nr": best[1], "nt": best[2]}
    a["model"] = m
    return a


# ---- the page ----
def pct(x, spec=".3f"):
    return "-" if x is None else format(100 * x, spec) + " %"


def table(rows, a, g):
    out = ["| nr x nt | h_r (um) | h_theta (deg) | nodes | process (s) | CPU (s) | loop (s) | error, transient | "
           "error, window | two-term model, window | time estimate / error, transient |", "|---|" + "---|" * 10]
    for r in rows:
        model = a["model"]["predicted_window"].get((r["nr"], r["nt"]))
        out.append(f"| {r['nr']} x {r['nt']} | {1e6 * g['Hr'] / r['nr']:.0f} | {90 / r['nt']:.2f} | {r['nodes']} | "
                   f"{r['process_seconds']:.2f} | {r['cpu_seconds']:.2f} | {r['loop_seconds']:.2f} | "
                   f"{pct(r['l1_transient'])} | {pct(r['l1_reversion'])} | {pct(model)} | "
                   f"{r['time_error_estimate_transient'] / r['l1_transient']:.3f} |")
    return out


def figure(rec):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5))
    rows = rec["rows"]
    series = [(f"(a) layers nr {LAYERS[0]}-{LAYERS[-1]} at nt {NT_DEFAULT}", [r for r in rows if r["nt"] == NT_DEFAULT], "o-")]
    series += [(f"(b) arc nt {ARCS[0]}-{ARCS[-1]} at nr {nr}", [r for r in rows if r["nr"] == nr], "s-") for nr in ARC_AT]
    if rec.get("target_check"):
        series.append(("the model's uniform mesh for 0.1 %", [rec["target_check"]], "*"))
    named = set()
    for label, rs, style in series:
        rs = sorted(rs, key=lambda r: r["nodes"])
        ax.loglog([r["process_seconds"] for r in rs], [100 * r["l1_reversion"] for r in rs], style, label=label)
        for r in (r for r in rs if (r["nr"], r["nt"]) not in named and not named.add((r["nr"], r["nt"]))):
            ax.annotate(f"{r['nr']}x{r['nt']}", (r["process_seconds"], 100 * r["l1_reversion"]), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
    rad = rec["radial"]
    ax.loglog([r["wall_seconds"] for r in rad], [100 * r["error_reversion"] for r in rad], "^--", color="gray",
              label="sleeve-radial nr 20-640 (1D; 80 s, 20 nr steps)")
    ax.axhline(100 * TARGET, color="k", lw=0.6, ls=":")
    ax.axvline(TARGET_SECONDS, color="k", lw=0.6, ls=":")
    ax.set(xlabel="whole process wall time (s)", ylabel="error over the reversion window (%)",
           title="sleeve-circular, paper scale, 1500 steps: the ring mesh's error")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, "mesh-refinement.png")


def conclusion(rec, a):
    m, g, t = a["model"], rec["geometry"], rec.get("target_check")
    rows = {(r["nr"], r["nt"]): r for r in rec["rows"]}
    u, d = m["uniform"], rows[(18, NT_DEFAULT)]
    n3 = max((r for r in rec["rows"] if r["process_seconds"] <= TARGET_SECONDS), key=lambda r: r["nodes"])
    text = (f"Both directions carry the error over the window, in different ways: the layers' term (order about "
            f"{m['k_window']:.1f} in h_r against p*) is the front's ({pct(m['radial_part_before'][18])} of p* before the "
            f"reversion at nr 18), while the arc's term (order {m['q']:.1f} in h_theta) is there before any front "
            f"({pct(m['arc_part_before'])}), presumably the straight-sided ring's geometry; on the default 18 x 18 "
            f"they are {pct(m['radial_part_window'][18])} and {pct(m['arc_part_window'])} of p* (together "
            f"{pct(d['l1_reversion'])}: they partly cancel), and refining one alone stalls on the other "
            f"({pct(rows[(LAYERS[-1], NT_DEFAULT)]['l1_reversion'])} at {LAYERS[-1]} x {NT_DEFAULT}, "
            f"{pct(rows[(18, ARCS[-1])]['l1_reversion'])} at 18 x {ARCS[-1]}). "
            f"Extrapolating the fitted orders, 0.1 % over the window needs h_r <= {1e6 * g['Hr'] / m['nr_alone']:.0f} um "
            f"(nr {m['nr_alone']:.0f}) with the arc resolved, or h_theta <= {90 / m['nt_alone']:.1f} deg (nt "
            f"{m['nt_alone']:.0f}) with the layers resolved; together, the uniform mesh of fewest nodes is "
            f"{u['nr']} x {u['nt']} ({u['nodes']} nodes: h_r {1e6 * g['Hr'] / u['nr']:.0f} um, h_theta "
            f"{90 / u['nt']:.1f} deg)")
    if t:
        text += (f", measured at {pct(t['l1_reversion'])} over the window in {t['process_seconds']:.1f} s whole "
                 f"process, {t['process_seconds'] / TARGET_SECONDS:.1f} times the 3 s target")
    return text + (f". An adaptive mesh therefore needs cells of about {1e6 * g['Hr'] / u['nr']:.0f} um through the "
                   f"thickness only in a band that follows the front, but about {u['nt']} segments "
                   f"({90 / u['nt']:.1f} deg) along the whole arc, front or not (or a curved boundary, which this "
                   f"study does not test). Within 3 s these runs afford about {n3['nodes']} nodes "
                   f"({n3['nr']} x {n3['nt']}: {n3['process_seconds']:.2f} s), that is about "
                   f"{n3['nodes'] / (u['nt'] + 1):.0f} nodes through the thickness at {u['nt']} arc segments: a band "
                   f"of fine layers at the front and a coarse rest must fit in them.")


def write_doc(rec):
    a = analyse(rec)
    m, g, rows, mach = a["model"], rec["geometry"], rec["rows"], rec["machine"]
    png = figure(rec)
    layers = sorted([r for r in rows if r["nt"] == NT_DEFAULT], key=lambda r: r["nr"])
    arcs = sorted([r for r in rows if r["nr"] in ARC_AT], key=lambda r: (r["nr"], r["nt"]))
    L = ["# The force curve's error against the 2D ring mesh (paper scale)", "",
         f"Written by `tools/bench/mesh_study.py` (its docstring states the method) from its runs of {mach['date']} "
         f"({mach['nproc']} cores, {mach['cpu_model']}, shared with other jobs: times are medians of {rec['repeat']} "
         f"runs and carry that load). sleeve-circular at the paper's scale, {rec['steps']} fixed steps over 150 s, "
         f"`-vtkevery 0`, on structured quarter rings of meshes/ring.geo (Ri {g['Ri']} m, Hr {g['Hr']} m): nr layers "
         f"through the thickness (h_r = Hr / nr), nt segments along the arc (h_theta = 90 deg / nt). The scene's "
         f"default mesh, meshes/sleeve-aniso.msh, is 18 x 18; meshes/sleeve-quarter.msh is 18 x 90. The heat on "
         f"the polygonal mesh's measure (`-curvedmeasure 0`): the arc's part of the error found here is the "
         f"polygon's missing heat, which the default, `-curvedmeasure 1`, removes "
         f"(docs/measurements.md#m-curved-measure).", "",
         f"Error: relative L1 in time of the mean contact pressure against p* (tools/bench/reference_curve.py --scale "
         f"paper: docs/reference-paper.md, p* known to about 0.005 % over the window), over the transient "
         f"[0, {a['t_A']:.3f} s] and the reversion window [{a['t_R']:.3f}, {a['t_A']:.3f} s] "
         f"(tools/bench/oracles/curve_error.py's l1_transient, l1_reversion). Process: the whole tools/ff process's "
         f"wall time; CPU: its user + system time; loop: summary.json `wall_seconds`; the two-term model: Orders.", "",
         f"## (a) Layers through the thickness, nt = {NT_DEFAULT}", ""] + table(layers, a, g) + [
         "", "## (b) Segments along the arc, nr = " + " and ".join(map(str, ARC_AT)), ""] + table(arcs, a, g)
    if rec.get("target_check"):
        L += ["", "The two-term model's uniform mesh for 0.1 % over the window (Orders), run once:", ""]
        L += table([rec["target_check"]], a, g)
    L += ["", "## The time steps' share", "",
          f"Each run's own estimate of its time error (summary.json `time_error_estimate_transient`) is at most "
          f"{max(r['time_error_estimate_transient'] / r['l1_transient'] for r in rows):.3f} of its mesh error over the "
          f"transient (the tables' last column; `time_error_estimate`, over the run, at most "
          f"{max(r['time_error_estimate'] for r in rows):.1e}). Directly, {2 * rec['steps']} steps against {rec['steps']}:",
          "", "| mesh | error over the window, 2x steps (1x) | change of the curve, transient | change, window |",
          "|---|---|---|---|"]
    for c in rec["time_checks"]:
        base = next(r for r in rows + [rec.get("target_check")] if r and (r["nr"], r["nt"]) == (c["nr"], c["nt"]))
        L.append(f"| {c['nr']} x {c['nt']} | {pct(c['l1_reversion'])} ({pct(base['l1_reversion'])}) | "
                 f"{pct(c['difference_transient'], '.4f')} | {pct(c['difference_reversion'], '.4f')} |")
    aw, at, rp = a["arcs_window"], a["arcs_transient"], m["radial_part_window"]
    devs = {(r["nr"], r["nt"]): abs(m["predicted_window"][(r["nr"], r["nt"])] / r["l1_reversion"] - 1) for r in rows}
    dev = max(devs.values())
    ds = a["layer_differences_window"]
    pairs = [difference_order(LAYERS[i:i + 3], ds[i:i + 2]) for i in range(len(ds) - 1)]
    L += ["", "## Orders", "",
          "**Arc (h_theta).** The differences of successive curves along (b) fall with order "
          + ", ".join(f"{aw[nr]['order']:.2f} at nr {nr}" for nr in ARC_AT) + " over the window ("
          + ", ".join(f"{at[nr]['order']:.2f}" for nr in ARC_AT) + " over the transient), and they are nearly the "
          f"same at both nr ({pct(aw[ARC_AT[0]]['differences'][0])} and {pct(aw[ARC_AT[-1]]['differences'][0])} from "
          f"nt {ARCS[0]} to {ARCS[1]}): the arc's error is a term B(t) h_theta^2 of its own, added to the layers'. It "
          f"is there before the reversion starts, with no front in the ring: {pct(m['arc_part_before'])} of p* over "
          f"[0, t_R] at nt {NT_DEFAULT} ({pct(m['arc_part_window'])} over the window).", "",
          f"**Layers (h_r).** Along (a) the error against p* flattens onto the arc's floor at nt {NT_DEFAULT} (slope "
          f"{a['layer_slope_window']:.2f} over nr >= 18, window). The differences of successive curves, which leave "
          f"the fixed arc term out, give order {a['layer_order_differences_window']:.2f} over nr {LAYERS[0]}-{LAYERS[-1]} "
          f"({a['layer_order_differences_from18_window']:.2f} from nr 18; transient "
          f"{a['layer_order_differences_transient']:.2f}); three levels at a time they swing from {min(pairs):.1f} to "
          f"{max(pairs):.1f}. The layers' part "
          f"against p* (the curve less B(t) {NT_DEFAULT}^-q) is " + ", ".join(f"{pct(rp[n])} at nr {n}" for n in LAYERS[2:])
          + f": order k = {m['k_window']:.2f} over the window ({m['k_transient']:.2f} over the transient), below the "
          f"radial model's 1.25; before the reversion it is {pct(m['radial_part_before'][18])} at nr 18: the layers' "
          f"error is the front's.", "",
          f"**Two-term model.** p(nr, nt) = p* + A(t) nr^-k + B(t) nt^-q, q = {m['q']:.2f} (B from nr {ARC_AT[-1]}, "
          f"nt {ARCS[-2]} and {ARCS[-1]}), k = {m['k_window']:.2f} (A from nr {LAYERS[-1]}), the norm taken of the sum "
          f"(the terms partly cancel): the tables' model column, within {100 * dev:.0f} % of the measured errors "
          f"at every mesh of (a) and (b).", "",
          "## Conclusion", "", conclusion(rec, a), "", f"![error against wall time]({os.path.basename(png)})", ""]
    write_whole(DOC, wrap("\n".join(L)))  # prose at 100 columns (a page's line: at most 400)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", action="store_true", help="make the runs (else read results/mesh-study/summary.json)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per mesh; the median times (default 3)")
    opts = parser.parse_args()
    if opts.run:
        rec = measure(opts.repeat)
        save_record(rec)
        u = analyse(rec)["model"]["uniform"]
        rec["target_check"] = run_case(u["nr"], u["nt"], STEPS, opts.repeat)
        rec["time_checks"].append(time_check(rec["target_check"]))
        save_record(rec)
    else:
        rec = json.load(open(os.path.join(OUT, "summary.json")))
    write_doc(rec)
    print(f"mesh_study: {os.path.relpath(DOC, ROOT)}, docs/benchmarks/mesh-refinement.png, results/mesh-study/")
