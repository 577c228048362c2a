#!/usr/bin/python3
"""A 2D sleeve run's contact section against a 3D run's mid-length ring (the plane hypothesis:
sleeve-3d -ends held against sleeve-elliptic or sleeve-elliptic-friction), from their
contact-final.csv files (one row per bore node: x, y, angle_deg, normal_force, tangential_force,
tributary_length, tangential_density; the 3D's also z, the 2D's its whole section).

    weighted_pressure(rows2d, weight, column="normal_force") -> Pa
        sum |column| w over sum tributary_length w, w = weight(x, y) per node: weight 1 is the ring
        average (sleeve-3d's summary final_pressure_mid), |x| / r and |y| / r the pressures weighted
        towards the x and the y axes (its final_pressure_mid_x, _y); column tangential_force gives
        the ring-averaged |traction| (final_traction_mid).
    density_misfit(rows2d, rows) -> Pa
        the largest |run - 2D| of the filtered tangential density at the other run's mid-length nodes
        (a 3D's z = 0; every node of another 2D run's), the 2D's profile interpolated piecewise
        linearly in the angle at theirs.
"""
import math

from curve_error import interpolate


def weighted_pressure(rows2d, weight, column="normal_force"):
    force = sum(abs(float(r[column])) * weight(float(r["x"]), float(r["y"])) for r in rows2d)
    return force / sum(float(r["tributary_length"]) * weight(float(r["x"]), float(r["y"])) for r in rows2d)


def towards_x(x, y):
    return abs(x) / math.hypot(x, y)


def towards_y(x, y):
    return abs(y) / math.hypot(x, y)


def density_profile(rows, mid_length=False):
    """(angle_deg, tangential_density) sorted by angle: every row, or the mid-length ring (z = 0; a 2D
    run's rows have no z: all of them)."""
    return sorted((float(r["angle_deg"]), float(r["tangential_density"]))
                  for r in rows if not mid_length or float(r.get("z", 0)) == 0)


def density_misfit(rows2d, rows):
    profile = density_profile(rows2d)
    angles, densities = [a for a, _ in profile], [t for _, t in profile]
    return max(abs(t - interpolate(angles, densities, a)) for a, t in density_profile(rows, mid_length=True))
