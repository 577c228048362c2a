"""Reading back what a scene wrote (summary.json, the CSVs), for the plot tools: a missing, cut or
damaged file is named in one error line, never a Python traceback (issue 26: files are trusted).
And the results folder's ownership for the Python tools that write into one: record() lists a
file in the folder's manifest, claim() takes a folder by the scenes' own rules (plugin/core/
files.hpp, through plugin/build/sma-results: one implementation).

    from sma.results_io import ResultsError, guard, read_csv, read_json
    guard(main)   # runs main(); a ResultsError prints "error: ..." and exits 1
"""
import contextlib
import csv
import json
import math
import os
import subprocess
import sys

from .repository import ROOT

RESULTS_TOOL = os.path.join(ROOT, "plugin", "build", "sma-results")


def results_tool(verb, *words):
    """Runs plugin/build/sma-results VERB WORDS...; a ResultsError with its error line if it fails."""
    if not os.access(RESULTS_TOOL, os.X_OK):
        raise ResultsError(f"{RESULTS_TOOL} is not built: run 'make plugin'")
    done = subprocess.run([RESULTS_TOOL, verb, *words], capture_output=True, text=True)
    if done.returncode != 0:
        message = done.stderr.strip().splitlines()
        raise ResultsError(message[-1][len("error: "):] if message and message[-1].startswith("error: ")
                           else f"sma-results {verb} {words[0]} failed (exit {done.returncode})")


def record(path):
    """Lists `path` (a file a tool is about to write) in the manifest of the nearest results folder
    above it, as the scenes do (plugin/core/files.hpp record_result): a later run of the folder
    then replaces it, and refuses nothing of ours. Outside a results folder nothing is recorded
    (docs/variants' figures)."""
    results_tool("record", os.path.abspath(path))


def claim(folder, scene):
    """Takes `folder` for this process's writing, as a scene takes its -out: refused (ResultsError,
    nothing touched) when it holds anything its manifest does not list or another run holds it;
    else what an earlier run listed there goes (a complete run's into previous-run/, until this one
    calls complete()) and a manifest of `scene` started. The lock
    goes with release(folder) or this process's end (a later run finds it stale)."""
    results_tool("claim", folder, scene, str(os.getpid()))


@contextlib.contextmanager
def publishing(path, partial=None):
    """Writes the result file `path` as the scenes do: listed first in its folder's manifest
    (record), written under the temporary name `partial` (default path + ".partial"), which the
    block gets, and renamed into place when the block ends well. An OSError inside that names no
    file (a write that fails as the file is flushed or closed: a full disk, a file-size limit) is
    given the temporary name, so that the message names it."""
    partial = partial or path + ".partial"
    record(path)
    try:
        yield partial
    except OSError as e:
        if e.filename is None:
            raise OSError(e.errno, e.strerror or str(e), partial) from None
        raise
    os.replace(partial, path)


def console(stream):
    """A print to `stream` that stops printing, never failing, once a write to it fails (a reader
    that went away, `| head -1`; a closed or full stream): the caller's work goes on. The stream's
    descriptor is then pointed at /dev/null, so that Python's own flush at exit says nothing."""
    broken = []

    def say(*args, **kwargs):
        if broken:
            return
        try:
            print(*args, file=stream, **kwargs)
            stream.flush()
        except (OSError, ValueError):  # (ValueError: a closed file object)
            broken.append(True)
            try:
                null = os.open(os.devnull, os.O_WRONLY)
                os.dup2(null, stream.fileno())
                os.close(null)
            except (OSError, ValueError):
                pass
    return say


def resume(folder, scene, patterns):
    """Takes `folder` for this process's resumed run of `scene`, whose manifest it must hold: only
    its listed entries matching the shell patterns of `patterns` (what the run writes again) go."""
    results_tool("resume", folder, scene, patterns, str(os.getpid()))


def complete(folder):
    """This process's run of `folder` (taken by claim) is complete: the earlier complete run, kept
    in its previous-run/ since the claim, is removed."""
    results_tool("complete", folder, str(os.getpid()))


def release(folder):
    """Removes this process's lock of `folder` (taken by claim); a run that did not complete is told
    on stderr where the last complete run is kept (previous-run/)."""
    done = subprocess.run([RESULTS_TOOL, "release", folder, str(os.getpid())], capture_output=True, text=True)
    if done.stderr.startswith("note: "):
        print(done.stderr.strip(), file=sys.stderr)


class ResultsError(Exception):
    """A results file that is missing, cut or damaged; the message names it."""


def opened(path, **kwargs):
    """open(path, **kwargs) of a results file, or a ResultsError naming it: missing, a directory, a
    device or a pipe (whose read would block or never end), or unreadable."""
    if os.path.exists(path) and not os.path.isfile(path) and not os.path.isdir(path):
        raise ResultsError(f"{path} is not a regular file (a device or a pipe), not the run's file")
    try:
        return open(path, **kwargs)
    except FileNotFoundError:
        raise ResultsError(f"{path} is missing (the run did not finish, or wrote elsewhere)") from None
    except IsADirectoryError:
        raise ResultsError(f"{path} is a directory, not the run's file") from None
    except OSError as e:
        raise ResultsError(f"{path} cannot be read ({e.strerror})") from None


def read_json(path):
    """The object of a JSON file (a summary.json): a dict, or a ResultsError naming the file."""
    def no_constant(word):  # NaN, Infinity: no JSON the scenes write holds them
        raise ValueError(f"'{word}' is not a JSON number")

    def no_repeat(pairs):  # a key given twice: json keeps the last one without a word
        keys = [k for k, _ in pairs]
        repeated = sorted({k for k in keys if keys.count(k) > 1})
        if repeated:
            raise ValueError(f"the key {repeated[0]!r} is given twice")
        return dict(pairs)

    def no_huge(text):  # an integer beyond a double is no value the scenes write
        value = int(text)
        if abs(value) > 1.7976931348623157e308:
            raise ValueError(f"the number {text[:20]}... is beyond a double")
        return value
    try:
        with opened(path, encoding="utf-8") as f:
            value = json.load(f, parse_constant=no_constant, object_pairs_hook=no_repeat, parse_int=no_huge)
    except (ValueError, UnicodeDecodeError, RecursionError) as e:  # JSONDecodeError is a ValueError
        raise ResultsError(f"{path} is damaged ({type(e).__name__}: {str(e)[:200]}): run the scene again") from None
    if not isinstance(value, dict):
        raise ResultsError(f"{path} is damaged (not a JSON object): run the scene again")
    if not isinstance(value.get("parameters", {}), dict):
        raise ResultsError(f"{path} is damaged (its parameters are not a JSON object): run the scene again")
    return value


def _read_vtk_file(reader, path):
    """reader(path) of sma.vtu, its SceneError (which names the file) raised as a ResultsError."""
    from .errors import SceneError
    try:
        return reader(path)
    except SceneError as e:
        raise ResultsError(str(e)) from None


def read_vtu(path):
    """The mesh and fields of a scene's VTU file (sma.vtu.read_vtu: a Fields), or a ResultsError
    naming the file: missing, cut short (a run stopped while writing it) or damaged. The plot tools
    read VTU files here, never through VTK's reader, which prints its own complaint and hands back
    an empty grid (a traceback further on)."""
    from . import vtu
    return _read_vtk_file(vtu.read_vtu, path)


def read_pvd(path):
    """[(time in s, absolute path of the VTU)] of a fields.pvd (sma.vtu.read_pvd), or a ResultsError
    naming the file."""
    from . import vtu
    return _read_vtk_file(vtu.read_pvd, path)


def read_summary(outdir, tool):
    """summary.json of the run in `outdir`, for the plot tool `tool` (its path: tools/plot/plot_<x>.py).
    A run whose figures another tool draws (make run's rule: the scene's own plot_<scene>.py, else
    plot_sleeve.py for a sleeve-* scene) is refused naming that tool: the tool read on and failed
    on a key the other scene does not write ("KeyError: 'nr' ... an edited or foreign summary.json?")."""
    summary = read_json(os.path.join(outdir, "summary.json"))
    scene = summary.get("scene")
    if isinstance(scene, str):
        own = f"plot_{scene}.py"
        if not os.path.isfile(os.path.join(ROOT, "tools", "plot", own)):
            own = "plot_sleeve.py" if scene.startswith("sleeve-") else ""
        if own and own != os.path.basename(tool):
            raise ResultsError(f"{outdir} holds a run of {scene}, whose figures are tools/plot/{own}'s "
                               "(make run draws them)")
    return summary


def read_csv(path, skip_comment=True, text_columns=()):
    """{column: [float]} of a CSV with a header line (`#` lines skipped): every row must have the
    header's number of fields, every field a finite or nan number (those of `text_columns`, labels
    such as beam's `mesh`, are kept as strings); else a ResultsError naming the file, its line and
    its column."""
    try:
        # utf-8-sig: a byte-order mark (an editor's) is not part of the first column's name
        with opened(path, newline="", encoding="utf-8-sig") as f:
            lines = [(number, ln) for number, ln in enumerate(f, 1) if not (skip_comment and ln.startswith("#"))]
    except UnicodeDecodeError as e:
        raise ResultsError(f"{path} is damaged ({e}): run the scene again") from None
    if not lines:
        raise ResultsError(f"{path} has no header line")
    header = next(csv.reader([lines[0][1]]))
    repeated = sorted({name for name in header if header.count(name) > 1})
    if repeated:
        raise ResultsError(f"{path}: the column {repeated[0]} is named twice in the header (an edited file?)")
    rows = []
    for number, line in lines[1:]:
        if not line.strip():
            continue
        fields = next(csv.reader([line]))
        if len(fields) != len(header):
            raise ResultsError(f"{path}: line {number} has {len(fields)} fields, the header {len(header)} "
                               "(a cut or damaged file: run the scene again)")
        row = []
        for name, text in zip(header, fields):
            if name in text_columns:
                row.append(text)
                continue
            try:
                value = float(text)
            except ValueError:
                raise ResultsError(f"{path}: line {number}, column {name}: '{text}' is not a number") from None
            if math.isinf(value):
                raise ResultsError(f"{path}: line {number}, column {name}: '{text}' is not finite")
            row.append(value)
        rows.append(row)
    if not rows:
        raise ResultsError(f"{path} has no data rows")
    columns = {name: [r[k] for r in rows] for k, name in enumerate(header)}
    # The step and the time index every row: a nan there (a value a field may hold) is damage.
    for name in ("step", "t"):
        bad = next((i for i, v in enumerate(columns.get(name, [])) if math.isnan(v)), None)
        if bad is not None:
            raise ResultsError(f"{path}: data row {bad + 1}, column {name}: nan is not a {name} (a damaged file)")
    return columns


def guard(main):
    """Runs main(); a ResultsError, or a file that cannot be written (a full disk, a file-size
    limit), ends the process with its one error line and exit code 1."""
    try:
        main()
    except ResultsError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
    except OSError as e:
        where = f" {e.filename}" if e.filename else ""
        print(f"error: cannot write{where}: {e.strerror or e}", file=sys.stderr)
        sys.exit(1)
    except (KeyError, TypeError, ValueError, IndexError) as e:
        # Well-formed files whose content is not what the scenes write (a number given as a string,
        # a key missing): one line naming the value, not a traceback. (A bug of the tool shows the
        # same way; the text says which value.)
        print(f"error: the results read do not have the form the scenes write ({type(e).__name__}: {e}): "
              "an edited or foreign summary.json or CSV? run the scene again", file=sys.stderr)
        sys.exit(1)
