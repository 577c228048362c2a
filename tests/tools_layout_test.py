#!/usr/bin/python3
"""tools/ split by audience (docs: README.md, "tools/"): what the split promises, checked on the files.

  (a) the oracles (tools/bench/oracles/*.py: Lame's closed forms, the curve metric, sleeve-radial's
      scheme in numpy, ring-lame by GetFEM) import only the standard library, numpy, scipy, getfem
      and each other: nothing of the sma package (python/sma) or of the tools that reach it, so
      that what they check is computed twice, independently;
  (b) every path tools/... written in a tracked file (the Makefile, the tests, the docs, README,
      the scripts' comments, the tools themselves) names a file or folder that exists: a move
      that left a caller behind fails here, naming the file and line;
  (c) every Python file of tools/ is under 400 lines (one job a file);
  (d) every Python file of tools/ imports as its own script would (its folder first on sys.path,
      nothing run: __name__ is not "__main__"): a module it names that a move left behind fails
      here, not when a user's `make run` draws its figures.
Writes results/checks/tools_layout.json.
"""
import ast
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, check, finish, record  # noqa: E402

ORACLES = os.path.join(ROOT, "tools", "bench", "oracles")
THIRD_PARTY = {"numpy", "scipy", "getfem"}  # Debian's packages the oracles may use
# A path as written in prose or code; placeholders (<scene>, $(SCENE), *) are not paths.
TOOLS_PATH = re.compile(r"(?<![\w/.-])tools/[\w./<>$()*-]*")
MAX_LINES = 400


def imports(path):
    """[(line, top-level module)] of every import statement of the file, nested ones included."""
    found = []
    for node in ast.walk(ast.parse(open(path).read(), path)):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name.split(".")[0]) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            found.append((node.lineno, node.module.split(".")[0]))
    return found


# (a)
siblings = {name[:-3] for name in os.listdir(ORACLES) if name.endswith(".py")}
allowed = set(sys.stdlib_module_names) | THIRD_PARTY | siblings
outside = [f"tools/bench/oracles/{name}.py:{line} imports {module}" for name in sorted(siblings)
           for line, module in imports(os.path.join(ORACLES, name + ".py")) if module not in allowed]
check(len(siblings) >= 6 and not outside,
      f"(a) the {len(siblings)} oracles ({', '.join(sorted(siblings))}) import only the standard library, "
      f"{', '.join(sorted(THIRD_PARTY))} and each other" + (f": {'; '.join(outside)}" if outside else ""))

# (b)
tracked = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout.split("\0")
stale, named = [], 0
for rel in filter(None, tracked):
    path = os.path.join(ROOT, rel)
    if not os.path.isfile(path) or rel.endswith((".msh", ".png", ".csv")):
        continue
    try:
        text = open(path, encoding="utf-8").read()
    except UnicodeDecodeError:
        continue
    for number, line in enumerate(text.splitlines(), 1):
        for match in TOOLS_PATH.finditer(line):
            written = match.group(0).rstrip(".)")
            if any(c in written for c in "<>$*"):
                continue
            named += 1
            if not os.path.exists(os.path.join(ROOT, written)):
                stale.append(f"{rel}:{number}: {written}")
check(named > 100 and not stale, f"(b) {named} tools/ paths written in the tracked files, each names an "
      f"existing file or folder" + (f"; stale: {'; '.join(stale[:20])}" if stale else ""))

# (c)
lengths = {}
for folder, _, files in os.walk(os.path.join(ROOT, "tools")):
    for name in files:
        if name.endswith(".py"):
            rel = os.path.relpath(os.path.join(folder, name), ROOT)
            lengths[rel] = sum(1 for _ in open(os.path.join(ROOT, rel)))
longest = max(lengths, key=lengths.get)
check(lengths[longest] < MAX_LINES, f"(c) the {len(lengths)} Python files of tools/ are under {MAX_LINES} lines "
      f"(longest: {longest}, {lengths[longest]})")

# (d) One interpreter imports them all in turn (one per file cost 20 s, mostly numpy and matplotlib
# imported again each time): before each file its folder goes first on sys.path and every module
# of this repository is dropped from sys.modules, so that each file finds its own siblings as its
# script would; the third-party modules stay loaded, which changes only the time.
LOADER = """import importlib.util, json, os, sys
root, paths = sys.argv[1], sys.argv[2:]
base_path, broken = list(sys.path), {}
for path in paths:
    for name, module in list(sys.modules.items()):
        if os.path.abspath(getattr(module, "__file__", None) or "/").startswith(root + os.sep):
            del sys.modules[name]
    sys.path[:] = [os.path.dirname(path)] + base_path
    try:
        spec = importlib.util.spec_from_file_location("tool_under_test", path)
        spec.loader.exec_module(importlib.util.module_from_spec(spec))
    except SystemExit as e:
        if e.code not in (None, 0):
            broken[path] = "exit %s" % e.code
    except BaseException as e:
        broken[path] = "%s: %s" % (type(e).__name__, e)
print(json.dumps(broken))
"""
files = sorted(lengths)
proc = subprocess.run(["/usr/bin/python3", "-c", LOADER, ROOT, *(os.path.join(ROOT, rel) for rel in files)], cwd=ROOT,
                      capture_output=True, text=True, timeout=600)
try:
    broken = {os.path.relpath(path, ROOT): why for path, why in json.loads(proc.stdout.strip().splitlines()[-1]).items()}
except (ValueError, IndexError):
    broken = {"(the loader)": (proc.stderr.strip().splitlines() or ["exit %d" % proc.returncode])[-1]}
check(not broken, f"(d) the {len(lengths)} Python files of tools/ import as their scripts would"
      + "".join(f"; {rel}: {why}" for rel, why in broken.items()))

record("tools_layout", {"oracles": sorted(siblings), "tools_paths_named": named, "stale_paths": stale,
                        "python_files": len(lengths), "longest": [longest, lengths[longest]],
                        "import_failures": broken})
finish()
