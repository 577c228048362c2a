#!/usr/bin/python3
"""Error between two force-temperature histories of the sleeve scenes (history.csv of
edp/problems/sleeve/sleeve-2d.idp or edp/scenes/sleeve-radial.edp: columns t, pressure_mean, T_inner_mean,
contact_nodes, fraction_austenite).

    curve_error(history_csv, reference_csv) -> dict
    tools/bench/oracles/curve_error.py history.csv reference.csv      prints that dict as JSON

Both pressure curves p(t), p_ref(t) are taken as piecewise linear in t through their steps, with
p = 0 at t = 0 (the initial state touches nothing), and compared over [0, tEnd], tEnd the end of
the shorter history. Integrals are exact for piecewise linear functions (on the union of both time
grids each difference is linear on every sub-interval, and |linear| integrates in closed form).

Keys:
  l1     the headline metric: relative L1-in-time error of the pressure,
         int |p - p_ref| dt / int |p_ref| dt. The curve jumps when the ring turns back to
         austenite; a run that jumps one step earlier or later than the reference has a one-step
         error of the size of the jump in a max norm, whatever dt, while in L1 that error weighs
         jump x dt and vanishes as dt -> 0. So l1 measures convergence, linf does not.
  final  relative error of the final pressure |p(tEnd) - p_ref(tEnd)| / |p_ref(tEnd)|
  l1_transient  the same over [0, t_A], t_A the time from which the reference is austenite for
         good (the end of the story: zero, linear, reversion); over [0, tEnd] the long constant
         tail (about 135 of the sleeves' 150 s) dilutes the relative error
  l1_reversion  the same over the reversion window [t_R, t_A], t_R the reference's last step
         before its ring, martensite since its first contact, starts to turn back (where the
         force rises steeply and a whole-run metric hides the error); None without one
  linf   max |p - p_ref| / max |p_ref| (on the union grid, where a piecewise linear maximum is)
  peak   relative error of the highest pressure
  first_contact_dT   T_inner (K) at the first step in contact minus the reference's
  first_contact_dt   time (s) of that step minus the reference's
  austenite_dt       time (s) from which the ring is austenite for good, minus the reference's
  T_inner_l1         mean |T_inner - T_inner_ref| over [0, tEnd] (K), T piecewise linear in t
                     through the steps (from the first step on: T at t = 0 is not recorded)
  tend, steps, reference_steps
"""
import csv
import json
import sys


def read_history(path):
    """Columns of a history.csv as lists of floats (lines starting with # skipped)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        raise ValueError(f"{path}: no rows")
    for key in ("t", "pressure_mean"):
        if key not in rows[0]:
            raise ValueError(f"{path}: no column {key!r}")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def interpolate(ts, ys, t):
    """Value at t of the piecewise linear function through (ts, ys), ts increasing; held constant
    outside."""
    if t <= ts[0]:
        return ys[0]
    if t >= ts[-1]:
        return ys[-1]
    lo, hi = 0, len(ts) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if ts[mid] <= t:
            lo = mid
        else:
            hi = mid
    w = (t - ts[lo]) / (ts[hi] - ts[lo])
    return ys[lo] + w * (ys[hi] - ys[lo])


def abs_integral(t0, t1, d0, d1):
    """Exact integral of |d| over [t0, t1] for d linear from d0 to d1."""
    h = t1 - t0
    if d0 * d1 >= 0:
        return h * (abs(d0) + abs(d1)) / 2
    return h * (d0 * d0 + d1 * d1) / (2 * (abs(d0) + abs(d1)))


def first_index(values, predicate):
    return next((i for i, v in enumerate(values) if predicate(v)), None)


def austenite_time(h):
    """Time from which the ring is austenite for good (None if never, or no such column)."""
    if "fraction_austenite" not in h:
        return None
    last = max((i for i, f in enumerate(h["fraction_austenite"]) if f < 1), default=-1)
    return h["t"][last + 1] if last + 1 < len(h["t"]) else None


def reversion_time(h):
    """Time of the last step before the ring, martensite after its first contact, starts to turn
    back to austenite (None if it never does, or no such columns): the reversion window's start."""
    if "fraction_austenite" not in h or "contact_nodes" not in h:
        return None
    touched = first_index(h["contact_nodes"], lambda v: v > 0)
    if touched is None:
        return None
    i = first_index(range(touched, len(h["t"])), lambda k: h["fraction_austenite"][k] > 0)
    return h["t"][touched + i - 1] if i is not None and touched + i > 0 else None


def l1_errors(ta, pa, tb, pb, t_end, t_start=0.0):
    """(int |a - b| dt, int |b| dt) over [t_start, t_end], and the union grid with a and b on it."""
    grid = sorted({t for t in ta + tb if t_start <= t <= t_end} | {t_start, t_end})
    da = [interpolate(ta, pa, t) for t in grid]
    db = [interpolate(tb, pb, t) for t in grid]
    err = ref_norm = 0.0
    for i in range(len(grid) - 1):
        err += abs_integral(grid[i], grid[i + 1], da[i] - db[i], da[i + 1] - db[i + 1])
        ref_norm += abs_integral(grid[i], grid[i + 1], db[i], db[i + 1])
    return err, ref_norm, grid, da, db


def curve_error(history_csv, reference_csv):
    h, ref = read_history(history_csv), read_history(reference_csv)
    t_end = min(h["t"][-1], ref["t"][-1])
    ta, pa = [0.0] + h["t"], [0.0] + h["pressure_mean"]
    tb, pb = [0.0] + ref["t"], [0.0] + ref["pressure_mean"]
    err, ref_norm, grid, da, db = l1_errors(ta, pa, tb, pb, t_end)
    t_transient = min(austenite_time(ref) or t_end, t_end)
    err_tr, ref_tr, _, _, _ = l1_errors(ta, pa, tb, pb, t_transient)
    t_rev = reversion_time(ref)
    if t_rev is not None and t_rev < t_transient:
        err_w, ref_w, _, _, _ = l1_errors(ta, pa, tb, pb, t_transient, t_rev)
        window = {"l1_reversion": err_w / ref_w if ref_w > 0 else float("nan"), "reversion_start": t_rev}
    else:
        window = {"l1_reversion": None, "reversion_start": None}
    ref_max = max(abs(v) for v in db)
    result = {
        "l1": err / ref_norm if ref_norm > 0 else float("nan"),
        "l1_absolute_Pa_s": err,
        "l1_transient": err_tr / ref_tr if ref_tr > 0 else float("nan"),
        "transient_end": t_transient,
        "final": abs(da[-1] - db[-1]) / abs(db[-1]) if db[-1] != 0 else float("nan"),
        "linf": max(abs(x - y) for x, y in zip(da, db)) / ref_max if ref_max > 0 else float("nan"),
        "peak": abs(max(da) - max(db)) / max(db) if max(db) > 0 else float("nan"),
        "tend": t_end, "steps": len(h["t"]), "reference_steps": len(ref["t"]),
    }
    result.update(window)
    if "T_inner_mean" in h and "T_inner_mean" in ref:
        t0 = max(h["t"][0], ref["t"][0])
        tgrid = [t for t in grid if t >= t0]
        dT = [interpolate(h["t"], h["T_inner_mean"], t) - interpolate(ref["t"], ref["T_inner_mean"], t)
              for t in tgrid]
        total = sum(abs_integral(tgrid[i], tgrid[i + 1], dT[i], dT[i + 1]) for i in range(len(tgrid) - 1))
        # (no shared time at all: none; it raised IndexError on two curves meeting at one time only)
        result["T_inner_l1"] = (total / (tgrid[-1] - tgrid[0]) if len(tgrid) > 1
                                else abs(dT[0]) if tgrid else None)
    if "contact_nodes" in h and "contact_nodes" in ref:
        i = first_index(h["contact_nodes"], lambda v: v > 0)
        j = first_index(ref["contact_nodes"], lambda v: v > 0)
        if i is not None and j is not None:
            result["first_contact_dt"] = h["t"][i] - ref["t"][j]
            if "T_inner_mean" in h and "T_inner_mean" in ref:
                result["first_contact_dT"] = h["T_inner_mean"][i] - ref["T_inner_mean"][j]
    ta_h, ta_ref = austenite_time(h), austenite_time(ref)
    if ta_h is not None and ta_ref is not None:
        result["austenite_dt"] = ta_h - ta_ref
    return result


def main():
    if len(sys.argv) != 3:
        print("usage: tools/bench/oracles/curve_error.py history.csv reference.csv", file=sys.stderr)
        sys.exit(2)
    try:
        result = curve_error(sys.argv[1], sys.argv[2])
    except (OSError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
