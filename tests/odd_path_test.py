#!/usr/bin/python3
"""The checkout works under a path no shell may see: a folder whose name holds a space, both
quotes, `$(...)` command syntax, a backquote and UTF-8. The tracked files of this working tree are
copied there, with this checkout's built plugin objects but one unit's (load.cpp, the shortest
compile, 3 s: a compile there is then checked without compiling the other four again, 2 minutes
under ctest; output.cpp, the unit this test compiled before, took 11 s); `make plugin` compiles
that unit and links the plugin there, and `tools/ff` runs a short sleeve-radial there.
Asserts: both exit 0, the unit was compiled there, the run writes its summary.json, and the command
in the name never ran (no file named INJECTED appears, anywhere under the test's folder or in the
build's working folders).
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, TEST_RESULTS, check, finish, record  # noqa: E402

ODD = "odd p'q\"$(touch INJECTED)`touch INJECTED`é"
UNIT = "load"  # (the unit compiled there: plugin/glue/load.cpp)


def main():
    base = os.path.join(TEST_RESULTS, "odd-path")
    shutil.rmtree(base, ignore_errors=True)
    checkout = os.path.join(base, ODD, "repo")
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True).stdout
    for name in filter(None, files.decode().split("\0")):
        src = os.path.join(ROOT, name)
        if not os.path.isfile(src):
            continue  # a file deleted in the working tree
        dst = os.path.join(checkout, name)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copy2(src, dst)
    # The other units' objects as this checkout built them (make test builds them first; their
    # dependency files name sources by relative paths, and copy2 keeps the times make compares).
    built, there = os.path.join(ROOT, "plugin", "build"), os.path.join(checkout, "plugin", "build")
    os.makedirs(there, exist_ok=True)
    for name in os.listdir(built):
        if (name.endswith((".o", ".d")) and not name.startswith(UNIT + ".")) or name == "compile-flags":
            shutil.copy2(os.path.join(built, name), os.path.join(there, name))
    build = subprocess.run(["make", "--no-print-directory", "plugin"], cwd=checkout, capture_output=True, text=True)
    compiled = sorted(set(re.findall(r"compiling plugin/glue/(\w+)\.cpp", build.stdout + build.stderr)))
    check(build.returncode == 0 and os.path.isfile(os.path.join(checkout, "plugin", "build", "sma.so"))
          and UNIT in compiled,
          f"make plugin under {checkout!r}: exit {build.returncode}, compiled {compiled} (want {UNIT} among them)"
          + ("" if build.returncode == 0 else f": {(build.stdout + build.stderr)[-600:]}"))
    out = os.path.join(checkout, "results", "radial")
    run = subprocess.run([os.path.join(checkout, "tools", "ff"), "edp/scenes/sleeve-radial.edp", "-steps", "60",
                          "-nr", "20", "-quiet", "1", "-out", out], cwd=checkout, capture_output=True, text=True)
    check(run.returncode == 0 and os.path.isfile(os.path.join(out, "summary.json")),
          f"tools/ff edp/scenes/sleeve-radial.edp there: exit {run.returncode}"
          + ("" if run.returncode == 0 else f": {(run.stdout + run.stderr)[-600:]}"))
    # The preloads (its out-of-memory guard, its clock) loaded there too: the loader splits
    # LD_PRELOAD at spaces, and named by their paths neither was (40 "cannot be preloaded" lines).
    complaints = [ln for ln in (run.stdout + run.stderr).splitlines() if "cannot be preloaded" in ln]
    check(not complaints, f"the launcher's preloads load under the path with a space ({len(complaints)} loader "
          f"complaints{': ' + complaints[0] if complaints else ''})")
    injected = [os.path.join(d, f) for d, _, fs in os.walk(base) for f in fs if f == "INJECTED"]
    injected += [p for p in (os.path.join(ROOT, "INJECTED"), os.path.join(ROOT, "plugin", "build", "INJECTED"))
                 if os.path.exists(p)]
    check(not injected, f"the command in the folder's name never ran (INJECTED files: {injected})")
    record("odd_path", {"folder": ODD, "make_plugin_exit": build.returncode, "compiled": compiled,
                        "scene_exit": run.returncode,
                        "injected": injected})
    shutil.rmtree(base, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
