#!/usr/bin/python3
"""The sma Python package (python/sma; docs/python-api.md).

  (a) installable offline by Debian's pip and setuptools, as `make python` does (the same command,
      into a temporary PYTHONUSERBASE: the user's own install is not touched), and then
      `import sma` works for /usr/bin/python3 from another folder without touching sys.path; its
      sma.ROOT is this checkout. No target but `make python` installs it: `make -n` of run, test,
      sweep, ensemble, figures and lab prints no pip command (one checkout, one package: two
      checkouts took the package from each other at every make);
  (b) from that other folder, in that process: sma.run of sleeve-radial -steps 60 with a relative
      `out` returns the absolute folder under the repository, and sma.read of it gives the summary
      and history.csv as a DataFrame: one row per step, the last time tend, the last mean pressure
      the summary's final (two files written apart);
  (c) DataFrame columns carry their units: history.csv's t_s, T_inner_mean_K, pressure_mean_Pa,
      contact-final.csv's normal_force_N/m, counts (step) integers without a unit; every column
      documented in docs/outputs.md's tables (history, points, contact-final, fields) gets the unit
      the page gives it; so does every column of beam's phase-coarse.csv and dc-convergence.csv,
      ring-lame's pressure-l1.csv and free-ring's history.csv (short runs), whose frames keep the
      files' numbers: the triangles' areas from x1_m ... y3_m sum to the beam's L H, pressure_nodal_Pa
      = normal_force_N/m / tributary_length_m, stored_heat_J/m = boundary + latent per step;
  (d) the VTU reader (xml.etree + numpy) on sleeve-circular's coarse mesh (-steps 60 -vtkevery 20):
      node and triangle counts equal summary.json's nodes and triangles; every triangle's centroid
      (from the VTU's nodes and connectivity) is a row of fields-3-end.csv, whose sigma_rr equals
      the VTU's cell sigma_rr and whose T, ux, uy (means of the three nodes, written by the scene
      apart) equal the means of the VTU's nodal temperature and displacement over the triangle's
      nodes; fields.pvd's frame times are step x dt;
  (e) sma.sweep of sleeve-radial over interference (2e-4, 5e-4 m) x g (250, 1000 W/(m^2 K)),
      -steps 60, 2 jobs: 4 rows, each equal to its own run's summary.json (the parameters as run,
      the key figures, the times step x dt); the final pressure is Lame's closed form at each
      interference (within 2 dc_tol) and does not depend on g; sma.plot draws one line per g
      through the table's values; read_sweep gives the same table back; the panel figures exist;
  (f) errors name the culprit: a misspelt option (with its close match), a swept option the scene
      does not read, a value of the wrong type, a folder without a run, a CSV or VTU that is absent
      or damaged, a time fields.pvd does not list, a column without a known unit (docs/errors.md,
      "The Python package"); a sweep with a run that fails (g = -1) names it, its other run
      published and returned with the error;
  (h) run(..., ranks=2) runs the scene's edp/mpi script on 2 MPI ranks (sleeve-3d, a small mesh):
      its summary's "distributed" entry says 2 ranks and GenEO as asked (ddmgeneo=1, an option of
      the MPI run only); ranks for a scene without one, ranks=0, and a misspelt MPI option
      (ddmtoll) are refused naming the culprit before any run;
  (g) the command-line modules are the package's: tools/sma_driver.py, results_io.py and children.py
      re-export the same objects; docs/python-api.md is what tools/docs/python_api.py generates, and
      every public function, class and method of the package has a docstring.
Writes results/checks/python_package.json.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, TEST_RESULTS, check, finish, record  # noqa: E402
sys.path.insert(0, os.path.join(ROOT, "python"))  # this checkout's package, for the checks of this process
import sma  # noqa: E402
import sma.frames  # noqa: E402
import sma_driver  # noqa: E402  (checklib puts tools/ on the path)
import children as tools_children  # noqa: E402
import results_io as tools_results_io  # noqa: E402

PYTHON = "/usr/bin/python3"
HERE = os.path.realpath(ROOT)
OUT = os.path.join(TEST_RESULTS, "python_package")
# The same pip command as the Makefile's `python` target.
PIP = [PYTHON, "-m", "pip", "install", "--user", "--break-system-packages", "--no-index", "--no-build-isolation",
       "--no-deps", "--disable-pip-version-check", "-q", "-e", os.path.join(ROOT, "python")]
CHILD = """
import json, os, sys
before = list(sys.path)
import sma
out = sma.run("sleeve-radial", os.path.relpath(sys.argv[1], sma.ROOT), steps=60)
r = sma.read(out)
h = r.frame("history")
print(json.dumps({"root": sma.ROOT, "file": sma.__file__, "cwd": os.getcwd(), "path_unchanged": sys.path == before,
                  "out": out, "n_steps": r.summary["n_steps"], "tend": r.summary["parameters"]["tend"],
                  "final": r.summary["final_pressure_mean"], "rows": len(h), "t_last": float(h["t_s"].iloc[-1]),
                  "p_last": float(h["pressure_mean_Pa"].iloc[-1]), "columns": list(h.columns),
                  "step_dtype": str(h["step"].dtype)}))
"""


def error_of(call):
    try:
        call()
    except sma.SceneError as e:
        return str(e)
    return "no error"


def install_and_import(tmp):
    """(a) and (b): the package installed into a temporary user base, used from another folder."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env.update(PYTHONUSERBASE=os.path.join(tmp, "userbase"), PIP_ROOT_USER_ACTION="ignore")
    pip = subprocess.run(PIP, cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    elsewhere = os.path.join(tmp, "notebook")
    os.makedirs(elsewhere)
    child = subprocess.run([PYTHON, "-c", CHILD, os.path.join(OUT, "radial-relative")], cwd=elsewhere, env=env,
                           capture_output=True, text=True, timeout=120)
    got = json.loads(child.stdout) if child.returncode == 0 else {}
    check(pip.returncode == 0 and child.returncode == 0 and got.get("root") == HERE and got.get("path_unchanged")
          and got.get("cwd") == os.path.realpath(elsewhere)
          and os.path.realpath(got.get("file", "")).startswith(os.path.join(HERE, "python", "sma") + os.sep),
          f"(a) pip install --user -e python/ offline into a fresh user base (exit {pip.returncode}), then "
          f"`import sma` from {elsewhere} without sys.path: sma.ROOT {got.get('root')} "
          + (pip.stderr.strip()[-300:] + child.stderr.strip()[-300:] if not got else ""))
    installing = {}
    for goal in (["run"], ["test"], ["sweep", "SCENE=sleeve-radial", "PARAM=g", "VALUES=500"], ["ensemble"], ["figures"],
                 ["lab"], ["python"]):
        dry = subprocess.run(["make", "-n", "--no-print-directory", *goal], cwd=ROOT, capture_output=True, text=True,
                             timeout=120)
        installing[goal[0]] = "pip install" in dry.stdout
    check(installing.pop("python") and not any(installing.values()),
          f"(a) only `make python` installs the package for the user: `make -n` prints a pip install for "
          f"{[g for g, v in installing.items() if v] or 'no other target'} (run, test, sweep, ensemble, figures, lab)")
    if got:
        check(got["out"] == os.path.join(OUT, "radial-relative") and os.path.isabs(got["out"])
              and got["rows"] == got["n_steps"] == 60 and got["t_last"] == got["tend"] and got["p_last"] == got["final"],
              f"(b) sma.run with a relative out, from another folder, returns {got['out']}; sma.read: "
              f"{got['rows']} history rows for {got['n_steps']} steps, last t {got['t_last']} s = tend, last "
              f"pressure_mean_Pa {got['p_last']:.6e} = summary final {got['final']:.6e}")
    return got


def doc_units():
    """{column: unit} of docs/outputs.md's tables of history.csv, points.csv, contact-final.csv and
    fields-<instant>.csv ("" where the unit cell is empty)."""
    units, section = {}, None
    for line in open(os.path.join(ROOT, "docs", "outputs.md"), encoding="utf-8"):
        if line.startswith("## "):
            section = line[3:].strip()
        if section not in ("history.csv", "points.csv", "contact-final.csv", "fields-\\<instant\\>.csv",
                           "beam's CSV files", "ring-lame's pressure-\\<level\\>.csv", "free-ring's history.csv"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("| `") or len(cells) < 3:
            continue
        names = [n.strip().strip("`") for n in cells[0].split(",")]
        for n in names:
            if "<" not in n and not n.startswith("_"):
                units[n] = cells[1]
    return units


def units_checks(got):
    """(c)"""
    documented = doc_units()
    # The docs' rows that join a count with a quantity (`step`, `t` | s; `pressure_peak`, `peak_step` | Pa).
    joined_counts = {"step", "peak_step"}
    bad = []
    for name, unit in documented.items():
        try:
            _, mapped = sma.frames.unit_of_column(name)
        except sma.SceneError as e:
            bad.append(str(e))
            continue
        if mapped not in ("", unit) or (mapped == "" and unit not in ("", "1") and name not in joined_counts):
            bad.append(f"{name}: docs {unit!r}, frames {mapped!r}")
    check(len(documented) >= 40 and not bad,
          f"(c) every column of docs/outputs.md's CSV tables ({len(documented)}) gets the unit the page gives: "
          f"{bad[:4] or 'all'}")
    columns = got.get("columns", [])
    check({"t_s", "T_inner_mean_K", "pressure_mean_Pa", "u_inner_m", "reaction_per_radian_N/m", "step"} <= set(columns)
          and "t" not in columns and got.get("step_dtype") == "int64",
          f"(c) history DataFrame columns with units: {', '.join(columns[:4])} ... {', '.join(columns[-3:])}; "
          f"step {got.get('step_dtype')}")


def other_scene_frames(tmp):
    """(c) beam's, ring-lame's and free-ring's CSVs as DataFrames: every column documented with the
    unit frames gives it, the numbers those of the files (invariants the scenes do not print)."""
    runs = {"beam": ["-levels", "coarse"], "ring-lame": ["-levels", "l1"],
            "free-ring": ["-tcool", "4", "-thold", "2", "-theat", "4"]}
    documented, frames = doc_units(), {}
    for scene, args in runs.items():
        out = os.path.join(tmp, scene)
        run = subprocess.run([os.path.join(ROOT, "tools", "ff"), sma.script(scene), "-out", out, "-quiet", "1", *args],
                             cwd=ROOT, capture_output=True, text=True, timeout=120)
        check(run.returncode == 0, f"(c) {scene} {' '.join(args)} runs (exit {run.returncode})")
        for name in {"beam": ["phase-coarse", "dc-convergence"], "ring-lame": ["pressure-l1"],
                     "free-ring": ["history"]}[scene]:
            try:
                frames[name] = sma.frame(os.path.join(out, name + ".csv"))
            except (sma.SceneError, OSError) as e:
                frames[name] = None
                check(False, f"(c) sma.frame reads {scene}'s {name}.csv: {e}")
    bad = []
    for name, df in frames.items():
        for column, unit in (df.attrs["units"].items() if df is not None else []):
            bare = column[:-len(unit) - 1] if unit else column
            if bare not in documented and column not in documented:
                bad.append(f"{name}: {column} not in docs/outputs.md")
            elif bare in documented and documented[bare] != unit and not (unit == "" and (
                    documented[bare] in ("", "1") or bare in ("step", "peak_step"))):  # rows joining a count
                bad.append(f"{name}: {column} against the page's {documented[bare]!r}")
    check(all(df is not None for df in frames.values()) and not bad,
          f"(c) beam's, ring-lame's and free-ring's CSVs read with units, each column as docs/outputs.md gives it: "
          f"{bad[:4] or ', '.join(c for df in frames.values() if df is not None for c in df.columns[:2])}")
    if any(df is None for df in frames.values()):
        return
    t = frames["phase-coarse"]
    area = 0.5 * abs((t["x2_m"] - t["x1_m"]) * (t["y3_m"] - t["y1_m"]) - (t["x3_m"] - t["x1_m"]) * (t["y2_m"] - t["y1_m"]))
    dc = frames["dc-convergence"]
    p = frames["pressure-l1"]
    nodal = (p["pressure_nodal_Pa"] - p["normal_force_N/m"] / p["tributary_length_m"]).abs().max() / p["pressure_nodal_Pa"].abs().max()
    h = frames["history"]
    balance = (h["stored_heat_J/m"] - h["boundary_heat_J/m"] - h["latent_heat_J/m"]).abs().max() \
        / h["stored_heat_J/m"].abs().max()
    check(abs(area.sum() - 0.1 * 0.01) <= 1e-12 and set(t["phase"]) <= {0, 1, 2} and set(dc["mesh"]) == {"coarse"}
          and str(dc["iteration"].dtype) == "int64" and nodal <= 1e-12 and balance <= 1e-9,
          f"(c) the frames' numbers: beam's triangles cover {area.sum():.15g} m^2 (L H = 0.001), phases "
          f"{sorted(set(t['phase']))}, dc-convergence mesh {sorted(set(dc['mesh']))}; ring-lame pressure_nodal = "
          f"normal force / tributary length to {nodal:.1e}; free-ring stored = boundary + latent to {balance:.1e}")


def vtu_checks():
    """(d)"""
    out = sma.run("sleeve-circular", os.path.join(OUT, "circular"), steps=60, vtkevery=20,
                  mesh="meshes/sleeve-coarse.msh", scale="reduced")
    r = sma.read(out)
    f = r.fields("3-end")
    check(len(f.points) == r.summary["nodes"] and len(f.triangles) == r.summary["triangles"],
          f"(d) fields-3-end.vtu: {len(f.points)} nodes, {len(f.triangles)} triangles = summary.json's "
          f"{r.summary['nodes']}, {r.summary['triangles']}")
    csv = r.frame("fields-3-end")
    centroids = f.points[f.triangles].mean(axis=1)
    xy = csv[["x_m", "y_m"]].to_numpy()
    distance = np.linalg.norm(centroids[:, None, :] - xy[None, :, :], axis=2)
    row = distance.argmin(axis=1)
    matched = len(set(row.tolist())) == len(xy) == len(centroids)
    far = float(distance[np.arange(len(row)), row].max())

    def agree(a, b):  # the CSV's 10 significant digits
        a, b = np.asarray(a, float), np.asarray(b, float)
        return float(np.max(np.abs(a - b) / (np.abs(b).max() + 1e-300)))
    sigma = agree(f.cell_data["sigma_rr"], csv["sigma_rr_Pa"].to_numpy()[row])
    temperature = agree(f.point_data["temperature"][f.triangles].mean(axis=1), csv["T_K"].to_numpy()[row])
    ux = agree(f.point_data["displacement"][f.triangles, 0].mean(axis=1), csv["ux_m"].to_numpy()[row])
    uy = agree(f.point_data["displacement"][f.triangles, 1].mean(axis=1), csv["uy_m"].to_numpy()[row])
    check(matched and far < 1e-7 and max(sigma, temperature, ux, uy) < 1e-8,
          f"(d) each VTU triangle's centroid is one row of fields-3-end.csv (farthest {far:.1e} m: single-precision "
          f"nodes); relative differences: sigma_rr {sigma:.1e}, mean nodal T {temperature:.1e}, ux {ux:.1e}, "
          f"uy {uy:.1e} (< 1e-8)")
    dt = r.summary["parameters"]["tend"] / r.summary["parameters"]["steps"]
    frames = [(t, os.path.relpath(p, out)) for t, p in r.states() if "frames" in p]
    state = r.fields(frames[0][0]) if frames else None
    check([p for _, p in frames] == ["frames/step-000020.vtu", "frames/step-000040.vtu"]
          and all(abs(t - int(p[-10:-4]) * dt) < 1e-9 for t, p in frames)
          and state is not None and state.path.endswith("step-000020.vtu") and state.time == frames[0][0],
          f"(d) fields.pvd: frames {frames} at step x dt (dt {dt} s); fields({frames[0][0] if frames else None}) "
          "reads that frame")
    return r, f


def sweep_checks():
    """(e)"""
    grid = {"interference": [2e-4, 5e-4], "g": [250, 1000]}
    table = sma.sweep("sleeve-radial", grid, fixed={"steps": 60}, jobs=2, out=os.path.join(OUT, "sweep"))
    bad = []
    pairs = {"first_contact_step": "first_contact_step", "austenite_step": "austenite_step",
             "T_inner_austenite_K": "T_inner_austenite", "final_pressure_mean_Pa": "final_pressure_mean",
             "lame_pressure_Pa": "lame_pressure", "wall_s": "wall_seconds"}
    for _, row in table.iterrows():
        s = json.load(open(os.path.join(row["out"], "summary.json")))
        p = s["parameters"]
        if row["g_W/(m^2 K)"] != p["g"] or row["interference_m"] != s["interference"] or p["steps"] != 60:
            bad.append(f"{row['out']}: parameters {p['g']}, {s['interference']}")
        bad += [f"{row['out']}: {c}" for c, k in pairs.items() if row[c] != s[k]]
        dt = p["tend"] / p["steps"]
        if abs(row["austenite_time_s"] - s["austenite_step"] * dt) > 1e-9 * row["austenite_time_s"]:
            bad.append(f"{row['out']}: austenite_time_s")
    combos = sorted(zip(table["interference_m"], table["g_W/(m^2 K)"]))
    check(len(table) == 4 and combos == sorted((i, float(g)) for i in grid["interference"] for g in grid["g"])
          and not bad and all(os.path.isabs(o) for o in table["out"]),
          f"(e) sma.sweep 2 x 2: {len(table)} rows ({combos}), each equal to its run's summary.json "
          f"({bad[:3] or 'parameters, key figures, times'})")
    dc_tol = 1e-3
    lame = (table["final_pressure_mean_Pa"] / table["lame_pressure_Pa"] - 1).abs().max()
    by_g = table.groupby("interference_m")["final_pressure_mean_Pa"].agg(lambda p: p.max() / p.min() - 1).max()
    check(lame <= 2 * dc_tol and by_g <= 2 * dc_tol,
          f"(e) final pressure = Lame's closed form within {lame:.1e} (<= 2 dc_tol) at each interference, "
          f"independent of g within {by_g:.1e}")
    ax = sma.plot(table, "final_pressure_mean_Pa")
    lines = [(ln.get_label(), list(ln.get_xdata()), list(ln.get_ydata())) for ln in ax.get_lines()]
    expected = [(g, [0.2, 0.5], list(table[table["g_W/(m^2 K)"] == g].sort_values("interference_m")
                                       ["final_pressure_mean_Pa"] / 1e6)) for g in (250.0, 1000.0)]
    check(len(lines) == 2 and all(np.allclose(x, e[1], rtol=1e-15) and np.allclose(y, e[2], rtol=1e-15)
                                  and str(int(e[0])) in label for (label, x, y), e in zip(lines, expected)),
          f"(e) sma.plot: one line per g ({[ln[0] for ln in lines]}) through the table's final pressures (MPa) "
          "against the interference (mm)")
    again = sma.read_sweep(os.path.join(OUT, "sweep"))
    figures = table.attrs["figures"]
    check(again.equals(table) and [os.path.basename(p) for p in figures] == ["force-temperature.png", "final-pressure.png"]
          and all(os.path.getsize(p) > 10000 for p in figures),
          f"(e) read_sweep gives the same table; figures {[os.path.basename(p) for p in figures]}")
    return table


def error_checks(tmp, r, f):
    """(f)"""
    radial = os.path.join(OUT, "radial-relative")
    errors = {
        "misspelt option": error_of(lambda: sma.run("sleeve-radial", os.path.join(tmp, "x"), stpes=30)),
        "swept option": error_of(lambda: sma.sweep("sleeve-radial", {"gg": [1, 2]}, out=os.path.join(tmp, "s"))),
        "value type": error_of(lambda: sma.sweep("sleeve-radial", {"steps": [30, 2.5]}, out=os.path.join(tmp, "s"))),
        "no run": error_of(lambda: sma.read(tmp)),
        "absent CSV": error_of(lambda: sma.read(radial).frame("points")),
        "absent VTU": error_of(lambda: r.fields("9-never")),
        "time": error_of(lambda: r.fields(7.0)),
        "no state": error_of(lambda: r.fields(None)),
    }
    cut = os.path.join(tmp, "cut.vtu")
    with open(f.path, "rb") as src, open(cut, "wb") as dst:
        dst.write(src.read()[:5000])
    errors["cut VTU"] = error_of(lambda: sma.read_vtu(cut))
    foreign = os.path.join(tmp, "foreign.csv")
    with open(foreign, "w") as out:
        out.write("step,t,stress_guess\n1,2.5,3\n")
    errors["unknown unit"] = error_of(lambda: sma.frame(foreign))
    expected = {"misspelt option": "has no option -stpes (did you mean -steps?)",
                "swept option": "sleeve-radial has no option -gg (did you mean -g",
                "value type": "-steps = 2.5: an int option takes an integer",
                "no run": f"no summary.json in {tmp}",
                "absent CSV": os.path.join(radial, "points.csv") + " is missing",
                "absent VTU": os.path.join(r.out, "fields-9-never.vtu") + " is missing",
                "time": os.path.join(r.out, "fields.pvd") + " lists no state at t = 7.0 s",
                "no state": "fields(None): give an instant ('3-end'), a VTU file of",
                "cut VTU": cut,
                "unknown unit": f"{foreign}: no unit is known for the column 'stress_guess'"}
    # A value the scene refuses: every run checked by the scene first (-checkonly 1), nothing run
    # and the sweep's folder not made.
    refused_out = os.path.join(tmp, "refused")
    errors["refused value"] = error_of(lambda: sma.sweep("sleeve-radial", {"g": [500, -1]}, fixed={"steps": 30},
                                                         out=refused_out))
    expected["refused value"] = "-g -1: sleeve-radial -steps 30 -g -1 is refused (exit 1): sleeve-radial: -g -1 must be in [0, 1e15]"
    # A run that fails in its time loop: the others are published, the error names the failed one.
    partial_out = os.path.join(tmp, "partial")
    try:
        sma.sweep("sleeve-radial", {"stepmaxit": [50, 1]}, fixed={"steps": 30, "stepfallback": 0}, out=partial_out)
        errors["failed run"], finished = "no error", None
    except sma.SceneError as e:
        errors["failed run"], finished = str(e), getattr(e, "table", None)
    expected["failed run"] = f"1 of 2 runs of the sweep in {partial_out} failed:\n  {os.path.join(partial_out, 'stepmaxit=1')}: "
    wrong = {k: errors[k] for k in expected if expected[k] not in errors[k]}
    if os.path.exists(refused_out):
        wrong["refused value"] = f"{refused_out} was made"
    if "did not converge" not in errors["failed run"] or finished is None or len(finished) != 1:
        wrong["failed run"] = f"{errors['failed run']}; finished runs {None if finished is None else len(finished)}"
    check(not wrong and not os.path.exists(os.path.join(tmp, "x")) and not os.path.exists(os.path.join(tmp, "s")),
          f"(f) {len(expected)} errors name the option, value, folder, file or column, before any run: "
          + (f"wrong: {wrong}" if wrong else "; ".join(v.splitlines()[0][:70] for v in errors.values())))
    return errors


def ranks_checks(tmp):
    """(h)"""
    out = sma.run("sleeve-3d", os.path.join(tmp, "np2"), ranks=2, nr=2, nt=4, length=0.04, tend=20, ddmgeneo=1)
    distributed = sma.read(out).summary.get("distributed", {})
    errors = {"no MPI run": error_of(lambda: sma.run("beam", os.path.join(tmp, "y"), ranks=2)),
              "ranks 0": error_of(lambda: sma.run("sleeve-3d", os.path.join(tmp, "y"), ranks=0)),
              "MPI option": error_of(lambda: sma.run("sleeve-3d", os.path.join(tmp, "y"), ranks=2, ddmtoll=1e-9))}
    expected = {"no MPI run": "beam has no run on MPI ranks (ranks=): the scenes of edp/mpi have one: sleeve-3d",
                "ranks 0": "sleeve-3d: ranks=0 must be a whole number of MPI ranks",
                "MPI option": "sleeve-3d has no option -ddmtoll (did you mean -ddmtol"}
    wrong = {k: errors[k] for k in expected if expected[k] not in errors[k]}
    check(distributed.get("ranks") == 2 and distributed.get("geneo") == 1 and not wrong
          and not os.path.exists(os.path.join(tmp, "y")),
          f"(h) ranks=2: {distributed.get('ranks')} ranks, GenEO {distributed.get('geneo')}; refused before any run: "
          + (f"wrong: {wrong}" if wrong else "; ".join(v.splitlines()[0][:60] for v in errors.values())))


def main():
    os.makedirs(OUT, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="python-package-") as tmp:
        got = install_and_import(tmp)
        units_checks(got)
        other_scene_frames(tmp)
        r, f = vtu_checks()
        table = sweep_checks()
        errors = error_checks(tmp, r, f)
        ranks_checks(tmp)
    same = (sma_driver.run is sma.run and sma_driver.SceneError is sma.SceneError
            and tools_results_io.ResultsError is sma.results_io.ResultsError and tools_children.run is sma.children.run)
    api = subprocess.run([PYTHON, os.path.join(ROOT, "tools", "docs", "python_api.py"), "--check"], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    check(same and api.returncode == 0,
          f"(g) tools/sma_driver.py, results_io.py, children.py are the package's modules ({same}); docs/python-api.md is "
          f"current and every public name has a docstring ({api.stderr.strip() or 'yes'}; else `make docs`)")
    record("python_package", {"test": "python_package", "sweep_rows": len(table),
                              "final_pressures_Pa": list(table["final_pressure_mean_Pa"]),
                              "errors": {k: v.splitlines()[0] for k, v in errors.items()}})
    shutil.rmtree(os.path.join(OUT, "radial-relative"), ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
