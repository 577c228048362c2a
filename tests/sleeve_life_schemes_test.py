#!/usr/bin/python3
"""sleeve-life's service pressure at the coldest service temperature (the design chart's figure):
converged, and the two phase schemes agreeing, or the reason they cannot.

sleeve-life (the radial model) at -dissipation k = 0, 1 and 2 MPa:
  - the fraction model and the paper's on/off scheme (the scene's default) give the same
    pressure_at_service_Tmin within 1 %;
  - each is converged: nr 20 against the default nr 80 within 0.5 %, and the default 6620 steps
    against twice as many within 0.5 % (nr 20).
Near the threshold k at which the cold hold stops re-transforming the ring (between 1.25 and 1.35
MPa at the defaults) they cannot agree: at k = 1.3 MPa the on/off scheme's points either turn
martensite again or do not (its pressure on one of the two plateaus: within 6 % of the k = 1 or
2 MPa value, the lower plateau rising slowly with k),
while the fraction model re-transforms the ring in part (its pressure strictly between the
plateaus, at least 20 % from each): a cliff of the design chart, resolved by the fraction model.
Runs into build/test-results/life-schemes-*/; writes results/checks/sleeve_life_schemes.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, run_scene_captured, summary_of  # noqa: E402


def pressure(name, *args):
    """sleeve-life's pressure after the cold hold, run into build/test-results/life-schemes-<name>."""
    # (-meshestimate 0: the schemes are compared, not the meshes)
    out, proc = run_scene_captured("sleeve-life", "life-schemes-" + name, "-quiet", "1", "-meshestimate", "0", *args)
    if proc.returncode != 0:
        check(False, f"sleeve-life {' '.join(args)} exit {proc.returncode}: {proc.stderr[-300:]}")
        return float("nan")
    return summary_of(out)["pressure_at_service_Tmin"]


def main():
    data = {}
    for k in ("0", "1e6", "2e6"):
        onoff = pressure(f"onoff-{k}", "-dissipation", k)
        fraction = pressure(f"fraction-{k}", "-dissipation", k, "-phasemodel", "fraction")
        coarse = pressure(f"fraction-{k}-nr20", "-dissipation", k, "-phasemodel", "fraction", "-nr", "20")
        fine_t = pressure(f"fraction-{k}-nr20-2dt", "-dissipation", k, "-phasemodel", "fraction", "-nr", "20",
                          "-steps", "13240")
        data[k] = {"onoff": onoff, "fraction": fraction, "fraction_nr20": coarse, "fraction_nr20_steps13240": fine_t}
        check(abs(fraction / onoff - 1) < 0.01,
              f"k {k} Pa: fraction {fraction / 1e6:.3f} MPa, on/off {onoff / 1e6:.3f} MPa, within 1 %")
        check(abs(coarse / fraction - 1) < 0.005 and abs(fine_t / coarse - 1) < 0.005,
              f"k {k} Pa: fraction converged: nr 20 {coarse / 1e6:.3f} against nr 80 {fraction / 1e6:.3f} MPa, "
              f"twice the steps {fine_t / 1e6:.3f} MPa, each within 0.5 %")
    low, high = data["1e6"]["onoff"], data["2e6"]["onoff"]
    onoff = pressure("onoff-cliff", "-dissipation", "1.3e6")
    fraction = pressure("fraction-cliff", "-dissipation", "1.3e6", "-phasemodel", "fraction")
    data["1.3e6"] = {"onoff": onoff, "fraction": fraction, "plateau_low": low, "plateau_high": high}
    on_plateau = min(abs(onoff / low - 1), abs(onoff / high - 1))
    check(on_plateau < 0.06, f"k 1.3 MPa: on/off {onoff / 1e6:.2f} MPa on a plateau ({low / 1e6:.2f} or "
                             f"{high / 1e6:.2f} MPa: {100 * on_plateau:.1f} % from it)")
    check(fraction > 1.2 * low and fraction < high / 1.2,
          f"k 1.3 MPa: fraction {fraction / 1e6:.2f} MPa strictly between the plateaus (partly re-transformed)")
    record("sleeve_life_schemes", data)
    finish()


if __name__ == "__main__":
    main()
