#!/usr/bin/python3
"""An interrupted sweep stops every run, including one whose child was starting (python/sma/children.py).

A KeyboardInterrupt (Ctrl-C to a script's process group, a notebook's stop button) reaches the main
thread while the sweep's worker threads start and await their FreeFEM runs; the sweep's pool then
stops the running children (stop_running). A worker that was starting its child at that moment ran
it to its end and published it (signals_test's sma.sweep case, 1 run in 4 on a loaded machine).
Checked, with `sleep` as the child:
  - a child running in a worker thread is stopped by stop_running within seconds (not its 30 s);
  - after stop_running no child starts: run() returns at once with 128 + SIGINT and nothing runs;
  - a worker that registers its child after stop_running stops it at once (the "late" path);
  - allow_running (a new sweep's pool) lets children run again, to their normal end.
Writes results/checks/children_stop.json.
"""
import os
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, check, finish, record  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "python"))
from sma import children  # noqa: E402


def timed_run(argv, box):
    start = time.monotonic()
    box["result"] = children.run(argv)
    box["seconds"] = time.monotonic() - start


def main():
    measured = {}
    children.allow_running()
    running = {}
    worker = threading.Thread(target=timed_run, args=(["sleep", "30"], running))
    worker.start()
    time.sleep(0.5)
    children.stop_running()
    worker.join(20)
    measured["running_child_stopped_after_s"] = running.get("seconds")
    check(not worker.is_alive() and running["result"].returncode != 0 and running["seconds"] < 15,
          f"a running child stopped by stop_running: exit {running.get('result') and running['result'].returncode} "
          f"after {running.get('seconds')} s (want stopped, well before its 30 s)")
    start = time.monotonic()
    after = children.run(["sleep", "30"])
    took = time.monotonic() - start
    measured["after_stop"] = {"exit": after.returncode, "seconds": took}
    check(after.returncode == 128 + 2 and took < 1, f"after stop_running a run starts nothing: exit {after.returncode} "
          f"in {took:.2f} s (want 130 at once)")
    # The late path: a child registered after stop_running's copy of the running set is stopped at once.
    late = {}
    children.allow_running()
    gate = threading.Event()
    real_popen = children.subprocess.Popen

    class SlowStart(real_popen):  # the child exists, then stop_running comes before it is registered
        def __init__(self, *a, **k):
            super().__init__(*a, **k)
            children.stop_running()
            gate.set()
    children.subprocess.Popen = SlowStart
    try:
        worker = threading.Thread(target=timed_run, args=(["sleep", "30"], late))
        worker.start()
        gate.wait(10)
        worker.join(20)
    finally:
        children.subprocess.Popen = real_popen
    measured["late_child"] = {"exit": late["result"].returncode if "result" in late else None,
                              "seconds": late.get("seconds")}
    check("result" in late and late["result"].returncode != 0 and late["seconds"] < 15,
          f"a child that started as the others were stopped is stopped too: {measured['late_child']}")
    children.allow_running()
    again = children.run(["true"])
    check(again.returncode == 0, f"allow_running: children run again (exit {again.returncode}, want 0)")
    record("children_stop", measured)
    finish()


if __name__ == "__main__":
    main()
