#!/usr/bin/python3
"""tools/ff's scratch folder (the FIFO between FreeFEM and its output filter, $TMPDIR/sma-ff.XXXXXX)
does not outlive its run, even when the run is killed outright.

In a private TMPDIR:
  - a run that ends normally leaves no folder;
  - a tools/ff killed with SIGKILL while FreeFEM runs (no trap sees KILL; tests/signals_test.py's
    make ensemble cases left such a folder, one a run, its cause not traced) leaves its folder, and
    the next run removes it: its owner, the pid written in it, is gone;
  - that next run keeps a folder whose owner is alive (a run in progress) and one without an owner
    (not a tools/ff folder of this version).
Writes results/checks/ff_scratch.json.
"""
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402


def folders(tmp):
    return sorted(n for n in os.listdir(tmp) if n.startswith("sma-ff."))


def main():
    data = {}
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, TMPDIR=tmp)
        quick = os.path.join(tmp, "quick.edp")
        with open(quick, "w") as f:
            f.write("cout << 1 << endl;\n")
        slow = os.path.join(tmp, "slow.edp")
        with open(slow, "w") as f:
            f.write("real s = 0; for (int i = 0; i < 200000000; ++i) s += i; cout << s << endl;\n")
        ff = os.path.join(ROOT, "tools", "ff")
        done = subprocess.run([ff, quick], cwd=ROOT, env=env, capture_output=True, text=True)
        check(done.returncode == 0 and not folders(tmp), f"a run that ends leaves no folder (exit {done.returncode}, "
              f"left {folders(tmp) or 'none'})")
        # killed outright while FreeFEM runs
        proc = subprocess.Popen([ff, slow], cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        until = time.time() + 30
        while not folders(tmp) and time.time() < until:
            time.sleep(0.05)
        time.sleep(0.3)
        killed = folders(tmp)
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        time.sleep(0.5)  # (FreeFEM gets its TERM from the kernel as its parent dies: setpriv --pdeathsig)
        left = folders(tmp)
        # a folder of a live owner, and one with no owner
        live = os.path.join(tmp, "sma-ff.LIVE00")
        os.mkdir(live)
        with open(os.path.join(live, "pid"), "w") as f:
            f.write(f"{os.getpid()}\n")
        os.mkdir(os.path.join(tmp, "sma-ff.NOPID0"))
        again = subprocess.run([ff, quick], cwd=ROOT, env=env, capture_output=True, text=True)
        after = folders(tmp)
        data = {"killed_run_folders": killed, "left_by_kill": left, "after_next_run": after}
        check(len(killed) == 1 and left == killed, f"tools/ff killed outright leaves its folder {killed} (left: {left})")
        check(again.returncode == 0 and after == ["sma-ff.LIVE00", "sma-ff.NOPID0"],
              f"the next run removes it, keeps a live owner's and an ownerless one: {after}")
    record("ff_scratch", data)
    finish()


if __name__ == "__main__":
    main()
