#!/usr/bin/python3
"""Hostile values for every option of every scene and variant, classified (a red-team driver).

Not a ctest test (it runs hundreds of FreeFEM processes): run it by hand after a change to the
option checks, and read its table. Usage:

    tests/hostile_options.py [--only NAME ...] [--covered NAME ...] [--timeout 60] [--out FILE.tsv] [--all]

For each script of edp/scenes and edp/variants it lists the options (-help tsv) and runs the script
with the cheapest settings (-steps 2 where the script has -steps) and one option at a time set to a
hostile value: for a real -1, 0, 1e30, -1e30, 1e-300; for an int -1, 0, 2147483647; for a string
a path with a space and quotes, '..', a missing file, the empty string. The words getARGV refuses
for every option alike (nan, inf, a non-number, an empty value, 1e400, 1.5 for an int) are tried on
the first real and the first int option of each script only. An option seen in an earlier script
with the same default and meaning is skipped (the shared parameter blocks), unless --all (a
script that reads an option of the same name itself, ring-lobed's -Rp, says what it means: its
checks are its own); --covered NAME ...
counts the options of those scripts as seen without running them (their -help only), so that
--only a few scripts tries only what those add to the ones covered before.

Each run is classified:
  error-named   exit 1 with an `error:` line naming the option or the value (what the project promises)
  error-vague   exit 1 with an `error:` line that does not name the option
  accepted      exit 0: legitimate, or silently ignored/clamped (read the list: a defect if ignored)
  exec-error    exit 8 (FreeFEM Exec error): a defect unless the message names the option
  late          a failure (exit 1 or 8) after the run had taken the folder (an earlier complete
                run's results moved to previous-run/): before each run the -out folder holds what a
                finished run leaves (a manifest listing a summary.json, that file and the mark
                .sma-complete), as in tests/bad_inputs_test.py; a bad option must be refused before
                the folder is taken
  timeout       no end within --timeout s: a defect if nothing bounds what the value asks for
  crash         any other exit code
Writes a TSV (script, option, value, exit, class, message) and prints the counts per class.
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FF = os.path.join(ROOT, "tools", "ff")

REAL = ["-1", "0", "1e30", "-1e30", "1e-300"]
INT = ["-1", "0", "2147483647"]
STRING = ["a b'c\"d", "..", "/nonexistent/missing.msh", ""]
REAL_WORDS = ["nan", "inf", "abc", "", "1e400"]
INT_WORDS = ["1.5", "abc", "", "99999999999"]


def scripts():
    out = []
    for folder in ("edp/scenes", "edp/variants"):
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            if name.endswith(".edp"):
                out.append(os.path.join(folder, name))
    return out


def options(script):
    run = subprocess.run([FF, script, "-help", "tsv"], cwd=ROOT, capture_output=True, text=True)
    rows = []
    for line in run.stdout.splitlines()[1:]:
        cells = line.split("\t")
        if len(cells) == 4:
            rows.append(cells)
    return rows


def first_error(text):
    for line in text.splitlines():
        if line.startswith("error:") or "Exec error" in line:
            return line.strip()
    return ""


EARLIER = '{"scene": "an earlier run"}\n'


def plant_earlier_run(out):
    """What a finished earlier run leaves in `out`: its manifest, the summary.json it lists and the mark
    of a complete run."""
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    manifest = "sma-results manifest 1\nscene sleeve-circular\nsummary.json\n"
    for name, text in ((".sma-results", manifest), ("summary.json", EARLIER), (".sma-complete", "")):
        with open(os.path.join(out, name), "w") as f:
            f.write(text)


def earlier_run_kept(out):
    summary = os.path.join(out, "summary.json")
    return os.path.isfile(summary) and open(summary).read() == EARLIER


def classify(rc, message, option, value, kept=True):
    if rc is None:
        return "timeout"
    if rc in (1, 8) and not kept:
        return "late"
    if rc == 0:
        return "accepted"
    if rc == 1:  # named: the option, or the value itself (a file's name in "mesh X not found")
        named = option in message or (len(value) > 2 and value in message)
        return "error-named" if named else "error-vague"
    if rc == 8:
        return "exec-error"
    return "crash"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--only", nargs="*", default=[])
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--out", default="/tmp/hostile_options.tsv")
    parser.add_argument("--all", action="store_true")
    parser.add_argument("--covered", nargs="*", default=[])
    args = parser.parse_args()
    seen = set()
    for script in scripts():
        if os.path.basename(script)[:-4] in args.covered:
            seen.update((option, default, meaning) for option, _, default, meaning in options(script))
    counts = {}
    with open(args.out, "w") as table, tempfile.TemporaryDirectory() as tmp:
        table.write("script\toption\tvalue\texit\tclass\tmessage\n")
        for script in scripts():
            name = os.path.basename(script)[:-4]
            if args.only and name not in args.only:
                continue
            rows = options(script)
            names = {r[0] for r in rows}
            base = ["-steps", "2"] if "-steps" in names else []
            if name == "sleeve-life":  # its programme sets the steps: a coarse ring, 1 s steps, 1 cycle
                base = ["-nr", "20", "-dt", "1", "-cycles", "1"]
            if name == "sleeve-life-2d":  # the same on the 2D model's coarse ring
                base = ["-mesh", "meshes/sleeve-coarse.msh", "-dt", "1", "-cycles", "1"]
            words_done = set()
            for option, kind, default, meaning in rows:
                if option == "-out":  # tried by hand in a scratch copy: '..' would be the parent
                    continue
                values = {"real": REAL, "int": INT, "string": STRING}[kind]
                if kind in ("real", "int") and kind not in words_done:
                    values = values + (REAL_WORDS if kind == "real" else INT_WORDS)
                    words_done.add(kind)
                elif not args.all and (option, default, meaning) in seen:
                    continue
                seen.add((option, default, meaning))
                for value in values:
                    if value == default:
                        continue
                    extra = [w for i, w in enumerate(base) if option not in base[i - i % 2:i - i % 2 + 1]]
                    out = os.path.join(tmp, "out")
                    plant_earlier_run(out)
                    cmd = [FF, script, *extra, option, value, "-out", out]
                    # Its own process group: a timeout ends FreeFEM too, not only tools/ff.
                    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                            text=True, start_new_session=True)
                    try:
                        text, _ = proc.communicate(timeout=args.timeout)
                        rc = proc.returncode
                    except subprocess.TimeoutExpired:
                        os.killpg(proc.pid, signal.SIGKILL)
                        proc.communicate()
                        rc, text = None, ""
                    message = first_error(text)
                    kind_seen = classify(rc, message, option, value, earlier_run_kept(out))
                    counts[kind_seen] = counts.get(kind_seen, 0) + 1
                    table.write(f"{name}\t{option}\t{value!r}\t{rc}\t{kind_seen}\t{message[:300]}\n")
                    table.flush()
                    print(f"{name} {option} {value!r}: {kind_seen} {message[:120]}", flush=True)
    print(counts)
    return 0


if __name__ == "__main__":
    sys.exit(main())
