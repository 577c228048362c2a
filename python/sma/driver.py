"""Run the scenes and read what they wrote (the driver behind sma.run, sma.read, sma.options).

    import sma
    out = sma.run("sleeve-radial", "results/my-g1000", g=1000, steps=300)
    r = sma.read(out)
    r.summary["final_pressure_mean"], r.history["T_inner_mean"][-1]   # numpy arrays
    r.frame("history")                                                 # a DataFrame, units in its names

options(scene) lists a scene's options as the scene itself prints them (`-help tsv`, parsed by
sma.helptsv, the one parser of that format); run() refuses an unknown name before starting
FreeFEM, naming close matches; every run goes through tools/ff as an argument list, never through
a shell, from the repository root (the scenes' mesh paths are relative to it: a relative `out` is
relative to the root too, in run() and read() alike; run() returns the absolute path).
"""
import difflib
import math
import numbers
import os
import re
import subprocess
import sys

import numpy as np

from . import children, frames, results_io, units, vtu
from .errors import SceneError
from .helptsv import parse_tsv
from .repository import FF, FF_MPI, ROOT

SCENE_FOLDERS = ("edp/scenes", "edp/variants")
MPI_FOLDER = "edp/mpi"  # the scenes' runs on MPI ranks (run(..., ranks=2): tools/ff-mpi)
LOG_LINES = 8  # the last lines of a failed run's log that an error quotes


def scenes():
    """Every scene and variant name, sorted."""
    return sorted(os.path.splitext(f)[0] for folder in SCENE_FOLDERS
                  for f in os.listdir(os.path.join(ROOT, folder)) if f.endswith(".edp"))


SCENE_NAME = re.compile(r"[A-Za-z0-9_-]+\Z")  # the Makefile's check-scene rule, the same words


def script(scene):
    """The path of a scene (edp/scenes) or variant (edp/variants), relative to the repository: the
    one resolver of the Python entry points (run, options, sweep). A name is letters, digits, -
    and _ only (no path: '../x' or 'a/b' never reaches a folder), and must be a scene's or a
    variant's."""
    if not isinstance(scene, str) or not SCENE_NAME.match(scene):
        raise SceneError(f"{scene!r} is not a scene name (letters, digits, - and _ only); scenes: "
                         + " ".join(scenes()))
    for folder in SCENE_FOLDERS:
        path = os.path.join(folder, scene + ".edp")
        if os.path.isfile(os.path.join(ROOT, path)):
            return path
    known = scenes()
    close = difflib.get_close_matches(scene, known, n=3)
    raise SceneError(f"unknown scene '{scene}'" + (f" (did you mean {', '.join(close)}?)" if close else "")
                     + f"; scenes: {' '.join(known)}")


def launcher(scene, ranks=None):
    """The words that start `scene`: tools/ff and its script, or with `ranks` (a whole number >= 1)
    tools/ff-mpi on that many MPI ranks and the scene's edp/mpi script (sleeve-3d's: every
    stiffness and heat solve through ffddm, docs/model.md#the-scene-on-ffddm)."""
    path = script(scene)
    if ranks is None:
        return [FF, path]
    if isinstance(ranks, bool) or not isinstance(ranks, numbers.Integral) or not 1 <= ranks <= 8 * (os.cpu_count() or 1):
        raise SceneError(f"{scene}: ranks={ranks!r} must be a whole number of MPI ranks from 1 to "
                         f"{8 * (os.cpu_count() or 1)}")
    mpi = os.path.join(MPI_FOLDER, scene + ".edp")
    if not os.path.isfile(os.path.join(ROOT, mpi)):
        have = sorted(os.path.splitext(f)[0] for f in os.listdir(os.path.join(ROOT, MPI_FOLDER)) if f.endswith(".edp"))
        raise SceneError(f"{scene} has no run on MPI ranks (ranks=): the scenes of {MPI_FOLDER} have one: "
                         + " ".join(have))
    return [FF_MPI, str(int(ranks)), mpi]


_OPTIONS = {}


def options(scene, ranks=None):
    """{name without the dash: {"type", "default", "meaning"}} of a scene, in the order it reads
    them, from its `-help tsv` (cached: one FreeFEM start per scene and process); with `ranks`, its
    run on MPI ranks' (the scene's options, ffddm's and its own)."""
    key = scene if ranks is None else (scene, "mpi")
    if key not in _OPTIONS:
        words = launcher(scene, None if ranks is None else 1)
        help_run = subprocess.run(words + ["-help", "tsv"], cwd=ROOT, capture_output=True, text=True)
        if help_run.returncode != 0:
            raise SceneError(f"{scene}: -help tsv failed (exit {help_run.returncode}): "
                             + "\n".join((help_run.stdout + help_run.stderr).strip().splitlines()[-LOG_LINES:]))
        try:
            parsed = parse_tsv(scene, help_run.stdout)
        except ValueError as e:
            raise SceneError(str(e)) from None
        _OPTIONS[key] = {o["name"][1:]: {k: o[k] for k in ("type", "default", "meaning")} for o in parsed}
    return _OPTIONS[key]


def check_option(scene, name, ranks=None):
    """Fails naming `name` and its close matches when the scene (on MPI ranks: its run there) does
    not read -name."""
    known = options(scene, ranks)
    if name not in known:
        close = difflib.get_close_matches(name, list(known), n=3)
        raise SceneError(f"{scene} has no option -{name}"
                         + (f" (did you mean {', '.join('-' + c for c in close)}?)" if close else "")
                         + "; its options: " + " ".join("-" + k for k in known))


def is_switch(option):
    """An int option that is an on/off switch: its meaning starts "1:" (`-quiet 1: no progress
    line`), its default 0 or 1. Only these take True and False."""
    return option["type"] == "int" and option["meaning"].startswith("1:") and option["default"] in ("0", "1")


def is_temperature(option):
    """An absolute temperature option (kelvin): its meaning starts "K:" or holds "(K)"."""
    return option["meaning"].startswith("K:") or "(K)" in option["meaning"]


def word(scene, name, value, ranks=None):
    """An option value as FreeFEM's getARGV reads it, checked against the option's type (from the
    scene's -help): an int takes a Python int (or a numeric string of one), a real a finite int or
    float (or such a string; a temperature's string may end in its unit, "20C" or "293.15K"), a
    string a str; True/False only for a switch (is_switch); None, lists
    and other objects are refused, naming the option. A number's text goes on as typed, a Python
    int as itself, a float in full precision (repr)."""
    option = options(scene, ranks)[name]
    kind = option["type"]

    typed = None  # a number given as text goes on as typed (an error line shows -g 250, not 250.0)

    def refuse(why):
        shown = repr(typed) if typed is not None else repr(value)
        raise SceneError(f"{scene}: -{name} = {shown}: {why} (-{name} is {kind}: {option['meaning']})")
    if value is None or isinstance(value, (list, tuple, dict, set)):
        refuse("not a single value")
    if isinstance(value, (bool, np.bool_)):
        if not is_switch(option):
            refuse("a boolean for an option that is not an on/off switch")
        return "1" if value else "0"
    if kind == "string":
        if not isinstance(value, str):
            refuse("a string option takes a str")
        if value == "" or any(c in value for c in "\n\r\0"):
            refuse("empty, or with a line break or a NUL")
        if value.startswith("-") and value.lstrip("-").isalpha():
            # tools/ff and the scripts take "-help" anywhere for a request to list the options: the
            # run would print them, exit 0 and compute nothing
            refuse("an option name, not a value")
        return value
    if isinstance(value, str) and kind == "real" and is_temperature(option) and units.temperature_word(value):
        # A temperature may carry its unit, as on the command line ("20C", "293.15K"): passed on as
        # written, the scene reads it in kelvin (edp/lib/errors.idp KelvinWord).
        return value.strip()
    if isinstance(value, str):
        typed = value.strip()
        pattern = r"[+-]?\d+\Z" if kind == "int" else r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z"
        if not re.match(pattern, typed, re.ASCII):  # (FreeFEM reads ASCII digits only: not "２５０")
            refuse(f"not a whole {'integer' if kind == 'int' else 'number'}")
        value = int(typed) if kind == "int" else float(typed)
    if kind == "int":
        if not isinstance(value, numbers.Integral):
            refuse("an int option takes an integer")
        if not -2**31 <= int(value) < 2**31:
            refuse("outside FreeFEM's 32-bit int")
        return typed or str(int(value))
    if kind == "real":
        if not isinstance(value, numbers.Real):
            refuse("a real option takes a finite number")
        try:
            number = float(value)
        except OverflowError:  # an int or a fraction beyond a double (float() of 10**400)
            refuse("beyond a double")
        if not math.isfinite(number):
            refuse("a real option takes a finite number")
        if number == 0 and typed is not None and re.search(r"[1-9]", typed.lower().split("e")[0]):
            refuse("below a double's smallest, it would run as 0")  # (1e-400: the run said g = 0)
        if typed is not None:
            return typed
        return str(int(value)) if isinstance(value, numbers.Integral) else repr(number)  # (250, not 250.0)
    refuse(f"an option of unknown type {kind!r}")


def command(scene, out, ranks=None, **values):
    """The argument list that runs `scene` into `out` with the options `values` (name=value),
    each name checked first; on `ranks` MPI ranks with ranks (launcher)."""
    words = launcher(scene, ranks)
    for name, value in values.items():
        if name == "out":
            raise SceneError(f"{scene}: give the output folder as run()'s `out`, not as an option")
        check_option(scene, name, ranks)
        words += ["-" + name, word(scene, name, value, ranks)]
    return words + ["-out", folder(out)]


def given_options(words):
    """The options of a command() (its words after the launcher and the script)."""
    return words[3:] if words[0] == FF_MPI else words[2:]


def folder(out):
    """`out` as an absolute path: a str or an os.PathLike (pathlib), not empty, a relative one
    taken from the repository root (where the scenes run: run() and read() alike, so that
    read(run(...)) works from any directory, a notebook's included); anything else (None, bytes,
    a number) is refused rather than turned into a folder named "None" or "b'...'"."""
    if not isinstance(out, (str, os.PathLike)) or isinstance(out, bytes):
        raise SceneError(f"the output folder {out!r} is not a path (a str or a pathlib.Path)")
    path = os.fspath(out)
    if not isinstance(path, str) or path == "" or any(c in path for c in "\n\r\0"):
        raise SceneError(f"the output folder {out!r} is not a usable path (empty, bytes, or with a line break)")
    if path == "~" or path.startswith("~/"):
        raise SceneError(f"the output folder {path!r}: ~ is not expanded here; give os.path.expanduser({path!r})")
    return os.path.normpath(os.path.join(ROOT, path))


def check(scene, out, ranks=None, **values):
    """Checks what run(scene, out, **values) would run, in the scripts' check-only mode (-checkonly
    1: every check of a run, then exit where the run would take `out`; nothing written): raises
    SceneError with the scene's error line. A caller that takes a folder of its own before its
    runs (a sweep) checks them first: a run refusing its options after that would come after the
    folder's earlier results were deleted."""
    words = command(scene, out, ranks, **values) + ["-checkonly", "1"]
    result = children.run(words, cwd=ROOT, capture_output=True, text=True)
    if result.returncode != 0:
        log = (result.stdout + "\n" + result.stderr).strip().splitlines()
        errors = [ln for ln in log if ln.startswith("error:")]
        raise SceneError(f"{scene} {' '.join(given_options(words)[:-4])} is refused (exit {result.returncode})"
                         + (f": {errors[0][len('error:'):].strip()}" if errors else ": " + " / ".join(log[-3:])))


def run(scene, out, quiet=True, notes=True, ranks=None, **values):
    """Runs the scene into `out` with the options `values` (g=1000, steps=300); returns `out` as an
    absolute path (a relative `out` is taken from the repository root). ranks=2: on 2 MPI ranks,
    the scene's edp/mpi script through tools/ff-mpi (sleeve-3d: every solve through ffddm; its
    options, ffddm's and ddmtol, ddmgeneo, with options(scene, ranks)).
    quiet=True adds -quiet 1 when the scene has that option (no line per step). The run's `note:`
    and `warning:` lines (a ring that never cleared the pipe, a loop that did not converge) are
    printed to stderr (notes=True), passed to `notes` when it is a function of the line, or
    dropped (False). Raises SceneError naming the scene and its options, with the run's error line
    and the last lines of its log."""
    # (a TERM or HUP from the options' reading on is said and passed on, as in sweep)
    with children.terminable():
        if quiet and "quiet" in options(scene, ranks) and "quiet" not in values:
            values["quiet"] = 1
        path = folder(out)
        words = command(scene, path, ranks, **values)
        result = children.run(words, cwd=ROOT, capture_output=True, text=True)
    if result.returncode != 0:
        log = (result.stdout + "\n" + result.stderr).strip().splitlines()
        errors = [ln for ln in log if ln.startswith("error:")]
        given = " ".join(given_options(words))
        raise SceneError(f"{scene} {given} failed (exit {result.returncode})"
                         + (f": {errors[0][len('error:'):].strip()}" if errors else "")
                         + "\n  last lines of its log:\n    " + "\n    ".join(log[-LOG_LINES:]))
    written = os.path.join(path, "summary.json")
    if not os.path.isfile(written):
        raise SceneError(f"{scene} {' '.join(given_options(words))} exited 0 but wrote no {written}: nothing was computed")
    if notes:
        say = notes if callable(notes) else (lambda line: print(line, file=sys.stderr, flush=True))
        for line in (result.stdout + "\n" + result.stderr).splitlines():
            if line.startswith(("note:", "warning:")):
                say(line)
    return path


def read_csv(path):
    """{column: numpy array} of a CSV the scenes write, read by results_io.read_csv (the plot
    tools' reader: every field a number, a damaged file named); None if the file is absent."""
    if not os.path.lexists(path):
        return None
    try:
        return {name: np.array(values) for name, values in results_io.read_csv(path).items()}
    except results_io.ResultsError as e:
        raise SceneError(str(e)) from None


class Results:
    """What a scene wrote to a folder `out` (absolute): summary (dict from summary.json); history,
    points, contact (history.csv, points.csv, contact-final.csv as {column: numpy array}; None
    where the scene writes no such file). frame() gives any of its CSV files as a DataFrame with
    units in the column names, fields() and states() its VTU files as mesh and numpy arrays."""

    def __init__(self, out):
        self.out = folder(out)
        path = os.path.join(self.out, "summary.json")
        if not os.path.isfile(path):
            raise SceneError(f"no summary.json in {out}: no run finished there (a scene writes it last)")
        try:
            self.summary = results_io.read_json(path)
        except results_io.ResultsError as e:
            raise SceneError(str(e)) from None
        self.history = read_csv(os.path.join(self.out, "history.csv"))
        self.points = read_csv(os.path.join(self.out, "points.csv"))
        self.contact = read_csv(os.path.join(self.out, "contact-final.csv"))

    def __repr__(self):
        files = [n for n in ("history", "points", "contact") if getattr(self, n) is not None]
        return f"Results({self.out!r}: summary, {', '.join(files) or 'no CSV'})"

    def path(self, name):
        """The absolute path of the file `name` of this run (relative to its folder)."""
        return os.path.join(self.out, name)

    def frame(self, name="history"):
        """A CSV file of the run as a pandas DataFrame, columns named with their units
        (sma.frames: `t_s`, `pressure_mean_Pa`, `T_inner_mean_K`; counts without a unit). `name`:
        "history", "points", "contact" (contact-final.csv), or a file name of the folder with or
        without .csv ("fields-3-end"). Fails (SceneError) naming the file when it is absent."""
        file = {"contact": "contact-final.csv"}.get(name, name)
        if not file.endswith(".csv"):
            file += ".csv"
        path = self.path(file)
        if not os.path.isfile(path):
            present = sorted(f for f in os.listdir(self.out) if f.endswith(".csv"))
            raise SceneError(f"{path} is missing: the run wrote no {file} (its CSV files: {' '.join(present) or 'none'})")
        return frames.frame(path)

    def states(self):
        """[(time in s, absolute path)] of the run's VTU files, in time order, from its fields.pvd
        (the three instants and the frames of -vtkevery)."""
        return vtu.read_pvd(self.path("fields.pvd"))

    def fields(self, name="3-end"):
        """One VTU state of the run (sma.vtu.Fields: points, triangles, point_data, cell_data as
        numpy arrays, time in s from fields.pvd): `name` an instant ("1-dilated", "2-contact",
        "3-end"), a file of the folder ("frames/step-000050.vtu"), or a time in s (the state
        listed at that time in fields.pvd). Fails (SceneError) naming the file or the time."""
        states = self.states() if os.path.isfile(self.path("fields.pvd")) else []
        if isinstance(name, numbers.Real) and not isinstance(name, bool):
            matches = [p for t, p in states if abs(t - name) <= 1e-9 * max(1.0, abs(name))]
            if not matches:
                raise SceneError(f"{self.path('fields.pvd')} lists no state at t = {name} s "
                                 f"(its times: {' '.join(f'{t:g}' for t, _ in states) or 'none'})")
            path = matches[-1]
        elif isinstance(name, str) and name:
            path = self.path(name if name.endswith(".vtu") else f"fields-{name}.vtu")
        else:
            raise SceneError(f"fields({name!r}): give an instant ('3-end'), a VTU file of {self.out} or a time in s")
        state = vtu.read_vtu(path)
        state.time = next((t for t, p in states if os.path.normpath(p) == os.path.normpath(path)), None)
        return state


def read(out):
    """The results a finished run wrote to `out` (a Results; `out` relative to the repository root
    unless absolute). Fails (SceneError) naming the folder when no run finished there."""
    return Results(out)
