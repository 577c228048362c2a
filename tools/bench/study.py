"""make bench, sections 1 and 1b (tools/bench/bench.py): the radial reference curve, and the
force curve under refinement (issue 13): sleeve-radial and sleeve-circular with dt and h refined
together, against the reference and against each other, observed orders, the paper's on/off model
beside the fraction model, the defaults, and the exchange coefficient from 125 to 4000 W/(m^2 K)
(reversal steps, pressure zigzags). doc() writes their pages of docs/benchmarks.md."""
import math
import os

from common import FINE_FPMAXIT, OUT, QUICK, chatter_of, observed_orders, run
from curve_error import curve_error

# The refinement study (issue 13), over the first 30 s (the transient ends near 16 s): dt and h
# together. The radial levels (elements, steps) and the 2D ones (layers, mesh, steps).
STUDY_TEND = 30
REFERENCE_LEVEL = (640, 4800)
STUDY_RADIAL = [(20, 150), (40, 300), (80, 600), (160, 1200), (320, 2400)]
STUDY_2D = [(6, "meshes/sleeve-coarse.msh", 100), (9, "meshes/sleeve-nr9.msh", 150),
            (12, "meshes/sleeve-nr12.msh", 200), (18, "meshes/sleeve-quarter.msh", 300),
            (27, "meshes/sleeve-nr27.msh", 450), (36, "meshes/sleeve-nr36.msh", 600)]
G_SWEEP = [125, 250, 500, 1000, 2000, 4000]
if QUICK:
    REFERENCE_LEVEL = (80, 600)
    STUDY_RADIAL = STUDY_RADIAL[:2]
    STUDY_2D = STUDY_2D[:2]
    G_SWEEP = [250, 1000]


def radial_reference(results):
    """Section 1: the finest radial run affordable; returns its history.csv (the reference)."""
    nr_ref, steps_ref = REFERENCE_LEVEL
    print(f"bench: radial reference (sleeve-radial nr {nr_ref}, {steps_ref} steps over {STUDY_TEND} s)", flush=True)
    ref_dir = os.path.join(OUT, "radial-reference")
    ref_wall, ref_summary, _ = run("edp/scenes/sleeve-radial.edp", ref_dir, "-quiet", 1, "-nr", nr_ref,
                                   "-steps", steps_ref, "-tend", STUDY_TEND, *FINE_FPMAXIT)
    reference = os.path.join(ref_dir, "history.csv")
    results["radial_reference"] = {"wall_seconds": ref_wall, "nr": ref_summary.get("nr"),
                                   "steps": ref_summary.get("n_steps", ref_summary.get("steps")),
                                   "tend": STUDY_TEND, "final_pressure_mean": ref_summary["final_pressure_mean"]}
    return reference


def refinement_study(reference):
    """The force curve under refinement (issue 13): see the module docstring, item 1b."""
    study = {"tend": STUDY_TEND}
    ladder = []
    for nr, steps in STUDY_RADIAL:
        print(f"bench: study, sleeve-radial nr {nr} steps {steps}", flush=True)
        out = os.path.join(OUT, f"study-radial-{nr}")
        wall, s, _ = run("edp/scenes/sleeve-radial.edp", out, "-quiet", 1, "-nr", nr, "-steps", steps,
                         "-tend", STUDY_TEND, *FINE_FPMAXIT)
        ladder.append({"nr": nr, "steps": steps, "wall_seconds": wall, "history": os.path.join(out, "history.csv"),
                       "error": curve_error(os.path.join(out, "history.csv"), reference)["l1_transient"],
                       **chatter_of(s)})
    for a, b in zip(ladder, ladder[1:]):
        a["difference_to_next"] = curve_error(a["history"], b["history"])["l1_transient"]
    sizes = [x["nr"] for x in ladder]
    study["radial"] = ladder
    study["radial_orders"] = observed_orders(sizes, [x["error"] for x in ladder])
    study["radial_orders_successive"] = observed_orders(sizes[:-1], [x["difference_to_next"] for x in ladder[:-1]])
    for model in ("fraction", "onoff"):
        rows = []
        for nr, mesh, steps in STUDY_2D:
            print(f"bench: study, sleeve-circular nr {nr} steps {steps} ({model})", flush=True)
            out = os.path.join(OUT, f"study-2d-{model}-{nr}")
            wall, s, failure = run("edp/scenes/sleeve-circular.edp", out, "-quiet", 1, "-mesh", mesh, "-steps", steps,
                                   "-tend", STUDY_TEND, "-vtkevery", 0, "-phasemodel", model, *FINE_FPMAXIT,
                                   allow_failure=True)
            if s is None:
                rows.append({"nr": nr, "steps": steps, "failure": failure})
                continue
            hist = os.path.join(out, "history.csv")
            rows.append({"nr": nr, "nodes": s["nodes"], "steps": steps, "wall_seconds": wall, "history": hist,
                         "error": curve_error(hist, reference)["l1_transient"],
                         "fixed_point_iterations_max": s["fixed_point_iterations_max"], **chatter_of(s)})
        ok = [x for x in rows if "error" in x]
        for a, b in zip(ok, ok[1:]):
            a["difference_to_next"] = curve_error(a["history"], b["history"])["l1_transient"]
        study[f"2d_{model}"] = rows
        study[f"2d_{model}_orders"] = observed_orders([x["nr"] for x in ok], [x["error"] for x in ok])
        if len(ok) >= 2:
            study[f"2d_{model}_order_overall"] = (math.log(ok[0]["error"] / ok[-1]["error"])
                                                  / math.log(ok[-1]["nr"] / ok[0]["nr"]))
    # The defaults over the whole 150 s (what a user runs), and the anisotropic mesh with twice the
    # layers: the error against the reference over its transient.
    defaults = []
    circular, radial = "edp/scenes/sleeve-circular.edp", "edp/scenes/sleeve-radial.edp"
    for key, name, script, args in (
            ("circular", "sleeve-circular (default: meshes/sleeve-aniso.msh, 1500 steps)", circular, []),
            ("circular-aniso36", "sleeve-circular -mesh meshes/sleeve-aniso36.msh (36 layers x 18 segments)",
             circular, ["-mesh", "meshes/sleeve-aniso36.msh"]),
            ("circular-quarter", "sleeve-circular -mesh meshes/sleeve-quarter.msh (18 x 90, the old default)",
             circular, ["-mesh", "meshes/sleeve-quarter.msh"]),
            ("circular-onoff", "sleeve-circular -phasemodel onoff -mesh meshes/sleeve-quarter.msh (the paper's scheme)",
             circular, ["-phasemodel", "onoff", "-mesh", "meshes/sleeve-quarter.msh"]),
            ("radial", "sleeve-radial (default: nr 160, 1000 steps)", radial, [])):
        if QUICK and key == "circular-aniso36":
            continue
        print(f"bench: study, {name}", flush=True)
        out = os.path.join(OUT, "study-default-" + str(len(defaults)))
        wall, s, _ = run(script, out, "-quiet", 1, *args)
        defaults.append({"key": key, "name": name, "wall_seconds": wall, "loop_seconds": s["wall_seconds"],
                         "error": curve_error(os.path.join(out, "history.csv"), reference)["l1_transient"],
                         "fixed_point_iterations_max": s["fixed_point_iterations_max"],
                         "fixed_point_iterations_mean": s["fixed_point_iterations_mean"], **chatter_of(s)})
    study["defaults"] = defaults
    sweep = []
    for g in G_SWEEP:
        for model, mesh in (("fraction", None), ("onoff", "meshes/sleeve-quarter.msh")):
            print(f"bench: study, g {g} ({model})", flush=True)
            out = os.path.join(OUT, f"study-g{g}-{model}")
            wall, s, failure = run("edp/scenes/sleeve-circular.edp", out, "-quiet", 1, "-g", g, "-gcontact", g,
                                   "-vtkevery", 0, "-phasemodel", model, *(["-mesh", mesh] if mesh else []),
                                   allow_failure=True)
            sweep.append({"g": g, "model": model, "wall_seconds": wall, "failure": failure or None,
                          **(chatter_of(s) if s else {}),
                          "austenite_step": s["austenite_step"] if s else None,
                          "fixed_point_iterations_max": s["fixed_point_iterations_max"] if s else None})
    study["g_sweep"] = sweep
    for rows in [ladder] + [study[f"2d_{m}"] for m in ("fraction", "onoff")]:
        for x in rows:
            x.pop("history", None)
    return study


def doc(r, w):
    """The error metric and the refinement study of docs/benchmarks.md."""
    st = r["study"]
    w("")
    w("## Error metric")
    w("")
    w("The reference curve is the radial model `sleeve-radial` at the finest level affordable "
      f"({r['radial_reference']['nr']} elements in r, {r['radial_reference']['steps']} steps over the first "
      f"{r['radial_reference']['tend']} s, {r['radial_reference']['wall_seconds']:.1f} s; its own error, from the "
      "successive differences of the study below, is about a quarter of the next level's): the centred "
      "circular sleeve is radially symmetric, so it is the same problem in one dimension. The curve "
      "error is the relative L1-in-time error of the mean contact pressure, "
      "int |p - p_ref| dt / int |p_ref| dt, over the transient [0, t_A], t_A the time from which the "
      "reference ring is austenite for good (about 16 s: zero force, linear rise, reverse "
      "transformation), where the curve has its content (tools/bench/oracles/curve_error.py `l1_transient`). Over "
      "the whole 150 s (`l1`) the constant tail dilutes it about 30 times; both are tabulated. "
      "L1 rather than a max norm: a max norm is dominated by the one-step shift of the jumps at the "
      "reverse transformation, which L1 weighs by dt. The final pressure is compared with Lame's closed form for the all-austenite, elastic "
      "final state (thick ring on a rigid shaft, interference = pipe radius - mesh inner radius). "
      "This reference is the scheme's own finest run: docs/reference.md (make reference) measures the "
      "same errors against the Richardson extrapolation of the radial curve, its assumptions tested, "
      "and the on/off scheme against it.")
    w("")
    w("## Refinement study of the force curve")
    w("")
    w(f"Over the first {st['tend']} s (the transient ends near 16 s), dt and h refined together; error = "
      "transient L1 against the reference above; *to next* = the same metric between a level and the next "
      "finer one; *order* = log(e_i / e_i+1) / log(n_i+1 / n_i); reversal steps: steps where a point "
      "went back towards martensite while heating; zigzags: step-to-step oscillations of the mean pressure "
      "(summary.json, edp/solvers/dct.idp `CurveZigzag`).")
    w("")
    w("Radial model (sleeve-radial, default fraction model):")
    w("")
    w("| elements | steps | wall (s) | error | to next | order | reversal steps | zigzags |")
    w("|---|---|---|---|---|---|---|---|")
    orders = st["radial_orders"] + [None]
    for x, o in zip(st["radial"], orders):
        w(f"| {x['nr']} | {x['steps']} | {x['wall_seconds']:.2f} | {100 * x['error']:.3f} % | "
          + (f"{100 * x['difference_to_next']:.3f} %" if "difference_to_next" in x else "-")
          + f" | {'-' if o is None else f'{o:.2f}'} | {x['reversal_steps']} | {x['pressure_zigzag_steps']} |")
    w("")
    for model, title in (("fraction", "2D (sleeve-circular, structured quarter rings), fraction model (the default)"),
                         ("onoff", "2D, the paper's on/off model (-phasemodel onoff)")):
        w(title + ":")
        w("")
        w("| layers | nodes | steps | wall (s) | error | to next | order | reversal steps | zigzags | max fixed-point its |")
        w("|---|---|---|---|---|---|---|---|---|---|")
        ok = [x for x in st[f"2d_{model}"] if "error" in x]
        orders = dict(zip([x["nr"] for x in ok], st[f"2d_{model}_orders"] + [None]))
        for x in st[f"2d_{model}"]:
            if "error" not in x:
                w(f"| {x['nr']} | | {x['steps']} | failed: {x['failure']} | | | | | | |")
                continue
            o = orders.get(x["nr"])
            w(f"| {x['nr']} | {x['nodes']} | {x['steps']} | {x['wall_seconds']:.2f} | {100 * x['error']:.2f} % | "
              + (f"{100 * x['difference_to_next']:.2f} %" if "difference_to_next" in x else "-")
              + f" | {'-' if o is None else f'{o:.2f}'} | {x['reversal_steps']} | {x['pressure_zigzag_steps']} | "
              f"{x['fixed_point_iterations_max']} |")
        if st.get(f"2d_{model}_order_overall") is not None:
            w("")
            w(f"Overall order from the coarsest to the finest level: **{st[f'2d_{model}_order_overall']:.2f}**.")
        w("")
    fr2 = [x for x in st["2d_fraction"] if "error" in x]
    if fr2 and st["radial"]:
        w(f"The 2D and 1D models against each other: the finest 2D level ({fr2[-1]['nr']} layers) is "
          f"{100 * fr2[-1]['error']:.2f} % from the reference, the 1D run with {st['radial'][-1]['nr']} elements "
          f"{100 * st['radial'][-1]['error']:.3f} %: both converge to the same curve, the 2D one at order "
          f"{st.get('2d_fraction_order_overall', float('nan')):.2f} in its layers.")
    w("")
    w("The defaults over the whole 150 s (what a user runs), same metric:")
    w("")
    w("| run | wall (s) | error | fixed-point its mean / max | reversal steps | zigzags |")
    w("|---|---|---|---|---|---|")
    for d in st["defaults"]:
        w(f"| {d['name']} | {d['wall_seconds']:.2f} | {100 * d['error']:.2f} % | {d['fixed_point_iterations_mean']:.2f} / "
          f"{d['fixed_point_iterations_max']} | {d['reversal_steps']} | {d['pressure_zigzag_steps']} |")
    w("")
    w("The exchange coefficient (-g and -gcontact together, 150 s): fraction model on the default mesh, "
      "the paper's on/off model on meshes/sleeve-quarter.msh:")
    w("")
    w("| g (W/(m^2 K)) | model | wall (s) | reversal steps (most points at once) | zigzags | austenite from step | max fixed-point its |")
    w("|---|---|---|---|---|---|---|")
    for x in st["g_sweep"]:
        if x["failure"]:
            w(f"| {x['g']} | {x['model']} | {x['wall_seconds']:.2f} | failed: {x['failure']} | | | |")
        else:
            w(f"| {x['g']} | {x['model']} | {x['wall_seconds']:.2f} | {x['reversal_steps']} ({x['reversal_points_max']}) | "
              f"{x['pressure_zigzag_steps']} | {x['austenite_step']} | {x['fixed_point_iterations_max']} |")
