"""The scenes' CSV files as pandas DataFrames whose column names carry their units.

A column is named `<name>_<unit>` with the SI unit docs/outputs.md gives it (`t_s`,
`T_inner_mean_K`, `pressure_mean_Pa`, `normal_force_N/m`); a name that already ends in its unit
(`T_x_axis_K`, `angle_deg`, `gap_x_axis_m`) is kept; counts, flags and ratios (`step`,
`contact_nodes`, `fraction_austenite`, `phase`) have no unit and keep their name. A column whose
unit is not known here is refused, naming it and its file (never a number without its unit): read
such a file as arrays with sma.read_csv. pandas (Debian's python3-pandas) is imported only here.
"""
import os

from .errors import SceneError
from .results_io import ResultsError, read_csv as _read_columns

# The SI unit of each column the scenes write (docs/outputs.md: history.csv, points.csv,
# contact-final.csv, fields-<instant>.csv; sleeve-radial's history.csv and fields-<instant>.csv).
UNITS = {
    "t": "s", "dt": "s", "T_inner_mean": "K", "T_min": "K", "T_max": "K",
    "pressure_mean": "Pa", "pressure_min": "Pa", "pressure_max": "Pa",
    "u_inner": "m", "gap_inner": "m", "reaction_per_radian": "N/m",
    "x": "m", "y": "m", "normal_force": "N/m", "tangential_force": "N/m", "tributary_length": "m",
    "pressure": "Pa", "tangential_density": "Pa", "slip_last_step": "m", "slip_total": "m", "gap": "m",
    "pressure_peak": "Pa",
    "T": "K", "sigma_rr": "Pa", "sigma_tt": "Pa", "T0_local": "K", "ux": "m", "uy": "m",
    "r": "m", "s": "Pa", "u": "m",
    # beam: phase-<mesh>.csv (the triangles' vertices), dc-convergence.csv (L_II per metre of depth)
    "x1": "m", "y1": "m", "x2": "m", "y2": "m", "x3": "m", "y3": "m",
    "lagrangian_after_global": "J/m", "lagrangian_after_local": "J/m",
    # ring-lame: pressure-<level>.csv
    "pressure_nodal": "Pa",
    # free-ring: history.csv (heats per step and metre of depth of the quarter ring)
    "T_outside": "K", "T_mean": "K", "T_inner": "K",
    "stored_heat": "J/m", "boundary_heat": "J/m", "latent_heat": "J/m", "dissipated_heat": "J/m",
}
# Counts, flags, fractions and ratios: no unit (1).
NO_UNIT = {"step", "fraction_austenite", "fraction_m1", "fraction_m2", "contact_nodes", "tangential_over_normal",
           "fixed_point_iterations", "slip_iterations", "dc_iterations", "psor_sweeps", "last_slip_step",
           "cone_ratio", "sticking", "peak_step", "phase", "martensite_fraction",
           "iteration", "relative_change", "points_changed", "before_stop", "fixed_point_residual"}
# Labels kept as text (beam's dc-convergence.csv names its mesh level).
TEXT = {"mesh"}
# A name ending in one of these is in that unit already (docs/outputs.md's convention).
SUFFIXES = {"_K": "K", "_Pa": "Pa", "_m": "m", "_s": "s", "_deg": "deg"}


def unit_of_column(name, path="a CSV"):
    """(the DataFrame's name of the column `name`, its unit or ""); a SceneError naming the column
    and `path` when its unit is not known."""
    if name in NO_UNIT or name in TEXT:
        return name, ""
    if name in UNITS:
        return f"{name}_{UNITS[name]}", UNITS[name]
    for suffix, unit in SUFFIXES.items():
        if name.endswith(suffix) and len(name) > len(suffix):
            return name, unit
    raise SceneError(f"{path}: no unit is known for the column '{name}' (sma/frames.py lists those of "
                     "docs/outputs.md): read the file as arrays with sma.read_csv")


def frame(path):
    """The CSV file at `path` as a pandas DataFrame, its columns renamed with their units
    (`pressure_mean` -> `pressure_mean_Pa`; counts stay integers); `attrs["units"]` maps each new
    name to its unit ("" for none), `attrs["file"]` is the absolute path. Fails (SceneError)
    naming the file when it is missing or damaged, or a column whose unit is unknown."""
    import pandas as pd
    path = os.path.abspath(path)
    try:
        columns = _read_columns(path, text_columns=TEXT)
    except ResultsError as e:
        raise SceneError(str(e)) from None
    names = [unit_of_column(name, path) for name in columns]
    df = pd.DataFrame({new: columns[old] for (new, _), old in zip(names, columns)})
    for (new, _), old in zip(names, columns):
        if old in ("step", "last_slip_step", "peak_step", "contact_nodes", "sticking", "iteration", "points_changed",
                   "before_stop") or old.endswith("_iterations") or old == "psor_sweeps":
            if df[new].notna().all() and (df[new] == df[new].round()).all():
                df[new] = df[new].astype("int64")
    df.attrs["units"] = dict(names)
    df.attrs["file"] = path
    return df
