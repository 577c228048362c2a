#!/usr/bin/python3
"""Verification of the Monte Carlo ensemble on MPI (edp/ensemble/sleeve-random-ensemble.edp) on
the coarse mesh, 150 steps, 4 seeds.

- Parallel = serial: the ensemble on 2 ranks and on 1 rank gives the same peak, final, node peak
  ratio and T0 sample spread seed by seed, bit for bit, and each seed's child wrote a
  byte-identical history.csv (the whole force history, not only the figures read back); the
  statistics are then the same bit for bit too.
- The split: both ranks ran seeds, each seed on rank (seed - seed0) mod 2 (round-robin).
- The statistics of summary.json (mean, sample standard deviation, quantiles 5/25/50/75/95 %
  by linear interpolation, min, max) equal a recomputation with numpy from seeds.csv (1e-12
  relative), and the force columns are pressure x 2 pi Ri with Ri from the children's summaries.
- The draw is seeded: each child recorded the seed, steps and mesh it was asked for, and the four
  seeds give four different T0 samples and four different node peak ratios.
- A child's failure stops the ensemble loudly: seed 2 (rank 1) killed while it runs gives a non-zero exit,
  an error naming seed 2 and its log, no other seed blamed, and no seeds.csv or summary.json.
- A child stopped by a signal (TERM to seed 2's FreeFEM) stops the ensemble: an error naming seed 2
  and the signal, no other seed started on its rank (seed 4), nothing published.
Writes results/checks/ensemble_mpi.json.
"""
import filecmp
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record, rows  # noqa: E402

DRIVER = "edp/ensemble/sleeve-random-ensemble.edp"
SEED0, SEEDS = 1, 4
COMMON = ["-seeds", str(SEEDS), "-seed0", str(SEED0), "-mesh", "meshes/sleeve-coarse.msh", "-steps", "150"]
COLUMNS = ["peak_pressure_mean_Pa", "final_pressure_mean_Pa", "node_peak_over_final_max", "T0_local_std_K"]
STATISTICS = {"peak_pressure_mean_Pa": "peak_pressure_mean_Pa",
              "final_pressure_mean_Pa": "final_pressure_mean_Pa",
              "peak_force_N_per_m": "peak_force_N_per_m", "final_force_N_per_m": "final_force_N_per_m",
              "peak_over_final": "peak_over_final", "node_peak_over_final_max": "node_peak_over_final_max",
              "peak_step": "peak_step", "T_inner_peak_K": "T_inner_peak_K", "T0_local_std_K": "T0_local_std_K",
              "austenite_step": "austenite_step", "T_inner_austenite_K": "T_inner_austenite_K"}


def environment():
    env = dict(os.environ, OMPI_MCA_mpi_yield_when_idle="1",
               FF_INCLUDEPATH=f"{ROOT}/edp/lib;{ROOT}/edp/model;{ROOT}/edp/solvers;{ROOT}/edp/problems;/usr/include/freefem++/idp;./")
    if os.geteuid() == 0:  # OpenMPI refuses root without both
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return env


def ensemble(name, ranks, *args, fresh=True):
    """Runs the driver on `ranks` MPI ranks into build/test-results/<name>; returns (out, process)."""
    out = os.path.join(TEST_RESULTS, name)
    if fresh and os.path.isdir(out):
        shutil.rmtree(out)
    proc = subprocess.run(["ff-mpirun", "-np", str(ranks), DRIVER, "-v", "0", *COMMON, "-out", out, *args],
                          cwd=ROOT, env=environment(), capture_output=True, text=True, timeout=300)
    return out, proc


def quantile7(values, p):
    """Hyndman-Fan type 7, written out (numpy's default 'linear' is checked against it too)."""
    s = sorted(values)
    h = p * (len(s) - 1)
    lo = math.floor(h)
    hi = min(lo + 1, len(s) - 1)
    return s[lo] + (h - lo) * (s[hi] - s[lo])


def close(a, b, rel=1e-12):
    return a == b or abs(a - b) <= rel * max(abs(a), abs(b))


def main():
    runs = {}
    for name, ranks in (("mpi2", 2), ("serial", 1)):
        out, proc = ensemble("ensemble-" + name, ranks)
        print(proc.stdout.strip().splitlines()[-1] if proc.stdout.strip() else "(no output)")
        if proc.returncode != 0:
            print(proc.stdout + proc.stderr)
        check(proc.returncode == 0, f"{name}: the ensemble on {ranks} rank(s) exits 0 (got {proc.returncode})")
        if proc.returncode != 0:
            finish()
        runs[name] = {"out": out, "rows": rows(os.path.join(out, "seeds.csv")),
                      "summary": json.load(open(os.path.join(out, "summary.json")))}

    mpi, serial = runs["mpi2"], runs["serial"]
    seeds = [int(r["seed"]) for r in mpi["rows"]]
    check(seeds == list(range(SEED0, SEED0 + SEEDS)) and seeds == [int(r["seed"]) for r in serial["rows"]],
          f"both runs list seeds {seeds} in order")

    # Parallel = serial, seed by seed and bit for bit (the text of 17 significant digits).
    same = sum(a[c] == b[c] and float(a[c]) == float(b[c])
               for a, b in zip(mpi["rows"], serial["rows"]) for c in COLUMNS)
    check(same == SEEDS * len(COLUMNS), f"2 ranks = 1 rank seed by seed, bit for bit: {same} of "
          f"{SEEDS * len(COLUMNS)} values ({', '.join(COLUMNS)})")
    histories = [s for s in seeds if filecmp.cmp(os.path.join(mpi["out"], f"seed-{s}", "history.csv"),
                                                  os.path.join(serial["out"], f"seed-{s}", "history.csv"),
                                                  shallow=False)]
    check(histories == seeds, f"each seed's history.csv byte-identical on 2 ranks and 1: seeds {histories}")
    same_stats = [k for k in STATISTICS if mpi["summary"][k] == serial["summary"][k]]
    check(len(same_stats) == len(STATISTICS), f"statistics identical on 2 ranks and 1: {len(same_stats)} "
          f"of {len(STATISTICS)} quantities")

    # The split.
    ranks = [int(r["rank"]) for r in mpi["rows"]]
    check(sorted(set(ranks)) == [0, 1] and mpi["summary"]["n_ranks"] == 2 and mpi["summary"]["ranks_used"] == 2,
          f"both ranks ran seeds: ranks {ranks}, n_ranks {mpi['summary']['n_ranks']}")
    check(ranks == [(s - SEED0) % 2 for s in seeds], f"round-robin: seed s on rank (s - {SEED0}) mod 2")
    check({int(r["rank"]) for r in serial["rows"]} == {0} and serial["summary"]["n_ranks"] == 1,
          "serial run: every seed on rank 0")

    # Statistics recomputed from the per-seed table.
    children = {s: json.load(open(os.path.join(mpi["out"], f"seed-{s}", "summary.json"))) for s in seeds}
    Ri = children[seeds[0]]["parameters"]["ring_inner_radius"]
    table = {c: [float(r[c]) for r in mpi["rows"]] for c in mpi["rows"][0]}
    force_ok = all(close(table[f"{w}_force_N_per_m"][i], table[f"{w}_pressure_mean_Pa"][i] * 2 * math.pi * Ri)
                   for w in ("peak", "final") for i in range(SEEDS))
    check(force_ok, f"force per unit length = pressure x 2 pi Ri (Ri = {Ri} m from the children's summaries)")
    ratio_ok = all(close(table["peak_over_final"][i],
                         table["peak_pressure_mean_Pa"][i] / table["final_pressure_mean_Pa"][i])
                   for i in range(SEEDS))
    check(ratio_ok, "peak_over_final = peak / final per seed")
    worst, compared = 0.0, 0
    for key in STATISTICS:
        v = np.array(table[key])
        ours = mpi["summary"][key]
        expected = {"mean": float(np.mean(v)), "std": float(np.std(v, ddof=1)), "min": float(v.min()),
                    "max": float(v.max())}
        for p in (5, 25, 50, 75, 95):
            expected[f"q{p:02d}"] = quantile7(list(v), p / 100)
            assert close(expected[f"q{p:02d}"], float(np.percentile(v, p)), 1e-14)
        for stat, value in expected.items():
            scale = max(abs(value), abs(expected["mean"]))  # a zero std is compared on the mean's scale
            err = abs(ours[stat] - value) / scale if scale > 0 else abs(ours[stat] - value)
            worst = max(worst, err)
            compared += 1
    check(worst <= 1e-12, f"summary.json statistics = numpy from seeds.csv: {compared} values, worst "
          f"relative difference {worst:.2e} <= 1e-12")

    # Seeded draw.
    asked = [(c["parameters"]["seed"], c["parameters"]["steps"], c["parameters"]["mesh"]) for c in children.values()]
    check(asked == [(s, 150, "meshes/sleeve-coarse.msh") for s in seeds],
          f"each child ran the seed, steps and mesh asked for: {asked}")
    t0_means = [c["T0_local_mean"] for c in children.values()]
    check(len(set(table["T0_local_std_K"])) == SEEDS and len(set(t0_means)) == SEEDS,
          f"{SEEDS} seeds, {SEEDS} different T0 samples: std {[round(x, 4) for x in table['T0_local_std_K']]} K, "
          f"mean {[round(x, 4) for x in t0_means]} K")
    check(len(set(table["node_peak_over_final_max"])) == SEEDS,
          f"{SEEDS} different node peak ratios: {[round(x, 4) for x in table['node_peak_over_final_max']]}")
    final_spread = (max(table["final_pressure_mean_Pa"]) - min(table["final_pressure_mean_Pa"])) / \
        table["final_pressure_mean_Pa"][0]
    print(f"info final pressure over the seeds: {np.mean(table['final_pressure_mean_Pa']) / 1e6:.6f} MPa, "
          f"relative spread {final_spread:.1e} (all austenite: the draw no longer acts); peak / final "
          f"{min(table['peak_over_final']):.12f} to {max(table['peak_over_final']):.12f}")

    # The histogram is drawn from these files.
    plot = subprocess.run(["/usr/bin/python3", "tools/plot/plot_ensemble.py", mpi["out"]], cwd=ROOT,
                          capture_output=True, text=True)
    png = os.path.join(mpi["out"], "histogram.png")
    check(plot.returncode == 0 and os.path.getsize(png) > 10000 if os.path.isfile(png) else False,
          f"tools/plot/plot_ensemble.py draws histogram.png (exit {plot.returncode})")

    # A failing child: seed 2's FreeFEM is killed while it runs (a crash), in a folder that holds
    # an earlier ensemble's results (its manifest lists them: they go, nothing is refused). The
    # children run 3000 steps (the last -steps wins), long enough to be caught running.
    out = os.path.join(TEST_RESULTS, "ensemble-failure")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with open(os.path.join(out, ".sma-results"), "w") as f:
        f.write("sma-results manifest 1\nscene sleeve-random-ensemble\nseeds.csv\n")
    with open(os.path.join(out, "seeds.csv"), "w") as f:
        f.write("an earlier ensemble's table\n")
    victim = f"FreeFem.* -seed 2 .*{out}/seed-2"
    longer = [*COMMON[:COMMON.index("-steps")], "-steps", "3000", *COMMON[COMMON.index("-steps") + 2:]]  # (not twice)
    driver = subprocess.Popen(["ff-mpirun", "-np", "2", DRIVER, "-v", "0", *longer, "-out", out],
                              cwd=ROOT, env=environment(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    killed, deadline = False, time.time() + 120
    while not killed and driver.poll() is None and time.time() < deadline:
        found = subprocess.run(["pgrep", "-f", victim], capture_output=True, text=True).stdout.split()
        for pid in found:
            os.kill(int(pid), signal.SIGKILL)
            killed = True
        time.sleep(0.01)
    stdout, stderr = driver.communicate(timeout=300)
    proc = subprocess.CompletedProcess(driver.args, driver.returncode, stdout, stderr)
    check(killed, "seed 2's FreeFEM was caught running and killed")
    blamed = [s for s in seeds if f"seed {s} (rank" in proc.stderr]
    print("\n".join(line for line in proc.stderr.splitlines() if "error" in line))
    check(proc.returncode != 0 and blamed == [2] and "seed 2 (rank 1) failed" in proc.stderr
          and os.path.join(out, "seed-2.log") in proc.stderr,
          f"a failing child (seed 2, rank 1): exit {proc.returncode}, seeds blamed {blamed}, its log named")
    report = os.path.join(out, "failed.txt")
    check(os.path.isfile(report) and "seed 2 (rank 1) failed" in open(report).read(),
          "the failure report is kept in failed.txt")
    leftovers = [f for f in ("seeds.csv", "summary.json") if os.path.exists(os.path.join(out, f))]
    check(not leftovers, f"no ensemble result written after the failure (found: {leftovers or 'none'})")
    # A child stopped by a signal (a job manager's TERM, a Ctrl-C that reaches the seeds' runs): the
    # ensemble is being stopped, not a seed that failed: its rank stops at once, naming the seed and
    # the signal, and starts no other seed (it went on to seed 4, a seed or two more ran before
    # mpiexec's kill).
    out = os.path.join(TEST_RESULTS, "ensemble-stopped")
    shutil.rmtree(out, ignore_errors=True)
    driver = subprocess.Popen(["ff-mpirun", "-np", "2", DRIVER, "-v", "0", *longer, "-out", out],
                              cwd=ROOT, env=environment(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    victim = f"FreeFem.* -seed 2 .*{out}/seed-2"
    stopped, deadline = False, time.time() + 120
    while not stopped and driver.poll() is None and time.time() < deadline:
        for pid in subprocess.run(["pgrep", "-f", victim], capture_output=True, text=True).stdout.split():
            os.kill(int(pid), signal.SIGTERM)
            stopped = True
        time.sleep(0.01)
    stdout, stderr = driver.communicate(timeout=300)
    said = [ln for ln in (stdout + stderr).splitlines() if "stopped by a signal" in ln]
    started = sorted(int(n[len("seed-"):-len(".log")]) for n in os.listdir(out) if n.endswith(".log"))
    check(stopped and driver.returncode != 0 and said and "seed 2's run was stopped by a signal (exit 143)" in said[0]
          and 4 not in started and not os.path.exists(os.path.join(out, "summary.json")),
          f"seed 2's run stopped by TERM: exit {driver.returncode}, said {said[:1]}, seeds started {started} "
          "(not 4: its rank started no other seed), nothing published")
    # Counts beyond reason refused up front, naming the option (-seeds 1e9 segfaulted both ranks
    # allocating the per-seed table; -seed0 2147483647 -seeds 2 failed after its first seed)
    for extra, said in ((["-seeds", "1000000000"], "-seeds 1000000000 must be in [1, 999999]"),
                        (["-seed0", "2147483647", "-seeds", "2"], "the seeds must be in [0, 2147483647]")):
        bad = subprocess.run(["ff-mpirun", "-np", "2", DRIVER, "-v", "0", *extra, "-out",
                              os.path.join(TEST_RESULTS, "ensemble-mpi-bad-seeds")], cwd=ROOT, env=environment(),
                             capture_output=True, text=True, timeout=120)
        check(bad.returncode != 0 and said in bad.stdout + bad.stderr,
              f"{' '.join(extra)}: refused up front ({said!r}: exit {bad.returncode})")

    record("ensemble_mpi", {
        "test": "ensemble_mpi", "mesh": "meshes/sleeve-coarse.msh", "steps": 150, "seeds": seeds,
        "ranks_mpi": ranks, "values_identical_mpi_serial": same, "histories_identical": histories,
        "statistics_worst_relative_difference": worst, "ring_inner_radius": Ri,
        "peak_pressure_mean_Pa": table["peak_pressure_mean_Pa"],
        "final_pressure_mean_Pa": table["final_pressure_mean_Pa"],
        "node_peak_over_final_max": table["node_peak_over_final_max"],
        "T0_local_std_K": table["T0_local_std_K"], "failure_exit_code": proc.returncode,
        "wall_seconds": {"mpi2": mpi["summary"]["wall_seconds"], "serial": serial["summary"]["wall_seconds"]}})
    finish()


if __name__ == "__main__":
    main()
