#!/usr/bin/python3
"""Writes docs/parameter-reference.md: every command-line option of every scene and variant, its
default, its type and its meaning, read from the FreeFEM sources.

Usage: tools/param_reference.py [--out FILE] [--json]
  --out FILE  write there instead of docs/parameter-reference.md ('-': standard output)
  --json      print the parsed options as JSON instead (for tests/param_reference_test.py)

What it reads, per script (edp/scenes/*.edp and edp/variants/*.edp, sorted: new scenes are picked
up by the glob):
  * option calls, in the script and in the edp/lib files it includes (followed recursively, in
    include order; FreeFEM's own getARGV.idp is not followed). An option call is
        NAME("-option", default ...)
    where NAME is getARGV, or a wrapper whose name contains Option or Arg (OptionReal,
    RegisterOption, getArg, ...): the first argument must be a string literal starting with "-",
    the second is the default, any further argument is ignored (a wrapper may add a description
    or bounds). A name already found earlier (the scene, then its includes) is kept at its first
    occurrence, as FreeFEM would read the same command-line value for both.
  * the meaning: the // comment at the end of the line of the call; if none, the // comment lines
    right above the line (not a "// ----" banner); if none, a short glossary below, marked
    "(glossary)"; else "-". Put the unit first in the comment ("Pa: ...", "K: ...").
  * the scene parameter block: simple declarations in the scene file, `type name = value[, name =
    value];` (e.g. `real sleeveMu = 0;` before `include "sleeve.idp"`), so that a default that is
    such a variable, or a string concatenation of literals and such variables
    ("results/" + sleeveScene), is shown with the scene's value.
  * the type: what the command-line value must parse as (edp/lib/errors.idp's getARGV: the
    default's type is the option's): integer, number or text.
  * a default from the scene block without a comment on the option's line takes the comment of
    the variable's declaration in the scene (marked "scene block: name").
Regenerate with `make docs`; tests/param_reference_test.py fails when the file is out of date and
checks that each scene accepts every option found (a fast probe run that stops in CheckOptions).
"""
import argparse
import glob
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIB = os.path.join(ROOT, "edp", "lib")
SCRIPT_GLOBS = ["edp/scenes/*.edp", "edp/variants/*.edp"]
OUTPUT = os.path.join(ROOT, "docs", "parameter-reference.md")

CALL = re.compile(r'\b(getARGV|[A-Za-z_]\w*Option\w*|Option\w*|[A-Za-z_]\w*Arg\w*|Arg\w*)\s*\(\s*"(-[^"]*)"\s*,')
INCLUDE = re.compile(r'^\s*include\s+"([^"]+)"')
DECLARATION = re.compile(r'^\s*(real|int|bool|string)\s+(.*);')
TYPES = {"real": "number", "int": "integer", "bool": "integer", "string": "text"}

# Meanings of options that some sources read without a comment (fallback only).
GLOSSARY = {
    "-E": "Pa: Young's modulus (paper: 85 GPa)",
    "-nu": "Poisson's ratio (paper: 0.3)",
    "-rho": "kg/m^3: density (paper: 7900)",
    "-a": "J/(K kg): slope of alpha(T) = rho a (Tc - T) (paper: 300)",
    "-latent": "J/kg: latent heat L of the phase change (paper: 3000)",
    "-T0": "K: temperature where c(T) changes sign (paper: 210)",
    "-Tc": "K: temperature above which alpha = 0 (paper: 280)",
    "-plane": "2D model: strain or stress (docs/parameters.md)",
    "-dctol": "relative change of u that stops the DC loop",
    "-dcmaxit": "DC iteration limit (reaching it fails the run unless -keepgoing 1)",
    "-keepgoing": "1: warn and go on when a loop does not converge, 0: fail",
    "-out": "output directory",
    "-mesh": "mesh file",
    "-levels": "mesh levels, space-separated",
    "-quiet": "1: no progress lines",
    "-theta": "theta of the theta-method (1/2: Crank-Nicolson)",
    "-rannacher": "backward-Euler steps at the start (docs/formulation.md)",
    "-fptol": "relative change of T that stops the heat <-> phases fixed point",
    "-fpmaxit": "heat <-> phases fixed-point iteration limit",
    "-sliptol": "relative change of the slip threshold that stops the Coulomb fixed point",
    "-slipmaxit": "slip-threshold (Coulomb) fixed-point iteration limit",
    "-psormode": "contact solver: condensed (Delassus operator) or full (paper's PSOR)",
    "-omega": "PSOR over-relaxation (paper: 1.88)",
    "-psortol": "PSOR stop: relative change over a sweep",
    "-psormaxit": "PSOR sweep limit",
    "-psorpolish": "sweeps between active-set polish attempts (0: plain PSOR)",
    "-mu": "Coulomb friction coefficient",
    "-steps": "number of time steps",
    "-tend": "s: end time",
    "-seed": "seed of the random draw",
    "-Tinit": "K: initial temperature",
    "-Tlow": "K: lowest outside temperature of the thermal programme",
    "-Thigh": "K: highest outside temperature of the thermal programme",
    "-tcool": "s: duration of the cooling ramp",
    "-thold": "s: duration of each hold",
    "-theat": "s: duration of the heating ramp",
    "-dt": "s: time step",
    "-pipeA": "m: pipe semi-axis along x (a circle when equal to -pipeB)",
    "-pipeB": "m: pipe semi-axis along y",
    "-cdist": "law of the random transformation temperature: normal or uniform",
    "-Ri": "m: inner radius of the ring",
    "-Ro": "m: outer radius of the ring",
    "-Rp": "m: pipe radius",
    "-C0": "J/(kg K): heat capacity (not in the paper)",
    "-k": "W/(m K): conductivity (not in the paper)",
    "-g": "W/(m^2 K): exchange coefficient (paper: 500)",
    "-gcontact": "W/(m^2 K): exchange coefficient where in contact",
    "-Text": "K: outside (air and pipe) temperature",
}


def strip_comment(line):
    """(code, comment) of one line: the comment after the first // outside a string literal."""
    in_string = False
    for i, ch in enumerate(line):
        if ch == '"':
            in_string = not in_string
        elif not in_string and line.startswith("//", i):
            return line[:i], line[i + 2:].strip()
    return line, ""


def argument_end(text, start):
    """Index just past the argument starting at text[start] (ends at a top-level , or ))."""
    depth, i, in_string = 0, start, False
    while i < len(text):
        ch = text[i]
        if in_string:
            if ch == '"':
                in_string = False
        elif ch == '"':
            in_string = True
        elif ch in "([":
            depth += 1
        elif ch in ")]":
            if depth == 0:
                return i
            depth -= 1
        elif ch == "," and depth == 0:
            return i
        i += 1
    return i


def split_top_level(text):
    """Splits at the commas outside parentheses and strings."""
    parts, start = [], 0
    while start <= len(text):
        end = argument_end(text, start)
        parts.append(text[start:end].strip())
        if end >= len(text) or text[end] == ")":
            break
        start = end + 1
    return parts


def literal(expr):
    """(value, type) of a literal, or None."""
    expr = expr.strip()
    if re.fullmatch(r'"[^"]*"', expr):
        return expr[1:-1], "text"
    if re.fullmatch(r"[+-]?\d+", expr):
        return expr, "integer"
    if re.fullmatch(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", expr):
        return expr, "number"
    return None


def resolve(expr, block):
    """Value and type of a default expression: a literal, a scene block variable, or a string
    concatenation of those; (expr, None) when it cannot be resolved."""
    found = literal(expr)
    if found:
        return found
    if expr in block:
        return block[expr]
    parts = [p.strip() for p in expr.split("+")]
    if len(parts) > 1:
        values = [literal(p) or block.get(p) for p in parts]
        if all(values) and any(t == "text" for _, t in values):
            return "".join(v for v, _ in values), "text"
    return expr, None


def add_declarations(code, comment, block, owner, keep_existing=False):
    """Adds the simple declarations `type name = value[, ...];` of one line of code to block
    (name -> (value, type)), their comment to block_comments under owner (a scene file);
    keep_existing: a name already in block keeps its value."""
    m = DECLARATION.match(code)
    if not m or "getARGV" in code:
        return
    for part in split_top_level(m.group(2)):
        name, _, value = (s.strip() for s in part.partition("="))
        if not value or not re.fullmatch(r"[A-Za-z_]\w*", name) or (keep_existing and name in block):
            continue
        found = resolve(value, block)
        if found[1]:
            block[name] = (found[0], TYPES[m.group(1)] if found[1] != "text" else "text")
            block_comments[(owner, name)] = comment


def scene_block(path):
    """Simple declarations `type name = value[, ...];` of a scene file: name -> (value, type)."""
    block = {}
    for line in open(path, encoding="utf-8"):
        add_declarations(*strip_comment(line), block, path)
    return block


block_comments = {}  # (scene file, variable) -> the comment of its declaration line


def first_sentence(text):
    """Text up to the end of its first sentence (a period followed by a space)."""
    cut = text.find(". ")
    return text if cut < 0 else text[:cut + 1]


def comment_above(lines, index):
    """First sentence of the // lines right above lines[index] (no blank line, no "// ----"
    banner)."""
    above = []
    j = index - 1
    while j >= 0:
        stripped = lines[j].strip()
        if not stripped.startswith("//") or stripped.startswith("// ----") or stripped.startswith("//---"):
            break
        above.insert(0, stripped[2:].strip())
        j -= 1
    return first_sentence(" ".join(above))


def options_of_file(path, seen_files, block, found, scene_path=None):
    """Appends the option calls of `path` and of the edp/lib files it includes to `found`."""
    scene_path = scene_path or path
    real_path = os.path.realpath(path)
    if real_path in seen_files:
        return
    seen_files.add(real_path)
    lines = open(path, encoding="utf-8").read().split("\n")
    rel = os.path.relpath(path, ROOT)
    for index, line in enumerate(lines):
        code, comment = strip_comment(line)
        if path != scene_path:
            # A library's own default (e.g. sleeve.idp's dctPhaseModelDefault): the scene's wins.
            add_declarations(code, comment, block, scene_path, keep_existing=True)
        inc = INCLUDE.match(code)
        if inc:
            lib = os.path.join(LIB, inc.group(1))
            if os.path.isfile(lib):
                options_of_file(lib, seen_files, block, found, scene_path)
            continue
        for m in CALL.finditer(code):
            name = m.group(2)
            start = m.end()
            end = argument_end(code, start)
            default_expr = code[start:end].strip()
            value, kind = resolve(default_expr, block)
            variables = [t for t in re.findall(r"[A-Za-z_]\w*", default_expr) if t in block]
            from_block = " ".join(block_comments.get((scene_path, v), "") for v in variables).strip()
            meaning = comment or (f"{from_block} (scene block: {', '.join(variables)})" if from_block else "") \
                or comment_above(lines, index)
            source = "comment"
            if not meaning and name in GLOSSARY:
                meaning, source = GLOSSARY[name] + " (glossary)", "glossary"
            if any(o["name"] == name for o in found):
                continue
            found.append({"name": name, "default": value, "type": kind or "expression",
                          "default_expression": default_expr,
                          "from_scene_block": any(t in block for t in re.findall(r"[A-Za-z_]\w*", default_expr)),
                          "meaning": meaning or "-", "meaning_source": source if meaning else "none",
                          "where": f"{rel}:{index + 1}", "call": m.group(1)})


def parse_all():
    """{script name: {"path", "kind", "options": [...], "block": {...}, "checks_options"}}."""
    scripts = {}
    for pattern in SCRIPT_GLOBS:
        for path in sorted(glob.glob(os.path.join(ROOT, pattern))):
            name = os.path.splitext(os.path.basename(path))[0]
            block = scene_block(path)
            found, files = [], set()
            options_of_file(path, files, block, found)
            text = "".join(open(f, encoding="utf-8").read() for f in files)
            scripts[name] = {"path": os.path.relpath(path, ROOT),
                             "kind": "scene" if "/scenes/" in path else "variant",
                             "options": found, "block": {k: v[0] for k, v in block.items()},
                             "checks_options": bool(re.search(r"^\s*CheckOptions\s*\(", text, re.M))}
    return scripts


def markdown(scripts):
    def cell(text):
        return str(text).replace("|", "\\|")

    out = ["# Parameter reference", "",
           "Generated by `tools/param_reference.py` from the scripts' option calls (`make docs`; do not edit:",
           "`tests/param_reference_test.py` fails when this file is out of date). Every option is given on",
           "the command line as `-name value` (`make run SCENE=<scene> ARGS='-name value'`, or",
           "`tools/ff <script> -name value`); a name a script does not read is refused",
           "(`CheckOptions`, edp/lib/errors.idp). Defaults marked * come from the scene's parameter block",
           "(the variables it sets before `include \"sleeve.idp\"`). Meanings are the sources' comments;",
           "where the source has none, a glossary entry of the generator (marked so). Why each value:",
           "docs/parameters.md.", ""]
    for kind, title in (("scene", "Scenes (edp/scenes)"), ("variant", "Variants (edp/variants, docs/variants.md)")):
        out += [f"## {title}", ""]
        for name, s in scripts.items():
            if s["kind"] != kind:
                continue
            out += [f"### {name}", "", f"`{s['path']}`, {len(s['options'])} options.", "",
                    "| option | default | type | meaning | read at |", "|---|---|---|---|---|"]
            for o in s["options"]:
                default = o["default"] if o["type"] != "text" else f"\"{o['default']}\""
                mark = " *" if o["from_scene_block"] else ""
                out.append(f"| `{o['name']}` | `{cell(default)}`{mark} | {o['type']} | {cell(o['meaning'])} | "
                           f"{o['where']} |")
            out.append("")
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=OUTPUT)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    scripts = parse_all()
    if args.json:
        json.dump(scripts, sys.stdout, indent=1)
        return
    text = markdown(scripts)
    if args.out == "-":
        sys.stdout.write(text)
        return
    with open(args.out + ".partial", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(args.out + ".partial", args.out)
    print(f"wrote {os.path.relpath(args.out, ROOT)}: {sum(len(s['options']) for s in scripts.values())} options "
          f"of {len(scripts)} scripts")


if __name__ == "__main__":
    main()
