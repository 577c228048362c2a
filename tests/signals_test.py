#!/usr/bin/python3
"""Every entry point ends on a signal, its children with it, says so, and publishes nothing.

Each entry point (make run, make sweep, make ensemble, tools/ff, sma.run and sma.sweep from a
Python script; and tools/ff with -meshestimate 1 and with its default companion (under coreutils'
timeout, in a process group of its own), signalled while the scene's own child, its mesh-error
companion, runs) starts a long run (sleeve-circular, 100000 steps) as the leader of its own session
and process group, as a shell starts a command. Once a FreeFEM process of that session runs it is
sent, in turn:
  - TERM to the leader alone (a job manager's `kill`, a closed batch job): the leader must pass it on;
  - INT to the whole group (Ctrl-C at a terminal: every process of the group gets it at once);
and for tools/ff also INT to the FreeFEM process alone (it ran on, INT ignored, and published).
Checked for each: the leader ends within a minute (it hung for ever, waiting on itself, in
tools/run_scene.py's handler), with a non-zero exit and a line saying it was stopped; no process
of its session is left once it has ended; the run's folder holds no summary.json.
"""
import os
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, TEST_RESULTS, check, finish, record  # noqa: E402

LONG = ["-steps", "100000", "-quiet", "1"]
PYTHON = "/usr/bin/python3"


def session_processes(sid):
    """{pid: command name} of the processes of session sid (from /proc/<pid>/stat)."""
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                stat = f.read()
        except OSError:
            continue
        name = stat[stat.index("(") + 1:stat.rindex(")")]
        fields = stat[stat.rindex(")") + 2:].split()  # state ppid pgrp session ...
        if int(fields[3]) == sid and fields[0] != "Z":
            found[int(entry)] = name
    return found


def entry_points(tmp):
    """(name, argv, output folder) of each entry point, each running a long sleeve-circular."""
    sma = (f"import sys; sys.path.insert(0, {os.path.join(ROOT, 'python')!r}); import sma; ")
    points = []
    for name, out, argv in (
            ("make run", "make-run", ["make", "--no-print-directory", "run", "SCENE=sleeve-circular",
                                      "ARGS=" + " ".join(LONG) + " -out {out}"]),
            ("make sweep", "make-sweep", ["make", "--no-print-directory", "sweep", "SCENE=sleeve-circular",
                                          "PARAM=g", "VALUES=400 500", "ARGS=" + " ".join(LONG), "OUT={out}"]),
            ("make ensemble", "make-ensemble", ["make", "--no-print-directory", "ensemble", "NP=1", "SEEDS=2",
                                                "ARGS=-steps 100000", "OUT={out}"]),
            ("tools/ff", "ff", [os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", *LONG,
                                "-out", "{out}"]),
            # the signal arrives while the run's own child, its mesh-error companion, runs
            ("tools/ff -meshestimate 1", "ff-meshestimate",
             [os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", "-steps", "20000", "-quiet", "1",
              "-meshestimate", "1", "-out", "{out}"]),
            # the same with the default companion (-meshestimate not given), which runs under coreutils'
            # timeout (its budget) in a process group of its own: a Ctrl-C to the run's group reaches
            # the scene alone, and the companion must still end with it
            ("tools/ff, its default companion", "ff-default-companion",
             [os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-circular.edp", "-steps", "20000", "-quiet", "1",
              "-out", "{out}"]),
            ("sma.run", "sma-run", [PYTHON, "-c", sma + "sma.run('sleeve-circular', {out!r}, steps=100000, quiet=1)"]),
            ("sma.sweep", "sma-sweep", [PYTHON, "-c", sma + "sma.sweep('sleeve-circular', {{'g': [400, 500]}}, "
                                        "fixed={{'steps': 100000, 'quiet': 1}}, out={out!r})"])):
        points.append((name, out, argv))
    return points


def published(out):
    """The summary.json files under out (a run's publication), if any."""
    found = []
    for folder, _, files in os.walk(out):
        found += [os.path.join(folder, f) for f in files if f == "summary.json"]
    return found


def stop(name, argv, out, how, processes=1):
    """Starts argv in its own session, signals it as `how` says once `processes` FreeFEM processes
    run (2: a scene and its child); "INT to FreeFEM alone" goes to the first (the scene); returns
    the measured facts."""
    leader = subprocess.Popen(argv, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                              start_new_session=True)
    deadline = time.time() + 120
    freefem = []
    while time.time() < deadline and leader.poll() is None:
        freefem = sorted(p for p, n in session_processes(leader.pid).items() if n.startswith("FreeFem++"))
        if len(freefem) >= processes:
            break
        time.sleep(0.1)
    time.sleep(0.5)  # FreeFEM past its start, into the run
    if how == "TERM to the leader":
        os.kill(leader.pid, signal.SIGTERM)
    elif how == "INT to the group":
        os.killpg(leader.pid, signal.SIGINT)
    else:  # INT to FreeFEM alone (the scene, the oldest: not its child)
        os.kill(freefem[0], signal.SIGINT)
    try:
        _, err = leader.communicate(timeout=60)
        ended = True
    except subprocess.TimeoutExpired:
        ended = False
    # The leader's end is not its children's: give them the leader's own grace (10 s) to go.
    left = session_processes(leader.pid)
    until = time.time() + 15
    while left and time.time() < until:
        time.sleep(0.2)
        left = session_processes(leader.pid)
    if not ended:
        left[leader.pid] = "the entry point"
    cleanup = dict(left)
    while cleanup:  # cleaned up for the next case (then reported): a killed parent's child may start
        for pid in cleanup:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.2)
        cleanup = session_processes(leader.pid)
    if not ended:
        _, err = leader.communicate()
    said = [ln for ln in err.splitlines() if "signal" in ln or "interrupted" in ln or "Interrupt" in ln]
    return {"freefem_started": bool(freefem), "ended": ended, "exit": leader.returncode, "left": sorted(left.values()),
            "said": said[-1] if said else "", "published": published(out)}


def main():
    tmp = os.path.join(TEST_RESULTS, "signals")
    subprocess.run(["rm", "-rf", tmp], check=True)
    os.makedirs(tmp)
    measured = {}
    only = sys.argv[1:]
    for name, folder, argv in entry_points(tmp):
        if only and name not in only:
            continue
        ways = ["TERM to the leader", "INT to the group"] + (["INT to FreeFEM alone"] if name == "tools/ff" else [])
        if name == "tools/ff -meshestimate 1":
            ways = ["TERM to the leader", "INT to FreeFEM alone"]
        if name == "tools/ff, its default companion":
            ways = ["TERM to the leader", "INT to the group", "INT to FreeFEM alone"]
        for how in ways:
            out = os.path.join(tmp, f"{folder}-{how.split()[0].lower()}-{how.split()[-1]}")
            words = [w.format(out=out) for w in argv]
            m = stop(name, words, out, how, 2 if "-meshestimate" in name or "companion" in name else 1)
            measured[f"{name}: {how}"] = m
            check(m["freefem_started"] and m["ended"] and m["exit"] not in (0, None) and not m["left"]
                  and m["said"] and not m["published"],
                  f"{name}, {how}: FreeFEM started {m['freefem_started']}, ended {m['ended']} with exit {m['exit']}, "
                  f"left running {m['left'] or 'nothing'}, said '{m['said'][:120]}', published {m['published'] or 'nothing'}")
    record("signals", {"cases": measured})
    finish()


if __name__ == "__main__":
    main()
