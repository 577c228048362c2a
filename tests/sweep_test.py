#!/usr/bin/python3
"""The Python driver and the sweep (tools/sma_driver.py, tools/sweep.py, make sweep).

On sleeve-radial (300 steps, about 0.5 s a run), -g swept over 250, 500, 1000 through `make sweep`:
  - each row of table.csv equals that run's summary.json (first contact, austenite, pressures);
  - the g = 500 run's history.csv equals, byte for byte, the same scene run directly by tools/ff
    with the same options (an invocation that does not go through the driver);
  - the physics of the sweep: a larger exchange coefficient warms the ring faster, so the first
    contact and the austenite come no later (strictly earlier here); the final state (all
    austenite, the ring elastic on the pipe: one linear contact problem whatever the history) has
    the same pressure to round-off (relative 1e-9);
  - sma_driver.read gives the arrays: the last history row's mean pressure is the summary's final;
  - the two figures and sweep.json are written, and the legend groups no curves (they differ);
    a sweep of -slipnoise on sleeve-circular (it only classifies the final nodes) gives curves
    that coincide, which share one legend entry;
  - an unknown PARAM, an unknown scene, and a misspelt option among ARGS each fail (non-zero
    exit) naming it; ARGS holding `; touch <file>` runs nothing.
Writes results/checks/sweep.json.
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))

from checklib import ROOT, check, finish, record  # noqa: E402
import sma_driver as sma  # noqa: E402

VALUES = ["250", "500", "1000"]
COMMON = ["-steps", "300"]


def make(*words, env_extra=None):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    return subprocess.run(["make", "--no-print-directory", "sweep", *words], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300)


def main():
    measured = {}
    with tempfile.TemporaryDirectory(prefix="sweep-") as tmp:
        out = os.path.join(tmp, "g sweep")
        swept = make("SCENE=sleeve-radial", "PARAM=g", f"VALUES={' '.join(VALUES)}", "ARGS=" + " ".join(COMMON),
                     f"OUT={out}")
        check(swept.returncode == 0, f"make sweep exits 0 ({swept.stderr.strip()[-300:]})")
        rows = sma.read_csv(os.path.join(out, "table.csv"))
        summaries = [sma.read(os.path.join(out, f"g={v}")).summary for v in VALUES]
        same = all(rows[col][i] == s[key] for i, s in enumerate(summaries)
                   for key, col in (("first_contact_step", "first_contact_step"), ("austenite_step", "austenite_step"),
                                    ("final_pressure_mean", "final_pressure_mean_Pa"),
                                    ("peak_pressure_mean", "peak_pressure_mean_Pa")))
        check(same and list(rows["g"]) == [float(v) for v in VALUES],
              "table.csv: one row per value, equal to each run's summary.json")

        direct = os.path.join(tmp, "direct")
        subprocess.run([sma.FF, "edp/scenes/sleeve-radial.edp", *COMMON, "-g", "500", "-quiet", "1", "-out", direct],
                       cwd=ROOT, check=True, capture_output=True)
        a = open(os.path.join(out, "g=500", "history.csv"), "rb").read()
        b = open(os.path.join(direct, "history.csv"), "rb").read()
        check(a == b, f"the sweep's g = 500 history.csv equals a direct tools/ff run's byte for byte ({len(a)} bytes)")

        first = [s["first_contact_step"] for s in summaries]
        austenite = [s["austenite_step"] for s in summaries]
        finals = [s["final_pressure_mean"] for s in summaries]
        spread = (max(finals) - min(finals)) / finals[0]
        check(first[0] > first[1] > first[2] and austenite[0] > austenite[1] > austenite[2],
              f"larger g: earlier first contact {first} and austenite {austenite}")
        check(spread <= 1e-9, f"final pressure independent of g: {[round(p / 1e6, 6) for p in finals]} MPa, "
              f"relative spread {spread:.1e} <= 1e-9")
        r = sma.read(os.path.join(out, "g=1000"))
        check(r.history["pressure_mean"][-1] == r.summary["final_pressure_mean"] and r.points is None,
              "sma_driver.read: history arrays (last mean pressure = the summary's final); no points.csv in 1D")
        sweep = json.load(open(os.path.join(out, "sweep.json")))
        check(sweep["figures"] == ["force-temperature.png", "force-time.png"]
              and all(os.path.getsize(os.path.join(out, f)) > 10000 for f in sweep["figures"])
              and all(run["status"] == "done" for run in sweep["runs"]),
              f"sweep.json lists the runs and the two figures ({sweep['figures']})")
        check(sweep.get("jobs") == min(2, os.cpu_count() or 1), f"runs in parallel on {sweep.get('jobs')} jobs")
        check(sweep["curves_coinciding_within_0.1_percent"] == [], "the three g curves differ: no shared legend")
        # -slipnoise only classifies the final contact nodes (sticking or not): the curves coincide.
        same_out = os.path.join(tmp, "slipnoise")
        same = make("SCENE=sleeve-circular", "PARAM=slipnoise", "VALUES=1e-12 1e-9",
                    "ARGS=-mesh meshes/sleeve-coarse.msh -steps 300 -vtkevery 0", f"OUT={same_out}")
        groups = json.load(open(os.path.join(same_out, "sweep.json")))["curves_coinciding_within_0.1_percent"] \
            if same.returncode == 0 else None
        check(groups == [["1e-12", "1e-9"]], f"curves that coincide share one legend entry: {groups}")

        bad_param = make("SCENE=sleeve-radial", "PARAM=gg", "VALUES=1 2", f"OUT={os.path.join(tmp, 'x')}")
        check(bad_param.returncode != 0 and "has no option -gg (did you mean -g" in bad_param.stderr,
              f"an unknown PARAM fails naming it: {bad_param.stderr.strip().splitlines()[:1]}")
        bad_scene = subprocess.run([sys.executable, "tools/sweep.py", "sleeve-radail", "g", "1"], cwd=ROOT,
                                   capture_output=True, text=True)
        check(bad_scene.returncode != 0 and "unknown scene 'sleeve-radail' (did you mean sleeve-radial" in bad_scene.stderr,
              f"an unknown scene fails naming it: {bad_scene.stderr.strip()[:120]}")
        injected = os.path.join(tmp, "injected")
        bad_args = make("SCENE=sleeve-radial", "PARAM=g", "VALUES=300", f"ARGS=-steps 30; touch {injected}",
                        f"OUT={os.path.join(tmp, 'y')}")
        check(bad_args.returncode != 0 and not os.path.exists(injected),
              f"ARGS with '; touch' runs nothing and fails: {bad_args.stderr.strip().splitlines()[:1]}")
        typo = make("SCENE=sleeve-radial", "PARAM=g", "VALUES=300", "ARGS=-stpes 30", f"OUT={os.path.join(tmp, 'z')}")
        check(typo.returncode != 0 and "no option -stpes (did you mean -steps" in typo.stderr,
              f"a misspelt option among ARGS fails before any run: {typo.stderr.strip().splitlines()[:1]}")
        measured = {"first_contact_steps": first, "austenite_steps": austenite, "final_pressures_Pa": finals,
                    "final_relative_spread": spread}
    record("sweep", {"test": "sweep", **measured})
    finish()


if __name__ == "__main__":
    main()
