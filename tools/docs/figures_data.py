"""What tools/docs/figures.py reads and how it words it: the results of make figures (summary.json,
the tests' records in results/checks/, the runs' CSVs, the PNGs it copies to docs/figures/), the
curve's phases and coincident curves measured from them, and the small formatters of its text. An
input that is missing is listed in `missing` (figures.py stops naming them)."""
import json
import math
import os
import shutil
import sys

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# tools/ (units), the sleeve's plot helpers (tools/plot) and the least-squares fit (tools/bench/oracles).
sys.path[:0] = [TOOLS, os.path.join(TOOLS, "plot"), os.path.join(TOOLS, "bench", "oracles")]
from sleeve_curves import coincident_groups, point_labels, read_csv  # noqa: E402
from units import KELVIN_AT_0C  # noqa: E402
from fits import r_squared  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RESULTS = os.path.join(ROOT, "results")
DOCS = os.path.join(ROOT, "docs")
missing = []


def summary(scene):
    path = os.path.join(RESULTS, scene, "summary.json")
    if not os.path.exists(path):
        missing.append(path)
        return None
    return json.load(open(path))


def checks(name):
    path = os.path.join(RESULTS, "checks", name + ".json")
    if not os.path.exists(path):
        missing.append(path)
        return None
    return json.load(open(path))


def figure(scene, png):
    """Copies results/<scene>/<png> to docs/figures/<scene>-<png>; returns its Markdown image."""
    src = os.path.join(RESULTS, scene, png)
    if not os.path.exists(src):
        missing.append(src)
        return f"*(missing: results/{scene}/{png})*"
    os.makedirs(os.path.join(DOCS, "figures"), exist_ok=True)
    name = f"{scene}-{png}"
    dst = os.path.join(DOCS, "figures", name)
    shutil.copyfile(src, dst + ".partial")  # then renamed: never a half-copied figure
    os.replace(dst + ".partial", dst)
    return f"![{scene} {png}](figures/{name})"


def coldest_radius(scene, instant="2-contact"):
    """Radius (mm) of the coldest triangle and the ring's radii range, from fields-<instant>.csv."""
    path = os.path.join(RESULTS, scene, f"fields-{instant}.csv")
    if not os.path.exists(path):
        missing.append(path)
        return None
    fields = read_csv(path)
    radius = [1e3 * math.hypot(x, y) for x, y in zip(fields["x"], fields["y"])]
    coldest = min(range(len(radius)), key=lambda i: fields["T"][i])
    return radius[coldest], min(radius), max(radius)


def run_files(scene):
    """history.csv and points.csv of results/<scene> (the default run), as columns; None if missing."""
    out = {}
    for name in ("history", "points"):
        path = os.path.join(RESULTS, scene, name + ".csv")
        if not os.path.exists(path):
            missing.append(path)
            return None
        out[name] = read_csv(path)
    return out


def phase_radii(scene, instant="2-contact"):
    """Mean radius (m) of the austenite triangles (phase 0) and of the others at an instant, as
    tests/sleeve_gvar_test.py measures it."""
    path = os.path.join(RESULTS, scene, f"fields-{instant}.csv")
    if not os.path.exists(path):
        missing.append(path)
        return None
    f = read_csv(path)
    radius = {True: [], False: []}
    for x, y, phase in zip(f["x"], f["y"], f["phase"]):
        radius[phase == 0].append(math.hypot(x, y))
    return {"austenite": sum(radius[True]) / max(1, len(radius[True])),
            "martensite": sum(radius[False]) / max(1, len(radius[False]))}



def curve_phases(run, summary, point):
    """The four phases of a default run's force-temperature curve at one point of points.csv:
    steps (from 1) of the first contact at the point, of the first austenite (history.csv), of
    austenite for good (summary.json); the linear phase's R^2 and slope (Pa/K); the largest
    one-step rise of the reversion and the mean rise per step of the linear phase (Pa); the final
    force's relative spread once all austenite."""
    T, p = run["points"][f"T_{point}_K"], run["points"][f"pressure_{point}_Pa"]
    first = next(i for i, v in enumerate(p) if v > 0)
    reversion = next(i for i, f in enumerate(run["history"]["fraction_austenite"]) if f > 0)
    austenite = summary["austenite_step"] - 1
    r2, slope = r_squared(T[first:reversion], p[first:reversion]) if reversion - first >= 3 else (float("nan"),) * 2
    rises = [b - a for a, b in zip(p[reversion - 1:austenite], p[reversion:austenite + 1])]
    linear = p[first:reversion]
    final = p[austenite:]
    return {"first": first + 1, "reversion": reversion + 1, "austenite": austenite + 1, "r2": r2, "slope": slope,
            "largest_rise": max(rises), "mean_linear_rise": (linear[-1] - linear[0]) / max(1, len(linear) - 1),
            "final_spread": (max(final) - min(final)) / final[-1]}


def coincidence(run, summary):
    """The force-temperature legend of tools/plot/plot_sleeve.py: [(label, members)]."""
    p = run["points"]
    names = [k[len("pressure_"):-len("_Pa")] for k in p if k.startswith("pressure_")]
    labels = point_labels(summary, names)
    return coincident_groups({labels[n]: (p[f"T_{n}_K"], p[f"pressure_{n}_Pa"]) for n in names})


def coincide_text(run, summary):
    """'the three points coincide within x % of full scale' or which of them coincide."""
    groups = coincidence(run, summary)
    if len(groups) == 1:
        return f"the three points' curves coincide ({groups[0][0].split('(coincide ')[-1][:-1]})"
    parts = [g[0] for g in groups]
    return "the points' curves: " + "; ".join(parts)


def celsius_text(kelvin):
    return f"{kelvin - KELVIN_AT_0C:.1f} C"


def section(title, scene, paper, pngs):
    """The head of a figure's entry: its title, the paper's account, our figures."""
    return [f"## {title}, scene `{scene}`", "", "*Paper:* " + paper, "",
            *(figure(scene, png) for png in pngs), ""]


def verdict(ok):
    return "**agrees**" if ok else "**does not agree**"


def mpa(x):
    return f"{x / 1e6:.2f} MPa"

