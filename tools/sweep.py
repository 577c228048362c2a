#!/usr/bin/python3
"""Sweeps one option of a scene, or two over their grid: runs each value (in parallel up to the
cores), then writes a table and overlay figures.

Usage: tools/sweep.py SCENE PARAM VALUE [VALUE ...] [--param2 PARAM2 --values2 'V1 V2 ...']
                      [--jobs N] [--out DIR] [--env-args NAME] [-- SCENE OPTIONS ...]
       make sweep SCENE=... PARAM=... VALUES='...' [PARAM2=... VALUES2='...'] [ARGS='...'] [JOBS=2] [OUT=dir]
PARAM is an option name without its dash (g, mu, steps); a value may be negative (-5e-6). The
options after `--` go to every run; so do those in the environment variable NAME with --env-args
(make sweep's ARGS: split into words like a shell's, quotes grouping, but never run by one, so a
`;` or `$(...)` in it is a character). --jobs N runs min(N, cores, values) at a time (default:
the cores). Writes DIR (default results/sweeps/<scene>-<param> of the checkout; a relative DIR is
the current folder's):
  <param>=<value>/     each run's own results folder
  table.csv            one row per finished value: the summary's key figures (first contact and
                       austenite: step, time, inner temperature; final and peak mean pressure;
                       iteration maxima; wall time), each column named with its unit; a scene
                       without those keys (beam, ring-lame, free-ring): every number of its
                       summary.json, named by its key (docs/outputs.md gives the units)
  force-temperature.png, force-time.png   scenes whose history.csv has a contact pressure: the
                       mean contact pressure (MPa) against the mean inner-surface temperature (°C),
                       and against time (s) zoomed on the transient (0 to a quarter past the last
                       run's austenite), the whole run in a small panel; curves that coincide
                       within 0.1 % share a legend entry that says so. Other scenes: the table only
                       (said on the console and in sweep.json)
  design-chart.png     a sweep of sleeve-life (one parameter, numeric values): the clamping pressure,
                       the service minimum and the pressure after the hold at -serviceTmin (MPa)
                       and the storage margin (K) against the parameter, -minpressure marked
  sweep.json           the scene, the parameter, the values, the other options, each run's folder
                       and status
With --param2 (make sweep's PARAM2, VALUES2) every combination runs, each into
<param>=<v>,<param2>=<w>/ of DIR (default results/sweeps/<scene>-<param>-<param2>): table.csv has one
row per run (both values first), force-temperature.png one panel per value of PARAM2 with PARAM's
curves overlaid, final-pressure.png the final mean pressure against PARAM, one line per value of
PARAM2 (as sma.sweep with two options).
Reads history.csv and summary.json only. Bad input (scene, option, value) fails before any run,
exit 2, naming it; a value whose run fails stops nothing else: the sweep then exits 1 naming it.
The command line of sma.sweep (python/sma/sweeps.py: the runs, the table, the figures, sweep.json;
sma.sweep() also sweeps several options at once); here only the parsing of the command line.
"""
import os
import shlex
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import children  # noqa: E402  (puts this checkout's python/ first on the path)
import results_io  # noqa: E402
import sma_driver as driver  # noqa: E402
import sma.sweeps as engine  # noqa: E402
from sma.sweeps import coincident_groups, same_curve, unit_of, value_label  # noqa: E402,F401  (tests use them)


class BadInput(Exception):
    """A bad command line: reported as `error: ...`, exit 2, before anything runs."""


def parse(argv):
    """{scene, param, values, jobs, out, extra}. Written by hand rather than with argparse, which
    takes a negative value such as -5e-6 for an unknown option."""
    if any(a in ("-h", "--help") for a in argv[:argv.index("--") if "--" in argv else len(argv)]):
        print(__doc__)
        sys.exit(0)
    extra = []
    if "--" in argv:
        cut = argv.index("--")
        argv, extra = argv[:cut], list(argv[cut + 1:])
    flags = {"--jobs": None, "--out": None, "--env-args": None, "--env-values": None, "--param2": None,
             "--values2": None, "--env-values2": None}
    positional = []
    i = 0
    while i < len(argv):
        arg = argv[i]
        name, _, inline = arg.partition("=")
        if name in flags:
            if inline:
                flags[name] = inline
            elif i + 1 < len(argv):
                i += 1
                flags[name] = argv[i]
            else:
                raise BadInput(f"{name} needs a value")
        elif arg.startswith("--"):
            raise BadInput(f"unknown flag {arg} (flags: {', '.join(flags)}; scene options go after --)")
        else:
            positional.append(arg)
        i += 1
    if flags["--env-values"]:
        # make sweep's VALUES: words of a variable, never flags (VALUES='--out=x 500' is a value)
        positional += os.environ.get(flags["--env-values"], "").split()
    if flags["--out"] is not None and not flags["--out"].strip():
        raise BadInput("--out (OUT) is empty: give a folder, or leave it out for results/sweeps/<scene>-<param>")
    if len(positional) < 3:
        raise BadInput("usage: tools/sweep.py SCENE PARAM VALUE [VALUE ...] [--jobs N] [--out DIR] "
                       "[-- SCENE OPTIONS ...]")
    jobs = os.cpu_count() or 1
    if flags["--jobs"] is not None:
        try:
            jobs = int(flags["--jobs"])
        except ValueError:
            jobs = 0
        if jobs < 1:
            raise BadInput(f"--jobs (JOBS) '{flags['--jobs']}' is not a whole number >= 1")
    if flags["--env-args"]:
        variable = flags["--env-args"]
        try:
            extra += shlex.split(os.environ.get(variable, ""))
        except ValueError as e:
            label = "ARGS" if variable == "SWEEP_ARGS" else variable
            raise BadInput(f"{label}: {e} (quote each value whole: ARGS=\"-mesh 'my dir/m.msh'\")") from None
    param = positional[1]
    if param.startswith("-"):
        raise BadInput(f"PARAM '{param}': give the option's name without its dash ({param.lstrip('-')})")
    if param in ("out", "help"):
        raise BadInput(f"PARAM '{param}' cannot be swept (-out is each run's folder DIR/<param>=<value>, "
                       "-help lists the options)")
    param2, values2 = flags["--param2"], (flags["--values2"] or "").split()
    if flags["--env-values2"]:
        values2 += os.environ.get(flags["--env-values2"], "").split()
    if param2 is not None or values2:
        if not param2 or not values2:
            raise BadInput("a second parameter needs both PARAM2 (--param2) and VALUES2 (--values2): "
                           f"got PARAM2 '{param2 or ''}' and VALUES2 '{' '.join(values2)}'")
        if param2.startswith("-"):
            raise BadInput(f"PARAM2 '{param2}': give the option's name without its dash ({param2.lstrip('-')})")
        if param2 in ("out", "help"):
            raise BadInput(f"PARAM2 '{param2}' cannot be swept")
        if param2 == param:
            raise BadInput(f"PARAM2 '{param2}' is PARAM too: sweep two different options")
    return {"scene": positional[0], "param": param, "values": positional[2:], "jobs": jobs,
            "out": flags["--out"], "extra": extra, "param2": param2, "values2": values2}


def extra_options(scene, params, words):
    """The -name value pairs of `words` as {name: value}, each checked against the scene."""
    pairs = {}
    i = 0
    while i < len(words):
        name = words[i]
        if not name.startswith("-") or len(name) < 2:
            raise BadInput(f"'{name}' among the scene options is not an option name (options are "
                           f"-name value pairs: ARGS='-steps 300 -mesh meshes/sleeve-coarse.msh')")
        if i + 1 >= len(words):
            raise BadInput(f"the option {name} has no value (options are -name value pairs)")
        pairs[name[1:]] = words[i + 1]
        i += 2
    for name in pairs:
        if name in ("out", "help"):
            raise BadInput(f"-{name} cannot be given to a sweep (each run's folder is DIR/<param>=<value>; "
                           f"OUT=dir moves DIR)" if name == "out" else
                           f"-help lists the options: tools/ff {driver.script(scene)} -help")
        if name in params:
            raise BadInput(f"-{name} is swept; do not also give it among the scene options")
        driver.check_option(scene, name)
    return pairs


def main(argv):
    try:
        args = parse(argv)
        scene, param, values = args["scene"], args["param"], args["values"]
        grid = {param: values}
        if args["param2"]:
            grid[args["param2"]] = args["values2"]
        params = list(grid)
        driver.script(scene)
        for p in params:
            driver.check_option(scene, p)
        fixed = extra_options(scene, params, args["extra"])
        engine.check_grid(scene, grid, fixed)  # the values, then their types
        # (a relative --out is the caller's, as on any command line: taken as it was, the sweep's
        # claim and table went there while its runs, whose folders the driver takes from the
        # checkout, went under the checkout: two halves, exit 0)
        out = os.path.abspath(args["out"]) if args["out"] else os.path.join(driver.ROOT, "results", "sweeps",
                                                                             "-".join([scene] + params))
        # every run checked by the scene itself before the folder is taken (its earlier results
        # would be gone by the time a run refused its options); then taken as a scene takes its
        # -out: a folder holding anything its manifest does not list is refused untouched; an
        # earlier sweep's runs, table and figures go first (with -resume 1 its runs stay)
        states, notes = engine.take_folder(out, scene, params, grid, fixed, args["jobs"])
    except (BadInput, driver.SceneError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    # (the console's lines through results_io.console: a reader that went away, `| head -1`, made
    # the next line's print raise, which stopped the runs and was reported as the results' write)
    say, complain = results_io.console(sys.stdout), results_io.console(sys.stderr)
    try:
        status, _, _ = engine.run_grid(out, scene, params, grid, fixed, args["jobs"],
                                       record={"args": args["extra"], "options": fixed}, states=states, notes=notes,
                                       say=say, warn=complain)
        if status == 0:  # every run ended well: the earlier sweep, kept in previous-run/, goes
            results_io.complete(out)
        return status
    except results_io.ResultsError as e:  # the mark of completion could not be written
        print(f"error: {e}", file=sys.stderr)
        return 1
    except OSError as e:  # a full disk, a file-size limit: the table or a figure could not be written
        where = f" {e.filename}" if e.filename else ""
        print(f"error: the sweep's runs finished, but writing its results failed: cannot write{where}: "
              f"{e.strerror or e}", file=sys.stderr)
        return 1
    finally:
        results_io.release(out)


if __name__ == "__main__":
    children.install()
    sys.exit(main(sys.argv[1:]))
