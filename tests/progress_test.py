#!/usr/bin/python3
"""A run's lines reach its reader as FreeFEM writes them, not at the run's end.

The launchers (tools/ff, tools/ff-mpi on 1 rank) pass FreeFEM's output through a filter of its
call trace (tools/launcher-common.sh run_filtered). mawk, Debian's awk, read that output a buffer
at a time: a scene's progress line (one every 5 s, flushed) reached the terminal in bursts or only
when the run ended, and a long run looked hung.

A handshake, not a clock: a probe script prints "first" and flushes, then waits (at most 30 s)
for a marker file that the test makes only once it has read "first", then prints "second". Through
a buffering launcher "first" comes only after the script's wait has run out ("no marker"). Checked
for each launcher: "first" read while the script still runs, then "second", exit 0.
Writes results/checks/progress.json.
"""
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

PROBE = """string marker = ARGV[ARGV.n - 1];
cout << "first" << endl;
cout.flush;
int waited = 0;
while (exec("test -e '" + marker + "'") != 0 && waited < 300) { exec("sleep 0.1"); waited++; }
cout << (waited < 300 ? "second" : "no marker") << endl;
"""
LAUNCHERS = {"tools/ff": [os.path.join(ROOT, "tools", "ff")], "tools/ff-mpi 1": [os.path.join(ROOT, "tools", "ff-mpi"), "1"]}


def handshake(launcher, folder):
    probe, marker = os.path.join(folder, "probe.edp"), os.path.join(folder, "marker")
    with open(probe, "w") as f:
        f.write(PROBE)
    if os.path.exists(marker):
        os.remove(marker)
    start = time.monotonic()
    proc = subprocess.Popen([*launcher, probe, marker], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    lines = []
    for line in proc.stdout:
        lines.append((round(time.monotonic() - start, 2), line.rstrip("\n")))
        if line.strip() == "first":
            open(marker, "w").close()
    rc = proc.wait(timeout=120)
    return rc, lines


def main():
    figures = {}
    with tempfile.TemporaryDirectory(prefix="sma-progress-") as folder:
        for name, launcher in LAUNCHERS.items():
            rc, lines = handshake(launcher, folder)
            figures[name] = {"exit": rc, "lines": lines}
            said = [text for _, text in lines]
            check(rc == 0 and "first" in said and "second" in said and "no marker" not in said,
                  f"{name}: the probe's first line read while it ran (it then saw the marker and said 'second'): "
                  f"exit {rc}, lines {lines}")
    record("progress", figures)
    finish()


if __name__ == "__main__":
    main()
