#!/usr/bin/python3
"""The sleeve's options beyond the material: the geometry (issue 14: -interference, -Ri,
-thickness) and the heat and time options of issue 17 (-gcontact following -g, -Tpipe, -gpipe, -dt).

meshes/sleeve-geometry.txt is the one place of the ring's and pipe's dimensions: the Makefile
meshes the ring from it, the radial model and the -pipeA default read it. The 2D model takes its
ring from the mesh unless -Ri / -interference / -thickness ask for another; it then stretches the
mesh radially. Asserts, with a 60 um interference and a 12 mm thickness (both unlike the meshes'):
  - the 2D (coarse mesh) and radial final pressures against Lame's shrink fit (tools/bench/oracles/lame.py),
    the final state being all austenite and elastic: within 0.5 % (2D, 6 layers) and 0.05 %
    (radial, nr 40);
  - the 2D summary's ring inner radius is -pipeA minus the interference (to 1e-12 m);
  - the defaults equal the geometry file (the radial summary's ring_inner_radius, thickness);
  - -Ri with -interference together fails, naming both;
  - and one option trap of the same kind (issue 17): -g alone also sets the contact exchange
    (-gcontact defaults to -g), so the summary's g_contact is the -g given;
  - -dt 0.3 over 150 s is -steps 500: the same history.csv byte for byte;
  - -Tpipe: a radial ring insulated outside (-g 0) and exchanging only with the pipe (-gpipe 500,
    -gcontact 500) tends to the pipe's temperature: after 2e5 s (about 50 time constants of the
    exchange) every node within 1e-6 K of -Tpipe 300 K, while -Text is 250 K.
Records results/checks/sleeve_options.json.
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools", "bench", "oracles"))

from checklib import ROOT, check, finish, record, rows, run_scene, sleeve_geometry, sleeve_outputs  # noqa: E402
from lame import lame_pressure  # noqa: E402


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    g = sleeve_geometry()
    E, nu, delta, thickness = 85e9, 0.3, 60e-6, 0.012
    Ri = g["pipe"] - delta
    lame = lame_pressure(E, nu, Ri, Ri + thickness, delta)
    common = ("-quiet", "1", "-steps", "300", "-interference", f"{delta}", "-thickness", f"{thickness}")
    two_d = sleeve_outputs(run_scene("sleeve-circular", "geometry-2d", "-mesh", "meshes/sleeve-coarse.msh", *common))
    radial = summary(run_scene("sleeve-radial", "geometry-radial", "-nr", "40", *common))
    p2, pr = two_d["summary"]["final_pressure_mean"], radial["final_pressure_mean"]
    e2, er = abs(p2 / lame - 1), abs(pr / lame - 1)
    print(f"info Lame {lame / 1e6:.4f} MPa; 2D {p2 / 1e6:.4f} MPa ({e2:.2e}); radial {pr / 1e6:.4f} MPa ({er:.2e})")
    check(e2 <= 5e-3, f"2D with -interference {delta} -thickness {thickness}: final pressure off Lame by {e2:.2e} > 0.5 %")
    check(er <= 5e-4, f"radial with -interference {delta} -thickness {thickness}: off Lame by {er:.2e} > 0.05 %")
    ri2 = two_d["summary"]["parameters"]["ring_inner_radius"]
    check(abs(ri2 - Ri) <= 1e-12, f"2D ring inner radius {ri2} != pipe - interference {Ri}")
    par = summary(run_scene("sleeve-radial", "geometry-default", "-quiet", "1", "-nr", "10", "-steps", "20"))["parameters"]
    check(par["ring_inner_radius"] == g["Ri"] and par["ring_thickness"] == g["Hr"] and par["pipe_A"] == g["pipe"],
          f"radial defaults {par['ring_inner_radius']}, {par['ring_thickness']}, {par['pipe_A']} differ from "
          f"meshes/sleeve-geometry.txt {g}")
    both = subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-Ri", "0.05",
                           "-interference", "5e-5", "-out", os.path.join(ROOT, "build", "test-results", "geometry-both")],
                          cwd=ROOT, capture_output=True, text=True)
    said = both.stdout + both.stderr  # FreeFEM writes cerr to stdout
    check(both.returncode != 0 and "-Ri 0.05 and -interference 5e-05 disagree" in said,
          f"-Ri with -interference that disagree: exit {both.returncode}, output {said.strip()[-200:]!r}")
    # Both, agreeing (Ri = pipeA - interference): every option at its printed default is valid.
    agree = summary(run_scene("sleeve-radial", "geometry-both-agree", "-quiet", "1", "-nr", "10", "-steps", "20",
                              "-Ri", "0.05", "-interference", "0.0005"))["parameters"]
    check(abs(agree["ring_inner_radius"] - 0.05) <= 1e-15,
          f"-Ri 0.05 -interference 0.0005 (they agree) run with Ri = {agree['ring_inner_radius']}")
    # -interference 0 given is no interference (it meant the 0.5 mm default once): the ring only
    # touches the pipe; the clearance note says it touches from the first step.
    zero = run_scene("sleeve-radial", "geometry-zero-interference", "-quiet", "1", "-nr", "10", "-steps", "50",
                     "-interference", "0")
    zs = summary(zero)
    check(zs["parameters"]["ring_inner_radius"] == zs["parameters"]["pipe_A"] and zs["final_pressure_mean"] == 0
          and zs["lame_pressure"] == 0,
          f"-interference 0: Ri = pipeA ({zs['parameters']['ring_inner_radius']} / {zs['parameters']['pipe_A']}), "
          f"final pressure {zs['final_pressure_mean']} Pa, Lame {zs['lame_pressure']} Pa")
    g_only = summary(run_scene("sleeve-radial", "geometry-g-only", "-quiet", "1", "-nr", "10", "-steps", "20",
                               "-g", "1000"))["parameters"]
    check(g_only["g"] == 1000 and g_only["g_contact"] == 1000,
          f"-g 1000 alone: g {g_only['g']}, g_contact {g_only['g_contact']} (must follow -g)")
    a = run_scene("sleeve-radial", "options-dt", "-quiet", "1", "-nr", "10", "-dt", "0.3")
    b = run_scene("sleeve-radial", "options-steps", "-quiet", "1", "-nr", "10", "-steps", "500")
    same = open(os.path.join(a, "history.csv"), "rb").read() == open(os.path.join(b, "history.csv"), "rb").read()
    check(same and summary(a)["n_steps"] == 500, f"-dt 0.3 equals -steps 500 (history identical: {same})")
    pipe_out = run_scene("sleeve-radial", "options-tpipe", "-quiet", "1", "-nr", "10", "-steps", "200",
                         "-tend", "2e5", "-g", "0", "-gpipe", "500", "-gcontact", "500", "-Text", "250",
                         "-Tpipe", "300", "-rannacher", "200")
    pipe = summary(pipe_out)
    last = rows(os.path.join(pipe_out, "history.csv"))[-1]
    tmin, tmax = float(last["T_min"]), float(last["T_max"])
    off = max(abs(tmin - 300), abs(tmax - 300))
    print(f"info -Tpipe 300 with the outside insulated: T in [{tmin}, {tmax}] K at the end")
    check(off <= 1e-6 and pipe["parameters"]["T_pipe"] == 300, f"-Tpipe 300 (outside insulated): the ring "
          f"ends {off:.2e} K from the pipe's temperature (> 1e-6)")
    record("sleeve_options", {"interference_m": delta, "thickness_m": thickness, "lame_Pa": lame,
                               "pressure_2d_Pa": p2, "pressure_radial_Pa": pr, "error_2d": e2, "error_radial": er,
                               "geometry_file": g})
    finish()


if __name__ == "__main__":
    main()
