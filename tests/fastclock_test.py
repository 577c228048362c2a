#!/usr/bin/python3
"""tools/ff's preloaded clock() (plugin/fastclock.c): it is the one FreeFEM calls, and it changes
no output.

  - A probe script reads FreeFEM's clock() around `exec("sleep 1")`. FreeFEM's own clock() is
    the process CPU time, which a sleeping child does not add to: it advances by < 0.5 s with
    SMA_FASTCLOCK=0. The preloaded one is the elapsed time: it advances by >= 0.9 s. So the
    probe tells which clock() FreeFEM called, on any machine speed.
  - sleeve-circular (coarse mesh, 200 steps) and sleeve-radial (200 steps), with and without the
    preloaded clock(): every output file but summary.json is byte-identical, and summary.json
    differs only in its timings (wall_seconds).
Writes results/checks/fastclock.json.
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

PROBE = """real c0 = clock();
exec("sleep 1");
real c1 = clock();
cout << "clock advance " << c1 - c0 << endl;
"""
# (-meshestimate 0: the companion's summary and log hold its own timings)
CASES = [("sleeve-circular", ["-mesh", "meshes/sleeve-coarse.msh", "-steps", "200", "-meshestimate", "0"]),
         ("sleeve-radial", ["-steps", "200", "-meshestimate", "0"])]
TIMING = ("wall_seconds", "backsolve_floor_seconds_per_step", "loop_over_floor",
          "stiffness_backsolve_seconds", "heat_backsolve_seconds", "backsolves_needed_seconds",
          "loop_over_backsolves_needed", "loop_over_backsolves_needed_transient", "loop_over_backsolves_needed_tail")


def ff(args, fastclock, **kw):
    env = dict(os.environ, SMA_FASTCLOCK="1" if fastclock else "0")
    return subprocess.run([os.path.join(ROOT, "tools", "ff"), *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=300, **kw)


def clock_advance(script, fastclock):
    r = ff([script], fastclock)
    for line in r.stdout.splitlines():
        if line.startswith("clock advance "):
            return float(line.split()[-1])
    raise RuntimeError(f"probe failed (exit {r.returncode}): {r.stdout}{r.stderr}")


def main():
    data = {}
    with tempfile.TemporaryDirectory() as tmp:
        probe = os.path.join(tmp, "probe.edp")
        with open(probe, "w") as f:
            f.write(PROBE)
        fast, stock = clock_advance(probe, True), clock_advance(probe, False)
        data["clock_advance_over_sleep_1s"] = {"preloaded": fast, "stock": stock}
        check(fast >= 0.9, f"preloaded clock() advances by the elapsed time over a 1 s sleep: {fast:.3f} s")
        check(stock < 0.5, f"FreeFEM's own clock() (CPU time) does not count the sleep: {stock:.3f} s")
        # FreeFEM's two hot timers (the statement loop, the sparse product) found in its executable:
        # they read the coarse clock; a script's clock() keeps the fine one.
        env = dict(os.environ, SMA_FASTCLOCK="1", SMA_FASTCLOCK_REPORT="1")
        r = subprocess.run([os.path.join(ROOT, "tools", "ff"), probe], cwd=ROOT, env=env, capture_output=True,
                           text=True, timeout=300)
        found = [line for line in r.stderr.splitlines() if line.startswith("fastclock: ")]
        data["coarse_timers"] = found
        # (one line per process the wrapper starts with the preload: FreeFem++'s is the one with timers)
        check("fastclock: 2 coarse timers" in found,
              f"both of FreeFEM's timers found in FreeFem++ (ListOfInst::operator(), HashMatrix::addMatMul): {found}")
        with open(os.path.join(tmp, "fine.edp"), "w") as f:
            f.write("real c0 = clock();\nreal s = 0;\nfor (int i = 0; i < 20000; ++i) s += i;\n"
                    "real c1 = clock();\ncout << \"clock advance \" << c1 - c0 << endl;\n")
        fine = clock_advance(os.path.join(tmp, "fine.edp"), True)
        data["script_clock_over_20000_statements"] = fine
        check(0 < fine < 0.5, f"a script's clock() still resolves a short loop: {fine * 1e3:.3f} ms")

        for scene, options in CASES:
            outs = {}
            for fastclock in (True, False):
                out = os.path.join(tmp, f"{scene}-{int(fastclock)}")
                r = ff([f"edp/scenes/{scene}.edp", *options, "-quiet", "1", "-out", out], fastclock)
                check(r.returncode == 0, f"{scene} runs with SMA_FASTCLOCK={int(fastclock)} (exit {r.returncode})")
                outs[fastclock] = out
            names = sorted(os.path.relpath(os.path.join(b, n), outs[True])
                           for b, _, ns in os.walk(outs[True]) for n in ns)
            other = sorted(os.path.relpath(os.path.join(b, n), outs[False])
                           for b, _, ns in os.walk(outs[False]) for n in ns)
            check(names == other, f"{scene}: the same {len(names)} files with and without it")
            differ = []
            for name in names:
                if name == "summary.json" or not os.path.exists(os.path.join(outs[False], name)):
                    continue
                with open(os.path.join(outs[True], name), "rb") as a, open(os.path.join(outs[False], name), "rb") as b:
                    if a.read() != b.read():
                        differ.append(name)
            check(not differ, f"{scene}: {len(names) - 1} output files byte-identical"
                  + (f" (differ: {differ})" if differ else ""))
            sa, sb = (json.load(open(os.path.join(outs[k], "summary.json"))) for k in (True, False))
            keys = sorted(k for k in set(sa) | set(sb) if k not in TIMING and sa.get(k) != sb.get(k))
            check(not keys, f"{scene}: summary.json equal but for {TIMING}" + (f" (differ: {keys})" if keys else ""))
            data[scene] = {"files": len(names), "differ": differ, "summary_keys_differ": keys}
    record("fastclock", data)
    finish()


if __name__ == "__main__":
    main()
