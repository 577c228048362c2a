#!/usr/bin/python3
"""The Python driver and the sweep (tools/sma_driver.py, tools/sweep.py, make sweep).

On sleeve-radial (300 steps, about 0.5 s a run), -g swept over 250, 500, 1000 through `make sweep`
(into a folder whose name holds a space):
  (a) each row of table.csv equals that run's summary.json, key by key (first contact and
      austenite steps and inner temperatures, final and peak mean pressure, iteration maxima, wall
      time), and its times equal step x dt (dt = tend / steps from the summary's parameters);
  (b) the g = 500 run's history.csv equals, byte for byte, the same scene run directly by tools/ff
      with the same options (an invocation that does not go through the driver);
  (c) physics: a larger exchange coefficient warms the ring no slower, so the first contact and
      the austenite come no later. The final pressure does not depend on g: every run ends all
      austenite (asserted on its last history row), where the law has neither a transformation
      nor a thermal strain, so the last step solves the same elastic contact problem whatever the
      temperature; each run accepts its displacement when the DC loop's relative change of u is at
      most its own dc_tol (summary.json parameters.dc_tol; fp_tol acts on T, which does not enter
      that problem), the pressure being linear in u: two runs may differ by up to dc_tol each, so
      the bound is 2 x the largest dc_tol. (Measured: 0, the last steps stop on the DC loop's
      exact test, no phase changed.)
  sma_driver.read gives the arrays (the last history row's mean pressure is the summary's final)
  and fails naming a folder without summary.json;
  the two figures and sweep.json are written, the g curves differ (no shared legend entry); a
  sweep of -checkpoint 0 / 100 (checkpoints change no output) gives curves that coincide, which
  share one entry; sweep.same_curve joins curves 0.05 % apart and not 0.2 %;
  a scene without a contact history (beam): the table only (every number of its summary.json, its
  meshes' figures named <mesh>.<key>), no figure, said on the console and in sweep.json;
  (d) an unknown PARAM and an unknown scene (through make and tools/sweep.py), and a misspelt
      option among ARGS each fail (non-zero exit) naming it, before any run;
  (e) ARGS holding `; touch <file>` and VALUES holding `$(touch <file>)` run nothing;
  a value whose run fails (g = -1) leaves the others done, exits 1, and sweep.json holds its error
  and the end of its log, the folder's earlier complete sweep kept whole in previous-run/; negative values (-5e-6) are values, not flags; a value given twice is
  refused;
  (f) two parameters through make sweep (PARAM=interference VALUES='2e-4 5e-4' PARAM2=g
  VALUES2='250 1000', -steps 60): one folder per combination, table.csv's rows in the grid's order
  with both values first, each equal to its run's summary.json; the final pressure is Lame's closed
  form (the summary's lame_pressure) within 2 dc_tol at each interference and the same for both g;
  the panel figures exist; PARAM2 without VALUES2 and PARAM2 = PARAM fail naming them, before any run;
  (g) sleeve-circular swept over -interference 55e-6, 60e-6 (coarse mesh, -scale reduced, 200
  steps): the table's lame_pressure_Pa (computed by the sweep for concentric circles) equals the
  oracle's closed form (tools/bench/oracles/lame.py, the ring's radii from the run's interference
  and meshes/sleeve-geometry.txt's thickness) within 1e-6, the final pressure it within 2e-3 (6
  layers); ring_cleared_pipe is 1 then 0 (at 60 um the ring never clears the pipe) and the sweep
  relays that run's note, naming it (one note in all); a superellipse obstacle's table has no Lame
  column; sma.run on sleeve-radial hands that note to its `notes` function at 60 um, none at 55 um;
  sleeve-axisymmetric's table has its closed forms (open_cylinder_pressure_Pa, plane_strain_pressure_Pa).
Writes results/checks/sweep.json.
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, check, finish, record, rows  # noqa: E402
import sma_driver as sma  # noqa: E402  (checklib puts tools/ on the path)
import sweep  # noqa: E402
from sma.sweeps import text_of  # noqa: E402
import lame  # noqa: E402  (tools/bench/oracles: Lame's closed forms, independent of the package)
from sleeve_geometry import sleeve_geometry  # noqa: E402

VALUES = ["250", "500", "1000"]
COMMON = ["-steps", "300"]
# table.csv column -> summary.json key (the columns sweep.py must write for a sleeve scene).
FROM_SUMMARY = {"first_contact_step": "first_contact_step", "T_inner_first_contact_K": "T_inner_first_contact",
                "austenite_step": "austenite_step", "T_inner_austenite_K": "T_inner_austenite",
                "final_pressure_mean_Pa": "final_pressure_mean", "peak_pressure_mean_Pa": "peak_pressure_mean",
                "fixed_point_iterations_max": "fixed_point_iterations_max",
                "dc_iterations_max": "dc_iterations_max", "wall_s": "wall_seconds",
                "mesh_error_estimate_transient": "mesh_error_estimate_transient",
                "run_error_estimate_transient": "run_error_estimate_transient"}
STEP_OF_TIME = {"first_contact_time_s": "first_contact_step", "austenite_time_s": "austenite_step"}


def make(*words):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    return subprocess.run(["make", "--no-print-directory", "sweep", *words], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)


def sweep_tool(*words):
    return subprocess.run([sys.executable, "tools/sweep.py", *words], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)


def first_error(result):
    lines = [ln for ln in result.stderr.splitlines() if ln.startswith("error:")]
    return lines[0][:160] if lines else result.stderr.strip()[-160:]


def table_matches(table, summaries):
    """The mismatches between table.csv's rows and the runs' summary.json (empty: none)."""
    bad = []
    missing = [c for c in list(FROM_SUMMARY) + list(STEP_OF_TIME) if c not in table[0]]
    if missing:
        return [f"columns {missing} missing"]
    for row, s in zip(table, summaries):
        for column, key in FROM_SUMMARY.items():
            if float(row[column]) != s[key]:
                bad.append(f"{column} {row[column]} != {s[key]}")
        dt = s["parameters"]["tend"] / s["parameters"]["steps"]
        for column, key in STEP_OF_TIME.items():
            if abs(float(row[column]) - s[key] * dt) > 1e-9 * s[key] * dt:
                bad.append(f"{column} {row[column]} != {s[key]} x {dt}")
    return bad


def main():
    measured = {}
    with tempfile.TemporaryDirectory(prefix="sweep-") as tmp:
        out = os.path.join(tmp, "g sweep")
        swept = make("SCENE=sleeve-radial", "PARAM=g", f"VALUES={' '.join(VALUES)}", "ARGS=" + " ".join(COMMON),
                     f"OUT={out}")
        check(swept.returncode == 0, f"make sweep exits 0 ({first_error(swept) if swept.returncode else ''})")
        if swept.returncode != 0:
            finish()
        table = rows(os.path.join(out, "table.csv"))
        runs = [sma.read(os.path.join(out, f"g={v}")) for v in VALUES]
        summaries = [r.summary for r in runs]
        bad = table_matches(table, summaries)
        check([row["g"] for row in table] == VALUES and not bad,
              f"(a) table.csv: one row per value, equal to each run's summary.json ({bad[:3] or 'every column'})")

        direct = os.path.join(tmp, "direct")
        subprocess.run([sma.FF, "edp/scenes/sleeve-radial.edp", *COMMON, "-g", "500", "-quiet", "1", "-out", direct],
                       cwd=ROOT, check=True, capture_output=True)
        a = open(os.path.join(out, "g=500", "history.csv"), "rb").read()
        b = open(os.path.join(direct, "history.csv"), "rb").read()
        check(a == b, f"(b) the sweep's g = 500 history.csv equals a direct tools/ff run's byte for byte "
              f"({len(a)} bytes)")

        first = [s["first_contact_step"] for s in summaries]
        austenite = [s["austenite_step"] for s in summaries]
        check(all(0 < later <= earlier for earlier, later in zip(first, first[1:]))
              and all(0 < later <= earlier for earlier, later in zip(austenite, austenite[1:])),
              f"(c) larger g ({', '.join(VALUES)}): first contact no later (steps {first}), austenite no later "
              f"(steps {austenite})")
        finals = [s["final_pressure_mean"] for s in summaries]
        spread = (max(finals) - min(finals)) / max(finals)
        bound = 2 * max(s["parameters"]["dc_tol"] for s in summaries)
        all_austenite = all(r.history["fraction_austenite"][-1] == 1 for r in runs)
        check(all_austenite and spread <= bound,
              f"(c) final pressure independent of g: {[round(p / 1e6, 6) for p in finals]} MPa, every run "
              f"all austenite at its end ({all_austenite}), relative spread {spread:.1e} <= 2 x dc_tol = {bound:g}")
        r = runs[2]
        check(r.history["pressure_mean"][-1] == r.summary["final_pressure_mean"]
              and len(r.history["t"]) == r.summary["n_steps"],
              "sma_driver.read: history.csv as arrays (one row a step; the last mean pressure is the summary's final)")
        try:
            sma.read(tmp)
            unfinished = "no error"
        except sma.SceneError as e:
            unfinished = str(e)
        check(unfinished.startswith(f"no summary.json in {tmp}"), f"sma_driver.read of an unfinished run: {unfinished}")

        record_ = json.load(open(os.path.join(out, "sweep.json")))
        check(record_["figures"] == ["force-temperature.png", "force-time.png"]
              and all(os.path.getsize(os.path.join(out, f)) > 10000 for f in record_["figures"])
              and [run["status"] for run in record_["runs"]] == ["done"] * 3
              and [run["out"] for run in record_["runs"]] == [os.path.join(out, f"g={v}") for v in VALUES]
              and record_["args"] == COMMON and record_["values"] == VALUES,
              f"sweep.json: the values, the options {record_['args']}, each run's folder and status, "
              f"the figures {record_['figures']}")
        check(record_["jobs"] == min(2, os.cpu_count() or 1), f"runs in parallel on {record_['jobs']} jobs (JOBS=2)")
        check(record_["curves_coinciding_within_0.1_percent"] == [], "the three g curves differ: no shared legend entry")
        # Checkpoints change no output (tests/resume_test.py): the two curves coincide.
        same_out = os.path.join(tmp, "checkpoint")
        same = make("SCENE=sleeve-radial", "PARAM=checkpoint", "VALUES=0 100", "ARGS=-steps 300", f"OUT={same_out}")
        groups = json.load(open(os.path.join(same_out, "sweep.json")))["curves_coinciding_within_0.1_percent"] \
            if same.returncode == 0 else first_error(same)
        t = np.linspace(0, 1, 50)
        p = np.sin(3 * t) + 1
        check(groups == [["0", "100"]] and sweep.same_curve((t, p), (t, p * 1.0005))
              and not sweep.same_curve((t, p), (t, p * 1.002)),
              f"curves that coincide share one legend entry ({groups}); 0.05 % apart coincide, 0.2 % do not")

        beam_out = os.path.join(tmp, "beam")
        beam = make("SCENE=beam", "PARAM=F", "VALUES=6e7 7e7", "ARGS=-levels coarse", f"OUT={beam_out}")
        beam_table = rows(os.path.join(beam_out, "table.csv")) if beam.returncode == 0 else []
        beam_record = json.load(open(os.path.join(beam_out, "sweep.json"))) if beam.returncode == 0 else {}
        fractions = [sma.read(os.path.join(beam_out, f"F={v}")).summary["meshes"][0]["fraction_austenite"]
                     for v in ("6e7", "7e7")] if beam.returncode == 0 else []
        check(beam.returncode == 0 and [float(row["coarse.fraction_austenite"]) for row in beam_table] == fractions
              and beam_record.get("figures") == [] and "table only" in beam_record.get("note", "")
              and "table only" in beam.stdout
              and not any(f.endswith(".png") for f in os.listdir(beam_out)),
              f"beam (no contact history): the table only, its numbers from summary.json ({fractions}), said so")

        bad_param = make("SCENE=sleeve-radial", "PARAM=gg", "VALUES=1 2", f"OUT={os.path.join(tmp, 'x')}")
        check(bad_param.returncode != 0 and "sleeve-radial has no option -gg (did you mean -g" in bad_param.stderr
              and not os.path.exists(os.path.join(tmp, "x")),
              f"(d) an unknown PARAM fails naming it, before any run: {first_error(bad_param)}")
        bad_scene = sweep_tool("sleeve-radail", "g", "1")
        bad_scene_make = make("SCENE=sleeve-radail", "PARAM=g", "VALUES=1")
        check(bad_scene.returncode != 0 and "unknown scene 'sleeve-radail' (did you mean sleeve-radial"
              in bad_scene.stderr and bad_scene_make.returncode != 0
              and "unknown scene 'sleeve-radail'" in bad_scene_make.stderr,
              f"(d) an unknown scene fails naming it: {first_error(bad_scene)}; make: {first_error(bad_scene_make)}")
        # One resolver for every Python entry point: a path is not a scene name, and nothing runs.
        escape = os.path.join(tmp, "escape.edp")
        with open(escape, "w") as f:
            f.write("cout << \"escaped\" << endl;\n")
        rel = os.path.relpath(escape[:-len(".edp")], os.path.join(ROOT, "edp", "scenes"))
        bad_path = sweep_tool(rel, "g", "1")
        try:
            sma.run(rel, os.path.join(tmp, "v"))
            driver = "ran"
        except sma.SceneError as e:
            driver = str(e)
        check(bad_path.returncode != 0 and "is not a scene name" in bad_path.stderr and "escaped" not in bad_path.stdout
              and driver.startswith(f"{rel!r} is not a scene name"),
              f"(d) a scene name with a path ({rel}) is refused by tools/sweep.py and sma_driver.run before any "
              f"FreeFEM start: {first_error(bad_path)}; driver: {driver[:60]}")
        # One option coercion: types from the scene's -help; True/False only for a switch.
        refusals = {}
        for name, value in (("g", None), ("g", [300, 400]), ("g", True), ("steps", 3.5), ("steps", 2**40),
                            ("g", float("nan")), ("phasemodel", 1), ("g", "1e-400"), ("g", "\uff12\uff15\uff10")):
            try:
                sma.command("sleeve-radial", os.path.join(tmp, "u"), **{name: value})
                refusals[f"{name}={value!r}"] = "accepted"
            except sma.SceneError as e:
                refusals[f"{name}={value!r}"] = str(e)
        accepted = sma.command("sleeve-radial", os.path.join(tmp, "u"), quiet=True, steps="30", g=500)
        # a text's surrounding spaces go from its folder's name as from the run's value (' 250' made "g= 250")
        check(text_of(" 250 ") == "250", f"a swept text's folder name without its spaces: {text_of(' 250 ')!r}")
        check(all(v.startswith(f"sleeve-radial: -{k.split('=')[0]} = ") for k, v in refusals.items())
              and accepted[2:8] == ["-quiet", "1", "-steps", "30", "-g", "500"],
              f"(d) option values checked against the scene's types: {len(refusals)} refused "
              f"(None, a list, True for a real, 3.5 and 2^40 for an int, nan, an int for a string, 1e-400 that would run as 0, "
              f"full-width digits); "
              f"quiet=True, steps='30', g=500 -> {' '.join(accepted[2:8])}")
        typo = make("SCENE=sleeve-radial", "PARAM=g", "VALUES=300", "ARGS=-stpes 30", f"OUT={os.path.join(tmp, 'z')}")
        check(typo.returncode != 0 and "no option -stpes (did you mean -steps" in typo.stderr,
              f"(d) a misspelt option among ARGS fails before any run: {first_error(typo)}")

        injected = os.path.join(tmp, "injected")
        bad_args = make("SCENE=sleeve-radial", "PARAM=g", "VALUES=300", f"ARGS=-steps 30; touch {injected}",
                        f"OUT={os.path.join(tmp, 'y')}")
        check(bad_args.returncode != 0 and not os.path.exists(injected) and not os.path.exists(os.path.join(tmp, "y")),
              f"(e) ARGS with '; touch' runs nothing and fails: {first_error(bad_args)}")
        injected_value = os.path.join(tmp, "injected-value")
        bad_value = make("SCENE=sleeve-radial", "PARAM=g", f"VALUES=300 $(touch {injected_value})",
                         "ARGS=-steps 5", f"OUT={os.path.join(tmp, 'w')}")
        check(bad_value.returncode != 0 and not os.path.exists(injected_value),
              f"(e) VALUES with '$(touch ...)' runs no command (the words are values FreeFEM refuses): "
              f"{first_error(bad_value)}")

        # A value the scene refuses: every run is checked by the scene (-checkonly 1) before the
        # sweep takes its folder, so nothing runs and nothing is made there.
        refused_out = os.path.join(tmp, "refused")
        refused = sweep_tool("sleeve-radial", "g", "500", "-1", "--out", refused_out, "--", "-steps", "30")
        check(refused.returncode == 2 and "-g -1: sleeve-radial -steps 30 -g -1 is refused" in refused.stderr
              and "sleeve-radial: -g -1 must be in [0, 1e15]" in refused.stderr and not os.path.exists(refused_out),
              f"a value the scene refuses (g = -1) stops the sweep before any run, its folder not made: "
              f"exit {refused.returncode}, {first_error(refused)[:150]}")
        # A run that fails in its time loop: the others still run; the sweep exits 1 naming it. It
        # runs in the folder of the -checkpoint sweep above, a complete sweep: kept whole in
        # previous-run/, since this one does not complete.
        partial_out = same_out
        with open(os.path.join(same_out, "sweep.json"), "rb") as f:
            complete_record = f.read()
        partial = sweep_tool("sleeve-radial", "stepmaxit", "50", "1", "--out", partial_out, "--", "-steps", "30",
                             "-stepfallback", "0")
        partial_runs = json.load(open(os.path.join(partial_out, "sweep.json")))["runs"]
        check(partial.returncode == 1 and [run["status"] for run in partial_runs] == ["done", "failed"]
              and "step solver (newton" in partial_runs[1]["error"] and "did not converge" in partial_runs[1]["error"]
              and "last lines of its log" in partial_runs[1]["error"]
              and [row["stepmaxit"] for row in rows(os.path.join(partial_out, "table.csv"))] == ["50"]
              and "for -stepmaxit 1 failed" in partial.stderr,
              f"a run that fails (stepmaxit = 1, no fallback) leaves the others; exit {partial.returncode}, "
              f"sweep.json has its error line and log: {partial_runs[1].get('error', '').splitlines()[0][:110]}")
        kept = os.path.join(partial_out, "previous-run", "sweep.json")
        check(os.path.isfile(kept) and open(kept, "rb").read() == complete_record
              and os.path.isfile(os.path.join(partial_out, "previous-run", "checkpoint=100", "summary.json"))
              and f"are kept whole in {partial_out}/previous-run" in partial.stderr,
              "the sweep that did not complete leaves the folder's complete sweep whole in previous-run/ "
              "(its sweep.json and runs) and says so")

        parsed = sweep.parse(["sleeve-offset", "offset", "-5e-6", "0", "5e-6", "--jobs", "1"])
        twice = sweep_tool("sleeve-radial", "g", "500", "500")
        check(parsed["values"] == ["-5e-6", "0", "5e-6"] and parsed["jobs"] == 1
              and twice.returncode == 2 and "500 of -g are given twice" in twice.stderr,
              f"negative values are values ({parsed['values']}); a value given twice: {first_error(twice)}")
        # (f) Two parameters through make sweep: the grid, one folder per combination.
        grid_out = os.path.join(tmp, "grid")
        interferences, gs = ["2e-4", "5e-4"], ["250", "1000"]
        grid = make("SCENE=sleeve-radial", "PARAM=interference", f"VALUES={' '.join(interferences)}", "PARAM2=g",
                    f"VALUES2={' '.join(gs)}", "ARGS=-steps 60", f"OUT={grid_out}")
        combos = [(i, g) for i in interferences for g in gs]
        grid_table = rows(os.path.join(grid_out, "table.csv")) if grid.returncode == 0 else []
        grid_runs = [sma.read(os.path.join(grid_out, f"interference={i},g={g}")).summary for i, g in combos] \
            if grid.returncode == 0 else []
        grid_bad = table_matches(grid_table, grid_runs) if grid_table else ["no table"]
        grid_finals = {c: r["final_pressure_mean"] for c, r in zip(combos, grid_runs)}
        lame_error = max((abs(r["final_pressure_mean"] / r["lame_pressure"] - 1) for r in grid_runs), default=1)
        by_g = max((abs(grid_finals[(i, gs[0])] / grid_finals[(i, gs[1])] - 1) for i in interferences), default=1) \
            if grid_runs else 1
        dc_tol = max((r["parameters"]["dc_tol"] for r in grid_runs), default=0)
        check(grid.returncode == 0 and [(row["interference"], row["g"]) for row in grid_table] == combos
              and list(grid_table[0])[:2] == ["interference", "g"] and not grid_bad
              and lame_error <= 2 * dc_tol and by_g <= 2 * dc_tol
              and all(os.path.isfile(os.path.join(grid_out, f)) for f in ("force-temperature.png", "final-pressure.png")),
              f"(f) make sweep PARAM=interference PARAM2=g: {len(grid_table)} rows in the grid's order, each its run's "
              f"summary ({grid_bad[:2] or 'every column'}); final pressure = Lame within {lame_error:.1e}, "
              f"independent of g within {by_g:.1e} (<= 2 dc_tol); panel figures written "
              f"{first_error(grid) if grid.returncode else ''}")
        no_values2 = make("SCENE=sleeve-radial", "PARAM=g", "VALUES=250", "PARAM2=interference",
                          f"OUT={os.path.join(tmp, 'y')}")
        same_param = sweep_tool("sleeve-radial", "g", "250", "--param2", "g", "--values2", "500")
        check(no_values2.returncode == 2 and "needs both PARAM2" in no_values2.stderr
              and same_param.returncode == 2 and "PARAM2 'g' is PARAM too" in same_param.stderr
              and not os.path.exists(os.path.join(tmp, "y")),
              f"(f) PARAM2 without VALUES2: {first_error(no_values2)}; PARAM2 = PARAM: {first_error(same_param)}")
        # (g) the 2D circle: Lame's column computed by the sweep, the clearance reported.
        circle_out, shape_out = os.path.join(tmp, "circle"), os.path.join(tmp, "shape")
        reduced = ["-mesh", "meshes/sleeve-coarse.msh", "-steps", "200", "-scale", "reduced"]
        circle = sweep_tool("sleeve-circular", "interference", "55e-6", "60e-6", "--out", circle_out, "--", *reduced)
        shape = sweep_tool("sleeve-superellipse", "p", "2.05", "--out", shape_out, "--", *reduced)
        circle_table = rows(os.path.join(circle_out, "table.csv")) if circle.returncode == 0 else []
        shape_table = rows(os.path.join(shape_out, "table.csv")) if shape.returncode == 0 else []
        geometry = sleeve_geometry()  # the mesh's ring; -interference moves its inner radius, its thickness kept
        circle_errors, circle_lame = [], []
        for row in circle_table:
            summary = sma.read(os.path.join(circle_out, f"interference={row['interference']}")).summary
            par = summary["parameters"]
            ri = par["pipe_A"] - float(row["interference"])
            closed = lame.lame_pressure(par["E"], par["nu"], ri, ri + geometry["Hr"], par["pipe_A"] - ri, par["plane"])
            circle_lame.append(closed)
            circle_errors.append((abs(float(row.get("lame_pressure_Pa") or 0) / closed - 1),
                                  abs(float(row["final_pressure_mean_Pa"]) / closed - 1)))
        notes = [ln for ln in circle.stderr.splitlines() if "note:" in ln]
        axi_out = os.path.join(tmp, "axi")
        axi = sweep_tool("sleeve-axisymmetric", "interference", "4e-4", "5e-4", "--out", axi_out, "--",
                         "-steps", "60", "-nr", "4")
        axi_table = rows(os.path.join(axi_out, "table.csv")) if axi.returncode == 0 else []
        axi_bad = [(row["interference"], key) for row in axi_table for key in ("open_cylinder_pressure", "plane_strain_pressure")
                   if float(row.get(key + "_Pa") or 0) != sma.read(os.path.join(axi_out, f"interference={row['interference']}")).summary[key]]
        check(len(axi_table) == 2 and not axi_bad,
              f"(g) sleeve-axisymmetric over -interference 4e-4 5e-4: table.csv's open_cylinder_pressure_Pa and "
              f"plane_strain_pressure_Pa are the runs' closed forms (differing: {axi_bad or 'none'}) {first_error(axi) if axi.returncode else ''}")
        run_notes = {}  # sma.run hands the run's notes to a function (a notebook sees them on stderr)
        for interference in (55e-6, 60e-6):
            run_notes[interference] = []
            sma.run("sleeve-radial", os.path.join(tmp, f"radial-{interference}"), notes=run_notes[interference].append,
                    interference=interference, scale="reduced", steps=60)
        # (60 steps of 2.5 s: both runs also warn that their own error is about a tenth, run-error.idp;
        # the notes compared are the clearance's)
        clearing = {k: [n for n in v if n.startswith("note:")] for k, v in run_notes.items()}
        check(not clearing[55e-6] and len(clearing[60e-6]) == 1
              and clearing[60e-6][0].startswith("note: sleeve-radial: the ring touches the pipe from the end of the first step")
              and "ring_cleared_pipe false" in clearing[60e-6][0],
              f"(g) sma.run(sleeve-radial, interference 55e-6 / 60e-6, reduced) hands the run's notes over: "
              f"{len(clearing[55e-6])} / {clearing[60e-6] or 'none'} (all: {run_notes})")
        check(len(circle_errors) == 2 and all(e[0] <= 1e-6 for e in circle_errors)
              and max(e[1] for e in circle_errors) <= 2e-3
              and [row["ring_cleared_pipe"] for row in circle_table] == ["1", "0"]
              and len(notes) == 1 and notes[0].startswith("-interference 60e-6: note: sleeve-circular: the ring touches the pipe")
              and shape_table and "lame_pressure_Pa" not in shape_table[0],
              f"(g) sleeve-circular over -interference 55e-6 60e-6 (coarse, reduced): lame_pressure_Pa = the "
              f"oracle's closed form within {max((e[0] for e in circle_errors), default=1):.1e} (<= 1e-6: the VTU's "
              f"single-precision outer radius), final pressure within {max((e[1] for e in circle_errors), default=1):.1e}"
              f" of it (<= 2e-3, 6 layers); ring_cleared_pipe {[row.get('ring_cleared_pipe') for row in circle_table]}"
              f" (expected 1, 0), notes {notes or first_error(circle)}; the superellipse's table without a Lame "
              f"column {list(shape_table[0]) if shape_table else first_error(shape)}")
        measured = {"circle_lame_Pa": circle_lame, "circle_lame_and_final_errors": circle_errors,
                    "grid_final_pressures_Pa": [grid_finals.get(c) for c in combos],
                    "first_contact_steps": first, "austenite_steps": austenite, "final_pressures_Pa": finals,
                    "final_relative_spread": spread, "final_spread_bound": bound,
                    "table_columns": list(table[0])}
    record("sweep", {"test": "sweep", **measured})
    finish()


if __name__ == "__main__":
    main()
