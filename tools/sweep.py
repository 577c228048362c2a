#!/usr/bin/python3
"""Sweeps one option of a scene: runs each value (in parallel up to the cores), then writes a table
and overlay figures.

Usage: tools/sweep.py SCENE PARAM VALUE [VALUE ...] [--jobs N] [--out DIR] [-- SCENE OPTIONS ...]
       (make sweep SCENE=... PARAM=... VALUES='...' [ARGS='...'] [JOBS=2] [OUT=dir])
PARAM is an option name without its dash (g, mu, steps); the options after `--` (or, from make,
in the environment variable SWEEP_ARGS, split into words and never run by a shell) go to every
run. Writes DIR (default results/sweeps/<scene>-<param>):
  <param>=<value>/     each run's own results folder
  table.csv            one row per value: the summary's key figures, each column named with its unit
  force-temperature.png, force-time.png   the sleeve scenes: the mean contact pressure (MPa) against
                       the mean inner-surface temperature (C), and against time, zoomed on the
                       transient (the whole run in a small panel); curves that coincide within
                       0.1 % share a legend entry that says so
  sweep.json           the scene, the parameter, the values, the other options, each run's folder
A value that fails stops nothing else; the sweep then exits 1 naming it.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import shlex
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sma_driver as sma  # noqa: E402
from units import KELVIN_AT_0C  # noqa: E402

# Key figures of summary.json, in table order: (key, column name with its unit).
TABLE_KEYS = [("first_contact_step", "first_contact_step"), ("austenite_step", "austenite_step"),
              ("final_pressure_mean", "final_pressure_mean_Pa"), ("peak_pressure_mean", "peak_pressure_mean_Pa"),
              ("final_pressure_non_uniformity", "final_pressure_non_uniformity"),
              ("T_inner_first_contact", "T_inner_first_contact_K"), ("T_inner_austenite", "T_inner_austenite_K"),
              ("fixed_point_iterations_max", "fixed_point_iterations_max"),
              ("dc_iterations_max", "dc_iterations_max"), ("psor_sweeps_max", "psor_sweeps_max"),
              ("wall_seconds", "wall_seconds")]
COINCIDE = 1e-3  # relative: curves closer than this share a legend entry


def parse(argv):
    extra = []
    if "--" in argv:
        cut = argv.index("--")
        argv, extra = argv[:cut], argv[cut + 1:]
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("param")
    parser.add_argument("values", nargs="+")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--out")
    args = parser.parse_args(argv)
    try:
        args.extra = extra + shlex.split(os.environ.get("SWEEP_ARGS", ""))
    except ValueError as e:
        parser.error(f"ARGS: {e}")
    return args


def extra_options(scene, words):
    """The -name value pairs of `words` as {name: value}, each checked against the scene."""
    if len(words) % 2:
        raise sma.SceneError(f"the options {' '.join(words)} are not -name value pairs")
    pairs = {}
    for name, value in zip(words[::2], words[1::2]):
        if not name.startswith("-"):
            raise sma.SceneError(f"'{name}' is not an option name (-name value pairs)")
        pairs[name[1:]] = value
    for name in pairs:
        sma.check_option(scene, name)
    return pairs


def coincident_groups(curves):
    """Indices grouped by curves (x, y arrays on the same steps) within COINCIDE of each other."""
    groups = []
    for i, (_, y) in enumerate(curves):
        scale = max(np.abs(y).max(), 1e-300)
        for group in groups:
            _, y0 = curves[group[0]]
            if len(y0) == len(y) and np.abs(y - y0).max() <= COINCIDE * scale:
                group.append(i)
                break
        else:
            groups.append([i])
    return groups


def figures(out, param, values, results, plt):
    """Draws the two overlays; returns (paths written, the groups of values whose curves coincide)."""
    histories = [r.history for r in results]
    if any(h is None or "pressure_mean" not in h for h in histories):
        return [], []
    labels, temperature, time = [], [], []
    for v, h in zip(values, histories):
        temperature.append((h["T_inner_mean"] - KELVIN_AT_0C, h["pressure_mean"] / 1e6))
        time.append((h["t"], h["pressure_mean"] / 1e6))
    groups = coincident_groups(time)
    for group in groups:
        names = ", ".join(f"{param} = {values[i]}" for i in group)
        labels.append(names + (" (coincide within 0.1 %)" if len(group) > 1 else ""))
    written = []
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for group, label in zip(groups, labels):
        x, y = temperature[group[0]]
        ax.plot(x, y, lw=1.2, label=label)
    ax.set_xlabel("mean inner-surface temperature (C)")
    ax.set_ylabel("mean contact pressure (MPa)")
    ax.set_title(f"{results[0].summary.get('scene', '')}: sweep of -{param}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    written.append(save(fig, os.path.join(out, "force-temperature.png"), plt))
    # Against time: the transient (up to a little after the last run's austenite) in the main
    # panel, the whole run in a small one.
    ends = [r.summary.get("austenite_step", -1) * r.summary["parameters"]["dt"] for r in results
            if "parameters" in r.summary and "dt" in r.summary["parameters"]]
    t_end = max(h["t"][-1] for h in histories)
    zoom = min(t_end, 1.3 * max(ends)) if ends and max(ends) > 0 else t_end
    fig, (ax, whole) = plt.subplots(1, 2, figsize=(10, 4.5), gridspec_kw={"width_ratios": [3, 1]})
    for group, label in zip(groups, labels):
        x, y = time[group[0]]
        ax.plot(x, y, lw=1.2, label=label)
        whole.plot(x, y, lw=0.8)
    ax.set_xlim(0, zoom)
    ax.set_xlabel("time (s), the transient")
    ax.set_ylabel("mean contact pressure (MPa)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    whole.set_xlabel("time (s), the whole run")
    whole.axvspan(0, zoom, color="0.9")
    whole.grid(alpha=0.3)
    fig.suptitle(f"{results[0].summary.get('scene', '')}: sweep of -{param}")
    fig.tight_layout()
    written.append(save(fig, os.path.join(out, "force-time.png"), plt))
    return written, [[values[i] for i in group] for group in groups]


def save(fig, path, plt):
    partial = path[:-len(".png")] + ".partial.png"
    fig.savefig(partial, dpi=110)
    plt.close(fig)
    os.replace(partial, path)
    return path


def main(argv):
    args = parse(argv)
    try:
        sma.script(args.scene)
        sma.check_option(args.scene, args.param)
        fixed = extra_options(args.scene, args.extra)
    except sma.SceneError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    if args.param in fixed:
        print(f"error: -{args.param} is swept; do not also give it among the options", file=sys.stderr)
        return 2
    for v in args.values:
        if "/" in v or v in (".", ".."):
            print(f"error: the value '{v}' cannot name a folder", file=sys.stderr)
            return 2
    out = args.out or os.path.join(sma.ROOT, "results", "sweeps", f"{args.scene}-{args.param}")
    os.makedirs(out, exist_ok=True)
    jobs = max(1, min(args.jobs, os.cpu_count() or 1, len(args.values)))
    folders = [os.path.join(out, f"{args.param}={v}") for v in args.values]

    def one(i):
        return sma.run(args.scene, folders[i], **fixed, **{args.param: args.values[i]})

    failures = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(one, i): i for i in range(len(args.values))}
        for future in concurrent.futures.as_completed(futures):
            i = futures[future]
            try:
                future.result()
                print(f"sweep: -{args.param} {args.values[i]} done", flush=True)
            except sma.SceneError as e:
                failures[i] = str(e)
                print(f"error: -{args.param} {args.values[i]}: {e}", file=sys.stderr, flush=True)
    done = [i for i in range(len(args.values)) if i not in failures]
    results = {i: sma.read(folders[i]) for i in done}
    present = [(k, col) for k, col in TABLE_KEYS if any(k in r.summary for r in results.values())]
    with open(os.path.join(out, "table.csv.partial"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([args.param] + [col for _, col in present])
        for i in done:
            w.writerow([args.values[i]] + [results[i].summary.get(k, "") for k, _ in present])
    os.replace(os.path.join(out, "table.csv.partial"), os.path.join(out, "table.csv"))
    written, groups = [], []
    if done:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        written, groups = figures(out, args.param, [args.values[i] for i in done], [results[i] for i in done], plt)
    record = {"scene": args.scene, "param": args.param, "values": args.values, "options": fixed,
              "runs": [{"value": v, "out": folders[i], "status": "failed" if i in failures else "done",
                        **({"error": failures[i]} if i in failures else {})} for i, v in enumerate(args.values)],
              "jobs": jobs, "figures": [os.path.basename(p) for p in written],
              "curves_coinciding_within_0.1_percent": [g for g in groups if len(g) > 1]}
    with open(os.path.join(out, "sweep.json.partial"), "w") as f:
        json.dump(record, f, indent=2, allow_nan=False)
    os.replace(os.path.join(out, "sweep.json.partial"), os.path.join(out, "sweep.json"))
    if not written:
        print("sweep: no history.csv with a contact pressure: the table only")
    print(f"sweep: {len(done)} of {len(args.values)} runs; table.csv and figures in {out}/")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
