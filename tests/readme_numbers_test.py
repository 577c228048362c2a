#!/usr/bin/python3
"""README's numbers are the runs' numbers: each figure README quotes of a default run (and of the
steel shaft and pull-out variants it names) is read from this checkout's run, formatted to the
digits README prints, and must appear in README as written. A number typed once and left behind
when the model moved (README said 0.151 GPa for the steel shaft, the runs 0.150) fails here.

Runs (paper scale, about 15 s in all): sleeve-circular at its defaults and with `-pipeE 2e11`,
sleeve-radial at its defaults and with `-pipeE 2e11` (Lamé's compound pressure), sleeve-axisymmetric
at its defaults and with `-mu 0.2 -pullout 1e-3`, sleeve-circular-gvar (its austenite time), sleeve-life
at k = 1 and 0 MPa (the pressure after the cold hold; k = 2 MPa is the headers' run).

The scenes' headers likewise (checklib.header_quotes; their step numbers are the fixed steps',
-tol 0, sleeve-radial's contact and austenite the default's adaptive steps' beside them; sleeve-circular's, sleeve-elliptic's and sleeve-offset's in tests/paper_scale_test.py, which
runs them): sleeve-radial's contact (temperature, time), Lamé's pressure, austenite's temperature
and time, and -scale reduced's pressure and austenite temperature; sleeve-elliptic-friction's defaults (-tol 1e-3): its steps, non-uniformity
and friction ratios; sleeve-life's defaults: the free ring's temperatures and width, the storage
margin, the clearance, the clamping and the service; free-ring's dissipative loop (-dissipation 1e6:
the ring's mean temperature before each transformation, the heat dissipated); and numbers an audit
found stale: sleeve-elliptic-friction's on/off axes (header and README), sleeve-axisymmetric's slip
iterations with -mu 0.2 (default and -tol 0), sleeve-life-2d's circle at k = 1 MPa. Ten more runs,
about 10 s.
Writes results/checks/readme_numbers.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, celsius, check, finish, header_quotes, record, rows, run_scene_captured, summary_of  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tools", "docs"))
from paper_scale_metrics import curve, ellipse_metrics  # noqa: E402


def run(scene, name, *args):
    out, done = run_scene_captured(scene, "readme-" + name, "-quiet", "1", *args)
    check(done.returncode == 0, f"{scene} {' '.join(args)}: exit {done.returncode} {done.stdout[-300:]}")
    return out if done.returncode == 0 else None


def headers():
    """The scene headers' numbers against the runs they describe (fixed steps, -tol 0, where they quote
    step numbers; else the defaults); returns the phrases and sleeve-life's default run (its folder)."""
    phrases = {}
    fixed = ["-tol", "0"]
    radial = run("sleeve-radial", "header-radial", *fixed)
    adaptive = run("sleeve-radial", "header-radial-default")  # (the Run line's: steps chosen by -tol 1e-3)
    reduced = run("sleeve-radial", "header-radial-reduced", "-scale", "reduced", *fixed)
    if radial and reduced and adaptive:
        s, r, d = summary_of(radial), summary_of(reduced), summary_of(adaptive)
        t = {int(h["step"]): float(h["t"]) for h in rows(os.path.join(radial, "history.csv"))}
        td = {int(h["step"]): float(h["t"]) for h in rows(os.path.join(adaptive, "history.csv"))}
        phrases["sleeve-radial"] = [
            f"contact at {celsius(d['T_inner_first_contact']):.1f} C at the inner surface "
            f"(t = {td[d['first_contact_step']]:.1f} s: the end of the step that touches; 1000 fixed steps, -tol 0: "
            f"{celsius(s['T_inner_first_contact']):.1f} C, t = {t[s['first_contact_step']]:.1f} s)",
            f"{s['final_pressure_mean'] / 1e6:.2f} MPa, once the whole ring is austenite "
            f"({celsius(d['T_inner_austenite']):.1f} C, t = {td[d['austenite_step']]:.0f} s; -tol 0: "
            f"{celsius(s['T_inner_austenite']):.1f} C)",
            f"({r['final_pressure_mean'] / 1e6:.2f} MPa, austenite at {celsius(r['T_inner_austenite']):.1f} C)"]
        header_quotes("edp/scenes/sleeve-radial.edp", phrases["sleeve-radial"])
    friction = run("sleeve-elliptic-friction", "header-elliptic-friction", "-vtkevery", "0")  # (its defaults: -tol 1e-3)
    if friction:
        s = summary_of(friction)
        phrases["sleeve-elliptic-friction"] = [
            f"tangential/normal {s['final_tangential_over_normal']:.3f} at most, {s['final_tangential_over_normal_total']:.3f} "
            "in total", f"At the default -tol 1e-3: {s['n_steps']} steps, (max - min)/mean "
            f"{100 * s['final_pressure_non_uniformity']:.3f} %"]
        header_quotes("edp/scenes/sleeve-elliptic-friction.edp", phrases["sleeve-elliptic-friction"])
    # numbers an audit found stale (each was typed once and the code moved): the on/off axes of
    # sleeve-elliptic-friction, sleeve-axisymmetric's slip iterations, sleeve-life-2d's circle
    onoff = run("sleeve-elliptic-friction", "header-elliptic-friction-onoff", "-phasemodel", "onoff", "-vtkevery", "0")
    if onoff:
        m = ellipse_metrics(onoff, 1.0)["major_over_minor"]
        apart = f"the axes come out {abs(100 * m):.1f} % apart, the {'minor' if m < 0 else 'major'} one higher"
        phrases["sleeve-elliptic-friction onoff"] = [f"-phasemodel onoff {apart}"]
        header_quotes("edp/scenes/sleeve-elliptic-friction.edp", phrases["sleeve-elliptic-friction onoff"])
        phrase = f"{abs(100 * m):.1f} % with `-phasemodel onoff` (the {'minor' if m < 0 else 'major'} axis higher"
        check(phrase in " ".join(open(os.path.join(ROOT, "README.md"), encoding="utf-8").read().split()),
              f"README quotes the on/off axes as the run gives them: '{phrase}'")
    slip = run("sleeve-axisymmetric", "header-axisymmetric-mu", "-mu", "0.2", "-meshestimate", "0")
    slip_fixed = run("sleeve-axisymmetric", "header-axisymmetric-mu-fixed", "-mu", "0.2", "-meshestimate", "0", *fixed)
    if slip and slip_fixed:
        phrases["sleeve-axisymmetric"] = [
            f"up to {summary_of(slip)['slip_threshold_iterations_max']} slip-threshold iterations in a step "
            f"({summary_of(slip_fixed)['slip_threshold_iterations_max']} with -tol 0)"]
        header_quotes("edp/scenes/sleeve-axisymmetric.edp", phrases["sleeve-axisymmetric"])
    circle = run("sleeve-life-2d", "header-life-2d-circle", "-dissipation", "1e6", "-pipeA", "0.0505", "-vtkevery", "0")
    if circle:
        phrases["sleeve-life-2d"] = [f"(a circle, -pipeA 0.0505: {summary_of(circle)['service_pressure_min'] / 1e6:.2f}, uniform)"]
        header_quotes("edp/scenes/sleeve-life-2d.edp", phrases["sleeve-life-2d"])
    life = run("sleeve-life", "header-life")  # (its defaults: fixed steps)
    if life:
        s = summary_of(life)
        forward, reverse = s["T_forward_free"], s["T_reverse_free"]
        phrases["sleeve-life"] = [
            f"turns martensite at {forward:.2f} K ({celsius(forward):.1f} C) and back at {reverse:.2f} K "
            f"({celsius(reverse):.1f} C): a width of {s['hysteresis_width_free']:.1f} K",
            f"storage margin {s['storage_margin']:.1f} K; clearance at installation {s['installation_clearance'] * 1e6:.2f} um; "
            f"on heating contact at {celsius(s['T_inner_first_contact']):.1f} C, all austenite from "
            f"{celsius(s['T_inner_austenite']):.1f} C, clamping pressure {s['clamp_pressure'] / 1e6:.3f} MPa",
            f"the inner surface reaches {celsius(s['service_T_inner_min']):.1f} C and the ring stays austenite: the pressure "
            f"stays {s['service_pressure_min'] / 1e6:.3f} MPa", f"{s['n_steps']} steps, about"]
        header_quotes("edp/scenes/sleeve-life.edp", phrases["sleeve-life"])
    ring = run("free-ring", "header-free-ring", "-dissipation", "1e6")
    if ring:
        history = rows(os.path.join(ring, "history.csv"))
        austenite = [float(h["fraction_austenite"]) for h in history]
        # the ring's mean temperature at the step before each transformation shows
        m = next(i for i, a in enumerate(austenite) if a < 1)
        a = next(i for i in range(m + 1, len(history)) if austenite[i] == 1 and austenite[i - 1] < 1)
        phrases["free-ring"] = [
            f"martensite once the ring's mean is at {float(history[m - 1]['T_mean']):.1f} K",
            f"austenite again at {float(history[a - 1]['T_mean']):.1f} K",
            f"{summary_of(ring)['heat_dissipated']:.0f} J/m dissipated"]
        header_quotes("edp/scenes/free-ring.edp", phrases["free-ring"])
    return phrases, life


def main():
    readme = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()
    flat = " ".join(readme.split())  # README wraps its lines; a phrase may straddle two
    quoted = {}
    circular = run("sleeve-circular", "circular", "-vtkevery", "0")
    steel = run("sleeve-circular", "circular-steel", "-vtkevery", "0", "-pipeE", "2e11")
    radial = run("sleeve-radial", "radial")
    radial_steel = run("sleeve-radial", "radial-steel", "-pipeE", "2e11")
    axi = run("sleeve-axisymmetric", "axisymmetric")
    pull = run("sleeve-axisymmetric", "pullout", "-mu", "0.2", "-pullout", "1e-3")
    gvar = run("sleeve-circular-gvar", "gvar", "-vtkevery", "0")
    if circular:
        s, c = summary_of(circular), curve(circular)
        quoted["sleeve-circular"] = [f"uniform final pressure {s['final_pressure_mean'] / 1e9:.3f} GPa",
                                     f"contact at {s['T_inner_first_contact'] - 273.15:.1f} C",
                                     f"the reversion from {c['T_onset_C']:.1f} C"]
        if gvar:
            quoted["sleeve-circular-gvar"] = [f"reached in {curve(gvar)['t_final_s']:.1f} s instead of "
                                              f"{c['t_final_s']:.1f} s"]
    if circular and steel and radial_steel:
        quoted["steel shaft"] = [f"from {summary_of(circular)['final_pressure_mean'] / 1e9:.3f} to "
                                 f"{summary_of(steel)['final_pressure_mean'] / 1e9:.3f} GPa",
                                 f"`-pipeE 2e11`: {summary_of(steel)['final_pressure_mean'] / 1e6:.1f} MPa; "
                                 f"Lamé {summary_of(radial_steel)['lame_pressure'] / 1e6:.1f} MPa"]
    if radial:
        quoted["sleeve-radial"] = [f"final pressure = Lamé ({summary_of(radial)['final_pressure_mean'] / 1e6:.2f} MPa"]
    if axi:
        s = summary_of(axi)
        quoted["sleeve-axisymmetric"] = [f"final pressure at mid-length {s['final_pressure_mid'] / 1e6:.2f} MPa",
                                         f"the open-ended thick cylinder's {s['open_cylinder_pressure'] / 1e6:.2f} MPa",
                                         f"not plane strain's {s['plane_strain_pressure'] / 1e6:.2f}"]
    if pull:
        quoted["pull-out"] = [f"the plateau mu N = {summary_of(pull)['pullout_force_final'] / 1e3:.1f} kN"]
    for what, phrases in quoted.items():
        for phrase in phrases:
            check(phrase in flat, f"README quotes the {what} run as the run gives it: '{phrase}'")
    quoted["headers"], life_default = headers()
    # sleeve-life's service at k = 2 (its default: headers' run), 1 and 0 MPa
    life = {"2": life_default}
    life.update({k: run("sleeve-life", f"life-k{k}", "-dissipation", f"{k}e6" if k != "0" else "0") for k in ("1", "0")})
    if all(life.values()):
        cold = {k: summary_of(out)["pressure_at_service_Tmin"] / 1e6 for k, out in life.items()}
        quoted["sleeve-life"] = [
            f"heating to clamp ({summary_of(life['2'])['clamp_pressure'] / 1e6:.2f} MPa)",
            f"the pressure after the hold at the lowest service temperature {cold['2']:.2f} MPa at k = 2 MPa, "
            f"{cold['1']:.2f} at 1 MPa, {cold['0']:.2f} at 0"]
        for phrase in quoted["sleeve-life"]:
            check(phrase in flat, f"README quotes the sleeve-life runs as they give it: '{phrase}'")
        s0, s1 = summary_of(life["0"]), summary_of(life["1"])
        header_quotes("edp/scenes/sleeve-life.edp", [
            f"from an inner surface at {celsius(s0['service_onset_T_inner']):.1f} C (k = 0) and "
            f"{celsius(s1['service_onset_T_inner']):.1f} C (k = 1 MPa)",
            f"falls to {cold['0']:.2f} MPa (k = 0) and {cold['1']:.2f} MPa (k = 1 MPa; service minimum "
            f"{s1['service_pressure_min'] / 1e6:.2f})"], "sleeve-life (k = 0, 1 MPa)")
    record("readme_numbers", quoted)
    finish()


if __name__ == "__main__":
    main()
