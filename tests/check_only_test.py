#!/usr/bin/python3
"""Check-only mode (-checkonly 1, edp/lib/errors.idp): every script of edp/scenes and edp/variants
checks its command line and stops where a run would take its results folder, touching nothing.

For each script, with its default options and -checkonly 1, into a folder holding what a finished
earlier run leaves (a manifest listing a summary.json, and that file), asserts: exit 0; the line
"<script>: options checked (-checkonly 1): a run would write <folder>"; the folder afterwards
holding exactly those two files, byte for byte (no lock, no partial file: nothing of the script
comes before its claim of the folder). Then that a bad option still fails with its message in
this mode (sleeve-radial -g -5, exit 1), that -checkonly takes only 1 or 0 (0: a run), and that
tools/ff drops FreeFEM's exit trailer after the check. make ensemble and the sweeps rely on this (they check their runs so before taking their own folder).
Records results/checks/check_only.json.
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

EARLIER = '{"scene": "an earlier run"}\n'
MANIFEST = "sma-results manifest 1\nscene sleeve-circular\nsummary.json\n"


def plant(out):
    os.makedirs(out, exist_ok=True)
    for name in os.listdir(out):
        os.remove(os.path.join(out, name))
    for name, text in ((".sma-results", MANIFEST), ("summary.json", EARLIER)):
        with open(os.path.join(out, name), "w") as f:
            f.write(text)


def untouched(out):
    names = sorted(os.listdir(out))
    texts = [open(os.path.join(out, n)).read() for n in names]
    return names == [".sma-results", "summary.json"] and texts == [MANIFEST, EARLIER]


def ff(script, *args):
    return subprocess.run([os.path.join(ROOT, "tools", "ff"), script, *args], cwd=ROOT, capture_output=True,
                          text=True)


def main():
    scripts = [os.path.join(folder, name) for folder in ("edp/scenes", "edp/variants")
               for name in sorted(os.listdir(os.path.join(ROOT, folder))) if name.endswith(".edp")]
    figures = {}
    with tempfile.TemporaryDirectory(prefix="check-only-") as tmp:
        out = os.path.join(tmp, "out")
        for script in scripts:
            name = os.path.basename(script)[:-4]
            plant(out)
            run = ff(script, "-checkonly", "1", "-out", out)
            said = run.stdout + run.stderr
            line = f"{name}: options checked (-checkonly 1): a run would write {out}"
            kept = untouched(out)
            check(run.returncode == 0 and line in said and kept,
                  f"{name} -checkonly 1: exit {run.returncode}, {'says' if line in said else 'does NOT say'} "
                  f"'options checked', the earlier run's folder {'untouched' if kept else 'CHANGED'}"
                  + ("" if run.returncode == 0 else f": {said.strip()[-200:]}"))
            figures[name] = run.returncode
        plant(out)
        bad = ff("edp/scenes/sleeve-radial.edp", "-checkonly", "1", "-g", "-5", "-out", out)
        said = bad.stdout + bad.stderr
        check(bad.returncode == 1 and "error: sleeve-radial: -g -5 must be in [0, 1e15]" in said and untouched(out),
              f"a bad option in check-only mode fails as in a run: exit {bad.returncode}")
        two = ff("edp/scenes/sleeve-radial.edp", "-checkonly", "2", "-out", out)
        check(two.returncode == 1 and "error: -checkonly '2' must be 1" in two.stdout + two.stderr,
              f"-checkonly 2 is refused: exit {two.returncode}")
        # -checkonly 0 is a run, as without the option (and tools/ff keeps its output streaming)
        zero = ff("edp/scenes/sleeve-radial.edp", "-checkonly", "0", "-steps", "3", "-out", out + "-run")
        check(zero.returncode == 0 and os.path.exists(os.path.join(out + "-run", "summary.json")),
              f"-checkonly 0 runs the scene: exit {zero.returncode}")
        # the exit trailer FreeFEM prints after exit(0) is not shown (tools/ff drops it, as for -help)
        quiet = ff("edp/scenes/sleeve-radial.edp", "-checkonly", "1", "-out", out)
        check("err code 0" not in quiet.stdout + quiet.stderr and "current line" not in quiet.stdout + quiet.stderr,
              "-checkonly 1's output ends with the script's line (no FreeFEM exit trailer)")
    record("check_only", {"scripts": len(figures), "exit_codes": figures})
    finish()


if __name__ == "__main__":
    main()
