#!/usr/bin/python3
"""Runs one scene for `make run` / `make ensemble`, then draws its figures from the folder it wrote.

Usage (the Makefile's):  tools/run_scene.py SCRIPT DEFAULT_OUT [PLOT COMMAND ...]
  with, from the environment:
    RUN_ARGS      the user's ARGS
    RUN_FIXED     words the Makefile puts before them (make ensemble: -v 0 -seeds N)
    RUN_OUT       an output folder the Makefile gives (make ensemble's OUT): one word, as typed
    RUN_LAUNCHER  the command that runs a script (default tools/ff; make ensemble: ff-mpirun -np N)
What the user types reaches this script through the environment, never pasted into a shell
command: it is split like a shell's words (quotes group: -out 'my dir') but nothing in it is ever
run (`;`, `$(...)` and backquotes are characters). The figures are drawn from the folder the run
actually wrote: the last -out among the words (getARGV takes the last), else DEFAULT_OUT; the plot
command gets it as its last argument. With -help among ARGS the script only lists its options and
nothing is drawn. Exit: the run's exit code, else the plot's.
"""
import os
import shlex
import shutil
import sys

import children

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def words_of(variable, default=""):
    """The shell words of an environment variable; exits 2 naming it when its quotes do not close."""
    try:
        return shlex.split(os.environ.get(variable, default))
    except ValueError as e:
        name = "ARGS" if variable == "RUN_ARGS" else variable
        print(f"error: {name}: {e} (quote each value whole: ARGS=\"-out 'my dir'\")", file=sys.stderr)
        sys.exit(2)


def output_folder(words, default):
    """The value of the last -out among `words`, or `default`."""
    out = default
    for i, word in enumerate(words[:-1]):
        if word == "-out":
            out = words[i + 1]
    return out


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    script, default_out, plot = argv[0], argv[1], argv[2:]
    launcher = words_of("RUN_LAUNCHER") or [os.path.join(ROOT, "tools", "ff")]
    # The programs the launcher starts, named before anything runs (mpiexec's own message for a
    # missing FreeFem++-mpi is OpenMPI's, exit 134).
    missing = [w for w in launcher if w in ("mpiexec", "FreeFem++-mpi") and shutil.which(w) is None]
    if missing:
        print(f"error: {missing[0]} is not installed (or not on PATH): run 'make deps' (Debian's freefem++ "
              "and openmpi)", file=sys.stderr)
        return 3
    user = words_of("RUN_ARGS")
    if "RUN_OUT" in os.environ and (not os.environ["RUN_OUT"].strip() or os.environ["RUN_OUT"].startswith("-")):
        print(f"error: OUT='{os.environ['RUN_OUT']}' is not a folder name (empty, or an option)", file=sys.stderr)
        return 2
    words = words_of("RUN_FIXED") + (["-out", os.environ["RUN_OUT"]] if os.environ.get("RUN_OUT") else []) + user
    # No shell ever sees these words, so nothing expands `~`: a folder named ~ would be made here.
    home = [w for w in words if w == "~" or w.startswith("~/")]
    if home:
        print(f"error: '{home[0]}': ~ is not expanded (no shell reads ARGS or OUT): give the folder's full "
              "path, e.g. $HOME/...", file=sys.stderr)
        return 2
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
