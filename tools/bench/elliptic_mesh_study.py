#!/usr/bin/python3
"""How the force curves of the elliptic-pipe scenes, sleeve-elliptic and sleeve-elliptic-friction (paper
Fig. 25-32), depend on the 2D ring mesh at the paper's scale, against a fine fixed mesh of their own whose
error is estimated and stated (issue 48).

What it runs. Each scene at its defaults (the paper's scale, `-curvedmeasure 1`), `-tol 0`: the paper's 1500
fixed steps of 0.1 s on every mesh, so that the time error is the same on all of them and the differences
between runs are the mesh's. The meshes are the structured quarter rings of tools/bench/mesh_study.py's
mesh(nr, nt) (meshes/ring.geo, build/mesh-study/ring-nr<nr>-nt<nt>.msh; the scene stretches them to its
ring, -Ri 0.05): nr layers through the thickness (h_r = Hr / nr), nt segments along the arc
(h_theta = 90 deg / nt). Two series per scene:
  (a) the joint ladder nr = nt = 9, 12, 18, 27, 36, 54, 72, 108 (h = 1 / nr), and the reference
      nr = nt = 144 (--reference), the finest that runs in about 10 minutes for the friction scene;
  (b) the layers alone at the scenes' default arc, nt = 90 (meshes/sleeve-quarter.msh is 18 x 90):
      nr = 18, 36, 72, 108.
One run per mesh, one at a time (the times: the tools/ff process's CPU time, user + system of the
children from resource.getrusage(RUSAGE_CHILDREN) differences, its wall time, and summary.json
`wall_seconds`, the loop's).

Errors. Of the mean contact pressure (history.csv `pressure_mean` against t) relative to the same scene's
reference run, by tools/bench/oracles/curve_error.py's curve_error(history, reference): l1 (the whole run),
l1_transient ([0, t_A], t_A the reference's austenite-for-good time), l1_reversion (the reversion window
[t_R, t_A]) and the final pressure's; besides, by the same exact L1 (curve_error.l1_errors), the error
before the reversion, [0, t_R] (where no front runs through the ring), and the distances between curves
the orders below need. The key figures of the ellipticity (summary.json, points.csv): the final mean
pressure, its non-uniformity (max - min) / mean, the major (y) axis minus the minor (x) axis over the mean,
the major axis's peak before the minor axis touches and its pressure at the step before (the paper's
loosening), the step the minor axis touches, the austenite step, and with friction the tangential over
normal ratio (max over the nodes and total) and the sticking nodes.

The reference's own error: Richardson from the three finest meshes, n1 < n2 < n3 = the reference, on the
curves' distances D1 = |p1 - p2|, D2 = |p2 - p3| (each norm over its interval, relative to the reference):
the order p solving D1 / D2 = (n1^-p - n2^-p) / (n2^-p - n3^-p), then |p3 - p*| = D2 / ((n3 / n2)^p - 1)
(the error curve taken as A(t) h^p); checked with the ratio-2 triple 36, 72, 144. Orders: the least-squares
slope of log error against log h over the ladder without the reference (and over 9-54, the meshes at
least 2.6 times coarser than it), the fit's mesh for 0.1 % over the reversion window; the order of the
successive differences along each series (mesh_study.difference_order, which the reference's error does
not enter).

    /usr/bin/python3 tools/bench/elliptic_mesh_study.py --run [--resume]  the runs, into results/elliptic-mesh-study/
    /usr/bin/python3 tools/bench/elliptic_mesh_study.py --analyse         the errors again from the runs' histories
    /usr/bin/python3 tools/bench/elliptic_mesh_study.py                   the page again from results/elliptic-mesh-study/summary.json
Writes docs/benchmarks/elliptic-mesh-refinement.md and .png. --run on a 2-core machine: 29.6 minutes measured
(the 144 x 144 references 8.3 and 9.6 minutes of CPU, elliptic and friction); the page alone: about 5 s.
"""
import argparse
import csv
import hashlib
import json
import math
import os
import resource
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import ROOT, machine, run, write_json  # noqa: E402
from mesh_study import mesh, difference_order  # noqa: E402
from curve_error import curve_error, read_history, l1_errors, reversion_time, austenite_time  # noqa: E402
import numpy as np  # noqa: E402

OUT = os.path.join(ROOT, "results", "elliptic-mesh-study")
DOC = os.path.join(ROOT, "docs", "benchmarks", "elliptic-mesh-refinement.md")
PNG = "elliptic-mesh-refinement.png"
SCENES = ["sleeve-elliptic", "sleeve-elliptic-friction"]
LADDER = [9, 12, 18, 27, 36, 54, 72, 108]
REFERENCE_N = 144
NT_DEFAULT = 90          # meshes/sleeve-quarter.msh, the scenes' default: 18 layers x 90 segments
LAYERS = [18, 36, 72, 108]
TARGET = 1e-3            # 0.1 % over the reversion window
PLUGIN = os.path.join(ROOT, "plugin", "build", "sma.so")
KINDS = ("l1", "l1_transient", "l1_before", "l1_reversion")


def plugin_sha():
    try:
        return hashlib.sha256(open(PLUGIN, "rb").read()).hexdigest()[:16]
    except OSError:
        return None


def cases(reference_n):
    """(nr, nt) in run order: the ladder, the layers, the reference last."""
    out = [(n, n) for n in LADDER] + [(n, NT_DEFAULT) for n in LAYERS]
    return out + [(reference_n, reference_n)]


def key_figures(out, s):
    """The ellipticity's figures of one run (summary.json s, points.csv and contact-final.csv in out)."""
    rows = list(csv.DictReader(open(os.path.join(out, "points.csv"))))
    major = [float(r["pressure_y_axis_Pa"]) for r in rows]
    minor = [float(r["pressure_x_axis_Pa"]) for r in rows]
    first = next((i for i, p in enumerate(major) if p > 0), None)
    minor_first = next((i for i, p in enumerate(minor) if p > 0), None)
    k = {"final_pressure_mean": s["final_pressure_mean"], "non_uniformity": s["final_pressure_non_uniformity"],
         "final_major": major[-1], "final_minor": minor[-1],
         "axes_over_mean": (major[-1] - minor[-1]) / s["final_pressure_mean"],
         "first_contact_step": s["first_contact_step"], "austenite_step": s["austenite_step"],
         "minor_first_step": None if minor_first is None else minor_first + 1}
    if first is not None and minor_first is not None and minor_first > first:
        peak = max(major[first:minor_first])
        k.update(major_peak_before_minor=peak, major_before_minor=major[minor_first - 1],
                 major_peak_step=major.index(peak) + 1, loosening=1 - major[minor_first - 1] / peak)
    final = list(csv.DictReader(open(os.path.join(out, "contact-final.csv"))))
    p = [float(r["pressure"]) for r in final]
    k.update(bore_pressure_min=min(p), bore_pressure_max=max(p))
    if s["parameters"].get("mu", 0) > 0:
        k.update(tangential_over_normal=s["final_tangential_over_normal"],
                 tangential_over_normal_total=s["final_tangential_over_normal_total"],
                 nodes_sticking=s["final_nodes_sticking"], nodes_in_contact=s["final_nodes_in_contact"])
    return k


def run_case(scene, nr, nt):
    """One run of scene on the nr x nt ring (retried while the plugin is being rebuilt by someone else)."""
    path = os.path.relpath(mesh(nr, nt), ROOT)
    out = os.path.join(OUT, "runs", scene, f"nr{nr}-nt{nt}")
    for attempt in range(30):
        sha = plugin_sha()
        cpu = sum(resource.getrusage(resource.RUSAGE_CHILDREN)[:2])
        wall, s, message = run(f"edp/scenes/{scene}.edp", out, "-scale", "paper", "-quiet", 1, "-vtkevery", 0,
                               "-tol", 0, "-mesh", path, allow_failure=True)
        cpu = sum(resource.getrusage(resource.RUSAGE_CHILDREN)[:2]) - cpu
        if s is not None or "plugin" not in message:
            break
        print(f"elliptic_mesh_study: {scene} {nr} x {nt}: {message}; again in 60 s", flush=True)
        time.sleep(60)
    row = {"scene": scene, "nr": nr, "nt": nt, "mesh": path, "history": os.path.relpath(os.path.join(out, "history.csv"), ROOT),
           "process_seconds": wall, "cpu_seconds": cpu, "plugin_sha256_16": sha, "attempts": attempt + 1}
    if s is None:
        row["failure"] = message
        print(f"elliptic_mesh_study: {scene} {nr} x {nt} FAILED: {message}", flush=True)
        return row
    row.update(loop_seconds=s["wall_seconds"], nodes=s["nodes"], triangles=s["triangles"], n_steps=s["n_steps"],
               steps_retried=s["steps_retried"], step_splits=s.get("step_splits"),
               unconverged_steps=s["unconverged_steps"], time_error_estimate=s["time_error_estimate"],
               time_error_estimate_transient=s["time_error_estimate_transient"], figures=key_figures(out, s))
    print(f"elliptic_mesh_study: {scene} {nr:3d} x {nt:3d}: {row['nodes']} nodes, CPU {cpu:.1f} s, loop "
          f"{row['loop_seconds']:.1f} s, final {s['final_pressure_mean'] / 1e6:.4f} MPa", flush=True)
    return row


def save_record(rec):
    write_json(os.path.join(OUT, "summary.json"), rec)


def measure(reference_n, resume):
    old = json.load(open(os.path.join(OUT, "summary.json"))) if resume and os.path.exists(os.path.join(OUT, "summary.json")) else {}
    done = {(r["scene"], r["nr"], r["nt"]): r for r in old.get("rows", []) if "failure" not in r}
    rec = {"machine": machine(), "started": time.strftime("%Y-%m-%d %H:%M"), "reference_n": reference_n,
           "ladder": LADDER, "layers": LAYERS, "nt_default": NT_DEFAULT, "steps": 1500, "rows": []}
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True)
    rec["commit"] = head.stdout.strip()
    start = time.perf_counter()
    for scene in SCENES:
        for nr, nt in cases(reference_n):
            row = done.get((scene, nr, nt)) or run_case(scene, nr, nt)
            rec["rows"].append(row)
            rec["study_seconds"] = time.perf_counter() - start
            save_record(rec)
    rec["finished"] = time.strftime("%Y-%m-%d %H:%M")
    return rec


# ---- the errors, from the runs' histories ----
def windows(ref):
    """The reference's intervals: {kind: (t0, t1)}."""
    t_end = ref["t"][-1]
    t_A = min(austenite_time(ref) or t_end, t_end)
    t_R = reversion_time(ref)
    return {"l1": (0.0, t_end), "l1_transient": (0.0, t_A), "l1_before": (0.0, t_R), "l1_reversion": (t_R, t_A)}


def curve(h):
    return [0.0] + h["t"], [0.0] + h["pressure_mean"]


def distance(ha, hb, ref, span):
    """int |p_a - p_b| dt / int |p_ref| dt over span (exact for the piecewise linear curves)."""
    ta, pa = curve(ha)
    tb, pb = curve(hb)
    tr, pr = curve(ref)
    d = l1_errors(ta, pa, tb, pb, span[1], span[0])[0]
    return d / l1_errors(tr, pr, tr, [0.0] * len(pr), span[1], span[0])[0]


def richardson(ns, d1, d2):
    """Order p and the finest's error from D1 = |p(n1) - p(n2)|, D2 = |p(n2) - p(n3)| (p(n) = p* + A n^-p)."""
    n1, n2, n3 = ns
    if not (d1 > 0 and d2 > 0):
        return None, None

    def f(p):
        return (n1 ** -p - n2 ** -p) / (n2 ** -p - n3 ** -p)
    lo, hi, target = 0.01, 8.0, d1 / d2
    if not f(lo) <= target <= f(hi):
        return None, None
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if f(mid) < target else (lo, mid)
    p = (lo + hi) / 2
    return p, d2 / ((n3 / n2) ** p - 1)


def difference_fit(ns, ds):
    """k and C of D_i = C abs(n_i^-k - n_i+1^-k) (mesh_study.difference_order's k, C by least squares in log):
    the model p(n) = p* + A n^-k, whose error C n^-k needs no reference."""
    k = difference_order(ns, ds)
    c = float(np.exp(np.mean([math.log(d) - math.log(abs(a ** -k - b ** -k)) for d, a, b in zip(ds, ns, ns[1:])])))
    return {"k": k, "C": c, "n_target": (c / TARGET) ** (1 / k)}


def fit(ns, es):
    """log e = a + k log h, h = 1 / n: (k, a)."""
    k, a = np.polyfit(np.log(1.0 / np.array(ns, float)), np.log(es), 1)
    return float(k), float(a)


def analyse(rec):
    """rec["analysis"][scene]: each run's errors against the reference, the differences, orders, Richardson."""
    N = rec["reference_n"]
    rec["analysis"] = {}
    for scene in SCENES:
        rows = {(r["nr"], r["nt"]): r for r in rec["rows"] if r["scene"] == scene and "failure" not in r}
        if (N, N) not in rows:
            continue
        H = {key: read_history(os.path.join(ROOT, r["history"])) for key, r in rows.items()}
        ref = H[(N, N)]
        W = windows(ref)
        a = {"t_R": W["l1_reversion"][0], "t_A": W["l1_reversion"][1], "errors": {}}
        for key, r in rows.items():
            e = curve_error(os.path.join(ROOT, r["history"]), os.path.join(ROOT, rows[(N, N)]["history"]))
            a["errors"][f"{key[0]}x{key[1]}"] = {"l1": e["l1"], "l1_transient": e["l1_transient"],
                                                "l1_reversion": e["l1_reversion"], "final": e["final"],
                                                "l1_before": distance(H[key], ref, ref, W["l1_before"]),
                                                "austenite_dt": e.get("austenite_dt")}

        def D(k1, k2, kind):
            return distance(H[k1], H[k2], ref, W[kind])
        joint = [n for n in LADDER if (n, n) in rows]
        full = joint + [N]
        a["joint_differences"] = {kind: [D((m, m), (n, n), kind) for m, n in zip(full, full[1:])] for kind in KINDS}
        a["joint_difference_order"] = {kind: difference_order(full, ds) for kind, ds in a["joint_differences"].items()}
        a["joint_difference_fit"] = {}
        for kind, ds in a["joint_differences"].items():
            df = a["joint_difference_fit"][kind] = difference_fit(full, ds)
            df["reference_error"] = df["C"] * N ** -df["k"]
        a["fits"] = {}
        for kind in KINDS:
            es = [a["errors"][f"{n}x{n}"][kind] for n in joint]
            k, c = fit(joint, es)
            coarse = [n for n in joint if N / n >= 2.6]
            k2, c2 = fit(coarse, [a["errors"][f"{n}x{n}"][kind] for n in coarse])
            a["fits"][kind] = {"k": k, "log_c": c, "over": [joint[0], joint[-1]], "k_coarse": k2, "log_c_coarse": c2,
                               "over_coarse": [coarse[0], coarse[-1]],
                               "n_target": math.exp(-(math.log(TARGET) - c) / k),
                               "n_target_coarse": math.exp(-(math.log(TARGET) - c2) / k2)}
        a["richardson"] = {}
        for name, ns in (("finest", tuple(full[-3:])), ("ratio2", (N // 4, N // 2, N))):
            if not all((n, n) in rows for n in ns):
                continue
            a["richardson"][name] = {"n": list(ns)}
            for kind in KINDS:
                d1, d2 = D((ns[0], ns[0]), (ns[1], ns[1]), kind), D((ns[1], ns[1]), (ns[2], ns[2]), kind)
                p, err = richardson(ns, d1, d2)
                a["richardson"][name][kind] = {"d1": d1, "d2": d2, "p": p, "error": err}
        layers = [n for n in LAYERS if (n, NT_DEFAULT) in rows]
        a["layer_differences"] = {kind: [D((m, NT_DEFAULT), (n, NT_DEFAULT), kind) for m, n in zip(layers, layers[1:])]
                                  for kind in KINDS}
        a["layer_difference_order"] = {kind: difference_order(layers, ds) if len(ds) >= 2 else None
                                       for kind, ds in a["layer_differences"].items()}
        a["layer_difference_fit"] = {kind: difference_fit(layers, ds) for kind, ds in a["layer_differences"].items()
                                     if len(ds) >= 2}
        a["layer_span"] = {kind: D((layers[0], NT_DEFAULT), (layers[-1], NT_DEFAULT), kind) for kind in KINDS}
        a["arc_differences"] = {str(n): {kind: D((n, n), (n, NT_DEFAULT), kind) for kind in KINDS}
                                for n in LAYERS if (n, n) in rows and (n, NT_DEFAULT) in rows}
        rec["analysis"][scene] = a
    return rec


# ---- the page ----
if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", action="store_true", help="make the runs (else read results/elliptic-mesh-study/summary.json)")
    parser.add_argument("--resume", action="store_true", help="with --run: keep the runs summary.json already has")
    parser.add_argument("--analyse", action="store_true", help="the errors again from the runs' histories")
    parser.add_argument("--reference", type=int, default=REFERENCE_N, help=f"nr = nt of the reference (default {REFERENCE_N})")
    opts = parser.parse_args()
    if opts.run:
        rec = measure(opts.reference, opts.resume)
        save_record(rec)
    else:
        rec = json.load(open(os.path.join(OUT, "summary.json")))
    if opts.run or opts.analyse:
        analyse(rec)
        save_record(rec)
    from elliptic_mesh_page import write_doc  # (the page: its own module)
    write_doc(rec)
    print(f"elliptic_mesh_study: {os.path.relpath(DOC, ROOT)}, docs/benchmarks/{PNG}, results/elliptic-mesh-study/")
