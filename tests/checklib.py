"""Shared helpers of the scene verification tests: named checks and the verification record."""
import csv
import json
import os
import subprocess
import time
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The command-line modules (tools/: sweep, sma_driver, units, ...) and the independent oracles the
# tests check against (tools/bench/oracles: lame, curve_error, fits, sleeve_geometry).
sys.path.insert(0, os.path.join(ROOT, "tools"))
sys.path.insert(0, os.path.join(ROOT, "tools", "bench", "oracles"))
from units import KELVIN_AT_0C  # noqa: E402,F401  (re-exported for the tests)
from fits import r_squared  # noqa: E402,F401  (re-exported for the tests)
from sleeve_geometry import sleeve_geometry  # noqa: E402,F401  (re-exported for the tests)
from results_io import read_json  # noqa: E402  (tools/results_io.py: the sma package's reader)
TEST_RESULTS = os.path.join(ROOT, "build", "test-results")
failures = []


def check(condition, message):
    """Prints ok/FAIL with the measured figures in `message`; remembers failures."""
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def record(name, data):
    """Writes results/checks/<name>.json (under a temporary name, then renamed)."""
    os.makedirs(os.path.join(ROOT, "results", "checks"), exist_ok=True)
    path = os.path.join(ROOT, "results", "checks", name + ".json")
    with open(path + ".partial", "w") as f:
        # allow_nan=False: a NaN or an infinity fails here, loudly, instead of writing invalid JSON.
        json.dump(dict(data, passed=not failures), f, indent=2, allow_nan=False)
    os.replace(path + ".partial", path)


# The scale the tests written before the paper's scale became the default check (their closed
# forms and thresholds are the reduced scale's: the printed a = 300 on a 55 um interference);
# tests/paper_scale_test.py checks the defaults. Only for the sleeve scenes (others have no -scale).
REDUCED = ["-scale", "reduced"]
SLEEVE_SCENES = ("sleeve-circular", "sleeve-circular-gvar", "sleeve-circular-single", "sleeve-elliptic",
                 "sleeve-elliptic-friction", "sleeve-offset", "sleeve-random-threshold", "sleeve-radial")


def run_scene(scene, out_name, *args):
    """Runs edp/scenes/<scene>.edp into build/test-results/<out_name>; returns that directory. A
    sleeve scene runs at -scale reduced unless args give -scale."""
    out = os.path.join(TEST_RESULTS, out_name)
    scale = REDUCED if scene in SLEEVE_SCENES and "-scale" not in args else []
    subprocess.run([os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", "-out", out, *scale, *args],
                   cwd=ROOT, check=True)
    return out


def run_scene_captured(scene, out_name, *args):
    """Runs edp/scenes/<scene>.edp into build/test-results/<out_name> as given (no -scale added, a
    failure allowed: the caller checks it); returns (that directory, the CompletedProcess with its
    captured stdout and stderr)."""
    out = os.path.join(TEST_RESULTS, out_name)
    done = subprocess.run([os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", "-out", out, *args],
                          cwd=ROOT, capture_output=True, text=True)
    return out, done


def ranks_alive(session, wait=5.0):
    """Whether a process of the session still runs `wait` seconds after mpiexec's exit (the ranks,
    once killed, are zombies until the system reaps them: not counted)."""
    deadline = time.monotonic() + wait
    while True:
        states = subprocess.run(["ps", "-o", "stat=", "-s", str(session)], capture_output=True, text=True).stdout.split()
        if not any(not state.startswith("Z") for state in states) or time.monotonic() > deadline:
            return any(not state.startswith("Z") for state in states)
        time.sleep(0.2)


def files_under(folder):
    """Every file under folder, by its path relative to it."""
    found = {}
    for base, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(base, name)
            found[os.path.relpath(path, folder)] = path
    return found


def header_quotes(script, quoted, label=None):
    """Checks that the header of `script` (its comment lines //, joined, white space collapsed: a
    phrase may straddle two lines) holds every phrase of `quoted`, each formatted by the caller from
    a run to the digits the header prints: a number typed once and left behind when the code moved
    fails here (as README's in readme_numbers_test). Returns the phrases not found."""
    with open(os.path.join(ROOT, script)) as f:
        header = " ".join(" ".join(line.lstrip("/").split()) for line in f if line.startswith("//"))
    missing = [q for q in quoted if q not in header]
    check(not missing, f"{label or script}'s header quotes its runs' numbers: {len(quoted) - len(missing)} of "
          f"{len(quoted)} found; not found: {missing}")
    return missing


def celsius(kelvin):
    """A temperature in degrees Celsius, as the headers and pages print them."""
    return kelvin - KELVIN_AT_0C


def sci(x, digits=2, sign=False):
    """x in scientific notation to `digits` significant digits, as the pages and headers print it:
    5.4e-4 (not Python's 5.4e-04), +1.2e-6 with sign, 0 for 0."""
    if x == 0:
        return "0"
    mantissa, exponent = f"{x:{'+' if sign else ''}.{digits - 1}e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def doc_quotes(document, quoted, label=None):
    """As header_quotes for a Markdown document (README.md, docs/*.md): its text joined, white space
    collapsed, holds every phrase of `quoted`. Returns the phrases not found."""
    with open(os.path.join(ROOT, document), encoding="utf-8") as f:
        text = " ".join(f.read().split())
    missing = [q for q in quoted if " ".join(q.split()) not in text]  # (a table's empty cell: "|  |")
    check(not missing, f"{label or document} quotes the runs' numbers: {len(quoted) - len(missing)} of {len(quoted)} "
          f"found; not found: {missing}")
    return missing


def summary_of(out):
    """The summary.json a scene wrote to `out`, read as the plot tools read it (sma.results_io
    read_json): a key given twice, NaN or a value that is not an object is refused, naming the file
    (python's json keeps the last of two keys without a word: sleeve-3d's summary gave pipe_A twice)."""
    return read_json(os.path.join(out, "summary.json"))


def rows(path):
    """The rows of a CSV file with a header line, as dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def own_error_line(proc):
    """The last line of a sleeve run's output stating its own error (run-error.idp), or ""."""
    lines = [line for line in proc.stdout.splitlines() if "the run's own error" in line]
    return lines[-1] if lines else ""


def sleeve_outputs(out):
    """What a sleeve scene wrote to `out`: summary.json, and the rows of history.csv, points.csv and
    contact-final.csv."""
    return {"summary": json.load(open(os.path.join(out, "summary.json"))),
            "history": rows(os.path.join(out, "history.csv")),
            "points": rows(os.path.join(out, "points.csv")),
            "final": rows(os.path.join(out, "contact-final.csv"))}



def four_phases(label, T, p, austenite, first_contact):
    """Checks the four phases of a sleeve's force-temperature curve
    (docs/model.md#fig-11-14-sleeve-circular) at one point:
    (1) zero force before contact (at least 3 steps); (2) contact while the ring is all
    martensite, the force linear in T (R^2 > 0.99 over at least 5 steps); (3) jumps while it
    turns back to austenite (largest one-step rise at least 3 x the mean rise per step of phase
    2); (4) constant once all austenite for good (relative spread < 1e-6); in that order.
    T, p: temperature and force density per step at the point; austenite: the ring's austenite
    fraction per step; first_contact: the step index (from 0) where the point's contact starts.
    Returns the figures measured."""
    reversion = next(i for i, f in enumerate(austenite) if f > 0)
    # All austenite for good: phase points near T* may flip back and forth for a few steps
    # (docs/model.md#two-hazards, hazard 2: on/off phases with Crank-Nicolson latent heat): the
    # jerks.
    all_austenite = max(i for i, f in enumerate(austenite) if f < 1) + 1
    flips = sum(1 for a, b in zip(austenite[reversion:all_austenite], austenite[reversion + 1:all_austenite + 1])
                if b < a)
    print(f"{label}: contact at step {first_contact + 1}, reversion from {reversion + 1}, all austenite "
          f"for good at {all_austenite + 1} of {len(p)}; the austenite fraction fell back {flips} times")
    check(first_contact >= 3 and all(v == 0 for v in p[:first_contact]),
          f"{label} phase 1: zero force over the {first_contact} steps before contact")
    lin_T, lin_p = T[first_contact:reversion], p[first_contact:reversion]
    check(len(lin_p) >= 5, f"{label} phase 2 lasts {len(lin_p)} >= 5 steps (contact, still martensite)")
    r2, slope = r_squared(lin_T, lin_p) if len(lin_p) >= 3 else (0, 0)
    check(r2 > 0.99 and slope > 0, f"{label} phase 2: force linear in T, R^2 = {r2:.5f} > 0.99, "
          f"slope {slope / 1e6:.3f} MPa/K > 0")
    rises = [b - a for a, b in zip(p[reversion - 1:all_austenite], p[reversion:all_austenite + 1])]
    mean_rise_linear = (lin_p[-1] - lin_p[0]) / max(1, len(lin_p) - 1)
    biggest = max(rises)
    check(biggest >= 3 * mean_rise_linear,
          f"{label} phase 3: jumps, largest one-step rise {biggest / 1e6:.3f} MPa >= 3 x the mean rise "
          f"per step of phase 2 ({mean_rise_linear / 1e6:.4f} MPa)")
    final = p[all_austenite:]
    spread = (max(final) - min(final)) / final[-1]
    check(spread < 1e-6, f"{label} phase 4: constant force once all austenite, relative spread {spread:.2e}")
    check(first_contact < reversion < all_austenite < len(p) - 5, f"{label}: the four phases come in order")
    return {"first_contact_step": first_contact + 1, "reversion_step": reversion + 1,
            "all_austenite_step": all_austenite + 1, "linear_r2": r2, "linear_slope_Pa_per_K": slope,
            "largest_jump_Pa": biggest, "austenite_fraction_decreases_in_phase_3": flips,
            "mean_linear_rise_Pa": mean_rise_linear, "final_spread": spread}


def finish():
    if failures:
        print(f"{len(failures)} checks failed", file=sys.stderr)
        sys.exit(1)
