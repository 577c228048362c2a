"""Run the scenes from Python and read what they wrote, as arrays.

    import sys; sys.path.insert(0, "tools")
    import sma_driver as sma
    out = sma.run("sleeve-radial", "results/my-g1000", g=1000, steps=300)
    r = sma.read(out)
    r.summary["final_pressure_mean"], r.history["T_inner_mean"][-1]

options(scene) lists a scene's options as the scene itself prints them (`-help tsv`, parsed by
tools/param_reference.py); run() refuses an unknown name before starting FreeFEM, naming close
matches; every run goes through tools/ff as an argument list, never through a shell. Standard
library and numpy only.
"""
import difflib
import json
import os
import subprocess

import numpy as np

import param_reference

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FF = os.path.join(ROOT, "tools", "ff")


class SceneError(RuntimeError):
    """A scene that does not exist, an option it does not read, or a run that failed."""


def script(scene):
    """The path of a scene (edp/scenes) or variant (edp/variants), relative to the repository."""
    for folder in ("edp/scenes", "edp/variants"):
        path = os.path.join(folder, scene + ".edp")
        if os.path.isfile(os.path.join(ROOT, path)):
            return path
    known = sorted(os.path.splitext(f)[0] for folder in ("edp/scenes", "edp/variants")
                   for f in os.listdir(os.path.join(ROOT, folder)) if f.endswith(".edp"))
    close = difflib.get_close_matches(scene, known, n=3)
    raise SceneError(f"unknown scene '{scene}'" + (f" (did you mean {', '.join(close)}?)" if close else "")
                     + f"; scenes: {' '.join(known)}")


_OPTIONS = {}


def options(scene):
    """{name without the dash: {"type", "default", "meaning"}} of a scene, from its -help tsv."""
    if scene not in _OPTIONS:
        path = script(scene)
        help_run = subprocess.run([FF, path, "-help", "tsv"], cwd=ROOT, capture_output=True, text=True)
        if help_run.returncode != 0:
            raise SceneError(f"{scene}: -help tsv failed (exit {help_run.returncode}): {help_run.stdout[-300:]}")
        parsed = param_reference.parse_tsv(scene, help_run.stdout)
        _OPTIONS[scene] = {o["name"][1:]: {k: o[k] for k in ("type", "default", "meaning")} for o in parsed}
    return _OPTIONS[scene]


def check_option(scene, name):
    """Fails naming `name` and its close matches when the scene does not read -name."""
    known = options(scene)
    if name not in known:
        close = difflib.get_close_matches(name, list(known), n=3)
        raise SceneError(f"{scene} has no option -{name}" + (f" (did you mean {', '.join('-' + c for c in close)}?)"
                                                             if close else "") + f"; its options: "
                         + " ".join("-" + k for k in known))


def command(scene, out, **values):
    """The argument list that runs `scene` into `out` with the options `values` (name=value)."""
    words = [FF, script(scene)]
    for name, value in values.items():
        check_option(scene, name)
        words += ["-" + name, str(value)]
    return words + ["-out", str(out)]


def run(scene, out, quiet=True, **values):
    """Runs the scene into `out`; returns `out`. Raises SceneError with the log's last lines."""
    if quiet and "quiet" in options(scene) and "quiet" not in values:
        values["quiet"] = 1
    result = subprocess.run(command(scene, out, **values), cwd=ROOT, capture_output=True, text=True)
    if result.returncode != 0:
        log = (result.stdout + result.stderr).strip().splitlines()
        errors = [ln for ln in log if ln.startswith("error:")]
        raise SceneError(f"{scene} into {out} failed (exit {result.returncode}): "
                         + ("\n".join(errors) if errors else "\n".join(log[-8:])))
    return out


def read_csv(path):
    """{column: numpy array} of a CSV the scenes write (`#` lines skipped); None if absent."""
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    names = lines[0].strip().split(",")
    rows = [ln.strip().split(",") for ln in lines[1:] if ln.strip()]
    columns = {}
    for k, name in enumerate(names):
        values = [r[k] for r in rows]
        try:
            columns[name] = np.array([float(v) for v in values])
        except ValueError:
            columns[name] = np.array(values)
    return columns


class Results:
    """What a scene wrote to a folder: summary (dict), history, points, contact (column arrays)."""

    def __init__(self, out):
        self.out = out
        with open(os.path.join(out, "summary.json")) as f:
            self.summary = json.load(f)
        self.history = read_csv(os.path.join(out, "history.csv"))
        self.points = read_csv(os.path.join(out, "points.csv"))
        self.contact = read_csv(os.path.join(out, "contact-final.csv"))


def read(out):
    return Results(out)
