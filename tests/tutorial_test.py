#!/usr/bin/python3
"""The students' lab notebook docs/tutorial/sleeve-lab.ipynb, executed headless as a student's
`jupyter nbconvert --to notebook --execute` would (Debian's jupyter-nbconvert and python3-ipykernel,
tools/install-deps.sh), into a temporary folder, its runs into build/test-results/tutorial (the
notebook reads SMA_LAB; this checkout's python/ on PYTHONPATH, so that its `import sma` is this
checkout's whatever the user's install points at). Checked from the executed notebook's outputs
(the cells tagged setup, radial, lame, sweep, fields, variants) against values computed here:
  (a) the committed notebook is stored without outputs (no output, no execution count), and valid;
  (b) it executes without an error, with this checkout's package, its runs in SMA_LAB, nothing
      written under docs/;
  (c) the curve's last mean pressure (history.csv, read by the notebook) is the run's summary.json
      final_pressure_mean, read here;
  (d) the Lame pressure it prints is the rigid-pipe limit of tools/bench/oracles/lame.py's compound_pressure
      (the textbook thick cylinders, another formula than the notebook's lame_pressure), computed
      here from the run's parameters, and the run's final pressure is within 2 dc_tol of it;
  (e) the sweep's printed table has one row per point of the printed grid (3 interferences x 2 g),
      as many as the sweep's table.csv; each final pressure is Lame's at its interference (the
      ring's inner radius the pipe's minus it, as -interference's help says) within 2 dc_tol, the
      same for both g; the larger g reaches austenite sooner at every interference;
  (f) the 2D fields: the nodes and triangles it prints are the run's summary.json's; its figures
      (curve, sweep, fields, variants) are drawn as images;
  (g) the law swap: the largest difference of the two mean pressure curves it prints is the one
      computed here from the two runs' history.csv (0: no point is ever compressed, the asymmetry
      never acts); the obstacle swap's printed final pressure is its summary.json's, with the
      superellipse's default pipe (A = B = 50.48 mm) in its parameters.
About 25 s (the notebook 16 s, the kernel and nbconvert the rest). Writes results/checks/tutorial.json.
"""
import ast
import itertools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, TEST_RESULTS, check, finish, record, rows  # noqa: E402
from lame import compound_pressure  # noqa: E402  (checklib puts tools/bench/oracles on the path)
import nbformat  # noqa: E402

NOTEBOOK = os.path.join(ROOT, "docs", "tutorial", "sleeve-lab.ipynb")
LAB = os.path.join(TEST_RESULTS, "tutorial")
TAGS = ("setup", "radial", "lame", "sweep", "fields", "variants")


def files_under(folder):
    return {os.path.join(d, f) for d, _, names in os.walk(folder) for f in names}


def stdout_of(nb, tag):
    """The printed text of the code cell tagged `tag` ("" if there is none)."""
    for cell in nb.cells:
        if cell.cell_type == "code" and tag in cell.get("metadata", {}).get("tags", []):
            return "".join(o.get("text", "") for o in cell.get("outputs", []) if o.get("output_type") == "stream")
    return ""


def value(text, name):
    """The value printed as `name = value` (a number, or the rest of the line); None if absent."""
    m = re.search(r"^" + re.escape(name) + r" = (.*?)(?: Pa)?$", text, re.M)
    if not m:
        return None
    try:
        return float(m.group(1))
    except ValueError:
        return m.group(1)


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def relative(a, b):
    return abs(a - b) / abs(b)


def main():
    stored = nbformat.read(NOTEBOOK, as_version=4)
    nbformat.validate(stored)
    code = [c for c in stored.cells if c.cell_type == "code"]
    tagged = {t for c in code for t in c.get("metadata", {}).get("tags", [])}
    check(all(not c.outputs and c.execution_count is None for c in code) and set(TAGS) <= tagged,
          f"(a) the committed notebook: {len(code)} code cells, none with an output or an execution count; "
          f"tags {sorted(tagged)}")

    if shutil.which("jupyter-nbconvert") is None:
        check(False, "(b) no jupyter-nbconvert on PATH: install Debian's jupyter-nbconvert and python3-ipykernel "
                     "(tools/install-deps.sh, make deps)")
        return finish()
    docs_before = files_under(os.path.join(ROOT, "docs"))
    shutil.rmtree(LAB, ignore_errors=True)
    with tempfile.TemporaryDirectory(prefix="sleeve-lab-") as tmp:
        shutil.copy(NOTEBOOK, tmp)
        env = dict(os.environ, SMA_LAB=LAB, PYDEVD_DISABLE_FILE_VALIDATION="1",
                   PYTHONPATH=os.pathsep.join([os.path.join(ROOT, "python")]
                                              + ([os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else [])))
        done = subprocess.run(["jupyter", "nbconvert", "--to", "notebook", "--execute",
                               "--ExecutePreprocessor.timeout=600", "--output-dir", os.path.join(tmp, "out"),
                               os.path.join(tmp, "sleeve-lab.ipynb")],
                              cwd=tmp, env=env, capture_output=True, text=True)
        executed_path = os.path.join(tmp, "out", "sleeve-lab.ipynb")
        if done.returncode != 0 or not os.path.exists(executed_path):
            print(done.stdout[-3000:], done.stderr[-6000:])
            check(False, f"(b) jupyter nbconvert --execute failed (exit {done.returncode}): the error above")
            return finish()
        nb = nbformat.read(executed_path, as_version=4)
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.get("output_type") == "error"]
    root = value(stdout_of(nb, "setup"), "package root")
    lab = value(stdout_of(nb, "setup"), "results folder")
    written_in_docs = sorted(files_under(os.path.join(ROOT, "docs")) - docs_before)
    check(not errors and root == os.path.realpath(ROOT) and lab == LAB and not written_in_docs,
          f"(b) executed headless: {len(errors)} errors, sma.ROOT {root}, runs into {lab}, "
          f"new files under docs/: {written_in_docs or 'none'}")

    radial_text = stdout_of(nb, "radial")
    radial = value(radial_text, "radial run")
    last = value(radial_text, "curve's last mean pressure")
    s = summary(radial) if isinstance(radial, str) and os.path.isfile(os.path.join(radial, "summary.json")) else {}
    final = s.get("final_pressure_mean", float("nan"))
    check(isinstance(radial, str) and radial.startswith(LAB + os.sep) and last is not None
          and relative(last, final) < 1e-9,
          f"(c) the curve's last mean pressure {last} Pa = summary.json's final_pressure_mean {final} Pa "
          f"({radial})")

    p = s.get("parameters", {})
    Ri, Ro = p.get("ring_inner_radius", 1.0), p.get("ring_inner_radius", 1.0) + p.get("ring_thickness", 0.0)
    rigid = compound_pressure(p.get("E", 1.0), p.get("nu", 0.0), Ri, Ro, float("inf"), 0.3, 0.0,
                              p.get("pipe_A", 2.0), plane=p.get("plane", "strain"))
    printed_lame = value(stdout_of(nb, "lame"), "Lame's pressure")
    dc_tol = p.get("dc_tol", 0.0)
    check(printed_lame is not None and relative(printed_lame, rigid) < 1e-12 and relative(final, rigid) <= 2 * dc_tol,
          f"(d) the notebook's Lame pressure {printed_lame} Pa = the compound cylinders' rigid limit {rigid:.6f} Pa; "
          f"the run's final pressure within {relative(final, rigid):.1e} of it (<= 2 dc_tol = {2 * dc_tol})")

    sweep_text = stdout_of(nb, "sweep")
    grid = ast.literal_eval(value(sweep_text, "grid") or "{}")
    table = [[float(w) for w in line.split()] for line in sweep_text.splitlines()
             if line.split() and all(re.fullmatch(r"[-+0-9.eE]+", w) for w in line.split())]
    points = list(itertools.product(grid.get("interference", []), grid.get("g", [])))
    on_disk = rows(os.path.join(value(sweep_text, "sweep folder"), "table.csv")) \
        if isinstance(value(sweep_text, "sweep folder"), str) else []
    check(len(points) == 6 and len(table) == len(points) == len(on_disk)
          and sorted((r[0], r[1]) for r in table) == sorted(points),
          f"(e) the sweep's table: {len(table)} rows, one per point of the grid {grid} ({len(points)}), as table.csv "
          f"({len(on_disk)} rows)")
    # -interference sets the ring's inner radius, the pipe's minus it; the thickness stays (its -help).
    pipe, thickness = p.get("pipe_A", 2.0), p.get("ring_thickness", 0.0)
    lame_gap = max((relative(r[2], compound_pressure(p.get("E", 1.0), p.get("nu", 0.0), pipe - r[0],
                                                     pipe - r[0] + thickness, float("inf"), 0.3, 0.0, pipe))
                    for r in table), default=float("inf"))
    by_g = {}
    for r in table:
        by_g.setdefault(r[0], []).append((r[1], r[2], r[3]))
    g_gap = max((relative(max(v[1] for v in runs), min(v[1] for v in runs)) for runs in by_g.values()),
                default=float("inf"))
    sooner = all(sorted(runs)[-1][2] < sorted(runs)[0][2] for runs in by_g.values()) and bool(by_g)
    check(lame_gap <= 2 * dc_tol and g_gap <= 2 * dc_tol and sooner,
          f"(e) each final pressure = Lame's at its interference within {lame_gap:.1e}, the two g within "
          f"{g_gap:.1e} (<= 2 dc_tol); the larger g reaches austenite sooner at every interference: {sooner}")

    fields_text = stdout_of(nb, "fields")
    run2d = value(fields_text, "2D run")
    m = re.search(r"^nodes = (\d+), triangles = (\d+)$", fields_text, re.M)
    s2d = summary(run2d) if isinstance(run2d, str) and os.path.isfile(os.path.join(run2d, "summary.json")) else {}
    counts = (int(m.group(1)), int(m.group(2))) if m else None
    images = sum("image/png" in o.get("data", {}) for c in nb.cells if c.cell_type == "code" for o in c.outputs)
    check(counts is not None and counts == (s2d.get("nodes"), s2d.get("triangles")) and images >= 4
          and os.path.isfile(os.path.join(LAB, "fields.png")),
          f"(f) the fields' VTU: {counts} nodes, triangles = summary.json's ({s2d.get('nodes')}, "
          f"{s2d.get('triangles')}); {images} figures drawn (>= 4); fields.png in the lab folder")

    variants_text = stdout_of(nb, "variants")
    base, law, shape = (value(variants_text, k) for k in ("base run", "law swap run", "obstacle swap run"))
    if all(isinstance(f, str) and os.path.isfile(os.path.join(f, "history.csv")) for f in (base, law, shape)):
        pb = [float(r["pressure_mean"]) for r in rows(os.path.join(base, "history.csv"))]
        pl = [float(r["pressure_mean"]) for r in rows(os.path.join(law, "history.csv"))]
        here = max(abs(a - b) for a, b in zip(pb, pl)) if len(pb) == len(pl) else float("inf")
        printed = value(variants_text, "largest difference of the mean pressure curves (law - base)")
        ss = summary(shape)
        printed_shape = value(variants_text, "superellipse final mean pressure")
        check(printed is not None and printed == here == 0.0 and len(pb) == 150
              and summary(law)["scene"] == "sleeve-asymmetric-law",
              f"(g) the law swap: the printed largest difference of the mean pressure curves {printed} Pa = the one "
              f"computed from the two history.csv ({here} Pa over {len(pb)} steps)")
        check(printed_shape is not None and relative(printed_shape, ss["final_pressure_mean"]) < 1e-12
              and ss["scene"] == "sleeve-superellipse" and ss["parameters"]["pipe_A"] == 0.05048
              and ss["parameters"]["pipe_B"] == 0.05048,
              f"(g) the obstacle swap's printed final pressure {printed_shape} Pa = its summary.json's "
              f"{ss['final_pressure_mean']} Pa (pipe {ss['parameters']['pipe_A']} x {ss['parameters']['pipe_B']} m)")
    else:
        check(False, f"(g) the variants' run folders printed by the notebook: {base}, {law}, {shape}")

    record("tutorial", {"radial_final_Pa": final, "lame_Pa": rigid, "sweep_rows": len(table),
                        "sweep_lame_gap": lame_gap, "nodes_triangles": counts, "figures": images})
    return finish()


if __name__ == "__main__":
    sys.exit(main())
