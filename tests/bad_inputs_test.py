#!/usr/bin/python3
"""Every bad input of docs/errors.md fails fast with its message and exit code.

Reads the table of docs/errors.md and the cases listed under it (so that the document and the
test cannot drift), runs each row's command from the repository root with $R = the root and $T =
a fresh scratch directory, and
asserts for each: the exit code of the table; one line starting with "error:" in its output
(on stderr: tools/ff moves a script's there too, tests/launch_test.py), matching the row's pattern; the run
over in under 20 s of processor time (it must stop before the time loop; processor time, which
the machine's load does not stretch); and that what a finished earlier run left
in $T/out (its marker and a summary.json) is still there byte for byte: every check comes before
anything is deleted. Also asserts that the table covers every kind of bad input the project
promises to catch, and that the commands in a SCENE or ARGS value never ran. The plugin cases use copies under $T through SMA_PLUGIN (tools/ff):
a copy of the real plugin dated 2000 (stale), a plugin built here that reports version 2, the
real one without its version stamp (unstamped), the real one cut short (corrupt), a missing path; the real plugin/build/sma.so is never touched. The
broken meshes are made here from meshes/sleeve-aniso.msh (and gmsh, for MSH 4.1).
Writes results/checks/bad_inputs.json.
"""
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record, sleeve_geometry  # noqa: E402

# What the table must cover (a word of the "bad input" column for each).
REQUIRED = ["unknown option", "T0 >= Tc", "omega", "mu < 0", "g < 0", "-gcontact", "-steps 0",
            "negative step count", "missing mesh file", "mesh without the expected boundary labels",
            "plugin not built", "plugin out of date", "another version", "unknown scene",
            "shell metacharacters", "option without its value", "not a number", "integer option",
            "MSH 4", "cut off", "clockwise", "labels swapped", "another directory", "corrupt plugin",
            "no such script", "overflows a double", "theta", "in Celsius", "user's own files",
            "shell syntax in ARGS", "offset beyond the interference", "exact ring differs", "TMPDIR"]

FAKE_PLUGIN = """// A stand-in SMA plugin that reports version 2 (tests/bad_inputs_test.py).
#include "ff++.hpp"
extern "C" __attribute__((used)) const char sma_plugin_version_stamp[] = "sma-plugin-version 2;";
static double SmaPluginVersion() { return 2.0; }
static void Init() { Global.Add("SmaPluginVersion", "(", new OneOperator0<double>(SmaPluginVersion)); }
LOADFUNC(Init)
"""


def code(cell):
    """The text of a Markdown code span (`x` or ``x``)."""
    cell = cell.strip()
    for fence in ("``", "`"):
        if cell.startswith(fence) and cell.endswith(fence):
            return cell[len(fence):-len(fence)].strip()
    raise ValueError(f"not a code span: {cell}")


# A case listed under the table (its command or message too long for a row of at most 400
# characters, tests/docs_test.py): "- **<bad input>**: exit <N>. Fix: <fix>", then a ```sh block
# holding the command and a ```text block holding the message's pattern, one line each.
CASE = re.compile(r"^- \*\*(.+?)\*\*: exit (\d+)\. Fix: (.*)$")


def listed_cases(lines):
    """The rows of the cases listed after the table, up to the next heading."""
    rows, fence, block = [], None, []
    for ln in lines:
        if ln.startswith("#"):
            break
        m = CASE.match(ln)
        if m and fence is None:
            rows.append({"input": m.group(1), "exit": int(m.group(2)), "fix": m.group(3)})
        elif ln.strip().startswith("```"):
            if fence is None:
                fence, block = ln.strip()[3:], []
            else:
                key = {"sh": "command", "text": "pattern"}.get(fence)
                if key is None or not rows or key in rows[-1] or len(block) != 1:
                    raise ValueError(f"docs/errors.md: a listed case's ```{fence} block is not its one "
                                     f"command or pattern line: {rows[-1]['input'] if rows else block}")
                rows[-1][key] = block[0].strip()
                fence = None
        elif fence is not None:
            block.append(ln)
    incomplete = [r["input"] for r in rows if "command" not in r or "pattern" not in r]
    if incomplete:
        raise ValueError(f"docs/errors.md: listed cases without a command or a pattern: {incomplete}")
    return rows


def table_rows():
    lines = open(os.path.join(ROOT, "docs", "errors.md")).read().splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("| bad input |"))
    rows = []
    end = start + 2
    for ln in lines[start + 2:]:
        if not ln.startswith("|"):
            break
        cells = [c.strip() for c in ln.strip().strip("|").split(" | ")]
        rows.append({"input": cells[0], "command": code(cells[1]), "exit": int(cells[2]),
                     "pattern": code(cells[3]), "fix": cells[4]})
        end += 1
    return rows + listed_cases(lines[end:])


def prepare(tmp):
    """$T/stale/sma.so, $T/v2/sma.so, $T/pref/freefem++.pref (docs/errors.md)."""
    os.makedirs(os.path.join(tmp, "stale"))
    stale = os.path.join(tmp, "stale", "sma.so")
    shutil.copyfile(os.path.join(ROOT, "plugin", "build", "sma.so"), stale)
    old = time.mktime((2000, 1, 1, 0, 0, 0, 0, 0, -1))
    os.utime(stale, (old, old))
    os.makedirs(os.path.join(tmp, "v2"))
    with open(os.path.join(tmp, "v2", "sma.cpp"), "w") as f:
        f.write(FAKE_PLUGIN)
    build = subprocess.run(["ff-c++", "sma.cpp"], cwd=os.path.join(tmp, "v2"), capture_output=True, text=True)
    check(build.returncode == 0 and os.path.exists(os.path.join(tmp, "v2", "sma.so")),
          f"a version-2 stand-in plugin built with ff-c++ (exit {build.returncode})")
    os.makedirs(os.path.join(tmp, "pref"))
    with open(os.path.join(tmp, "pref", "freefem++.pref"), "w") as f:
        f.write('loadpath += "./"\n')
    os.makedirs(os.path.join(tmp, "corrupt"))
    with open(os.path.join(ROOT, "plugin", "build", "sma.so"), "rb") as f:
        whole = f.read()
    head = whole[:50000]
    # The real plugin whose version stamp (plugin/glue/load.cpp) is overwritten, byte for byte.
    stamp = b"sma-plugin-version "
    check(whole.count(stamp) == 1, f"the real plugin holds its version stamp once ({whole.count(stamp)})")
    os.makedirs(os.path.join(tmp, "unstamped"))
    with open(os.path.join(tmp, "unstamped", "sma.so"), "wb") as f:
        f.write(whole.replace(stamp, b"x" * len(stamp)))
    with open(os.path.join(tmp, "corrupt", "sma.so"), "wb") as f:
        f.write(head)
    broken_meshes(os.path.join(tmp, "meshes"))


def broken_meshes(folder):
    """v4.msh, cut.msh, clockwise.msh, swapped.msh: meshes/sleeve-aniso.msh broken four ways."""
    os.makedirs(folder)
    source = os.path.join(ROOT, "meshes", "sleeve-aniso.msh")
    text = open(source).read()
    with open(os.path.join(folder, "cut.msh"), "w") as f:
        f.write(text[:20000])
    geometry = sleeve_geometry()
    gmsh = subprocess.run(["gmsh", "-2", "-format", "msh41", os.path.join(ROOT, "meshes", "ring.geo"),
                           "-setnumber", "Ri", str(geometry["Ri"]), "-setnumber", "Hr", str(geometry["Hr"]),
                           "-setnumber", "nr", "6", "-o", os.path.join(folder, "v4.msh")],
                          capture_output=True, text=True)
    check(gmsh.returncode == 0, f"gmsh wrote an MSH 4.1 ring (exit {gmsh.returncode})")
    clockwise, swapped, section, turned = [], [], False, False
    for line in text.splitlines(keepends=True):
        words = line.split()
        section = (section or line.startswith("$Elements")) and not line.startswith("$EndElements")
        if section and len(words) > 5 and words[1] == "2" and not turned:  # the first triangle
            clockwise.append(" ".join(words[:-2] + [words[-1], words[-2]]) + "\n")
            turned = True
        else:
            clockwise.append(line)
        if section and len(words) > 5 and words[1] == "1" and words[3] in ("1", "2"):  # an edge
            words[3] = {"1": "2", "2": "1"}[words[3]]
            swapped.append(" ".join(words) + "\n")
        else:
            swapped.append(line)
    with open(os.path.join(folder, "clockwise.msh"), "w") as f:
        f.write("".join(clockwise))
    with open(os.path.join(folder, "swapped.msh"), "w") as f:
        f.write("".join(swapped))


def main():
    rows = table_rows()
    inputs = " ".join(r["input"] for r in rows)
    missing = [w for w in REQUIRED if w not in inputs]
    check(not missing, f"docs/errors.md has {len(rows)} rows covering every required kind of bad input"
          + (f" (missing: {missing})" if missing else ""))
    # No plugin override, and no flags of an enclosing make (make test -j): the make rows must run
    # check-scene alone, first.
    env = {k: v for k, v in os.environ.items() if k not in ("SMA_PLUGIN", "MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    measured = []
    with tempfile.TemporaryDirectory(prefix="bad-inputs-") as tmp:
        prepare(tmp)
        env.update(T=tmp, R=ROOT)
        for row in rows:
            # What a finished earlier run leaves (its manifest, summary.json, the mark of a complete
            # run): every check must come before the folder is taken (its run moved to previous-run/).
            out = os.path.join(tmp, "out")
            shutil.rmtree(out, ignore_errors=True)
            os.makedirs(out)
            earlier = '{"scene": "an earlier run"}\n'
            manifest = "sma-results manifest 1\nscene sleeve-circular\nsummary.json\n"
            for name, text in ((".sma-results", manifest), ("summary.json", earlier), (".sma-complete", "")):
                with open(os.path.join(out, name), "w") as f:
                    f.write(text)
            # The processor time of the row's processes, not the wall clock: the machine's load
            # stretches the one and not the other (a row at 20 s of wall time failed under load).
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            run = subprocess.run(["bash", "-c", row["command"]], cwd=ROOT, env=env, capture_output=True,
                                 text=True, timeout=600)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            seconds = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
            errors = [ln for ln in (run.stderr + run.stdout).splitlines() if ln.startswith("error:")]
            matched = bool(errors) and re.search(row["pattern"], errors[0]) is not None
            summary = os.path.join(out, "summary.json")
            kept = os.path.exists(summary) and open(summary).read() == earlier
            check(run.returncode == row["exit"] and len(errors) == 1 and matched and seconds < 20 and kept,
                  f"{row['input']}: exit {run.returncode} (table {row['exit']}), {len(errors)} error line, "
                  f"{'matches' if matched else 'does not match'} the pattern, {seconds:.2f} s of processor time, the earlier "
                  f"summary.json {'kept' if kept else 'MOVED, DELETED or changed'}: "
                  f"{errors[0] if errors else run.stderr.strip()[-300:]}")
            measured.append({"input": row["input"], "exit": run.returncode, "cpu_seconds": round(seconds, 3),
                             "message": errors[0] if errors else None, "matched": matched})
        check(not os.path.exists(os.path.join(tmp, "injected")),
              "the commands in SCENE and ARGS never ran ($T/injected absent)")
    check(os.path.exists(os.path.join(ROOT, "plugin", "build", "sma.so")), "the real plugin is still there")
    record("bad_inputs", {"test": "bad_inputs", "rows": len(rows), "runs": measured,
                          "slowest_cpu_seconds": max(m["cpu_seconds"] for m in measured)})
    finish()


if __name__ == "__main__":
    main()
