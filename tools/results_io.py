"""Reading back what a scene wrote (summary.json, the CSVs), for the plot tools: a missing, cut or
damaged file is named in one error line, never a Python traceback (issue 26: files are trusted).

    from results_io import ResultsError, guard, read_csv, read_json
    guard(main)   # runs main(); a ResultsError prints "error: ..." and exits 1
"""
import csv
import json
import math
import sys


class ResultsError(Exception):
    """A results file that is missing, cut or damaged; the message names it."""


def read_json(path):
    """The object of a JSON file (a summary.json): a dict, or a ResultsError naming the file."""
    try:
        with open(path) as f:
            value = json.load(f)
    except FileNotFoundError:
        raise ResultsError(f"{path} is missing (the run did not finish, or wrote elsewhere)") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as e:
        raise ResultsError(f"{path} is damaged ({e}): run the scene again") from None
    if not isinstance(value, dict):
        raise ResultsError(f"{path} is damaged (not a JSON object): run the scene again")
    return value


def read_csv(path, skip_comment=True):
    """{column: [float]} of a CSV with a header line (`#` lines skipped): every row must have the
    header's number of fields, every field a finite or nan number; else a ResultsError naming the
    file, its line and its column."""
    try:
        with open(path, newline="") as f:
            lines = [(number, ln) for number, ln in enumerate(f, 1) if not (skip_comment and ln.startswith("#"))]
    except FileNotFoundError:
        raise ResultsError(f"{path} is missing (the run did not finish, or wrote elsewhere)") from None
    except UnicodeDecodeError as e:
        raise ResultsError(f"{path} is damaged ({e}): run the scene again") from None
    if not lines:
        raise ResultsError(f"{path} has no header line")
    header = next(csv.reader([lines[0][1]]))
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
    return {name: [r[k] for r in rows] for k, name in enumerate(header)}


def guard(main):
    """Runs main(); a ResultsError ends the process with its one error line and exit code 1."""
    try:
        main()
    except ResultsError as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(1)
