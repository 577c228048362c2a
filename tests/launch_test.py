#!/usr/bin/python3
"""How a user starts a run neither hangs it, nor splits it, nor loses its error line.

- Its output's reader goes away: `tools/ff ... | head -1` (the filter of FreeFEM's output died on
  the broken pipe, and the run, its output no longer read, blocked for ever once 64 KB were
  written), and its standard output closed (`>&-`): each run ends on its own and publishes.
- Its standard output sent away: a bad option's `error:` line is on standard error (FreeFEM prints
  a script's cerr on its standard output: with `> /dev/null` the line was lost).
- Its standard input closed (`<&-`): the run goes on (the launcher stopped, "Bad file descriptor").
- A sweep with a relative --out from another folder: its table and its runs in that one folder (the
  runs went under the checkout, the table beside the caller: two halves, exit 0).
- A sweep whose console goes away (`| head -1`) or is full (`> /dev/full`): its runs complete and
  it exits 0 (a failed print stopped the runs and was reported as "writing its results failed").
- A TERM as a run ends, after it published its results: its line says the results are whole (it
  said "nothing published ... continues with -resume 1", the checkpoint gone).
- On MPI ranks, a rank killed outright is said (the launcher exited 137 without a word), and the
  launcher killed outright takes mpiexec and the ranks with it (they ran on to their end).
- A plot tool interrupted (INT) while it starts: it ends by the signal, without a traceback.
Writes results/checks/launch.json.
"""
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

FF = os.path.join(ROOT, "tools", "ff")
PYTHON = "/usr/bin/python3"
# A run that prints a line a step, about 200 KB, more than a pipe holds.
CHATTY = [FF, "edp/scenes/sleeve-circular.edp", "-mesh", "meshes/sleeve-coarse.msh", "-tol", "0", "-steps", "3000",
          "-progressevery", "0", "-meshestimate", "0"]


def shell(command, cwd=ROOT, timeout=180):
    """(exit code of the shell line, stdout, stderr, seconds); exit None when it did not end in time."""
    start = time.time()
    try:
        p = subprocess.run(["bash", "-c", command], cwd=cwd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.time() - start
    except subprocess.TimeoutExpired:
        subprocess.run(["pkill", "-f", "sma-launch-test"], capture_output=True)
        return None, "", "", time.time() - start


def published(out):
    return os.path.isfile(os.path.join(out, "summary.json"))


def main():
    measured = {}
    with tempfile.TemporaryDirectory(prefix="sma-launch-test-") as tmp:
        words = " ".join(f"'{w}'" for w in CHATTY)
        for name, tail in (("| head -1", "| head -1; exit ${PIPESTATUS[0]}"), (">&-", ">&-")):
            out = os.path.join(tmp, "chatty-" + str(len(measured)))
            code, _, _, seconds = shell(f"{words} -out {out} {tail}")
            check(code == 0 and published(out), f"its output {name}: the run ends (exit {code}, {seconds:.1f} s) and "
                  f"publishes ({published(out)})")
            measured[name] = {"exit": code, "seconds": round(seconds, 1), "published": published(out)}

        code, out, err, _ = shell(f"'{FF}' edp/scenes/sleeve-radial.edp -stpes 3 -out {tmp}/bad > /dev/null")
        lines = [ln for ln in err.splitlines() if ln.startswith("error:")]
        check(code == 1 and len(lines) == 1 and "-stpes" in lines[0],
              f"a bad option with its output sent away: exit {code}, its error line on standard error: {lines}")

        run = os.path.join(tmp, "no-stdin")
        code, _, _, _ = shell(f"'{FF}' edp/scenes/sleeve-radial.edp -quiet 1 -out {run} <&-")
        check(code == 0 and published(run), f"standard input closed: exit {code}, published {published(run)}")

        elsewhere = os.path.join(tmp, "elsewhere")
        os.makedirs(elsewhere)
        sweep = f"{PYTHON} '{ROOT}/tools/sweep.py' sleeve-radial g 400 500 --out rel -- -steps 60"
        code, _, _, _ = shell(sweep, cwd=elsewhere)
        inside = sorted(os.listdir(os.path.join(elsewhere, "rel"))) if os.path.isdir(os.path.join(elsewhere, "rel")) else []
        stray = os.path.exists(os.path.join(ROOT, "rel"))
        check(code == 0 and {"g=400", "g=500", "table.csv", "sweep.json"} <= set(inside) and not stray,
              f"a sweep with a relative --out from another folder: exit {code}, its folder holds {inside}, "
              f"nothing under the checkout ({'rel/ FOUND' if stray else 'none'})")

        for name, tail in (("| head -1", "| head -1; exit ${PIPESTATUS[0]}"), ("> /dev/full", "> /dev/full")):
            out = os.path.join(tmp, "sweep-" + name.split()[-1].strip("-/"))
            code, _, err, _ = shell(f"{PYTHON} '{ROOT}/tools/sweep.py' sleeve-radial g 400 500 --out {out} -- -steps 60 {tail}")
            runs = [published(os.path.join(out, f"g={g}")) for g in (400, 500)]
            check(code == 0 and all(runs) and os.path.isfile(os.path.join(out, "table.csv")),
                  f"a sweep whose console {name}: exit {code}, runs published {runs}, table "
                  f"{os.path.isfile(os.path.join(out, 'table.csv'))} {err.strip()[-200:]}")

        # A TERM as the run ends, after it published its results: whatever the moment, the line never
        # says "nothing published" of a folder that holds the run's summary.json (it did, and that
        # -resume 1 continues a run whose checkpoint was gone). Three tries, each TERM sent as soon
        # as summary.json appears (a window of about 10 ms: a try that misses it ends with exit 0).
        told = []
        for k in range(3):
            out = os.path.join(tmp, f"ending-{k}")
            run_end = subprocess.Popen([FF, "edp/scenes/sleeve-circular.edp", "-mesh", "meshes/sleeve-coarse.msh",
                                        "-steps", "20000", "-quiet", "1", "-checkpoint", "5000", "-meshestimate", "0",
                                        "-out", out], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            deadline = time.time() + 120
            while not published(out) and run_end.poll() is None and time.time() < deadline:
                time.sleep(0.001)
            run_end.send_signal(signal.SIGTERM)
            _, err = run_end.communicate(timeout=60)
            line = [ln for ln in err.splitlines() if ln.startswith("error:")]
            told.append((run_end.returncode, line[0][:160] if line else ""))
            check(published(out) and (run_end.returncode == 0 or (line and "after its run had completed" in line[0]
                                                                  and "nothing published" not in line[0])),
                  f"TERM as the run ends ({k + 1}): exit {run_end.returncode}, summary.json {published(out)}, "
                  f"said {line[:1]}")
        measured["term_as_it_ends"] = told

        # On MPI ranks: a rank killed outright is said (tools/ff-mpi exited 137 without a word), and
        # the launcher killed outright takes mpiexec and its ranks with it (they ran on to their end).
        env = dict(os.environ, SMA_ROOT=ROOT)
        mpi = [os.path.join(ROOT, "tools", "ff-mpi"), "2", "edp/mpi/sleeve-3d.edp", "-nr", "2", "-nt", "4", "-nz", "4",
               "-steps", "20000", "-tol", "0", "-quiet", "1", "-meshestimate", "0"]
        for who in ("a rank", "the launcher"):
            out = os.path.join(tmp, "mpi-" + who.split()[-1])
            job = subprocess.Popen(mpi + ["-out", out], cwd=ROOT, env=env, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, start_new_session=True)
            pattern = "FreeFem[+][+]-mpi .*-out " + out if who == "a rank" else "tools/ff-mpi 2 .*-out " + out
            deadline, victims = time.time() + 60, []
            while not victims and job.poll() is None and time.time() < deadline:
                time.sleep(0.5 if not os.path.isdir(out) else 1.0)
                victims = subprocess.run(["pgrep", "-f", pattern], capture_output=True, text=True).stdout.split()
            if victims:
                os.kill(int(victims[0]), signal.SIGKILL)
            _, err = job.communicate(timeout=60)
            time.sleep(2)
            left = subprocess.run(["pgrep", "-f", "-out " + out], capture_output=True, text=True).stdout.split()
            lines = [ln for ln in err.splitlines() if ln.startswith("error:")]
            said = who == "the launcher" or (lines and "a rank died of signal SIGKILL" in lines[0])
            check(bool(victims) and said and not left,
                  f"sleeve-3d on 2 ranks, {who} killed outright: {'said ' + str(lines[:1]) if who == 'a rank' else ''} "
                  f"processes left running: {len(left)}")
            for pid in left:
                os.kill(int(pid), signal.SIGKILL)

        # the plot tool started, then interrupted while it imports its libraries
        plot = subprocess.Popen([PYTHON, os.path.join(ROOT, "tools", "plot", "plot_sleeve-radial.py"), run],
                                cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(0.2)
        plot.send_signal(signal.SIGINT)
        _, err = plot.communicate(timeout=60)
        check(plot.returncode in (-signal.SIGINT, 0) and "Traceback" not in err,
              f"a plot tool interrupted as it starts: ends by the signal ({plot.returncode}), no traceback "
              f"({'TRACEBACK' if 'Traceback' in err else 'none'})")
    record("launch", {"test": "launch", **measured})
    finish()


if __name__ == "__main__":
    main()
