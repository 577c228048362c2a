#!/usr/bin/python3
"""Fit the sleeve scenes' open parameters to the paper's own statements (issue 25, step 1).

Usage: /usr/bin/python3 tools/docs/paper_scale_fit.py [--quick] [--work DIR]

The paper (Pagano, Alart & Lebon 1998, section 4) prints a = 300 J/(kg K), which cannot open its
5 cm ring over its 5.05 cm pipe. This script keeps the paper's geometry (0.5 mm interference,
offset 0.05 cm, ellipse 5.05 x 5.04 cm) and measures, for candidate values of a and then of the
choices the paper leaves open (which faces exchange heat, the random threshold's spread), the
quantity behind each of the paper's statements (section / figure), with the default phase model
(fraction, step solver newton) and with -phasemodel onoff where the statement is about the paper's
own on/off scheme. It writes docs/paper-scale.md and docs/paper-scale.csv.

Stage 1 (a): sleeve-circular, -gvar, -offset, -elliptic, -elliptic-friction at each candidate a;
the best a is the one passing most a-dependent statements (ties: the gvar crossing temperature
closest to the paper's -30 C, then the smaller a); the neighbours of the best are then refined.
Stage 2 (at the chosen a): outer face exchanging (the defaults, g = 500 on both faces) against an
insulated outer face (-g 0 -gpipe 500 -gcontact 500 [2000 for gvar]); the random threshold's
spread (-cspread); the on/off phase model.

Runs go one at a time (never in parallel) into --work (default /tmp/paper-scale-fit), each with
its log <out>.log. A run that fails (exit code not 0, or no summary.json) is reported loudly with
its log; the steps the newton step solver leaves unsolved are solved by the nested loops within
the run (-stepfallback 1) and counted in the run table; if a whole run still fails and its spec
names a fallback (only -stepsolver fixedpoint, the paper's nested loops), the fallback is run and its use
is recorded in the table; if every attempt fails the script stops with exit code 1, naming the
run and its logs.
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper_scale_runs as runs  # noqa: E402
from paper_scale_metrics import curve, ellipse_metrics, gvar_crossing, offset_metrics, reversion_start, score, summ, tmin_position  # noqa: E402
from paper_scale_report import write_report  # noqa: E402
from paper_scale_runs import ELLIPSE, FALLBACK, HEATS, INTERF, OFFSET, RUNLOG, VTK, RunFailed, gvar_opts, run  # noqa: E402


# ------------------------------------------------------------------ stage 1: a
def stage_a(work, a, rows):
    A = ["-a", str(a), "-interference", str(INTERF)]
    tag = "a%d" % a
    oc = run(work, tag + "-circular", "sleeve-circular", A + VTK)
    og = run(work, tag + "-gvar", "sleeve-circular-gvar", A, FALLBACK)
    oo = run(work, tag + "-offset", "sleeve-offset", A + ["-offset", str(OFFSET)], FALLBACK)
    oe = run(work, tag + "-elliptic", "sleeve-elliptic", ["-a", str(a)] + ELLIPSE, FALLBACK)
    of = run(work, tag + "-friction", "sleeve-elliptic-friction", ["-a", str(a)] + ELLIPSE,
             FALLBACK)
    c = curve(oc)
    c["rho_start"], c["rho_frame"] = reversion_start(oc, c["onset_step"])
    pc = summ(oc)["final_pressure_mean"]
    m = dict(a=a, circ=c, gvar=curve(og), cross=gvar_crossing(oc, og),
             offset=offset_metrics(oo, pc), ell=ellipse_metrics(oe, pc),
             fric=ellipse_metrics(of, pc), used_fallback=[n for n, _, o, st, _, _ in RUNLOG
                                                          if n.startswith(tag) and
                                                          st.startswith("fallback ok")])
    rows[a] = m
    return m


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="fewer candidates (a 2750 and 3000, no refinement; spreads 0 and 5 K)")
    ap.add_argument("--work", default="/tmp/paper-scale-fit")
    ap.add_argument("--reuse", action="store_true",
                    help="keep runs already in --work made by the same command (to redo the tables)")
    args = ap.parse_args()
    runs.REUSE = args.reuse
    os.makedirs(args.work, exist_ok=True)
    t_start = time.time()
    coarse = [2750, 3000] if args.quick else [2500, 2750, 3000, 3500, 4000]
    rows = {}
    try:
        print("stage 1: a in %s" % coarse, flush=True)
        for a in coarse:
            stage_a(args.work, a, rows)
        best = max(rows.values(), key=score)["a"]
        for _ in range(0 if args.quick else 2):
            done = sorted(rows)
            i = done.index(best)
            extra = []
            for j in (i - 1, i + 1):
                if 0 <= j < len(done):
                    mid = int(round((best + done[j]) / 2 / 25.0) * 25)
                    if mid not in rows:
                        extra.append(mid)
            print("stage 1, refinement around %d: %s" % (best, extra), flush=True)
            for a in extra:
                stage_a(args.work, a, rows)
            best = max(rows.values(), key=score)["a"]
        print("chosen a = %d" % best, flush=True)

        # -------------------------------------------------- stage 2 at the chosen a
        A = ["-a", str(best), "-interference", str(INTERF)]
        tag = "a%d" % best
        oc = os.path.join(args.work, tag + "-circular")
        heat = {}
        circ_of = {}
        for key, H in HEATS:
            hs = key.replace(" ", "-").replace("=", "")
            o = oc if not H else run(args.work, "%s-circular-%s" % (tag, hs), "sleeve-circular",
                                     A + VTK + H)
            circ_of[key] = o
            c = curve(o)
            c["rho_start"], c["rho_frame"] = reversion_start(o, c["onset_step"])
            heat[key] = c
            o = run(args.work, "%s-gvar-vtk-%s" % (tag, hs), "sleeve-circular-gvar",
                    A + VTK + gvar_opts(H), FALLBACK)
            c = curve(o)
            c["rho_start"], c["rho_frame"] = reversion_start(o, c["onset_step"])
            c["cross"] = gvar_crossing(circ_of[key], o)
            heat["gvar " + key] = c
        spreads = [0, 5] if args.quick else [2, 5, 10, 15]
        rnd = {}
        for sp in spreads:
            if sp == 0:
                o = oc
                rnd[sp] = dict(curve(o), tmin=tmin_position(o))
                continue
            o = run(args.work, "%s-random-%g" % (tag, sp), "sleeve-random-threshold",
                    A + ["-cspread", str(sp)], FALLBACK)
            rnd[sp] = dict(curve(o), tmin=tmin_position(o))
        best_sp = min((s for s in rnd if s > 0), key=lambda s: abs(rnd[s]["T_onset_C"] + 25)
                      if not np.isnan(rnd[s]["T_onset_C"]) else 99)
        rnd_ins = {"both": rnd[best_sp]}
        for key, H in HEATS[1:]:
            o = run(args.work, "%s-random-%g-%s" % (tag, best_sp, key.replace(" ", "-")
                                                     .replace("=", "")),
                    "sleeve-random-threshold", A + ["-cspread", str(best_sp)] + H, FALLBACK)
            rnd_ins[key] = dict(curve(o), tmin=tmin_position(o))
        onoff = {}
        for key, sc, opts in (("circular", "sleeve-circular", A),
                              ("gvar", "sleeve-circular-gvar", A),
                              ("friction", "sleeve-elliptic-friction", ["-a", str(best)] + ELLIPSE)):
            o = run(args.work, "%s-onoff-%s" % (tag, key), sc, opts + ["-phasemodel", "onoff"])
            onoff[key] = o
        on_c, on_g = curve(onoff["circular"]), curve(onoff["gvar"])
        on_f = ellipse_metrics(onoff["friction"], summ(oc)["final_pressure_mean"])
    except RunFailed as e:
        print("\nFAILED: %s" % e, file=sys.stderr)
        sys.exit(1)
    wall = time.time() - t_start
    write_report(args, rows, best, heat, rnd, best_sp, rnd_ins, on_c, on_g, on_f, wall)




if __name__ == "__main__":
    main()
