"""Parameter sweeps: a scene run over a grid of option values, in parallel, into one folder, with a
table of the runs' key figures and overlay figures (tools/sweep.py and make sweep are the command
line of the one-parameter case; sma.sweep() the Python entry, one or several parameters).

    import sma
    table = sma.sweep("sleeve-radial", {"interference": [2e-4, 5e-4], "g": [250, 1000]},
                      fixed={"steps": 300}, jobs=2, out="results/sweeps/lab")
    table[["interference_m", "g_W/(m^2 K)", "final_pressure_mean_Pa"]]

The folder (default results/sweeps/<scene>-<param>[-<param>...]) is taken as a scene takes its
-out (results_io.claim: a folder holding files the suite did not write is refused untouched; an
earlier sweep's runs, table and figures go first). It holds each run's own folder, named
<param>=<value> for one parameter and <p1>=<v1>,<p2>=<v2> for several; table.csv (one row per
finished run: the parameters' values as given, then the key figures, each column named with its
unit); sweep.json (what ran, each run's folder and status); and the figures: one parameter,
force-temperature.png and force-time.png (one curve per value); several, force-temperature.png
with one panel per fixed value of the other parameters (the first parameter's curves overlaid)
and final-pressure.png (the final mean pressure against the first parameter, one line per fixed
value of the others). Every run is first checked by the scene (-checkonly 1: its checks, nothing
written): a value it refuses stops the sweep before the folder is taken. A run that fails later
(a loop that does not converge) stops nothing else; it is named at the end.
"""
import concurrent.futures
import contextlib
import csv
import hashlib
import itertools
import json
import math
import os
import re

import numpy as np

from . import children, driver, results_io, units
from .errors import SceneError
from .plotting import pyplot, save
from .units import KELVIN_AT_0C

# The key figures of a sleeve summary.json, in table order: (key, column named with its unit).
# The times come from history.csv (the t of the step's row); iteration maxima are appended after
# them in the summary's order (every key ending in _iterations_max or _sweeps_max).
KEY_FIGURES = [("first_contact_step", "first_contact_step"), ("first_contact_time", "first_contact_time_s"),
               ("T_inner_first_contact", "T_inner_first_contact_K"),
               ("austenite_step", "austenite_step"), ("austenite_time", "austenite_time_s"),
               ("T_inner_austenite", "T_inner_austenite_K"),
               ("final_pressure_mean", "final_pressure_mean_Pa"), ("peak_pressure_mean", "peak_pressure_mean_Pa"),
               ("peak_step", "peak_step"), ("final_pressure_non_uniformity", "final_pressure_non_uniformity"),
               ("lame_pressure", "lame_pressure_Pa"),  # Lame's closed form (the radial model's; a circle's: lame_2d)
               # sleeve-axisymmetric's closed forms: the open-ended long sleeve's and plane strain's
               ("open_cylinder_pressure", "open_cylinder_pressure_Pa"), ("plane_strain_pressure", "plane_strain_pressure_Pa"),
               ("ring_cleared_pipe", "ring_cleared_pipe"),  # 1 cleared; 0: in contact from step 1, no zero-force stage
               # the coupling's life (sleeve-life): the design chart's figures
               ("T_forward_free", "T_forward_free_K"), ("T_reverse_free", "T_reverse_free_K"),
               ("hysteresis_width_free", "hysteresis_width_free_K"), ("storage_margin", "storage_margin_K"),
               ("installation_clearance", "installation_clearance_m"), ("clamp_pressure", "clamp_pressure_Pa"),
               ("service_pressure_min", "service_pressure_min_Pa"),
               ("pressure_at_service_Tmin", "pressure_at_service_Tmin_Pa"),
               ("T_inner_at_service_Tmin", "T_inner_at_service_Tmin_K"), ("service_T_inner_min", "service_T_inner_min_K"),
               ("service_onset_T_inner", "service_onset_T_inner_K"),
               ("service_transformation_time", "service_transformation_time_s"),
               ("service_window_T_low", "service_window_T_low_K"), ("service_window_T_high", "service_window_T_high_K"),
               ("cycle_periodicity", "cycle_periodicity_Pa"),
               # the life on the 2D model (sleeve-life-2d): where the pipe's shape makes the pressure uneven
               ("installation_clearance_angle_deg", "installation_clearance_angle_deg"),
               ("clamp_non_uniformity", "clamp_non_uniformity"),
               ("service_pressure_node_min", "service_pressure_node_min_Pa"),
               ("service_pressure_node_min_angle_deg", "service_pressure_node_min_angle_deg")]
# (a sleeve run's steps, the rejected ones with -tol, and its own estimates of its time error, of
# its mesh's and of both over the transient: a sweep of -tol, -steps or the mesh is a work-precision
# table)
TRAILING_FIGURES = [("n_steps", "steps_taken"), ("steps_rejected", "steps_rejected"),
                    ("time_error_estimate", "time_error_estimate"),
                    ("time_error_estimate_transient", "time_error_estimate_transient"),
                    ("mesh_error_estimate_transient", "mesh_error_estimate_transient"),
                    ("run_error_estimate_transient", "run_error_estimate_transient"),
                    ("unconverged_loops", "unconverged_loops"), ("wall_seconds", "wall_s")]
STEP_TIMES = {"first_contact_time": "first_contact_step", "austenite_time": "austenite_step"}
COINCIDE = 1e-3  # relative to a curve's largest |pressure|: curves closer share a legend entry
ZOOM_PAST_AUSTENITE = 1.25  # the transient panel ends a quarter past the last austenite time
# Folders are named <param>=<value>: a value must not leave DIR.
BAD_VALUE_CHARACTERS = ("/", "\0")
NOT_SWEPT = ("out", "help")  # each run's folder; the option list


# The unit symbols an option's meaning may give in parentheses: "Young's modulus (Pa)",
# "heat exchange coefficient (W/(m^2 K))"; a group with any other word ("(0 included: ...)") is prose.
UNIT_WORDS = {"m", "mm", "um", "s", "K", "C", "Pa", "MPa", "GPa", "W", "J", "kg", "N", "deg", "rad"}


def is_unit(text):
    """Whether text is made only of unit symbols (UNIT_WORDS), powers and operators: "W/(m^2 K)"."""
    words = [w for w in re.split(r"[\s()/*^.\-0-9]+", text) if w]
    return bool(words) and all(w in UNIT_WORDS for w in words)


def unit_of(meaning):
    """The unit an option's meaning gives: the first parenthesised group that is a unit
    ("heat exchange coefficient (W/(m^2 K))"), else a unit before a colon at its start ("Pa: end
    traction", the beam's and the rings' form); or "" (a count, a switch such as "1: ...", a name)."""
    lead = re.match(r"([^\s:]+):\s", meaning)
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
                if is_unit(group):
                    return group
    return lead.group(1) if lead and is_unit(lead.group(1)) else ""


# ---- The words of the sweep figures: one table for every axis, legend and panel title ----
# An option or a table column -> (its words, the unit it is shown in); the value is converted from
# its SI unit (the option's -help unit, the column's suffix) by SHOWN. An option not listed is named
# by the head of its -help meaning, shown in its SI unit (or by SHOWN's default for that unit).
WORDS = {
    # options
    "g": ("heat exchange coefficient g", None), "gcontact": ("exchange coefficient in contact", None),
    "gpipe": ("exchange coefficient with the pipe", None), "interference": ("interference", "mm"),
    "dissipation": ("dissipation threshold k", "MPa"), "Text": ("air temperature", "°C"),
    "Tpipe": ("pipe temperature", "°C"), "Tinit": ("initial ring temperature", "°C"),
    "T0": ("martensite-start temperature T0", "°C"), "Tc": ("temperature Tc (alpha = 0 above)", "°C"),
    "E": ("Young's modulus E", "GPa"), "nu": ("Poisson's ratio", None), "a": ("coefficient a of alpha(T)", None),
    "latent": ("latent heat", None), "k": ("thermal conductivity", None), "C0": ("specific heat", None),
    "rho": ("density", None), "mu": ("friction coefficient mu", None), "pipeE": ("pipe's Young's modulus", "GPa"),
    "pipenu": ("pipe's Poisson's ratio", None), "pipeA": ("pipe radius", "mm"), "pipeRi": ("pipe inner radius", "mm"),
    "Ri": ("ring inner radius", "mm"), "thickness": ("ring thickness", "mm"), "length": ("sleeve length", "mm"),
    "steps": ("time steps", None), "dt": ("time step", None), "tend": ("simulated time", None),
    "tol": ("time-step tolerance", None), "nr": ("elements through the thickness", None),
    "checkpoint": ("checkpoint interval (steps)", None), "pullout": ("pull-out displacement", "mm"),
    "minpressure": ("least acceptable pressure", "MPa"), "phasemodel": ("phase model", None),
    "stepsolver": ("step solver", None), "plane": ("2D model", None), "scale": ("scale", None),
    "pulldirection": ("pull direction", None), "borefilter": ("bore pressure filter", None),
    # table columns (the key figures, by their summary key)
    "final_pressure_mean": ("final mean contact pressure", "MPa"), "peak_pressure_mean": ("peak mean contact pressure", "MPa"),
    "lame_pressure": ("Lame's shrink-fit pressure", "MPa"), "clamp_pressure": ("clamping pressure", "MPa"),
    "service_pressure_min": ("least service pressure", "MPa"),
    "pressure_at_service_Tmin": ("pressure after the hold at the lowest service temperature", "MPa"),
    "storage_margin": ("storage margin", "K"), "first_contact_time": ("time of first contact", None),
    "austenite_time": ("time the ring is austenite for good", None),
    "T_inner_first_contact": ("inner temperature at first contact", "°C"),
    "T_inner_austenite": ("inner temperature austenite for good", "°C"), "wall": ("wall time", None),
}
# SI unit -> the unit shown when WORDS names none (None: the SI unit itself).
SHOWN = {"Pa": "MPa", "m": "mm", "K": "°C"}
SCALE = {("Pa", "MPa"): 1e-6, ("Pa", "GPa"): 1e-9, ("m", "mm"): 1e3, ("m", "um"): 1e6}
PRETTY_UNITS = {"W/(m^2 K)": "W/(m² K)", "kg/m^3": "kg/m³", "um": "µm"}


def meaning_words(meaning):
    """The head of an option's -help meaning, as words: "threshold k (Pa) of ..." -> "threshold k";
    "Pa: end traction" -> "end traction"."""
    lead = re.match(r"([^\s:]+):\s+(.*)", meaning)
    if lead and is_unit(lead.group(1)):
        meaning = lead.group(2)
    return re.split(r"\s*[(;:,]", meaning, maxsplit=1)[0].strip() or meaning


def shown_unit(name, unit):
    """The unit `name` (an option, or a column's key) is shown in, given its SI unit."""
    listed = WORDS.get(name, (None, None))[1]
    if listed and (unit, listed) in SCALE or (unit == "K" and listed in ("°C", "K")):
        return listed
    return SHOWN.get(unit, unit) if unit else ""


def shown(name, unit, value):
    """An SI value (a number or numpy array) of `name` in its shown unit (shown_unit)."""
    to = shown_unit(name, unit)
    if unit == "K" and to == "°C":
        return units.celsius(value)
    return value * SCALE.get((unit, to), 1.0)


def words_of(name, meaning=None):
    """The words of an option or a column key: WORDS's, else the head of the -help meaning, else the
    name with spaces."""
    if name in WORDS:
        return WORDS[name][0]
    return meaning_words(meaning) if meaning else name.replace("_", " ")


def axis_label(name, unit, meaning=None):
    """An axis label in words with the shown unit: "interference (mm)", "time steps"."""
    to = shown_unit(name, unit)
    return words_of(name, meaning) + (f" ({PRETTY_UNITS.get(to, to)})" if to else "")


def value_label(param, value, unit, meaning=None):
    """A legend entry in words, the value in the shown unit: "interference 0.05 mm" for
    -interference 5e-05, "air temperature 20 °C" for -Text 293.15 or -Text 20C; a value that is not
    a number as typed."""
    text = str(value)
    word = units.temperature_word(text) if unit == "K" else None
    to = shown_unit(param, unit)
    try:
        number = float(word[0]) + (units.KELVIN_AT_0C if word[1] == "C" else 0.0) if word else float(text)
    except ValueError:
        return f"{words_of(param, meaning)} = {text}"
    return f"{words_of(param, meaning)} = {shown(param, unit, number):.6g}" + (f" {PRETTY_UNITS.get(to, to)}" if to else "")


def column_key(column):
    """(summary key, SI unit) of a table column named with its unit: final_pressure_mean_Pa ->
    (final_pressure_mean, Pa); wall_s -> (wall, s); a column without a unit -> (column, "")."""
    for unit in ("Pa", "K", "m", "s"):
        if column.endswith("_" + unit):
            return column[:-len(unit) - 1], unit
    return column, ""


def step_time(history, step):
    """The time t (s) at the end of `step` (history.csv's row), or None (null: never, or no row)."""
    if history is None or step is None or step < 1 or "step" not in history:
        return None
    rows = np.nonzero(history["step"] == step)[0]
    return float(history["t"][rows[0]]) if len(rows) else None


def _lame_shrink_fit(a, b, delta, E, nu, plane):
    """Lame's shrink-fit pressure (Pa) of a ring a < r < b (m), free outside, pushed out by delta
    (m) at r = a, plane strain or stress (edp/model/material.idp LameShrinkFitPressure); 0 for a
    clearance (delta < 0), as the script's."""
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    if plane == "stress":
        lam = 2 * lam * mu / (lam + 2 * mu)
    C = delta / (mu * a / ((lam + mu) * b ** 2) + 1 / a)
    return max(0.0, 2 * mu * C * (1 / a ** 2 - 1 / b ** 2))  # a clearance (delta < 0): no contact, 0


def lame_2d(results):
    """Lame's closed form (Pa) for a 2D sleeve run whose ring and rigid pipe are concentric circles,
    else None. The obstacle is checked, not assumed (a variant may replace it): at every node of
    contact-final.csv the initial gap (its gap minus n.u, n the radial direction, u from
    fields-3-end.vtu) must be the ring's inner radius minus -pipeA. The outer radius is the mesh's
    (the VTU's points, single precision: to about 1e-7). The final mean pressure of an
    all-austenite ring tends to it as the mesh is refined (the sweep table's lame_pressure_Pa)."""
    s = results.summary
    p = s.get("parameters", {})
    need = ("pipe_A", "pipe_B", "ring_inner_radius", "E", "nu", "plane")
    if "lame_pressure" in s or "pipe" in s or not all(k in p for k in need) or p.get("offset", 0) != 0 \
            or p["pipe_A"] != p["pipe_B"] or not all(os.path.isfile(results.path(n)) for n in
                                                    ("fields-3-end.vtu", "contact-final.csv")):
        return None
    fields = results.fields("3-end")
    points, u = fields.points[:, :2], fields.point_data["displacement"][:, :2]
    a, pipe = p["ring_inner_radius"], p["pipe_A"]
    contact = driver.read_csv(results.path("contact-final.csv"))
    if "gap" not in contact or len(contact["gap"]) == 0:
        return None
    xy = np.column_stack([contact["x"], contact["y"]])
    node = [int(np.argmin(np.hypot(*(points - q).T))) for q in xy]
    n = xy / np.hypot(*xy.T)[:, None]
    initial_gap = contact["gap"] - np.sum(n * u[node], axis=1)
    if np.abs(initial_gap - (a - pipe)).max() > 1e-6 * abs(pipe - a) + 1e-12:
        return None  # an obstacle or a ring of its own shape
    b = float(np.hypot(*points.T).max())
    return _lame_shrink_fit(a, b, pipe - a, p["E"], p["nu"], p["plane"]) + 0.0


def figures_of(summary, history, lame=None):
    """{key: value} of one run's key figures (the times from history.csv; `lame`, a 2D circle's
    Lame pressure from lame_2d, when the summary has none)."""
    figures = dict(summary)
    for time_key, step_key in STEP_TIMES.items():
        if step_key in summary:
            figures[time_key] = step_time(history, summary[step_key])
    if lame is not None and "lame_pressure" not in figures:
        figures["lame_pressure"] = lame
    if isinstance(figures.get("ring_cleared_pipe"), bool):  # a number, as every column of table.csv
        figures["ring_cleared_pipe"] = int(figures["ring_cleared_pipe"])
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
    """[(key, column)] of the table: the key figures that any run has, else None (every number)."""
    keys = set().union(*(r.keys() for r in runs)) if runs else set()
    if not any(k in keys for k, _ in KEY_FIGURES if k not in STEP_TIMES):
        return None
    iterations = []
    for r in runs:
        iterations += [k for k in r if (k.endswith("_iterations_max") or k.endswith("_sweeps_max"))
                       and k not in iterations]
    return ([(k, c) for k, c in KEY_FIGURES if k in keys] + [(k, k) for k in iterations]
            + [(k, c) for k, c in TRAILING_FIGURES if k in keys])


def table_rows(params, combos, runs):
    """(header, rows) of table.csv: the parameters' values as given, then each run's key figures
    (table_columns) or, for a scene without them, every number of its summary. A figure a run
    lacks (or null: the event never happened) is None."""
    columns = table_columns(runs)
    if columns is not None:
        header = list(params) + [c for _, c in columns]
        rows = [list(v) + [r.get(k) for k, _ in columns] for v, r in zip(combos, runs)]
    else:
        flat = [dict(flattened_numbers(r)) for r in runs]
        names = []
        for f in flat:
            names += [n for n in f if n not in names]
        header = list(params) + names
        rows = [list(v) + [f.get(n) for n in names] for v, f in zip(combos, flat)]
    return header, rows


def write_table(path, header, rows):
    """table.csv (listed in the folder's manifest, written under a temporary name); None is empty."""
    with results_io.publishing(path) as partial, open(partial, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows([["" if x is None else x for x in row] for row in rows])


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
    """The two overlays of a one-parameter sweep (force-temperature.png, force-time.png); returns
    (the paths written, the groups of values whose curves coincide)."""
    histories = [r.history for r in runs]
    temperature = [(h["T_inner_mean"] - KELVIN_AT_0C, h["pressure_mean"] / 1e6) for h in histories]
    time = [(h["t"], h["pressure_mean"] / 1e6) for h in histories]
    groups = coincident_groups(time)
    meaning = driver.options(scene)[param]["meaning"]
    labels = [", ".join(value_label(param, values[i], unit, meaning) for i in g)
              + (" (coincide within 0.1 %)" if len(g) > 1 else "") for g in groups]
    # The options every run shares, in the title: the figure says what was held fixed.
    held = " ".join(f"-{k} {v}" for k, v in (fixed or {}).items())
    title = f"{scene}: {words_of(param, meaning)} swept (-{param})" + (f"\n(all runs: {held})" if held else "")
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


# Lines of a sweep's figure that coincide (docs/parameters.md, coinciding curves): within this
# fraction of the y axis' span at every x, as tools/plot/sleeve_curves.py's force curves.
LINE_COINCIDE = 0.01
LINE_STYLES = ("-", "--", ":")  # within a group of coinciding lines


def line_groups(lines):
    """Groups the lines [(xs, ys)] (lists, NaN allowed) that coincide within LINE_COINCIDE of the y
    span at every x (the same xs); returns [(indices, largest difference as a fraction of the span)]."""
    finite = [y for _, ys in lines for y in ys if y == y]
    span = ((max(finite) - min(finite)) if finite else 0.0) or 1.0

    def gap(a, b):
        (xa, ya), (xb, yb) = lines[a], lines[b]
        if list(xa) != list(xb):
            return math.inf
        return max((abs(u - v) for u, v in zip(ya, yb) if u == u and v == v), default=0.0) / span
    groups = []
    for k in range(len(lines)):
        for group in groups:
            if all(gap(k, m) <= LINE_COINCIDE for m in group):
                group.append(k)
                break
        else:
            groups.append([k])
    return [(g, max((gap(a, b) for a in g for b in g if a < b), default=0.0)) for g in groups]


def draw_lines(ax, lines, labels, markers=None):
    """Draws the lines [(xs, ys)], each seen: coinciding lines (line_groups) in one colour, the first
    wide and pale, the others thin, dashed and dotted over it; each line keeps its own label, and the
    legend (returned handles and labels) says a group once: "a, b (coincide within 0.4 % of full scale)"."""
    handles, names = [], []
    for n, (group, worst) in enumerate(line_groups(lines)):
        for j, k in enumerate(group):
            under = j == 0 and len(group) > 1
            marker = markers[k] if markers else "o"
            line, = ax.plot(*lines[k], color=f"C{n}", marker=marker, ms=10 if under else 6 - (j > 0),
                            ls=LINE_STYLES[j % 3], lw=3 if under else 1.2, alpha=0.45 if under else 1,
                            mfc="white" if j > 0 else f"C{n}", label=labels[k])
            if j == 0:
                handles.append(line)
                names.append(said_once([labels[m] for m in group], worst))
    return handles, names


def said_once(labels, worst):
    """The legend entry of coinciding lines: their labels joined, the words before " = " said once
    when they share them ("g = 250 W/(m² K), 1000 W/(m² K)"), and how close they are."""
    if len(labels) == 1:
        return labels[0]
    heads = {str(label).split(" = ", 1)[0] for label in labels}
    if len(heads) == 1 and all(" = " in str(label) for label in labels):
        text = heads.pop() + " = " + ", ".join(str(label).split(" = ", 1)[1] for label in labels)
    else:
        text = " = ".join(str(label) for label in labels)
    return text + (" (identical)" if worst == 0 else f" (coincide within {100 * worst:.2g} % of full scale)")


# The coupling's life (sleeve-life): its design figures against the swept parameter.
DESIGN_PRESSURES = [("clamp_pressure", "clamping (end of heating)"), ("service_pressure_min", "service minimum"),
                    ("pressure_at_service_Tmin", "after the hold at the lowest service temperature")]
DESIGN_MARKERS = ("o", "D", "^")  # one per line of DESIGN_PRESSURES


def design_chart(out, scene, param, values, runs, plt, unit="", fixed=None):
    """design-chart.png of a one-parameter sweep of a scene whose summary has the life's figures
    (sleeve-life) and numeric values: the pressures (MPa) and the storage margin (K) against the
    parameter, the -minpressure line; [] for any other sweep. Returns the paths written."""
    if not runs or not all("pressure_at_service_Tmin" in r.summary for r in runs):
        return []
    try:
        x = [float(v) for v in values]
    except (TypeError, ValueError):
        return []
    order = sorted(range(len(x)), key=lambda i: x[i])
    xs = [shown(param, unit, x[i]) for i in order]
    meaning = driver.options(scene)[param]["meaning"]
    fig, ax = plt.subplots(figsize=(7, 5.6))
    # Every line seen: each its own marker; lines that coincide share one legend entry (draw_lines).
    curves = [[float("nan") if runs[i].summary.get(key) is None else runs[i].summary[key] / 1e6 for i in order]
              for key, _ in DESIGN_PRESSURES]
    handles, names = draw_lines(ax, [(xs, ys) for ys in curves], [label for _, label in DESIGN_PRESSURES],
                                DESIGN_MARKERS)
    ax.axhline(runs[0].summary["min_pressure"] / 1e6, color="k", ls="--", lw=0.8,
               label="least acceptable pressure (-minpressure)")
    ax.set_xlabel(axis_label(param, unit, meaning))
    ax.set_ylabel("mean contact pressure (MPa)")
    ax.ticklabel_format(axis="x", style="plain", useOffset=False)
    ax.grid(alpha=0.3)
    margin = ax.twinx()
    margin.plot(xs, [runs[i].summary["storage_margin"] for i in order], color="0.4", ls=":", marker="s",
                lw=1.0, label="storage margin (K, right axis)")
    margin.set_ylabel("storage margin: reverse start - storage T (K)")
    margin.ticklabel_format(axis="y", useOffset=False)
    line = ax.get_lines()[-1]  # the -minpressure line
    extra = margin.get_legend_handles_labels()
    ax.legend(handles + [line] + extra[0], names + [line.get_label()] + extra[1], fontsize=7, loc="upper center",
              bbox_to_anchor=(0.5, -0.14))  # below the axes: no point hidden
    held = " ".join(f"-{k} {v}" for k, v in (fixed or {}).items())
    ax.set_title(f"{scene}: design chart over the {words_of(param, meaning)} (-{param})"
                 + (f"\n(all runs: {held})" if held else ""), fontsize=10)
    fig.tight_layout()
    path = os.path.join(out, "design-chart.png")
    save(fig, path, 110)
    return [path]


def write_json(path, record):
    """A JSON record of the folder (listed in its manifest, written under a temporary name)."""
    with results_io.publishing(path) as partial, open(partial, "w") as f:
        json.dump(record, f, indent=2, allow_nan=False)


def text_of(value):
    """A parameter value as its folder and table show it: a string as given (without surrounding
    spaces), a number as Python writes it (5e-05, 500)."""
    # (a text's surrounding spaces go, as the run's value loses them: ' 250' made the folder "g= 250")
    return value.strip() if isinstance(value, str) else repr(value.item() if isinstance(value, np.generic) else value)


def run_folder(out, params, combo):
    """The folder of one run: <param>=<value>, or <p1>=<v1>,<p2>=<v2> for several parameters."""
    return os.path.join(out, ",".join(f"{p}={v}" for p, v in zip(params, combo)))


def check_grid(scene, grid, fixed):
    """Checks a sweep's scene, parameters, values and fixed options before anything runs; returns
    (params, {param: [value texts]}). Raises SceneError naming the culprit."""
    driver.script(scene)
    if not isinstance(grid, dict) or not grid:
        raise SceneError(f"{scene}: the grid must be a dict {{option name: [values]}} with at least one option, "
                         f"not {grid!r}")
    params = list(grid)
    for param in params:
        if not isinstance(param, str) or param.startswith("-"):
            raise SceneError(f"the swept option {param!r}: give its name without its dash")
        if param in NOT_SWEPT:
            raise SceneError(f"-{param} cannot be swept (-out is each run's folder, -help lists the options)")
        driver.check_option(scene, param)
    for name in fixed:
        if name in NOT_SWEPT:
            raise SceneError(f"-{name} cannot be a fixed option of a sweep (each run's folder is inside `out`)")
        if name in grid:
            raise SceneError(f"-{name} is swept; do not also give it among the fixed options")
        driver.check_option(scene, name)
        driver.word(scene, name, fixed[name])
    texts = {}
    for param in params:
        values = grid[param]
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise SceneError(f"-{param}: give a list of values, not {values!r}")
        texts[param] = [text_of(v) for v in values]
        if not texts[param]:
            raise SceneError(f"-{param}: the list of values is empty")
        for t in texts[param]:
            if not t or any(c in t for c in BAD_VALUE_CHARACTERS) or t in (".", ".."):
                raise SceneError(f"the value '{t}' of -{param} cannot name a folder ({param}={t})")
            if t.startswith("--"):
                raise SceneError(f"the value '{t}' of -{param} looks like a flag: flags go to --jobs/--out (JOBS=, OUT=)")
        repeated = sorted({t for t in texts[param] if texts[param].count(t) > 1})
        if repeated:
            raise SceneError(f"the value(s) {' '.join(repeated)} of -{param} are given twice (one folder each)")
    for param in params:  # each value against the option's type, before anything runs
        read = {}
        for t, v in zip(texts[param], grid[param]):
            same = read.setdefault(value_as_read(scene, param, driver.word(scene, param, v)), t)
            if same != t:  # 500 and 5e2, 20C and 293.15: one run, two folders, two rows of one value
                raise SceneError(f"the values {same} and {t} of -{param} are the same value: give it once")
    return params, texts


def value_as_read(scene, name, text):
    """The value a scene reads from the option word `text`: a number for a number (500 and 5e2 are
    one), a temperature with its unit in kelvin (20C is 293.15), else the word itself."""
    option = driver.options(scene)[name]
    if option["type"] == "string":
        return text
    kelvin = units.kelvin_of_word(text) if option["type"] == "real" and driver.is_temperature(option) else None
    return float(text) if kelvin is None else kelvin


def grid_runs(params, grid, jobs):
    """The runs of `grid` ({param: [values]}): (each parameter's value texts, the runs' texts and
    values in the grid's order, one tuple a run, and how many run at a time: `jobs`, at most the
    cores and the runs)."""
    texts = [[text_of(v) for v in grid[p]] for p in params]
    combos = list(itertools.product(*texts))
    values = list(itertools.product(*[grid[p] for p in params]))
    return texts, combos, values, max(1, min(jobs, os.cpu_count() or 1, len(combos)))


def run_label(params, combo):
    """A run named by its values, as on a command line: "-g 1000 -dt 0.1"."""
    return " ".join(f"-{p} {v}" for p, v in zip(params, combo))


@contextlib.contextmanager
def stoppable_pool(jobs):
    """A pool of `jobs` threads (each one waits on its FreeFEM process) that, when the caller's
    block is left by an exception (a refused run, a notebook's KeyboardInterrupt), starts no queued
    run and stops the running ones before the exception goes on."""
    children.allow_running()
    with children.terminable(), concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        try:
            yield pool
        except BaseException:
            pool.shutdown(wait=False, cancel_futures=True)
            children.stop_running()
            raise


# A sweep given -resume 1 (make sweep ARGS='-checkpoint 50 -resume 1', fixed={"resume": 1})
# continues the interrupted sweep of its folder, which must have run the same scene, grid and
# options (but these, which change nothing a run computes): its finished runs are kept, those
# with a checkpoint resume from it, the others run. Given to every run as it was, it cleared the
# folder first (a fresh claim) and then each run found no checkpoint.
PLAN = "sweep-plan.json"  # what the sweep runs, written as it takes its folder
PLAN_FREE = ("resume", "quiet", "checkpoint", "stopafter")
SWEEP_OUTPUTS = "table.csv sweep.json *.png"  # what a resumed sweep writes again


def resuming(fixed):
    """Whether the fixed options ask to continue the interrupted sweep (-resume 1)."""
    return "resume" in fixed and text_of(fixed["resume"]) not in ("0", "False")


def sweep_plan(scene, params, grid, fixed):
    """The record a resumed sweep must match: the scene, the grid's value texts, the options."""
    return {"scene": scene, "params": list(params), "values": {p: [text_of(v) for v in grid[p]] for p in params},
            "options": {k: text_of(v) for k, v in sorted(fixed.items()) if k not in PLAN_FREE}}


def summary_digest(folder):
    """The SHA-256 of a run's summary.json ("" without one): the plan's record of a finished run."""
    path = os.path.join(folder, "summary.json")
    if not os.path.isfile(path):
        return ""
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def run_state(folder, finished):
    """"complete" (its run published the summary.json the sweep recorded as it finished: `finished`,
    the plan's {folder name: digest}), "checkpoint" (a checkpoint to resume from) or "fresh"; and
    why a finished-looking run is not kept ("" otherwise). A complete run the sweep did not record
    (put there by hand, or finished as the sweep was stopped) runs again: kept, a run of other
    options would have joined the table under this sweep's."""
    if os.path.isfile(os.path.join(folder, "checkpoint.txt")):
        return "checkpoint", ""
    if os.path.isfile(os.path.join(folder, ".sma-complete")) and os.path.isfile(os.path.join(folder, "summary.json")):
        if finished.get(os.path.basename(folder)) == summary_digest(folder):
            return "complete", ""
        return "fresh", "its summary.json is not one this sweep recorded (a run put there, or finished as the sweep stopped)"
    return "fresh", ""


def record_finished(out, folder):
    """Adds the run in `folder`, just finished, to the plan's record (its summary.json's digest)."""
    path = os.path.join(out, PLAN)
    plan = results_io.read_json(path)
    plan.setdefault("finished", {})[os.path.basename(folder)] = summary_digest(folder)
    write_json(path, plan)


def run_options(fixed, state):
    """A run's fixed options in a (possibly resumed) sweep: -resume 1 only where it has a checkpoint."""
    options = {k: v for k, v in fixed.items() if k != "resume"}
    if state == "checkpoint":
        options["resume"] = 1
    return options


def take_folder(out, scene, params, grid, fixed, jobs):
    """Checks every run, then takes `out` for the sweep (results_io.claim: its earlier results go;
    resumed, -resume 1: only its table, figures and sweep.json, its runs kept) and writes the plan.
    Returns each run's state (run_state; all "fresh" unless resumed) and the notes of a resumed
    sweep: the runs that start again, and why (a finished-looking run it did not record, a
    checkpoint the scene refuses to continue). Raises SceneError naming the refused run, a plan
    that differs from the interrupted sweep's, or a folder that cannot be taken."""
    plan = sweep_plan(scene, params, grid, fixed)
    _, combos, _, _ = grid_runs(params, grid, jobs)
    folders = [run_folder(out, params, c) for c in combos]
    if resuming(fixed):
        path = os.path.join(out, PLAN)
        if not os.path.isfile(path):
            raise SceneError(f"-resume 1: {out} holds no sweep to resume ({path} is missing: a sweep writes it "
                             "as it starts): run the sweep without -resume")
        try:
            before = results_io.read_json(path)
        except results_io.ResultsError as e:
            raise SceneError(f"-resume 1: {e}") from None
        for key in plan:
            if before.get(key) != plan[key]:
                raise SceneError(f"-resume 1: the sweep in {out} ran {key} {json.dumps(before.get(key))}, this one "
                                 f"{json.dumps(plan[key])}: resume with the interrupted sweep's scene, values and "
                                 f"options (only {', '.join('-' + f for f in PLAN_FREE)} may differ)")
        finished = before.get("finished") if isinstance(before.get("finished"), dict) else {}
        found = [run_state(f, finished) for f in folders]
        states = [s for s, _ in found]
        notes = [f"{run_label(params, c)}: {why}: it runs again" for c, (_, why) in zip(combos, found) if why]
    else:
        states, notes = ["fresh"] * len(folders), []
    notes += check_runs(out, scene, params, grid, fixed, jobs, states)
    try:
        if resuming(fixed):
            results_io.resume(out, "sweep " + scene, SWEEP_OUTPUTS)
        else:
            results_io.claim(out, "sweep " + scene)
            try:
                write_json(os.path.join(out, PLAN), plan)
            except OSError as e:
                results_io.release(out)
                raise SceneError(f"cannot write {os.path.join(out, PLAN)}: {e.strerror or e}") from None
    except results_io.ResultsError as e:
        raise SceneError(str(e)) from None
    return states, notes


def check_runs(out, scene, params, grid, fixed, jobs, states=None):
    """Checks every run of the grid (driver.check: the scene's check-only mode, nothing written),
    `jobs` at a time, before the caller takes `out`: a run that refused its options only after
    the sweep's folder was taken came after an earlier sweep's results there were deleted
    (ARGS='-gpipe -5'). A resumed sweep's finished runs (`states`) are not run, nor checked; a run
    whose checkpoint the scene refuses to continue (changed since, damaged) starts again: its state
    becomes "fresh" (in `states`) and a note says why (the list returned). Before, the whole sweep
    was refused with the run's own advice, "run again without -resume", which then deleted the
    sweep's finished runs. Raises SceneError naming the first refused run's values and its error."""
    _, combos, values, jobs = grid_runs(params, grid, jobs)
    states = states if states is not None else ["fresh"] * len(combos)
    notes = {}

    def one(i):
        folder, given = run_folder(out, params, combos[i]), dict(zip(params, values[i]))
        if states[i] == "checkpoint":
            try:
                driver.check(scene, folder, **run_options(fixed, states[i]), **given)
                return
            except SceneError as e:
                notes[i] = f"{run_label(params, combos[i])}: its checkpoint cannot be continued ({e}): it runs again"
                states[i] = "fresh"
        if states[i] != "complete":
            driver.check(scene, folder, **run_options(fixed, states[i]), **given)
    with stoppable_pool(jobs) as pool:
        futures = [pool.submit(one, i) for i in range(len(combos))]
        for i, future in enumerate(futures):  # in the grid's order: the first refused run is named
            try:
                future.result()
            except SceneError as e:
                raise SceneError(f"{run_label(params, combos[i])}: {e}") from None
    return [notes[i] for i in sorted(notes)]


def run_grid(out, scene, params, grid, fixed, jobs, record=None, say=print, warn=None, states=None, notes=()):
    """Runs every combination of the values of `grid` ({param: [values]}, checked by check_grid)
    into its folder of `out` (taken by the caller), then publishes table.csv, the figures and
    sweep.json. `grid`'s values go to the scene as given; their texts (text_of) name the folders
    and fill the table. Returns (exit status 0, or 1 when a run failed, the record written to
    sweep.json, the finished runs as [(combo texts, Results)]). `say` and `warn` print the
    progress and the errors (the command line's console). `states` and `notes` (take_folder): a
    resumed sweep's finished runs are kept, those with a checkpoint resume; each run that finishes
    is recorded in the plan (record_finished), which a later resume keeps it by."""
    import sys
    warn = warn or (lambda line: print(line, file=sys.stderr, flush=True))
    texts, combos, values, jobs = grid_runs(params, grid, jobs)
    folders = [run_folder(out, params, c) for c in combos]
    label = [run_label(params, c) for c in combos]
    states = states or ["fresh"] * len(combos)
    say(f"sweep: {scene} " + " x ".join(f"-{p} over {' '.join(t)}" for p, t in zip(params, texts))
        + f" ({jobs} at a time) into {out}/", flush=True)
    if resuming(fixed):
        say(f"sweep: -resume 1: {states.count('complete')} run(s) finished before are kept, "
            f"{states.count('checkpoint')} resume from their checkpoint, {states.count('fresh')} run", flush=True)
    for note in notes:
        warn(f"note: {note}")

    def one(i):  # the run's notes and warnings named by its values
        if states[i] == "complete":
            return folders[i]
        return driver.run(scene, folders[i], notes=lambda line: warn(f"{label[i]}: {line}"),
                          **run_options(fixed, states[i]), **dict(zip(params, values[i])))

    failures = {}
    with stoppable_pool(jobs) as pool:
        futures = {pool.submit(one, i): i for i in range(len(combos))}
        for future in concurrent.futures.as_completed(futures):
            i = futures[future]
            try:
                future.result()
                if states[i] != "complete":
                    record_finished(out, folders[i])
                say(f"sweep: {label[i]} " + ("kept (finished before)" if states[i] == "complete" else "done"), flush=True)
            except SceneError as e:
                failures[i] = str(e)
                warn(f"error: {label[i]}: {e}")
    results = {}
    for i in range(len(combos)):
        if i not in failures:
            try:
                results[i] = driver.read(folders[i])
            except SceneError as e:
                failures[i] = str(e)
                warn(f"error: {label[i]}: {e}")
    done = [i for i in range(len(combos)) if i not in failures]
    header, rows = table_rows(params, [combos[i] for i in done],
                              [figures_of(results[i].summary, results[i].history, lame_2d(results[i])) for i in done])
    write_table(os.path.join(out, "table.csv"), header, rows)

    runs = [results[i] for i in done]
    drawn = runs and all(r.history is not None and "pressure_mean" in r.history for r in runs)
    written, groups, note = [], [], None
    options = driver.options(scene)
    if drawn:
        plt = pyplot()
        if len(params) == 1:
            unit = unit_of(options[params[0]]["meaning"])
            written, groups = draw(out, scene, params[0], [combos[i][0] for i in done], runs, plt, unit, fixed)
            written += design_chart(out, scene, params[0], [values[i][0] for i in done], runs, plt, unit, fixed)
        else:
            written = draw_grid(out, scene, params, [combos[i] for i in done], runs, rows, header, fixed, plt)
    elif runs:
        note = f"{scene} writes no history.csv with a contact pressure (pressure_mean): the table only"
        say(f"sweep: {note}")
    if len(params) == 1:
        param = params[0]
        sweep_record = {
            "scene": scene, "param": param, "param_meaning": options[param]["meaning"],
            "values": texts[0], **(record or {"args": [], "options": fixed}), "jobs": jobs,
            "runs": [{"value": c[0], "out": folders[i], "status": "failed" if i in failures else "done",
                      **({"error": failures[i]} if i in failures else {}), **resumed_of(states[i])}
                     for i, c in enumerate(combos)],
            "table": "table.csv", "table_columns": header,
            "figures": [os.path.basename(p) for p in written],
            "curves_coinciding_within_0.1_percent": [g for g in groups if len(g) > 1],
            **({"note": note} if note else {}), **({"resume_notes": list(notes)} if notes else {})}
    else:
        sweep_record = {
            "scene": scene, "params": params, "param_meanings": {p: options[p]["meaning"] for p in params},
            "grid": dict(zip(params, texts)), "options": {k: v if isinstance(v, str) else text_of(v)
                                                          for k, v in fixed.items()}, "jobs": jobs,
            "runs": [{"values": dict(zip(params, c)), "out": folders[i],
                      "status": "failed" if i in failures else "done",
                      **({"error": failures[i]} if i in failures else {}), **resumed_of(states[i])}
                     for i, c in enumerate(combos)],
            "table": "table.csv", "table_columns": header,
            "figures": [os.path.basename(p) for p in written], **({"note": note} if note else {}),
            **({"resume_notes": list(notes)} if notes else {})}
    write_json(os.path.join(out, "sweep.json"), sweep_record)
    say(f"sweep: {len(done)} of {len(combos)} runs; table.csv{', figures' if written else ''} "
        f"and sweep.json in {out}/")
    if failures:
        which = (f"-{params[0]} {' '.join(combos[i][0] for i in sorted(failures))}" if len(params) == 1
                 else "; ".join(label[i] for i in sorted(failures)))
        warn(f"error: the sweep's run(s) for {which} failed (sweep.json has each error)")
    return (1 if failures else 0), sweep_record, [(combos[i], results[i]) for i in done]


def resumed_of(state):
    """A run's entry in sweep.json of a resumed sweep: how it continued (nothing for a fresh run)."""
    return {"resumed": {"complete": "kept", "checkpoint": "from its checkpoint"}[state]} if state != "fresh" else {}


def draw_grid(out, scene, params, combos, runs, rows, header, fixed, plt):
    """The figures of a sweep of several parameters: force-temperature.png, one panel per fixed
    value of the other parameters with the first parameter's curves overlaid, and
    final-pressure.png (plot() of the table). Returns the paths written."""
    options = driver.options(scene)
    units = {p: unit_of(options[p]["meaning"]) for p in params}
    meanings = {p: options[p]["meaning"] for p in params}
    first, others = params[0], params[1:]
    panels = []
    for c in combos:
        if c[1:] not in panels:
            panels.append(c[1:])
    held = " ".join(f"-{k} {text_of(v)}" for k, v in fixed.items())
    columns = min(3, len(panels))
    lines = -(-len(panels) // columns)
    fig, axes = plt.subplots(lines, columns, figsize=(4.2 * columns, 3.4 * lines + 0.6), squeeze=False,
                             sharex=True, sharey=True)
    for ax, panel in zip(axes.flat, panels):
        for c, r in zip(combos, runs):
            if c[1:] == panel:
                h = r.history
                ax.plot(h["T_inner_mean"] - KELVIN_AT_0C, h["pressure_mean"] / 1e6, lw=1.2,
                        label=value_label(first, c[0], units[first], meanings[first]))
        ax.set_title(", ".join(value_label(p, v, units[p], meanings[p]) for p, v in zip(others, panel)), fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("mean inner-surface temperature (°C)")
    for ax in axes[:, 0]:
        ax.set_ylabel("mean contact pressure (MPa)")
    fig.suptitle(f"{scene}: " + " x ".join(f"{words_of(p, meanings[p])} (-{p})" for p in params) + " swept"
                 + (f"\n(all runs: {held})" if held else ""), fontsize=10)
    fig.tight_layout()
    written = [os.path.join(out, "force-temperature.png")]
    save(fig, written[-1], 110)

    if "final_pressure_mean_Pa" in header:
        table = frame_of(scene, params, header, rows, [r.out for r in runs])
        fig, ax = plt.subplots(figsize=(7, 4.5))
        plot(table, "final_pressure_mean_Pa", ax=ax)
        ax.set_title(f"{scene}: final mean contact pressure" + (f"\n(all runs: {held})" if held else ""), fontsize=10)
        fig.tight_layout()
        written.append(os.path.join(out, "final-pressure.png"))
        save(fig, written[-1], 110)
    return written


def parameter_column(scene, param):
    """The DataFrame's name of a swept option's column: <param>_<unit> with the unit its -help
    meaning gives (interference_m, g_W/(m^2 K)), the bare name for a count or a switch."""
    unit = unit_of(driver.options(scene)[param]["meaning"])
    return f"{param}_{unit}" if unit else param


def frame_of(scene, params, header, rows, outs):
    """The sweep's table as a DataFrame: the parameters (numbers where the option is int or real,
    named with their units), the key figures of table.csv, and `out`, each run's folder."""
    import pandas as pd
    options = driver.options(scene)
    data = {}
    for k, name in enumerate(header):
        column = [row[k] for row in rows]
        if k < len(params):
            kind = options[name]["type"]
            column = [float(v) if kind == "real" else int(v) if kind == "int" else v for v in column]
            data[parameter_column(scene, name)] = column
        else:
            data[name] = [np.nan if v is None else v for v in column]
    data["out"] = list(outs)
    table = pd.DataFrame(data)
    table.attrs["params"] = {p: parameter_column(scene, p) for p in params}
    return table


def plot(table, y="final_pressure_mean_Pa", x=None, by=None, ax=None):
    """Draws a key figure of a sweep's table against one swept parameter, one line per fixed value
    of the others: `table` a DataFrame of sweep() (or read_sweep()); `y` a column; `x` a swept
    parameter's name (default: the first); `by` the parameters that make the lines (default: the
    others). The axes and the legend say words with their units (sweeps.WORDS: pressures in MPa,
    lengths in mm, temperatures in °C), without offset. Returns the matplotlib Axes (a new figure's
    unless `ax`). Fails (SceneError) naming an unknown column or parameter."""
    params = table.attrs.get("params")
    if not params:
        raise SceneError("plot() takes the DataFrame of sma.sweep() or sma.read_sweep() (its attrs name the parameters)")
    x = x or next(iter(params))
    if x not in params:
        raise SceneError(f"x = {x!r} is not a swept parameter of this table ({', '.join(params)})")
    if y not in table.columns:
        raise SceneError(f"y = {y!r} is not a column of this table ({', '.join(table.columns)})")
    by = [p for p in params if p != x] if by is None else list(by)
    unknown = [p for p in by if p not in params or p == x]
    if unknown:
        raise SceneError(f"by = {unknown}: not swept parameters other than x ({', '.join(params)})")
    if ax is None:
        ax = pyplot().subplots(figsize=(7, 4.5))[1]
    key_of_y, y_unit = column_key(y)
    y_label = axis_label(key_of_y, y_unit)
    keys = [params[p] for p in by]
    groups = table.groupby(keys if len(keys) > 1 else keys[0], sort=False) if by else [((), table)]
    def unit(p):  # the unit in a parameter's column name (interference_m: m)
        return params[p][len(p) + 1:]
    lines, labels = [], []
    for key, part in groups:
        key = key if isinstance(key, tuple) else (key,)
        part = part.sort_values(params[x])
        labels.append(", ".join(value_label(p, f"{v:g}" if isinstance(v, (int, float)) else v, unit(p))
                                for p, v in zip(by, key)) or None)
        xs, ys = part[params[x]], part[y]
        lines.append((list(shown(x, unit(x), xs) if is_number(xs) else xs), list(shown(key_of_y, y_unit, ys))))
    handles, names = draw_lines(ax, lines, labels)
    ax.set_xlabel(axis_label(x, unit(x)))
    ax.set_ylabel(y_label)
    for axis in ("x", "y"):  # no offset: the tick labels are the values
        try:
            ax.ticklabel_format(axis=axis, useOffset=False)
        except AttributeError:  # a categorical axis (a string option)
            pass
    ax.grid(alpha=0.3)
    if by:
        ax.legend(handles, names, fontsize=8)
    return ax


def is_number(column):
    """Whether a DataFrame column holds numbers (a real or int option), not words."""
    import pandas as pd
    return pd.api.types.is_numeric_dtype(column)


def sweep(scene, grid, fixed=None, jobs=2, out=None):
    """Runs `scene` over every combination of the values of `grid` ({option name: [values]}, one
    or several options), with the options `fixed` ({name: value}) in every run, `jobs` runs at a
    time (at most the cores), into `out` (default results/sweeps/<scene>-<param>[-<param>...];
    relative to the repository root). Everything is checked before anything runs (SceneError
    naming the scene, option or value), every run by the scene itself in its check-only mode
    (-checkonly 1), before the folder is taken. Writes table.csv, sweep.json and the figures (module
    docstring) and returns the table as a pandas DataFrame: one row per run, the parameters
    (named with their units: interference_m, g_W/(m^2 K)), the key figures (first_contact_time_s,
    final_pressure_mean_Pa, ...), and `out`, the run's folder (absolute); attrs["out"] is the
    sweep's folder, attrs["figures"] its figures. When a run fails the others still run and are
    published; then a SceneError names the failed runs (its `table` attribute holds the others').
    fixed={"resume": 1, ...} continues the interrupted sweep in `out` (same grid and options): its
    finished runs kept, those with a checkpoint (-checkpoint N) resumed, the others run."""
    # (a TERM or HUP anywhere in the sweep is said and passed on: between the checks' pool and the
    # runs' pool, each terminable() alone, Python's default ended the sweep without a word,
    # tests/signals_test.py, 1 run in 6)
    with children.terminable():
        fixed = dict(fixed or {})
        params, texts = check_grid(scene, grid, fixed)
        grid = {p: list(grid[p]) for p in params}
        if not isinstance(jobs, int) or isinstance(jobs, bool) or jobs < 1:
            raise SceneError(f"jobs = {jobs!r}: a whole number of runs at a time >= 1")
        out = driver.folder(out if out is not None else os.path.join("results", "sweeps", "-".join([scene] + params)))
        states, notes = take_folder(out, scene, params, grid, fixed, jobs)
        try:
            status, record, done = run_grid(out, scene, params, grid, fixed, jobs, notes=notes,
                                            record={"args": [w for k, v in fixed.items() for w in (f"-{k}", text_of(v))],
                                                    "options": {k: text_of(v) for k, v in fixed.items()}},
                                            say=lambda *a, **k: None, warn=lambda line: None, states=states)
            if status == 0:
                results_io.complete(out)
        except results_io.ResultsError as e:
            raise SceneError(str(e)) from None
        finally:
            results_io.release(out)
        table = read_sweep(out)
        if status:
            failed = [r for r in record["runs"] if r["status"] == "failed"]
            error = SceneError(f"{len(failed)} of {len(record['runs'])} runs of the sweep in {out} failed:\n"
                               + "\n".join(f"  {r['out']}: {r['error'].splitlines()[0]}" for r in failed))
            error.table = table
            raise error
        return table


def read_sweep(out):
    """The table of a finished sweep in `out` (its table.csv and sweep.json) as the DataFrame sweep()
    returns. Fails (SceneError) naming the folder or file when it holds no finished sweep."""
    out = driver.folder(out)
    try:
        record = results_io.read_json(os.path.join(out, "sweep.json"))
    except results_io.ResultsError as e:
        raise SceneError(str(e)) from None
    params = record.get("params", [record.get("param")])
    path = os.path.join(out, "table.csv")
    try:
        with results_io.opened(path, newline="") as f:
            lines = list(csv.reader(f))
    except results_io.ResultsError as e:
        raise SceneError(str(e)) from None
    if not lines or lines[0][:len(params)] != params:
        raise SceneError(f"{path} does not start with the swept parameters {params} (a damaged or foreign table)")
    header, body = lines[0], lines[1:]
    done = [r for r in record["runs"] if r["status"] == "done"]
    if len(body) != len(done) or any(len(row) != len(header) for row in body):
        raise SceneError(f"{path}: {len(body)} rows for {len(done)} finished runs, or a row of the wrong length "
                         "(a damaged table: run the sweep again)")
    rows = []
    for number, row in enumerate(body, 2):
        converted = list(row[:len(params)])
        for name, text in zip(header[len(params):], row[len(params):]):
            try:
                converted.append(None if text == "" else int(text) if re.fullmatch(r"-?\d+", text) else float(text))
            except ValueError:
                raise SceneError(f"{path}: line {number}, column {name}: '{text}' is not a number") from None
        rows.append(converted)
    table = frame_of(record["scene"], params, header, rows, [r["out"] for r in done])
    table.attrs["out"] = out
    table.attrs["figures"] = [os.path.join(out, f) for f in record.get("figures", [])]
    return table
