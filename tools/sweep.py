#!/usr/bin/python3
"""Sweeps one option of a scene: runs each value (in parallel up to the cores), then writes a table
and overlay figures.

Usage: tools/sweep.py SCENE PARAM VALUE [VALUE ...] [--jobs N] [--out DIR] [--env-args NAME]
                      [-- SCENE OPTIONS ...]
       make sweep SCENE=... PARAM=... VALUES='...' [ARGS='...'] [JOBS=2] [OUT=dir]
PARAM is an option name without its dash (g, mu, steps); a value may be negative (-5e-6). The
options after `--` go to every run; so do those in the environment variable NAME with --env-args
(make sweep's ARGS: split into words like a shell's, quotes grouping, but never run by one, so a
`;` or `$(...)` in it is a character). --jobs N runs min(N, cores, values) at a time (default:
the cores). Writes DIR (default results/sweeps/<scene>-<param>):
  <param>=<value>/     each run's own results folder
  table.csv            one row per finished value: the summary's key figures (first contact and
                       austenite: step, time, inner temperature; final and peak mean pressure;
                       iteration maxima; wall time), each column named with its unit; a scene
                       without those keys (beam, ring-lame, free-ring): every number of its
                       summary.json, named by its key (docs/outputs.md gives the units)
  force-temperature.png, force-time.png   scenes whose history.csv has a contact pressure: the
                       mean contact pressure (MPa) against the mean inner-surface temperature (C),
                       and against time (s) zoomed on the transient (0 to a quarter past the last
                       run's austenite), the whole run in a small panel; curves that coincide
                       within 0.1 % share a legend entry that says so. Other scenes: the table only
                       (said on the console and in sweep.json)
  sweep.json           the scene, the parameter, the values, the other options, each run's folder
                       and status
Reads history.csv and summary.json only. Bad input (scene, option, value) fails before any run,
exit 2, naming it; a value whose run fails stops nothing else: the sweep then exits 1 naming it.
"""
import concurrent.futures
import csv
import json
import os
import re
import shlex
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import children  # noqa: E402
import results_io  # noqa: E402
import sma_driver as sma  # noqa: E402
from units import KELVIN_AT_0C  # noqa: E402

# The key figures of a sleeve summary.json, in table order: (key, column named with its unit).
# The times come from history.csv (the t of the step's row); iteration maxima are appended after
# them in the summary's order (every key ending in _iterations_max or _sweeps_max).
KEY_FIGURES = [("first_contact_step", "first_contact_step"), ("first_contact_time", "first_contact_time_s"),
               ("T_inner_first_contact", "T_inner_first_contact_K"),
               ("austenite_step", "austenite_step"), ("austenite_time", "austenite_time_s"),
               ("T_inner_austenite", "T_inner_austenite_K"),
               ("final_pressure_mean", "final_pressure_mean_Pa"), ("peak_pressure_mean", "peak_pressure_mean_Pa"),
               ("peak_step", "peak_step"), ("final_pressure_non_uniformity", "final_pressure_non_uniformity"),
               ("lame_pressure", "lame_pressure_Pa")]  # (the radial model: Lame's closed form at the end)
TRAILING_FIGURES = [("unconverged_loops", "unconverged_loops"), ("wall_seconds", "wall_s")]
STEP_TIMES = {"first_contact_time": "first_contact_step", "austenite_time": "austenite_step"}
COINCIDE = 1e-3  # relative to a curve's largest |pressure|: curves closer share a legend entry
ZOOM_PAST_AUSTENITE = 1.25  # the transient panel ends a quarter past the last austenite time
# Folders are named <param>=<value>: a value must not leave DIR.
BAD_VALUE_CHARACTERS = ("/", "\0")


# The unit symbols an option's meaning may give in parentheses: "Young's modulus (Pa)",
# "heat exchange coefficient (W/(m^2 K))"; a group with any other word ("(0 included: ...)") is prose.
UNIT_WORDS = {"m", "mm", "um", "s", "K", "C", "Pa", "MPa", "GPa", "W", "J", "kg", "N", "deg", "rad"}


def unit_of(meaning):
    """The unit an option's meaning gives (the first parenthesised group made only of unit symbols,
    powers and operators), or "" (a count, a switch, a name)."""
    depth, start = 0, None
    for i, c in enumerate(meaning):
        if c == "(":
            if depth == 0:
                start = i + 1
            depth += 1
        elif c == ")" and depth > 0:
            depth -= 1
            if depth == 0:
                group = meaning[start:i]
                words = [w for w in re.split(r"[\s()/*^.\-0-9]+", group) if w]
                if words and all(w in UNIT_WORDS for w in words):
                    return group
    return ""


def value_label(param, value, unit):
    """A legend entry: "-interference 5e-05 m" (the option as typed, with its unit)."""
    return f"-{param} {value}" + (f" {unit}" if unit else "")


class BadInput(Exception):
    """A bad command line: reported as `error: ...`, exit 2, before anything runs."""


def parse(argv):
    """{scene, param, values, jobs, out, extra}. Written by hand rather than with argparse, which
    takes a negative value such as -5e-6 for an unknown option."""
    if any(a in ("-h", "--help") for a in argv[:argv.index("--") if "--" in argv else len(argv)]):
        print(__doc__)
        sys.exit(0)
    extra = []
    if "--" in argv:
        cut = argv.index("--")
        argv, extra = argv[:cut], list(argv[cut + 1:])
    flags = {"--jobs": None, "--out": None, "--env-args": None, "--env-values": None}
    positional = []
    i = 0
    while i < len(argv):
        arg = argv[i]
        name, _, inline = arg.partition("=")
        if name in flags:
            if inline:
                flags[name] = inline
            elif i + 1 < len(argv):
                i += 1
                flags[name] = argv[i]
            else:
                raise BadInput(f"{name} needs a value")
        elif arg.startswith("--"):
            raise BadInput(f"unknown flag {arg} (flags: {', '.join(flags)}; scene options go after --)")
        else:
            positional.append(arg)
        i += 1
    if flags["--env-values"]:
        # make sweep's VALUES: words of a variable, never flags (VALUES='--out=x 500' is a value)
        positional += os.environ.get(flags["--env-values"], "").split()
    if flags["--out"] is not None and not flags["--out"].strip():
        raise BadInput("--out (OUT) is empty: give a folder, or leave it out for results/sweeps/<scene>-<param>")
    if len(positional) < 3:
        raise BadInput("usage: tools/sweep.py SCENE PARAM VALUE [VALUE ...] [--jobs N] [--out DIR] "
                       "[-- SCENE OPTIONS ...]")
    jobs = os.cpu_count() or 1
    if flags["--jobs"] is not None:
        try:
            jobs = int(flags["--jobs"])
        except ValueError:
            jobs = 0
        if jobs < 1:
            raise BadInput(f"--jobs (JOBS) '{flags['--jobs']}' is not a whole number >= 1")
    if flags["--env-args"]:
        variable = flags["--env-args"]
        try:
            extra += shlex.split(os.environ.get(variable, ""))
        except ValueError as e:
            label = "ARGS" if variable == "SWEEP_ARGS" else variable
            raise BadInput(f"{label}: {e} (quote each value whole: ARGS=\"-mesh 'my dir/m.msh'\")") from None
    param = positional[1]
    if param.startswith("-"):
        raise BadInput(f"PARAM '{param}': give the option's name without its dash ({param.lstrip('-')})")
    if param in ("out", "help"):
        raise BadInput(f"PARAM '{param}' cannot be swept (-out is each run's folder DIR/<param>=<value>, "
                       "-help lists the options)")
    return {"scene": positional[0], "param": param, "values": positional[2:], "jobs": jobs,
            "out": flags["--out"], "extra": extra}


def extra_options(scene, param, words):
    """The -name value pairs of `words` as {name: value}, each checked against the scene."""
    pairs = {}
    i = 0
    while i < len(words):
        name = words[i]
        if not name.startswith("-") or len(name) < 2:
            raise BadInput(f"'{name}' among the scene options is not an option name (options are "
                           f"-name value pairs: ARGS='-steps 300 -mesh meshes/sleeve-coarse.msh')")
        if i + 1 >= len(words):
            raise BadInput(f"the option {name} has no value (options are -name value pairs)")
        pairs[name[1:]] = words[i + 1]
        i += 2
    for name in pairs:
        if name in ("out", "help"):
            raise BadInput(f"-{name} cannot be given to a sweep (each run's folder is DIR/<param>=<value>; "
                           f"OUT=dir moves DIR)" if name == "out" else
                           f"-help lists the options: tools/ff {sma.script(scene)} -help")
        if name == param:
            raise BadInput(f"-{param} is swept; do not also give it among the scene options")
        sma.check_option(scene, name)
    return pairs


def check_values(param, values):
    for v in values:
        if not v or any(c in v for c in BAD_VALUE_CHARACTERS) or v in (".", ".."):
            raise BadInput(f"the value '{v}' of -{param} cannot name a folder ({param}={v})")
        if v.startswith("--"):
            raise BadInput(f"the value '{v}' of -{param} looks like a flag: flags go to --jobs/--out (JOBS=, OUT=)")
    repeated = sorted({v for v in values if values.count(v) > 1})
    if repeated:
        raise BadInput(f"the value(s) {' '.join(repeated)} of -{param} are given twice (one folder each)")


def step_time(history, step):
    """The time t (s) at the end of `step` (history.csv's row), or None (null: never, or no row)."""
    if history is None or step is None or step < 1 or "step" not in history:
        return None
    rows = np.nonzero(history["step"] == step)[0]
    return float(history["t"][rows[0]]) if len(rows) else None


def figures_of(summary, history):
    """{key: value} of one run's key figures (the times from history.csv)."""
    figures = dict(summary)
    for time_key, step_key in STEP_TIMES.items():
        if step_key in summary:
            figures[time_key] = step_time(history, summary[step_key])
    return figures


def flattened_numbers(summary):
    """(column, value) of every number in a summary without the sleeve's key figures: the top
    level's, then those of its lists of named entries as <name>.<key> (beam's meshes, ring-lame's
    levels), parameters excluded (they are the options)."""
    out = []
    for key, value in summary.items():
        if key == "parameters":
            continue
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            out.append((key, value))
        elif isinstance(value, list):
            for k, entry in enumerate(value):
                if isinstance(entry, dict):
                    label = entry.get("name", str(k))
                    out += [(f"{label}.{sub}", v) for sub, v in entry.items()
                            if isinstance(v, (int, float)) and not isinstance(v, bool)]
    return out


def table_columns(runs):
    """[(key, column)] of the table: the key figures that any run has, else every number."""
    keys = set().union(*(r.keys() for r in runs)) if runs else set()
    if not any(k in keys for k, _ in KEY_FIGURES if k not in STEP_TIMES):
        return None
    iterations = []
    for r in runs:
        iterations += [k for k in r if (k.endswith("_iterations_max") or k.endswith("_sweeps_max"))
                       and k not in iterations]
    return ([(k, c) for k, c in KEY_FIGURES if k in keys] + [(k, k) for k in iterations]
            + [(k, c) for k, c in TRAILING_FIGURES if k in keys])


def write_table(path, param, values, runs):
    """table.csv; returns its columns. A figure a run lacks (or null: the event never happened) is empty."""
    columns = table_columns(runs)
    if columns is not None:
        header = [param] + [c for _, c in columns]
        rows = [[v] + ["" if r.get(k) is None else r[k] for k, _ in columns] for v, r in zip(values, runs)]
    else:
        flat = [dict(flattened_numbers(r)) for r in runs]
        names = []
        for f in flat:
            names += [n for n in f if n not in names]
        header = [param] + names
        rows = [[v] + [f.get(n, "") for n in names] for v, f in zip(values, flat)]
    results_io.record(path)
    with open(path + ".partial", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    os.replace(path + ".partial", path)
    return header


def same_curve(a, b):
    """Whether two (t, p) curves agree within COINCIDE of the larger |p| at every time of `a`
    inside both (b interpolated when the steps differ); the runs must end at the same time."""
    (ta, pa), (tb, pb) = a, b
    if abs(ta[-1] - tb[-1]) > 1e-9 * max(abs(ta[-1]), 1e-300):
        return False
    pb_on_a = pb if len(ta) == len(tb) and np.array_equal(ta, tb) else np.interp(ta, tb, pb)
    scale = max(np.abs(pa).max(), np.abs(pb).max(), 1e-300)
    return bool(np.abs(pa - pb_on_a).max() <= COINCIDE * scale)


def coincident_groups(curves):
    """Indices of `curves` grouped: each curve joins the first group whose first curve it
    coincides with (same_curve)."""
    groups = []
    for i, curve in enumerate(curves):
        for group in groups:
            if same_curve(curves[group[0]], curve):
                group.append(i)
                break
        else:
            groups.append([i])
    return groups


def draw(out, scene, param, values, runs, plt, unit="", fixed=None):
    """The two overlays; returns (the paths written, the groups of values whose curves coincide)."""
    from plot_sleeve import save  # every tool's PNGs: a temporary name, then renamed
    histories = [r.history for r in runs]
    temperature = [(h["T_inner_mean"] - KELVIN_AT_0C, h["pressure_mean"] / 1e6) for h in histories]
    time = [(h["t"], h["pressure_mean"] / 1e6) for h in histories]
    groups = coincident_groups(time)
    labels = [", ".join(value_label(param, values[i], unit) for i in g) + (" (coincide within 0.1 %)" if len(g) > 1 else "")
              for g in groups]
    # The options every run shares, in the title: the figure says what was held fixed.
    held = " ".join(f"-{k} {v}" for k, v in (fixed or {}).items())
    title = f"{scene}: sweep of -{param}" + (f"\n(all runs: {held})" if held else "")
    written = []

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for group, label in zip(groups, labels):
        ax.plot(*temperature[group[0]], lw=1.2, label=label)
    ax.set_xlabel("mean inner-surface temperature (°C)")
    ax.set_ylabel("mean contact pressure (MPa)")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    written.append(os.path.join(out, "force-temperature.png"))
    save(fig, written[-1], 110)

    # Against time: the transient in the main panel, up to a quarter past the last run's austenite
    # (the whole run when one never turns austenite), the whole run in a small panel beside it.
    t_end = max(float(h["t"][-1]) for h in histories)
    austenite = [step_time(r.history, r.summary.get("austenite_step")) for r in runs]
    zoom = t_end if None in austenite else min(t_end, ZOOM_PAST_AUSTENITE * max(austenite))
    fig, (ax, whole) = plt.subplots(1, 2, figsize=(10, 4.5), gridspec_kw={"width_ratios": [3, 1]})
    for group, label in zip(groups, labels):
        ax.plot(*time[group[0]], lw=1.2, label=label)
        whole.plot(*time[group[0]], lw=0.8)
    ax.set_xlim(0, zoom)
    ax.set_xlabel("time (s): the transient")
    ax.set_ylabel("mean contact pressure (MPa)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    whole.axvspan(0, zoom, color="0.9", label="left panel")
    whole.set_xlabel("time (s): the whole run")
    whole.set_ylabel("mean contact pressure (MPa)")
    whole.grid(alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    written.append(os.path.join(out, "force-time.png"))
    save(fig, written[-1], 110)
    return written, [[values[i] for i in g] for g in groups]


def write_json(path, record):
    results_io.record(path)
    with open(path + ".partial", "w") as f:
        json.dump(record, f, indent=2, allow_nan=False)
    os.replace(path + ".partial", path)


def main(argv):
    try:
        args = parse(argv)
        scene, param, values = args["scene"], args["param"], args["values"]
        sma.script(scene)
        sma.check_option(scene, param)
        fixed = extra_options(scene, param, args["extra"])
        check_values(param, values)
        for v in values:  # each value against the option's type, before anything runs
            sma.word(scene, param, v)
    except (BadInput, sma.SceneError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    out = args["out"] or os.path.join(sma.ROOT, "results", "sweeps", f"{scene}-{param}")
    # Taken as a scene takes its -out: a folder holding anything its manifest does not list is
    # refused untouched; an earlier sweep's runs, table and figures go first.
    try:
        results_io.claim(out, "sweep " + scene)
    except results_io.ResultsError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    try:
        return run_all(out, scene, param, values, args, fixed)
    finally:
        results_io.release(out)


def run_all(out, scene, param, values, args, fixed):
    """Runs every value into its folder of `out` (taken), then publishes the table and figures."""
    jobs = max(1, min(args["jobs"], os.cpu_count() or 1, len(values)))
    folders = [os.path.join(out, f"{param}={v}") for v in values]
    print(f"sweep: {scene} -{param} over {' '.join(values)} ({jobs} at a time) into {out}/", flush=True)

    def one(i):
        return sma.run(scene, folders[i], **fixed, **{param: values[i]})

    failures = {}
    # Threads suffice: each one waits on its FreeFEM process.
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(one, i): i for i in range(len(values))}
        for future in concurrent.futures.as_completed(futures):
            i = futures[future]
            try:
                future.result()
                print(f"sweep: -{param} {values[i]} done", flush=True)
            except sma.SceneError as e:
                failures[i] = str(e)
                print(f"error: -{param} {values[i]}: {e}", file=sys.stderr, flush=True)
    results = []
    for i in range(len(values)):
        if i in failures:
            continue
        try:
            results.append(sma.read(folders[i]))
        except sma.SceneError as e:
            failures[i] = str(e)
            print(f"error: -{param} {values[i]}: {e}", file=sys.stderr, flush=True)
    done = [i for i in range(len(values)) if i not in failures]
    done_values = [values[i] for i in done]
    try:
        return publish(out, scene, param, values, args, fixed, jobs, folders, failures, done, done_values, results)
    except OSError as e:  # a full disk, a file-size limit: the table or a figure could not be written
        where = f" {e.filename}" if e.filename else ""
        print(f"error: the sweep's runs finished, but writing its results failed: cannot write{where}: "
              f"{e.strerror or e}", file=sys.stderr)
        return 1


def publish(out, scene, param, values, args, fixed, jobs, folders, failures, done, done_values, results):
    """table.csv, the overlay figures and sweep.json of the finished runs; 0, or 1 when a run failed."""
    header = write_table(os.path.join(out, "table.csv"), param, done_values,
                         [figures_of(r.summary, r.history) for r in results])

    drawn = results and all(r.history is not None and "pressure_mean" in r.history for r in results)
    written, groups, note = [], [], None
    if drawn:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        unit = unit_of(sma.options(scene)[param]["meaning"])
        written, groups = draw(out, scene, param, done_values, results, plt, unit, fixed)
    else:
        if results:
            note = f"{scene} writes no history.csv with a contact pressure (pressure_mean): the table only"
            print(f"sweep: {note}")
    write_json(os.path.join(out, "sweep.json"), {
        "scene": scene, "param": param, "param_meaning": sma.options(scene)[param]["meaning"],
        "values": values, "args": args["extra"], "options": fixed, "jobs": jobs,
        "runs": [{"value": v, "out": folders[i], "status": "failed" if i in failures else "done",
                  **({"error": failures[i]} if i in failures else {})} for i, v in enumerate(values)],
        "table": "table.csv", "table_columns": header,
        "figures": [os.path.basename(p) for p in written],
        "curves_coinciding_within_0.1_percent": [g for g in groups if len(g) > 1],
        **({"note": note} if note else {})})
    print(f"sweep: {len(done)} of {len(values)} runs; table.csv{', figures' if written else ''} "
          f"and sweep.json in {out}/")
    if failures:
        print(f"error: the sweep's run(s) for -{param} {' '.join(values[i] for i in sorted(failures))} failed "
              f"(sweep.json has each error)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    children.install()
    sys.exit(main(sys.argv[1:]))
