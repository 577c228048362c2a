#!/usr/bin/python3
"""Runs one scene for `make run` / `make ensemble`, then draws its figures from the folder it wrote.

Usage (the Makefile's):
  tools/run_scene.py [--env-args VAR] [--env-out VAR] [--mpi NP --seeds N] SCRIPT DEFAULT_OUT [PLOT COMMAND ...]
    --env-args VAR  the user's ARGS, read from the environment variable VAR (make run: RUN_ARGS)
    --env-out VAR   an output folder the user gave (make run's and make ensemble's OUT), read from VAR: one word
    --mpi NP        run on NP MPI ranks (mpiexec --quiet --oversubscribe -np NP FreeFem++-mpi -nw -ne)
                    instead of tools/ff
    --seeds N       put -v 0 -seeds N before the user's words (make ensemble)
    --ranks NP      run a distributed scene (edp/mpi/*.edp) on NP ranks through tools/ff-mpi
                    (make run SCENE=sleeve-3d NP=2), into DEFAULT_OUT unless the words name a folder
Only the variables named here are read: nothing of the user's environment (a stray RUN_ARGS,
RUN_OUT, a launcher's name) changes what runs unless its name is on this command line.
What the user types reaches this script through the environment, never pasted into a shell
command: it is split like a shell's words (quotes group: -out 'my dir') but nothing in it is ever
run (`;`, `$(...)` and backquotes are characters). The figures are drawn from the folder the run
actually wrote: the last -out among the words (getARGV takes the last), else DEFAULT_OUT; the plot
command gets it as its last argument. With -help among ARGS the script only lists its options and
nothing is drawn. Exit: the run's exit code, else the plot's.
"""
import signal

# A Ctrl-C during the imports ends this tool without a traceback (children.install, below,
# then passes it on to the runs and says so).
signal.signal(signal.SIGINT, signal.SIG_DFL)

import os
import re
import shlex
import shutil
import sys

import children

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def words_of(variable, name):
    """The shell words of the environment variable `variable` (the user's `name`, for the
    messages); exits 2 naming it when its quotes do not close."""
    try:
        return shlex.split(os.environ.get(variable, ""))
    except ValueError as e:
        print(f"error: {name}: {e} (quote each value whole: {name}=\"-out 'my dir'\")", file=sys.stderr)
        sys.exit(2)


def whole_number(text, what, largest, target="make ensemble"):
    """text as a whole number from 1 to largest, written without leading zeros, or exit 2 naming
    the make target's variable `what` ("NP='1;x' ..." a word, never a shell's)."""
    digits = len(str(largest))
    if not re.fullmatch(rf"[1-9][0-9]{{0,{digits - 1}}}", text):
        kind = "MPI ranks" if what == "NP" else "seeds"
        print(f"error: {target}: {what}='{text}' must be a whole number of {kind} from 1 to {largest}",
              file=sys.stderr)
        sys.exit(2)
    return text


def parse(argv):
    """The leading --options of argv (see the docstring), then SCRIPT, DEFAULT_OUT and PLOT."""
    opts = {"env-args": None, "env-out": None, "mpi": None, "seeds": None, "ranks": None}
    while argv and argv[0].startswith("--"):
        name = argv[0][2:]
        if name not in opts or len(argv) < 2:
            print(f"error: tools/run_scene.py: unknown option or missing value: {argv[0]}", file=sys.stderr)
            sys.exit(2)
        opts[name], argv = argv[1], argv[2:]
    return opts, argv


# Options that change how a run reports or where it stops, not what it computes: they do not name
# its folder (the checkpoint's options too, as edp/problems/sleeve/checkpoint.idp leaves them out
# of a checkpoint: a run stopped with -checkpoint 500 -stopafter 900 and continued with -resume 1
# must find its folder).
REPORTING = {"-quiet", "-vtkevery", "-out", "-help", "-checkonly", "-checkpoint", "-resume", "-stopafter"}


def named_folder(default, words):
    """The folder of a run given options that change its results and no -out: DEFAULT@name=value,...
    (results/sleeve-circular@g=1000,steps=300), so that it never replaces the defaults' run (a
    variant and its baseline side by side); None when the words change nothing (or are not pairs:
    the scene names the fault)."""
    if len(words) % 2 or any(not w.startswith("-") for w in words[::2]) or "-out" in words[::2]:
        return None
    named = []
    for name, value in zip(words[::2], words[1::2]):
        if name not in REPORTING:
            text = "".join(c if c.isalnum() or c in ".+-" else "_" for c in value)
            named.append(f"{name[1:]}={text}")
    if not named:
        return None
    suffix = ",".join(named)
    if len(suffix) > 100:  # a folder name stays readable and within the file system's limit
        suffix = suffix[:80] + ",and-" + str(len(named)) + "-options-" + \
            format(sum(ord(c) * (i + 1) for i, c in enumerate(suffix)) % 16**8, "08x")
    return default + "@" + suffix


def output_folder(words, default):
    """The value of the last -out among `words`, or `default`."""
    out = default
    for i, word in enumerate(words[:-1]):
        if word == "-out":
            out = words[i + 1]
    return out


def main(argv):
    opts, argv = parse(argv)
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    script, default_out, plot = argv[0], argv[1], argv[2:]
    launcher = [os.path.join(ROOT, "tools", "ff")]
    fixed = []
    if opts["mpi"] is not None:
        # (--quiet: no banner of mpiexec's after a rank's own error line, as tools/ff-mpi)
        launcher = ["mpiexec", "--quiet", "--oversubscribe", "-np", whole_number(opts["mpi"], "NP", 9999),
                    "FreeFem++-mpi", "-nw", "-ne"]
    if opts["ranks"] is not None:
        # (at most the cores times 8: more ranks than that only wait for each other)
        launcher = [os.path.join(ROOT, "tools", "ff-mpi"),
                    whole_number(opts["ranks"], "NP", 8 * (os.cpu_count() or 1), "make run")]
    if opts["seeds"] is not None:
        fixed = ["-v", "0", "-seeds", whole_number(opts["seeds"], "SEEDS", 999999)]
    # The programs the launcher starts, named before anything runs (mpiexec's own message for a
    # missing FreeFem++-mpi is OpenMPI's, exit 134).
    missing = [w for w in launcher if w in ("mpiexec", "FreeFem++-mpi") and shutil.which(w) is None]
    if missing:
        print(f"error: {missing[0]} is not installed (or not on PATH): run 'make deps' (Debian's freefem++ "
              "and openmpi)", file=sys.stderr)
        return 3
    user = words_of(opts["env-args"], "ARGS") if opts["env-args"] else []
    out_given = os.environ.get(opts["env-out"], "") if opts["env-out"] else None
    if out_given is not None and (not out_given.strip() or out_given.startswith("-")):
        print(f"error: OUT='{out_given}' is not a folder name (empty, or an option)", file=sys.stderr)
        return 2
    words = fixed + (["-out", out_given] if out_given else []) + user
    # No shell ever sees these words, so nothing expands `~`: a folder named ~ would be made here.
    home = [w for w in words if w == "~" or w.startswith("~/")]
    if home:
        print(f"error: '{home[0]}': ~ is not expanded (no shell reads ARGS or OUT): give the folder's full "
              "path, e.g. $HOME/...", file=sys.stderr)
        return 2
    # (OUT given names the folder: make run's OUT=dir as ARGS='-out dir')
    named = None if opts["mpi"] is not None or "-help" in words or out_given is not None \
        else named_folder(default_out, user)
    if named:
        print(f"{os.path.basename(default_out)} with {' '.join(user)}: results in {named}/ (the defaults' "
              f"{default_out}/ is left as it is; -out names another folder)")
        words = words + ["-out", named]
    elif opts["ranks"] is not None and "-out" not in words and "-help" not in words:
        # (the distributed run's folder is its own: the sequential scene's default is another curve)
        words = words + ["-out", default_out]
    try:
        run = children.run(launcher + [script] + words)
    except OSError as e:  # the launcher itself missing (mpiexec, FreeFem++-mpi not installed)
        print(f"error: cannot start {launcher[0]}: {e.strerror} (run 'make deps')", file=sys.stderr)
        return 3
    if run.returncode != 0:
        return run.returncode
    if "-help" in user:
        return 0
    out = output_folder(words, default_out)
    if plot:
        try:
            drawn = children.run(plot + [out])
        except OSError as e:
            print(f"error: cannot start the plot command {plot[0]}: {e.strerror}", file=sys.stderr)
            return 3
        if drawn.returncode != 0:
            print(f"error: drawing the figures of {out} failed ({' '.join(plot)})", file=sys.stderr)
            return drawn.returncode
    print(f"results in {out}/")
    return 0


if __name__ == "__main__":
    children.install()
    sys.exit(main(sys.argv[1:]))
