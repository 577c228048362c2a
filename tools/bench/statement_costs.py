#!/usr/bin/python3
"""Instructions of each statement of the sleeve's time loop and of DCTStep's newton path, per time
step, deterministic (callgrind), for deciding what to move into the plugin.

  git clone -q . /tmp/cg && make -C /tmp/cg plugin meshes && rm /tmp/cg/freefem++.pref
  tools/bench/statement_costs.py /tmp/cg --steps 1001:1008 [-- scene options...]

CLONE is a clone of the repository (its scripts are edited: a mark before every statement of
edp/problems/sleeve/time-loop.idp's loop and of edp/solvers/dct.idp's DCTStep up to its nested
loops), with its plugin built and no freefem++.pref (FreeFEM would read the repository's paths
from it). The marks call CgMark (tools/bench/cgmark.cpp, built here into CLONE/plugin/build), which
dumps callgrind's counters at steps FIRST..LAST only; each line of the table is the mean over
those steps of the instructions from one mark to the next (the statements between them), with
the first line of those statements. A mark's own cost, about 1100 instructions, is in every line:
a line near 1100 is a statement that costs next to nothing. The default scene is sleeve-circular
at its defaults, whose steps after about 700 are the tail (every point austenite: one evaluation
of the step solver a step). Lines that ran at fewer than all the steps (a branch) are marked.
Wall-clock-dependent work (the progress line, fields.pvd's publication) runs more often under
valgrind than in a run: lines holding it show as outliers at some steps.
"""
import argparse
import collections
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import without_companion  # noqa: E402

LOOP = ("edp/problems/sleeve/time-loop.idp", "for (int n = firstStep; n < nSteps; ++n) {",
        "CheckWritten(hist, outDir", (4,), "tl")
STEP = ("edp/solvers/dct.idp", "func int DCTStep(", "if (!newtonSolved) {", (2, 4, 6), "dct")


def insert_marks(path, start, end, indents, prefix):
    """A mark before each statement at the given indents between the lines holding start and end
    (not between an if/for/while and its body, nor inside a continued expression); returns the
    source line after each mark, by label."""
    lines = open(path).read().split("\n")
    first = next(i for i, l in enumerate(lines) if start in l)
    last = next(i for i, l in enumerate(lines) if i > first and end in l)
    out, texts, previous = lines[:first + 1], {}, lines[first]
    for i in range(first + 1, last):
        line = lines[i]
        text = line.strip()
        code = re.sub(r"//.*", "", previous).strip()
        header = (re.match(r"^(\}?\s*else\s*)?(if|for|while)\b", code) and code.endswith(")")) or code in ("else", "} else")
        indent = len(line) - len(line.lstrip(" "))
        if (text and not text.startswith(("//", "}", "else", "<<", "+", "&&", "||")) and indent in indents
                and code.endswith((";", "{", "}", ")")) and not header):
            label = "%s%d" % (prefix, i + 1)
            out.append(" " * indent + 'CGM("%s")' % label)
            texts[label] = "%s:%d %s" % (os.path.basename(path), i + 1, text)
        out.append(line)
        if text and not text.startswith("//"):
            previous = line
    out += lines[last:]
    open(path, "w").write("\n".join(out))
    return texts


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("clone")
    parser.add_argument("--steps", default="1001:1008", help="FIRST:LAST, the steps measured")
    parser.add_argument("--scene", default="edp/scenes/sleeve-circular.edp")
    parser.add_argument("options", nargs="*", help="scene options (after --)")
    args = parser.parse_args()
    clone = os.path.abspath(args.clone)
    if os.path.exists(os.path.join(clone, "freefem++.pref")):
        sys.exit(f"error: {clone}/freefem++.pref exists: remove it (FreeFEM would read its paths first)")
    first, last = (int(x) for x in args.steps.split(":"))
    here = os.path.dirname(os.path.abspath(__file__))
    build = os.path.join(clone, "plugin", "build")
    shutil.copy(os.path.join(here, "cgmark.cpp"), build)
    made = subprocess.run(["ff-c++", "cgmark.cpp"], cwd=build, capture_output=True, text=True)
    if made.returncode != 0:
        sys.exit(f"error: ff-c++ could not build cgmark.so in {build}:\n{made.stdout}{made.stderr}")
    dct = os.path.join(clone, STEP[0])
    source = open(dct).read()
    if "CgMark" not in source:  # the loader and the mark macro, once
        source = source.replace('include "heat.idp"\n', 'include "heat.idp"\nload "cgmark"\n'
                                'macro CGM(l) if (failureStep >= %d) if (failureStep <= %d) CgMark(l); //\n'
                                % (first, last), 1)
        open(dct, "w").write(source)
        texts = insert_marks(os.path.join(clone, LOOP[0]), *LOOP[1:])
        texts.update(insert_marks(dct, *STEP[1:]))
    else:
        sys.exit(f"error: {clone}'s scripts are marked already (a run of this tool): reset them (git checkout edp)")
    out = tempfile.mkdtemp(prefix="statement-costs-")
    subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}/cg.%p", "--trace-children=yes",
                    "--trace-children-skip=*readelf*,*dirname*,*sed*,*grep*,*cat*,*awk*", "tools/ff", args.scene,
                    "-out", os.path.join(out, "results")] + args.options
                   # (the run's statements, not its default mesh estimate's companion's)
                   + without_companion(args.scene, args.options),
                   cwd=clone, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    dumps = []
    for path in glob.glob(os.path.join(out, "cg.*")):
        text = open(path, errors="replace").read()
        label = re.search(r"Trigger: Client Request: (\S+)", text)
        part = re.search(r"^part: (\d+)", text, re.M)
        total = re.search(r"^(?:summary|totals): (\d+)", text, re.M)
        if label and part and total:
            dumps.append((int(part.group(1)), label.group(1), int(total.group(1))))
    dumps.sort()
    steps = last - first + 1
    spans = collections.OrderedDict()
    for (_, before, _), (_, label, count) in zip(dumps, dumps[1:]):
        spans.setdefault(before, []).append(count)
    print(f"instructions per step (mean of steps {first}-{last}), from each mark to the next; the marks' own ~1100 included")
    for label, counts in spans.items():
        note = "" if len(counts) >= steps - 1 else f"  ({len(counts)} of {steps} steps)"
        print(f"{sum(counts) / len(counts):10.0f}  {texts.get(label, label)[:110]}{note}")
    print(f"(callgrind dumps in {out})")


if __name__ == "__main__":
    main()
