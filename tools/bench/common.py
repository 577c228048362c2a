"""What the sections of make bench (tools/bench/bench.py) share: where they write, how they run a
script (tools/ff), the machine, the fits of their tables and the saving of their figures."""
import json
import math
import os
import platform
import subprocess
import sys
import time

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# tools/ (results_io: this checkout's sma package, which reads the CSVs and writes the PNGs whole)
# and the independent oracles the sections measure against (tools/bench/oracles).
sys.path[:0] = [TOOLS, os.path.join(TOOLS, "bench", "oracles")]
from results_io import read_csv  # noqa: E402,F401  (the sections' CSV reader: a damaged file named)
from scene_steps import fixed_steps  # noqa: E402
from sma.plotting import save as save_png  # noqa: E402

ROOT = os.path.dirname(TOOLS)
OUT = os.path.join(ROOT, "results", "bench")
DOC = os.path.join(ROOT, "docs", "benchmarks.md")
PNG_DIR = os.path.join(ROOT, "docs", "benchmarks")
QUICK = "--quick" in sys.argv


# The heat <-> fraction fixed point's limit for the fine levels (a limit only: nothing changes where
# the loop converges below it). The fixed point takes up to about 200 iterations at a few steps of
# the finest radial levels, and where it ends near the default limit of 200 round-off decides
# (docs/parameters.md, sleeve-radial); measured: 212 at nr 640, 4800 steps over 30 s.
FINE_FPMAXIT = ["-fpmaxit", 1000]


def write_whole(path, text):
    """path written as path.partial, then renamed: a run stopped meanwhile leaves no cut file."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path + ".partial", "w") as f:
        f.write(text)
    os.replace(path + ".partial", path)


def write_json(path, data):
    """data as JSON (indented; a NaN fails here, not in a reader), written whole."""
    write_whole(path, json.dumps(data, indent=2, allow_nan=False))


def without_companion(script, args):
    """["-meshestimate", "0"] for a sleeve scene whose args do not ask for the mesh estimate (its
    default companion, a second run, would enter the timings and the compared files), else []."""
    words = [str(a) for a in args]
    asked = "-meshestimate" in words or "-balance" in words
    return ["-meshestimate", "0"] if "/sleeve-" in str(script) and not asked else []


def run(script, out, *args, allow_failure=False, result="summary.json", env=None):
    """Runs tools/ff script -out out args (env: variables added to the environment); returns
    (process wall seconds, the JSON file `result` it wrote in out or None, the error message or "")."""
    os.makedirs(out, exist_ok=True)
    # The bench measures the reduced scale (docs/benchmarks.md: its studies were built there).
    scale = ["-scale", "reduced"] if "/sleeve-" in script and "-scale" not in args else []
    # Its studies refine fixed steps: a sleeve run takes them (-tol 0: the scene's -steps) unless its
    # args choose the steps (-steps, -dt, -tol; time_steps.py sets the adaptive default's -tol).
    steps = fixed_steps(args) if "/sleeve-" in script else []
    # Its timings are a run's, not its mesh estimate's companion's (the sleeve scenes' default): the
    # studies that want the estimate ask for it (-meshestimate, -balance).
    estimate = without_companion(script, args)
    start = time.perf_counter()
    proc = subprocess.run([os.path.join(ROOT, "tools", "ff"), script, "-out", out, *scale, *steps, *estimate,
                           *map(str, args)],
                          cwd=ROOT, capture_output=True, text=True, env=dict(os.environ, **(env or {})))
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        # FreeFEM prints a script's error: line on stdout, its own errors on stderr
        lines = (proc.stdout + "\n" + proc.stderr).splitlines()
        errors = [l for l in lines if l.startswith("error:")]
        message = errors[-1] if errors else (lines[-1] if lines else "(no message)")
        if not allow_failure:
            sys.exit(f"bench: {script} {' '.join(map(str, args))} failed: {message}")
        return wall, None, message
    path = os.path.join(out, result)
    summary = json.load(open(path)) if os.path.exists(path) else None
    return wall, summary, ""


def time_goals(rows, paper, target, seconds, loose, share):
    """A work-precision section's two goals (issue 48): the quickest of rows within `target` over the
    reversion window (l1_reversion) in at most `seconds` of whole process (process_seconds), and the
    quickest within `loose` in at most `share` of the fixed steps' run `paper`. Returns their records."""
    best = min((r for r in rows if r["l1_reversion"] <= target), key=lambda r: r["process_seconds"], default=None)
    fast = min((r for r in rows if r["l1_reversion"] <= loose), key=lambda r: r["process_seconds"], default=None)
    return ({"target": target, "seconds": seconds, "best": best,
             "met": best is not None and best["process_seconds"] <= seconds},
            {"target": loose, "share": share, "best": fast,
             "share_measured": fast["process_seconds"] / paper["process_seconds"] if fast else None,
             "met": fast is not None and fast["process_seconds"] <= share * paper["process_seconds"]})


def work_precision_main(doc, name, measure, write_doc):
    """A work-precision section run alone (mesh_adaptation.py, elliptic_adaptation.py): --repeat, --quick,
    or --page (the page again from results/bench/<name>.json)."""
    import argparse
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--page", action="store_true", help=f"the page again from results/bench/{name}.json")
    opts = parser.parse_args()
    write_doc(json.load(open(os.path.join(OUT, f"{name}.json"))) if opts.page
              else measure(repeat=opts.repeat, quick=opts.quick))


def machine():
    model = "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "freefem++"],
                             capture_output=True, text=True).stdout.strip()
    return {"nproc": os.cpu_count(), "cpu_model": model, "freefem": version,
            "python": platform.python_version(), "date": time.strftime("%Y-%m-%d %H:%M")}


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def observed_orders(sizes, errors):
    """Orders between successive levels: log(e_i / e_i+1) / log(n_i+1 / n_i)."""
    return [math.log(a / b) / math.log(m / n) if a > 0 and b > 0 else None
            for (n, a), (m, b) in zip(zip(sizes, errors), zip(sizes[1:], errors[1:]))]


def chatter_of(s):
    return {k: s.get(k) for k in ("reversal_steps", "reversal_points_max", "pressure_zigzag_steps")}


def save(fig, name):
    """docs/benchmarks/<name> (sma.plotting.save: temporary name, renamed; closes the figure);
    returns its path relative to docs/."""
    os.makedirs(PNG_DIR, exist_ok=True)
    fig.tight_layout()
    save_png(fig, os.path.join(PNG_DIR, name), 110)
    return f"benchmarks/{name}"


def run_alone(name, measure, section):
    """A section run as its own script (`tools/bench/<name>.py [--quick]`): measure(out, quick) into
    results/bench-<name>/, its record written there as summary.json (temporary name, renamed), its
    figures saved beside it and its part of docs/benchmarks.md printed; returns the record."""
    out = os.path.join(ROOT, "results", f"bench-{name}")
    record = measure(out, QUICK)
    os.makedirs(out, exist_ok=True)
    write_json(os.path.join(out, "summary.json"), record)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def save_here(fig, png):
        fig.tight_layout()
        save_png(fig, os.path.join(out, png), 110)
        return os.path.join(out, png)
    print("\n".join(section(record, plt, save_here)))
    return record
