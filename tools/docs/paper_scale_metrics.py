"""The measures of tools/docs/paper_scale_fit.py (and tools/docs/claims.py), read from a run's
outputs: the force curve's phases, the reversion's start, the variable-g crossing, the offset and
elliptic pipes' figures; and how a candidate a scores against the paper's statements."""
import json
import os

import numpy as np


def hist(out):
    return np.genfromtxt(os.path.join(out, "history.csv"), delimiter=",", names=True)


def summ(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def points(out):
    return np.genfromtxt(os.path.join(out, "points.csv"), delimiter=",", names=True)


def C(TK):
    """Celsius of a temperature in K; nan for an event that did not happen (summary.json's null)."""
    return float("nan") if TK is None else TK - 273.15


def step_or_never(step):
    """A summary.json event step, or -1 (this tool's 'never') where it is null."""
    return -1 if step is None else step


def curve(out):
    """The force curve's stages from history.csv and summary.json."""
    h, s = hist(out), summ(out)
    fa = h["fraction_austenite"]
    base = fa[1:10].min()                       # after the first transformation to martensite
    contact = step_or_never(s["first_contact_step"])
    on = np.nonzero((fa > base + 1e-4) & (h["step"] >= 3))[0]
    onset = int(h["step"][on[0]]) if len(on) else -1
    aus = step_or_never(s["austenite_step"])
    p = h["pressure_mean"]
    pf = s["final_pressure_mean"]
    r = dict(first_contact_step=contact, T_contact_C=C(s["T_inner_first_contact"]),
             zero_steps=contact - 1 if contact > 0 else float("nan"), onset_step=onset,
             T_onset_C=C(h["T_inner_mean"][onset - 1]) if onset > 0 else float("nan"),
             austenite_step=aus, T_austenite_C=C(s["T_inner_austenite"]),
             linear_steps=(onset - contact) if onset > 0 and contact > 0 else 0,
             final_GPa=pf / 1e9, non_uniformity=s["final_pressure_non_uniformity"],
             peak_over_final=s["peak_pressure_mean"] / pf if pf > 0 else float("nan"),
             node_peak_over_final=s.get("node_peak_over_final_max", float("nan")),
             t_final_s=float(h["t"][aus - 1]) if aus > 0 else float("nan"))
    # linearity of p(T) over the linear stage (R^2 of a straight line)
    if r["linear_steps"] > 5:
        i0, i1 = contact, onset - 1              # rows of steps contact+1 .. onset-1
        T, pp = h["T_inner_mean"][i0:i1], p[i0:i1]
        res = pp - np.polyval(np.polyfit(T, pp, 1), T)
        r["linear_R2"] = 1 - (res ** 2).sum() / ((pp - pp.mean()) ** 2).sum()
    else:
        r["linear_R2"] = float("nan")
    # jerks: largest one-step rise of the mean pressure during the reversion, over the final value
    if onset > 0 and aus > 0:
        dp = np.diff(p)[onset - 2:aus]
        r["max_jump"] = dp.max() / pf
        r["jumps_over_1pct"] = int((dp > 0.01 * pf).sum())
    else:
        r["max_jump"], r["jumps_over_1pct"] = float("nan"), 0
    r["four_phases"] = bool(r["zero_steps"] > 0 and r["linear_steps"] > 0 and onset > 0
                            and aus >= onset)
    return r


def read_vtu(path):
    import base64
    import re
    import struct
    s = open(path).read()
    d = {}
    for m in re.finditer(r'<DataArray([^>]*)>\s*([^<]*)</DataArray>', s):
        attrs, data = m.group(1), m.group(2).strip()
        nm = re.search(r'Name="([^"]*)"', attrs)
        nm = nm.group(1) if nm else "Points"
        typ = re.search(r'type="([^"]*)"', attrs).group(1)
        nc = re.search(r'NumberOfComponents="(\d+)"', attrs)
        nc = int(nc.group(1)) if nc else 1
        raw = base64.b64decode(data)
        n = struct.unpack("<I", raw[:4])[0]
        a = np.frombuffer(raw[4:4 + n], dtype={"Float32": "<f4", "Float64": "<f8",
                                                "Int32": "<i4", "UInt8": "u1"}[typ])
        d[nm] = a.reshape(-1, nc) if nc > 1 else a
    return d


def reversion_start(out, onset):
    """Where the reversion starts through the thickness: the austenite-weighted mean of
    (r - Ri) / (Ro - Ri) over the triangles at the first frame at or after the onset step
    (0: inner surface, 1: outer surface), and that frame's step."""
    fr = os.path.join(out, "frames")
    steps = sorted(int(f[5:11]) for f in os.listdir(fr) if f.startswith("step-"))
    for st in steps:
        if st < onset:
            continue
        d = read_vtu(os.path.join(fr, "step-%06d.vtu" % st))
        xy = d["Points"][:, :2]
        tri = d["types"] == 5
        conn = d["connectivity"]
        offs = d["offsets"]
        cells = [conn[o - 3:o] for o, t in zip(offs, tri) if t]
        r = np.hypot(xy[:, 0], xy[:, 1])
        rc = np.array([r[c].mean() for c in cells])
        Ri, Ro = r.min(), r.max()
        aus = 1 - d["martensite_fraction"][tri]
        if aus.sum() < 1e-9:
            continue
        rho = (rc - Ri) / (Ro - Ri)
        return float((aus * rho).sum() / aus.sum()), st
    return float("nan"), -1


def gvar_crossing(out_circ, out_gvar):
    """Lowest inner temperature (C, 0.25 K grid) from which the gvar pressure is at least the
    constant-g one, both read at the first step their inner surface reaches that temperature;
    and the largest relative deficit below it."""
    hc, hg = hist(out_circ), hist(out_gvar)

    def p_at(h, T):
        i = int(np.argmax(h["T_inner_mean"] >= T))
        return h["pressure_mean"][i] if h["T_inner_mean"][i] >= T else float("nan")
    sc = summ(out_circ)
    T0 = max(sc["T_inner_first_contact"], summ(out_gvar)["T_inner_first_contact"]) + 0.5
    T1 = min(hc["T_inner_mean"].max(), hg["T_inner_mean"].max())
    pf = sc["final_pressure_mean"]
    for T in np.arange(T0, T1, 0.25):
        pc, pg = p_at(hc, T), p_at(hg, T)
        if pg >= pc - 1e-3 * pf:
            # both at the final level does not count as the gvar curve rising above
            if pc >= 0.999 * pf and pg >= 0.999 * pf:
                return float("nan")
            return C(T)
    return float("nan")


def ellipse_metrics(out, p_circ):
    P, s = points(out), summ(out)
    py, px = P["pressure_y_axis_Pa"], P["pressure_x_axis_Pa"]   # y: major axis (5.05 cm)
    iy = int(np.argmax(py > 0)) if (py > 0).any() else -1
    ix = int(np.argmax(px > 0)) if (px > 0).any() else -1
    lift = bool(iy >= 0 and ix > iy and (py[iy:ix] <= 0).any())
    # paper 4.4.1 "relachement": the major axis' pressure falls back before the minor axis touches
    relax = float((py[iy:ix].max() - py[ix]) / py[iy:ix].max()) if iy >= 0 and ix > iy else 0.0
    return dict(major_first_step=int(P["step"][iy]) if iy >= 0 else -1,
                minor_first_step=int(P["step"][ix]) if ix >= 0 else -1,
                major_lifts_before_minor=lift, major_relax=relax,
                major_over_minor=py[-1] / px[-1] - 1 if px[-1] > 0 else float("nan"),
                vs_circular=s["final_pressure_mean"] / p_circ - 1,
                non_uniformity=s["final_pressure_non_uniformity"],
                t_over_n=s["final_tangential_over_normal"],
                t_over_n_total=s["final_tangential_over_normal_total"],
                sticking=s["final_nodes_sticking"], in_contact=s["final_nodes_in_contact"],
                four_phases=curve(out)["four_phases"])


def offset_metrics(out, p_circ):
    P, s = points(out), summ(out)
    first = {}
    for k in ("near", "top", "far"):
        p = P["pressure_%s_Pa" % k]
        first[k] = int(P["step"][int(np.argmax(p > 0))]) if (p > 0).any() else -1
    return dict(first_near=first["near"], first_top=first["top"], first_far=first["far"],
                non_uniformity=s["final_pressure_non_uniformity"],
                vs_circular=s["final_pressure_mean"] / p_circ - 1,
                slide_um=s["anchor_displacement_x"] * 1e6, **{k: v for k, v in curve(out).items()
                                                               if k in ("zero_steps", "linear_steps",
                                                                        "four_phases")})


def tmin_position(out):
    """(r - Ri)/(Ro - Ri) of the coldest node of fields-2-contact.csv (paper 4.4.3: minima at
    mid-thickness)."""
    f = os.path.join(out, "fields-2-contact.csv")
    if not os.path.exists(f):      # written once the reversion is over (its middle instant)
        return float("nan")
    d = np.genfromtxt(f, delimiter=",", names=True,
                      skip_header=1)
    r = np.hypot(d["x"], d["y"])
    return float((r[np.argmin(d["T"])] - r.min()) / (r.max() - r.min()))




def a_checks(m):
    """The a-dependent statements: (key, passed, quantity shown)."""
    c, g, o, e = m["circ"], m["gvar"], m["offset"], m["ell"]
    X = m["cross"]
    return [
        ("clear", c["zero_steps"] > 0, "%d" % c["zero_steps"]),
        ("four", c["four_phases"], "%d/%d/%d" % (c["zero_steps"], c["linear_steps"],
                                                 c["austenite_step"] - c["onset_step"])),
        ("gvar30", not np.isnan(X) and abs(X + 30) <= 5, "none" if np.isnan(X) else "%.1f" % X),
        ("gvarfour", g["four_phases"], "%d/%d" % (g["zero_steps"], g["linear_steps"])),
        ("offset", o["four_phases"] and o["non_uniformity"] < 0.05 and abs(o["vs_circular"]) < 0.05,
         "%d/%d, %.1f %%, %+.1f %%" % (o["zero_steps"], o["linear_steps"],
                                       100 * o["non_uniformity"], 100 * o["vs_circular"])),
        ("ell", e["major_first_step"] < e["minor_first_step"] and e["major_relax"] > 0.1
         and e["four_phases"], "%d<%d, falls %.0f %%, lift-off %s"
         % (e["major_first_step"], e["minor_first_step"], 100 * e["major_relax"],
            "yes" if e["major_lifts_before_minor"] else "no")),
    ]


def score(m):
    """Statements passed; ties: the variable-g run's reversion onset closest to the paper's
    -30 C (its force leaves the linear line there), then the smaller a."""
    ch = a_checks(m)
    X = m["gvar"]["T_onset_C"]
    return (sum(1 for _, ok, _ in ch if ok), -(abs(X + 30) if not np.isnan(X) else 99), -m["a"])

