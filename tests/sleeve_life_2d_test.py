#!/usr/bin/python3
"""The coupling's life on the 2D model (edp/scenes/sleeve-life-2d.edp; issue 28, item 2's "2D"), on
coarse quarter rings and 1 s steps (the paper's scale):
  * a circular pipe (-pipeA = -pipeB = 5.05 cm, the radial life's data), k = 2 MPa, on/off phases
    (both scenes' default): the clamping pressure and the cold-service pressure equal the radial
    life's (nr 80, the same steps) within the 2D discretisation's error, measured on two meshes (6
    and 9 layers: the difference falls with the mesh), and the clearance at installation too;
  * a circular pipe, k = 1 MPa (the service re-transforms the inner layers): the smallest service
    pressure equals the radial life's within the 2D discretisation's error (two meshes, 6 and 18
    layers: it falls); per cycle the dissipated heat the law reports equals the loop area
    k sum area |d beta| computed from the phases, to 1e-9, and is positive;
  * the elliptic pipe (the defaults' semi-axes 5.04 x 5.05 cm), no service: the clamped state equals
    sleeve-elliptic's own at the same mesh (its final state, all austenite: mean pressure, its
    non-uniformity, the smallest nodal pressure and where it sits, on the minor axis, 0 deg, where
    the interference is 0.1 mm smaller); the smallest clearance at installation sits on the major
    axis (90 deg), where the pipe is the radial life's, and the largest exceeds it by the 0.1 mm;
  * a run stopped in service and resumed from its checkpoint gives the uninterrupted run's files;
  * storage above the free ring's reverse start: the run fails with the radial scene's message;
  * the cooling without the mandrel (-mandrel 0) on sleeve-quarter, 1 s steps, leaves a
    checkerboard of martensite 2: the run fails at the cooling's end naming its fraction; with the
    mandrel (the default 20 MPa: the defaults' run below) the same cooling is martensite 1
    throughout and clears the pipe as the circle's closed form says (the radial life's clearance,
    1e-3; until 2026-11-30 a run of its own at 0.25 s steps, 4.8 s);
  * the scene's header quotes its defaults' run (one more run, about 8 s) and the circle's
    differences above as printed (checklib.header_quotes).
Writes results/checks/sleeve_life_2d.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import TEST_RESULTS, celsius, check, finish, header_quotes, record, sci  # noqa: E402
from checklib import run_scene_captured as run, summary_of as summary  # noqa: E402

CIRCLE = ["-pipeA", "0.0505", "-pipeB", "0.0505"]
QUICK = ["-quiet", "1", "-vtkevery", "0"]


def ran(out, done, what):
    check(done.returncode == 0, f"{what} ran (exit {done.returncode})")
    if done.returncode != 0:
        print((done.stdout + done.stderr)[-2000:])
        return None
    return summary(out)


def rel(a, b):
    return abs(a - b) / abs(b)


def defaults_quoted():
    """The header's figures of the scene's defaults (the elliptic pipe, k = 2 MPa), from a run of them."""
    s = ran(*run("sleeve-life-2d", "life2d-defaults", *QUICK), "sleeve-life-2d at its defaults")
    if not s:
        return None, []
    return s, [f"the free ring turns martensite at {s['T_forward_free']:.2f} K and back at {s['T_reverse_free']:.2f} K",
               f"clearance at installation {s['installation_clearance'] * 1e6:.2f} um at "
               f"{s['installation_clearance_angle_deg']:.0f} deg",
               f"and {(s['installation_clearance_max'] - s['installation_clearance']) * 1e6:.0f} um more on the minor axis",
               f"first contact at step {s['first_contact_step']} (inner {celsius(s['T_inner_first_contact']):.1f} C), all "
               f"austenite from step {s['austenite_step']}",
               f"clamping {s['clamp_pressure'] / 1e6:.3f} MPa, non-uniformity {100 * s['clamp_non_uniformity']:.2f} %, "
               f"smallest nodal pressure {s['clamp_pressure_node_min'] / 1e6:.2f} MPa on the minor axis "
               f"({s['clamp_pressure_node_min_angle_deg']:.0f} deg)",
               f"the service (inner surface down to {celsius(s['service_T_inner_min']):.1f} C) leaves it austenite: the pressure "
               f"stays {s['service_pressure_min'] / 1e6:.3f} MPa",
               f"{s['n_steps']} steps (1 s), {s['dc_iterations_mean']:.2f} DC iterations a step (at most "
               f"{s['dc_iterations_max']})"]


def main():
    figures = {}
    defaults, header = defaults_quoted()
    # ---- circular pipe, k = 2 MPa: clamping and cold service against the radial life ----
    radial = ran(*run("sleeve-life", "life2d-radial-k2e6", "-quiet", "1", "-dt", "1", "-cycles", "1"),
                 "sleeve-life -dt 1 -cycles 1 (nr 80)")
    errors = {}
    radial_clearance = radial["installation_clearance"] if radial else None
    for mesh in ("sleeve-coarse", "sleeve-nr9"):
        s = ran(*run("sleeve-life-2d", f"life2d-circle-{mesh}", *QUICK, *CIRCLE, "-mesh", f"meshes/{mesh}.msh",
                     "-cycles", "1"), f"sleeve-life-2d on a circular pipe, -mesh {mesh}")
        if s and radial:
            errors[mesh] = {key: rel(s[key], radial[key]) for key in
                            ("clamp_pressure", "service_pressure_min", "installation_clearance")}
            figures[f"circle_k2e6_{mesh}"] = {key: s[key] for key in ("clamp_pressure", "service_pressure_min",
                                                                        "installation_clearance",
                                                                        "clamp_non_uniformity")}
    if len(errors) == 2 and radial:
        c, f = errors["sleeve-coarse"], errors["sleeve-nr9"]
        figures["circle_k2e6_radial"] = {key: radial[key] for key in ("clamp_pressure", "service_pressure_min",
                                                                       "installation_clearance")}
        check(c["clamp_pressure"] <= 1e-3 and f["clamp_pressure"] < c["clamp_pressure"]
              and c["service_pressure_min"] <= 1e-3 and f["service_pressure_min"] < c["service_pressure_min"],
              f"circular pipe, k = 2 MPa: clamping and cold-service pressure against the radial life's "
              f"{radial['clamp_pressure'] / 1e6:.4f} MPa: relative {c['clamp_pressure']:.2g} (6 layers), "
              f"{f['clamp_pressure']:.2g} (9 layers); service {c['service_pressure_min']:.2g}, "
              f"{f['service_pressure_min']:.2g}")
        header.append(f"clamping within {sci(c['clamp_pressure'])} (6 layers) and {sci(f['clamp_pressure'])} "
                      "(9 layers) of the radial nr 80's")
        check(c["installation_clearance"] <= 1e-3 and f["installation_clearance"] <= 1e-3,
              f"clearance at installation against the radial life's {radial['installation_clearance'] * 1e6:.3f} um: "
              f"relative {c['installation_clearance']:.2g}, {f['installation_clearance']:.2g}")

    # ---- circular pipe, k = 1 MPa: the service re-transforms; energy per cycle ----
    radial = ran(*run("sleeve-life", "life2d-radial-k1e6", "-quiet", "1", "-dt", "1", "-cycles", "2",
                      "-dissipation", "1e6"), "sleeve-life -dissipation 1e6 -dt 1 -cycles 2 (on/off, nr 80)")
    service = {}
    for mesh in ("sleeve-coarse", "sleeve-aniso"):
        s = ran(*run("sleeve-life-2d", f"life2d-circle-k1e6-{mesh}", *QUICK, *CIRCLE, "-mesh", f"meshes/{mesh}.msh",
                     "-dissipation", "1e6", "-cycles", "2"),
                f"sleeve-life-2d on a circular pipe, -dissipation 1e6 -mesh {mesh}")
        if not s:
            continue
        service[mesh] = s["service_pressure_min"]
        heats, loops = s["cycle_heat_dissipated"], s["cycle_loop_area"]
        check(len(heats) == 2 and all(q > 0 and abs(q - l) <= 1e-9 * q for q, l in zip(heats, loops)),
              f"{mesh}: dissipated heat per cycle {', '.join(f'{q:.10g}' for q in heats)} J/m = loop area "
              f"k sum area |d beta| {', '.join(f'{l:.10g}' for l in loops)} (to 1e-9)")
        figures[f"circle_k1e6_{mesh}"] = {"service_pressure_min": s["service_pressure_min"],
                                          "cycle_heat_dissipated": heats, "cycle_loop_area": loops}
    # ---- a run stopped in service and resumed from its checkpoint (the life's 2D state included) ----
    base = ["-mesh", "meshes/sleeve-coarse.msh", *QUICK, *CIRCLE, "-dissipation", "1e6", "-cycles", "2",
            "-checkpoint", "700"]
    cut, done = run("sleeve-life-2d", "life2d-cut", *base, "-stopafter", "1600")
    stopped = done.returncode
    cut, done = run("sleeve-life-2d", "life2d-cut", *base, "-resume", "1")
    whole = os.path.join(TEST_RESULTS, "life2d-circle-k1e6-sleeve-coarse")
    files = ["history.csv", "points.csv", "contact-final.csv", "fields-1-dilated.csv", "fields-2-contact.csv",
             "fields-3-end.csv"]
    same = done.returncode == 0 and all(open(os.path.join(cut, f)).read() == open(os.path.join(whole, f)).read()
                                        for f in files)
    timeless = lambda d: {k: v for k, v in d.items() if "seconds" not in k and not k.startswith("loop_over")
                          and k != "resumed_from_step"}
    same = same and timeless(summary(cut)) == timeless(summary(whole))
    check(stopped == 4 and same, f"stopped after step 1600 (exit {stopped}, in service), resumed from step 1400: "
          f"{', '.join(files)} byte-identical to the uninterrupted run, summary.json equal but its timing keys")
    if len(service) == 2 and radial:
        c, f = (rel(service[m], radial["service_pressure_min"]) for m in ("sleeve-coarse", "sleeve-aniso"))
        figures["circle_k1e6_radial_service_pressure_min"] = radial["service_pressure_min"]
        header.append(f"the smallest service pressure within {100 * c:.2f} % (6 layers) and {100 * f:.2f} % (18 layers)")
        check(c <= 0.01 and f < c,
              f"circular pipe, k = 1 MPa: smallest service pressure {service['sleeve-coarse'] / 1e6:.3f} (6 layers), "
              f"{service['sleeve-aniso'] / 1e6:.3f} MPa (18 layers) against the radial life's "
              f"{radial['service_pressure_min'] / 1e6:.3f} MPa: relative {c:.2g}, {f:.2g}")

    # ---- the ellipse: the clamped state against sleeve-elliptic's at the same mesh ----
    coarse = ["-mesh", "meshes/sleeve-coarse.msh"]
    life = ran(*run("sleeve-life-2d", "life2d-ellipse", *QUICK, *coarse, "-cycles", "0"),
               "sleeve-life-2d (elliptic pipe) -cycles 0 on sleeve-coarse")
    ell_out, done = run("sleeve-elliptic", "life2d-elliptic", *coarse, "-quiet", "1", "-vtkevery", "0")
    ell = ran(ell_out, done, "sleeve-elliptic on sleeve-coarse")
    if life and ell:
        final = [r.split(",") for r in open(os.path.join(ell_out, "contact-final.csv")).read().split()[1:]]
        lowest = min(final, key=lambda r: float(r[6]))
        check(rel(life["clamp_pressure"], ell["final_pressure_mean"]) <= 1e-9
              and abs(life["clamp_non_uniformity"] - ell["final_pressure_non_uniformity"]) <= 1e-6
              and life["clamp_non_uniformity"] > 1e-3
              and rel(life["clamp_pressure_node_min"], float(lowest[6])) <= 1e-9
              and life["clamp_pressure_node_min_angle_deg"] == float(lowest[2]) and abs(float(lowest[2])) < 1e-6,
              f"ellipse: clamping {life['clamp_pressure'] / 1e6:.6f} MPa = sleeve-elliptic's final "
              f"{ell['final_pressure_mean'] / 1e6:.6f}; non-uniformity {life['clamp_non_uniformity']:.6g} "
              f"({ell['final_pressure_non_uniformity']:.6g}); smallest nodal pressure {life['clamp_pressure_node_min'] / 1e6:.4f}"
              f" MPa at {life['clamp_pressure_node_min_angle_deg']:g} deg ({float(lowest[6]) / 1e6:.4f} at {lowest[2]})")
        wider = life["installation_clearance_max"] - life["installation_clearance"]
        check(abs(life["installation_clearance_angle_deg"] - 90) < 1e-6 and life["installation_nodes_short"] == 0
              and abs(wider - 1e-4) <= 2e-6,
              f"ellipse: smallest clearance {life['installation_clearance'] * 1e6:.3f} um at "
              f"{life['installation_clearance_angle_deg']:g} deg (the major axis), the largest "
              f"{wider * 1e6:.3f} um more (the semi-axes differ by 100 um)")
        figures["ellipse"] = {key: life[key] for key in (
            "clamp_pressure", "clamp_non_uniformity", "clamp_pressure_node_min", "clamp_pressure_node_min_angle_deg",
            "installation_clearance", "installation_clearance_max", "installation_clearance_angle_deg")}
        figures["ellipse"]["elliptic_final_pressure_mean"] = ell["final_pressure_mean"]

    # ---- storage above the reverse start: the radial scene's message ----
    t_r = life["T_reverse_free"] if life else 255.563
    warm = f"{t_r + 5:.2f}"
    out, done = run("sleeve-life-2d", "life2d-recovered", *QUICK, *coarse, "-storageT", warm, "-cycles", "0")
    said = done.stdout + done.stderr
    check(done.returncode != 0 and "recovered too early at T=" in said and ", step " in said and "storage" in said,
          f"-storageT {warm} K (reverse start {t_r:.3f} K): the run fails (exit {done.returncode}) saying "
          f"'recovered too early at T=..., step ...'")
    # ---- the cooling without the mandrel: a checkerboard of martensite 2; with it, martensite 1 ----
    # (how much depends on the steps: 1 s steps leave 3 % martensite 2, 0.5 s steps 6 %, the
    # docs/errors.md row tests/bad_inputs_test.py runs)
    stop = ["-cycles", "0", "-installtime", "0", "-heattime", "1"]
    out, done = run("sleeve-life-2d", "life2d-martensite2", *QUICK, *stop, "-mandrel", "0")
    said = done.stdout + done.stderr
    check(done.returncode != 0 and "the cooling ends with a martensite 2 fraction" in said,
          f"-mandrel 0 (1 s steps) on sleeve-quarter: the run fails (exit {done.returncode}) at the cooling's "
          f"end naming the martensite 2 fraction")
    s = defaults  # (the same cooling with the mandrel, 20 MPa: the defaults' run)
    if s and radial_clearance:
        check(s["installation_nodes_short"] == 0 and rel(s["installation_clearance"], radial_clearance) <= 1e-3,
              f"with the mandrel: smallest clearance {s['installation_clearance'] * 1e6:.3f} um at "
              f"{s['installation_clearance_angle_deg']:g} deg, the radial life's {radial_clearance * 1e6:.3f} um "
              f"(relative {rel(s['installation_clearance'], radial_clearance):.2g})")
        figures["mandrel_clearance"] = s["installation_clearance"]
    header_quotes("edp/scenes/sleeve-life-2d.edp", header)
    record("sleeve_life_2d", {"test": "sleeve_life_2d", "header": header, **figures})
    finish()


if __name__ == "__main__":
    main()
