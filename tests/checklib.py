"""Shared helpers of the scene verification tests: named checks and the verification record."""
import csv
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_RESULTS = os.path.join(ROOT, "build", "test-results")
failures = []


def check(condition, message):
    """Prints ok/FAIL with the measured figures in `message`; remembers failures."""
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def record(name, data):
    """Writes results/checks/<name>.json (under a temporary name, then renamed)."""
    os.makedirs(os.path.join(ROOT, "results", "checks"), exist_ok=True)
    path = os.path.join(ROOT, "results", "checks", name + ".json")
    with open(path + ".partial", "w") as f:
        json.dump(dict(data, passed=not failures), f, indent=2)
    os.replace(path + ".partial", path)


def run_scene(scene, out_name, *args):
    """Runs edp/scenes/<scene>.edp into build/test-results/<out_name>; returns that directory."""
    out = os.path.join(TEST_RESULTS, out_name)
    subprocess.run([os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", "-out", out, *args],
                   cwd=ROOT, check=True)
    return out


def rows(path):
    """The rows of a CSV file with a header line, as dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def finish():
    if failures:
        print(f"{len(failures)} checks failed", file=sys.stderr)
        sys.exit(1)
