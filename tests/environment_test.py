#!/usr/bin/python3
"""A user's environment neither moves a run nor loses it: CDPATH, a relative TMPDIR, make run's OUT.

- CDPATH naming a folder that holds tools/ and edp/ (a `cd tools/..` then goes there and prints
  it: tools/ff's root was two lines and the run failed on a plugin "not built"; .ci/run would have
  tested another checkout): tools/ff, tools/ff-mpi and make run from the repository root run as
  without it, their fields byte-identical to a plain run's;
- make run's OUT=dir names the results folder (it was ignored: the results went to
  results/<scene>@... without a word), alone and with ARGS;
- a relative TMPDIR is made absolute by the launcher: the plugin's TemporaryDirectory (which follows
  only an absolute TMPDIR) makes its folder there;
- make clean (the Makefile run in a scratch copy) removes what the build made and keeps results/, a
  run's folder and a user's file in it (it removed results/ whole).
A TMPDIR that is not a directory is a bad input of docs/errors.md (tests/bad_inputs_test.py).
Writes results/checks/environment.json.
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

SCENE = ["edp/scenes/sleeve-radial.edp", "-steps", "5", "-quiet", "1"]


def run(command, env=None, cwd=ROOT):
    """The command's (exit code, stdout + stderr), from `cwd`."""
    p = subprocess.run(command, cwd=cwd, env=dict(os.environ, **(env or {})), capture_output=True, text=True,
                       timeout=300)
    return p.returncode, p.stdout + p.stderr


def same_fields(a, b):
    """The final fields of two sleeve-radial runs, byte for byte."""
    paths = [os.path.join(d, "fields-final.csv") for d in (a, b)]
    return all(os.path.exists(p) for p in paths) and open(paths[0]).read() == open(paths[1]).read()


def main():
    scratch = tempfile.mkdtemp(prefix="environment-")
    base = {k: v for k, v in os.environ.items()
            if k not in ("CDPATH", "TMPDIR", "OUT", "ARGS", "MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    try:
        plain = os.path.join(scratch, "plain")
        code, out = run(["tools/ff", *SCENE, "-out", plain])
        check(code == 0, f"a plain run: exit {code}")

        # A folder that looks like a checkout to `cd tools/..` and `cd edp/..`.
        lure = os.path.join(scratch, "lure")
        for sub in ("tools", "edp", ".ci"):
            os.makedirs(os.path.join(lure, sub))
        cdpath = dict(CDPATH=lure)
        ff = os.path.join(scratch, "ff")
        code, out = run(["tools/ff", *SCENE, "-out", ff], env=cdpath)
        check(code == 0 and same_fields(plain, ff),
              f"tools/ff under CDPATH={lure}: exit {code}, fields identical to the plain run's: "
              f"{same_fields(plain, ff)} {out.strip()[-200:] if code else ''}")
        code, out = run(["tools/ff-mpi", "1", "edp/mpi/sleeve-3d.edp", "-help"], env=cdpath)
        check(code == 0 and "-ddmtol" in out, f"tools/ff-mpi under CDPATH: -help exit {code}, lists -ddmtol")

        env = dict(base, CDPATH=lure)
        made = os.path.join(scratch, "made")
        p = subprocess.run(["make", "--no-print-directory", "run", "SCENE=sleeve-radial", "ARGS=-steps 5",
                            f"OUT={made}"], cwd=ROOT, env=env, capture_output=True, text=True, timeout=300)
        check(p.returncode == 0 and same_fields(plain, made)
              and os.path.exists(os.path.join(made, "force-temperature.png")),
              f"make run under CDPATH with OUT=dir and ARGS: exit {p.returncode}, its fields and figure in OUT "
              f"{(p.stdout + p.stderr).strip()[-200:] if p.returncode else ''}")
        alone = os.path.join(scratch, "alone")
        p = subprocess.run(["make", "--no-print-directory", "run", "SCENE=ring-lame", f"OUT={alone}"], cwd=ROOT,
                           env=base, capture_output=True, text=True, timeout=300)
        check(p.returncode == 0 and os.path.exists(os.path.join(alone, "summary.json")),
              f"make run with OUT=dir alone: exit {p.returncode}, summary.json in OUT")

        # A relative TMPDIR, from the repository root: the plugin's scratch folder under its absolute path.
        relative = os.path.relpath(os.path.join(scratch, "tmp"), ROOT)
        os.makedirs(os.path.join(scratch, "tmp"))
        probe = os.path.join(scratch, "probe.edp")
        with open(probe, "w") as f:
            f.write('load "sma"\nstring d = TemporaryDirectory("probe-");\ncout << "dir " << d << endl;\n')
        code, out = run(["tools/ff", probe], env=dict(TMPDIR=relative))
        folder = [ln.split(" ", 1)[1] for ln in out.splitlines() if ln.startswith("dir ")]
        inside = bool(folder) and folder[0].startswith(os.path.join(scratch, "tmp") + "/probe-")
        check(code == 0 and inside, f"TMPDIR={relative} (relative): the plugin's folder {folder} under "
              f"{os.path.join(scratch, 'tmp')}")

        # make clean in a copy holding the build's products and results: only the former go.
        copy = os.path.join(scratch, "clean")
        for folder in ("build", "plugin/build", "meshes", "results/sleeve-radial"):
            os.makedirs(os.path.join(copy, folder))
        shutil.copy(os.path.join(ROOT, "Makefile"), copy)
        shutil.copy(os.path.join(ROOT, "meshes", "sleeve-geometry.txt"), os.path.join(copy, "meshes"))
        made = ["build/CMakeCache.txt", "plugin/build/sma.so", "meshes/sleeve.msh"]
        kept = ["meshes/sleeve-geometry.txt", "results/sleeve-radial/summary.json", "results/notes.txt"]
        for name in made + kept:
            open(os.path.join(copy, name), "w").close()
        code, out = run(["make", "--no-print-directory", "clean"], cwd=copy)
        gone = [n for n in made if not os.path.exists(os.path.join(copy, n))]
        still = [n for n in kept if os.path.exists(os.path.join(copy, n))]
        check(code == 0 and gone == made and still == kept and "results/ kept" in out,
              f"make clean: exit {code}, removed {gone} (the build's {made}), kept {still} (of {kept})")
        record("environment", {"test": "environment", "lure": lure, "relative_tmpdir": relative})
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
