#!/usr/bin/python3
"""Writes docs/parameter-reference.md: every command-line option of every scene, variant, benchmark
and ensemble driver, with its type, default and meaning, as the script itself prints them.

Usage: tools/docs/param_reference.py [--out FILE] [--json]
  --out FILE  write there instead of docs/parameter-reference.md ('-': standard output)
  --json      print the options as JSON instead: {script: {"path", "kind", "options": [{"name",
              "type", "default", "meaning"}, ...]}}

How: each script (edp/scenes/*.edp, edp/variants/*.edp, edp/bench/*.edp, sorted; new ones are
picked up by the globs) is run with `-help tsv` through tools/ff (the ensemble driver, which needs
FreeFem++-mpi, through mpiexec -np 1 FreeFem++-mpi). edp/lib/errors.idp then prints every option the script
read, in the order read, as tab-separated `option, type, default, meaning` rows after a header
line, and exits 0 at the end of the parameter block (CheckOptions), before any computation: the
defaults are the values the script would use, the meanings the third argument of its getARGV
calls. Nothing is parsed from the sources. An empty meaning (a getARGV call with two arguments) is
shown as "(undocumented)"; tests/param_reference_test.py fails on one only for the scripts it
lists as documented.

Layout of the file: the sleeve scenes (edp/scenes/sleeve-*.edp) share most options, so one table
holds every option read by at least half of them with the default (and meaning) most of them
have, and a short table per sleeve scene and sleeve variant lists only what differs; another
variant lists only what differs from the scene it derives from (base_scene: beam-p2 from beam,
ring-lobed from ring-lame); the other scripts get a full table each. Deterministic: the same sources give the same bytes. About 1 s (one FreeFEM start per
script, run in parallel).

Regenerate with `make docs`; tests/param_reference_test.py fails when the file is out of date.
"""
import argparse
import collections
import concurrent.futures
import glob
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "python"))  # this checkout's sma package (python/sma)
from sma.helptsv import parse_tsv  # noqa: E402,F401  (the one parser of -help tsv)
OUTPUT = os.path.join(ROOT, "docs", "parameter-reference.md")
# (glob, kind), in the order of the file's sections.
SCRIPT_GLOBS = [("edp/scenes/*.edp", "scene"), ("edp/variants/*.edp", "variant"),
                ("edp/bench/*.edp", "bench"), ("edp/ensemble/*.edp", "ensemble"), ("edp/mpi/*.edp", "mpi")]
# A scene's version on MPI ranks (edp/mpi) is listed as "<scene> on MPI ranks", against the scene's table.
MPI_SUFFIX = " on MPI ranks"
UNDOCUMENTED = "(undocumented)"
TIMEOUT = 120  # s; a script that does not stop in CheckOptions would run its whole computation


def scripts():
    """[(name, path relative to ROOT, kind)], in section order, each glob sorted."""
    found = []
    for pattern, kind in SCRIPT_GLOBS:
        for path in sorted(glob.glob(os.path.join(ROOT, pattern)), key=lambda p: os.path.basename(p)[:-4]):
            name = os.path.splitext(os.path.basename(path))[0] + (MPI_SUFFIX if kind == "mpi" else "")
            found.append((name, os.path.relpath(path, ROOT), kind))
    return found


def help_command(path, kind, fmt="tsv"):
    """The command that prints the options of the script at `path` (relative to ROOT), and its
    environment."""
    help_args = ["-help"] + ([fmt] if fmt else [])
    if kind == "ensemble":
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   FF_INCLUDEPATH=f"{ROOT}/edp/lib;{ROOT}/edp/model;{ROOT}/edp/solvers;{ROOT}/edp/problems;/usr/include/freefem++/idp;./")
        return ["mpiexec", "--oversubscribe", "-np", "1", "FreeFem++-mpi", "-nw", "-ne", "-v", "0", path] \
            + help_args, env
    if kind == "mpi":
        return [os.path.join(ROOT, "tools", "ff-mpi"), "1", path] + help_args, None
    return [os.path.join(ROOT, "tools", "ff"), path] + help_args, None


def read_options(entry):
    """Runs one script with -help tsv; returns its entry for collect()."""
    name, path, kind = entry
    argv, env = help_command(path, kind)
    try:
        run = subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        raise ValueError(f"{name}: '{' '.join(argv)}' did not stop within {TIMEOUT} s (does the "
                         "script call CheckOptions at the end of its parameter block?)")
    if run.returncode != 0:
        raise ValueError(f"{name}: '{' '.join(argv)}' exited {run.returncode}: "
                         f"{(run.stdout + run.stderr).strip()[-600:]}")
    return name, {"path": path, "kind": kind, "options": parse_tsv(name, run.stdout)}


def collect():
    """{script name: {"path", "kind", "options"}}, in the order of scripts()."""
    entries = scripts()
    with concurrent.futures.ThreadPoolExecutor(max_workers=min(8, os.cpu_count() or 1)) as pool:
        return dict(pool.map(read_options, entries))


def is_sleeve(name, script):
    return script["kind"] == "scene" and name.startswith("sleeve-")


def common_options(sleeves):
    """The shared table: {option: {"type", "default", "meaning", "order"}} for the options read by
    at least half of the sleeve scenes; type and default: the pair most of the scenes that read
    it have (None when no two of them agree: then every scene lists its own), ties to the first
    scene in sorted order; meaning: the most frequent non-empty one, likewise."""
    readers = collections.defaultdict(list)  # option -> [(scene, option dict)], scenes in order
    for scene, script in sleeves.items():
        for o in script["options"]:
            readers[o["name"]].append((scene, o))
    common = {}
    for option, read in readers.items():
        if 2 * len(read) < len(sleeves):
            continue
        pairs = collections.Counter((o["type"], o["default"]) for _, o in read)
        best = max(pairs.values())
        pair = next((o["type"], o["default"]) for _, o in read if pairs[(o["type"], o["default"])] == best)
        meanings = collections.Counter(o["meaning"] for _, o in read if o["meaning"])
        meaning = ""
        if meanings:
            top = max(meanings.values())
            meaning = next(o["meaning"] for _, o in read if o["meaning"] and meanings[o["meaning"]] == top)
        types = {o["type"] for _, o in read}
        common[option] = {"type": pair[0] if len(types) == 1 else None,
                          "default": pair if best > 1 or len(read) == 1 else None,
                          "meaning": meaning, "readers": len(read)}
    # In the order of first appearance, scanning the scenes in order.
    first_seen = {}
    for scene, script in sleeves.items():
        for o in script["options"]:
            first_seen.setdefault(o["name"], len(first_seen))
    return dict(sorted(common.items(), key=lambda item: first_seen[item[0]]))


def cell(text):
    """Text for a table cell: | escaped, and < (GitHub would take <level> or <s> for a tag)."""
    return str(text).replace("|", "\\|").replace("<", "&lt;")


def shown_default(option_type, default):
    """The default as a code span (a string in double quotes)."""
    code = default.replace("|", "\\|")
    return f"`\"{code}\"`" if option_type == "string" else f"`{code}`"


def shown_meaning(meaning):
    return cell(meaning) if meaning else UNDOCUMENTED


def full_table(options):
    out = ["| option | type | default | meaning |", "|---|---|---|---|"]
    for o in options:
        out.append(f"| `{o['name']}` | {o['type']} | {shown_default(o['type'], o['default'])} | "
                   f"{shown_meaning(o['meaning'])} |")
    return out


def differences(name, s, common, against="the shared table"):
    """The section of a script read against a table of options (the sleeve scenes' shared table, or
    the scene a variant derives from): its options that are not in it, or whose type, default or
    meaning differ from it, then the options of the table it does not read."""
    names = {o["name"] for o in s["options"]}
    rows = []
    for o in s["options"]:
        c = common.get(o["name"])
        if c and c["default"] == (o["type"], o["default"]) and o["meaning"] == c["meaning"]:
            continue
        meaning = "as above" if c and o["meaning"] == c["meaning"] and c["meaning"] else shown_meaning(o["meaning"])
        rows.append(f"| `{o['name']}` | {o['type']} | {shown_default(o['type'], o['default'])} | {meaning} |")
    missing = [option for option in common if option not in names]
    out = [f"### {name}", "", f"`{s['path']}`: {len(s['options'])} options; "
           f"{len(rows)} differ from {against}" + (":" if rows else "."), ""]
    if rows:
        out += ["| option | type | default | meaning |", "|---|---|---|---|"] + rows + [""]
    if missing:
        out += ["Does not read: " + ", ".join(f"`{m}`" for m in missing) + ".", ""]
    return out


def base_scene(name, scenes):
    """The scene a variant derives from: the one named by the variant's first word (beam-p2: beam)
    or, failing that, the only scene whose name starts with that word (ring-lobed: ring-lame)."""
    word = name.split("-")[0]
    if word in scenes:
        return word
    named = [n for n in scenes if n.startswith(word + "-")]
    return named[0] if len(named) == 1 else None


def as_table(options):
    """A scene's options in the form of the shared table (for differences())."""
    return {o["name"]: {"default": (o["type"], o["default"]), "meaning": o["meaning"]} for o in options}


def sections_of(text):
    """{name: its text} of the ### sections of a reference (to name the scripts that changed)."""
    found, name = {}, None
    for line in text.splitlines():
        if line.startswith("### "):
            name = line[4:].strip()
            found[name] = []
        elif line.startswith("## "):
            name = None
        elif name is not None:
            found[name].append(line)
    return {n: "\n".join(lines) for n, lines in found.items()}


def markdown(all_scripts):
    sleeves = {n: s for n, s in all_scripts.items() if is_sleeve(n, s)}
    common = {}
    others = {n: s for n, s in all_scripts.items() if not is_sleeve(n, s)}
    out = ["# Parameter reference", "",
           "Generated by `tools/docs/param_reference.py` (`make docs`; do not edit: `tests/param_reference_test.py`",
           "fails when this file is out of date) from what each script prints with `-help tsv`: every option",
           "it reads, in the order read, with the default it uses and the meaning its `getARGV` call gives",
           "(`edp/lib/errors.idp`). `tools/ff <script> -help` prints the same for one script. Options are",
           "given as `-name value` (`make run SCENE=<scene> ARGS='-name value'`, or `tools/ff <script> -name",
           "value`); a name a script does not read is refused (`CheckOptions`). Types: `int` (digits), `real`",
           "(a decimal number), `string`. Real defaults have 6 significant digits, more where 6 would not read",
           f"back as the same double. {UNDOCUMENTED}: the script reads the option without a meaning yet. Why",
           "each value: docs/parameters.md.", ""]
    if sleeves:
        common = common_options(sleeves)
        out += ["## Sleeve scenes", "",
                f"The {len(sleeves)} sleeve scenes (`edp/scenes/sleeve-*.edp`) share most options. The first table",
                "lists every option read by at least half of them, with the type, default and meaning most of",
                "them have (\"per scene\": no two agree). Each scene's table then lists only what differs: its",
                "options that are not in the first table, and those whose type, default or meaning is not the",
                "one shown there (\"as above\": the same meaning); then the options of the first table it does",
                "not read.", "", "### Options shared by the sleeve scenes", "",
                "| option | type | default | meaning | read by |", "|---|---|---|---|---|"]
        for option, c in common.items():
            default = shown_default(c["default"][0], c["default"][1]) if c["default"] else "per scene"
            readers = "all" if c["readers"] == len(sleeves) else f"{c['readers']} of {len(sleeves)}"
            out.append(f"| `{option}` | {c['type'] or 'per scene'} | {default} | {shown_meaning(c['meaning'])} "
                       f"| {readers} |")
        out.append("")
        for name, s in sleeves.items():
            out += differences(name, s, common)
    sections = [("scene", "Other scenes (edp/scenes)"), ("variant", "Variants (edp/variants, docs/variants.md)"),
                ("bench", "Benchmark (edp/bench, docs/benchmarks.md)"),
                ("ensemble", "Ensemble driver (edp/ensemble, docs/ensembles.md)"),
                ("mpi", "On MPI ranks (edp/mpi, docs/model.md#the-scene-on-ffddm)")]
    for kind, title in sections:
        chosen = {n: s for n, s in others.items() if s["kind"] == kind}
        if not chosen:
            continue
        out += [f"## {title}", ""]
        if kind == "variant":
            out += ["Each variant lists only what differs from the table it derives from: a sleeve variant from",
                    "the sleeve scenes' shared table, another from its scene's (\"as above\": the same meaning).", ""]
        for name, s in chosen.items():
            if kind == "mpi":
                # The scene's options and the distributed run's: only what differs from the scene is listed.
                base = name[:-len(MPI_SUFFIX)]
                out += differences(name, s, as_table(all_scripts[base]["options"]), f"{base}'s table (above)")
                continue
            if common and kind == "variant" and name.startswith("sleeve-"):
                # A sleeve variant reads the sleeve scenes' options: only what differs is listed.
                out += differences(name, s, common)
                continue
            base = base_scene(name, {n: o for n, o in others.items() if o["kind"] == "scene"}) \
                if kind == "variant" else None
            if base:
                # Another variant: only what differs from the scene it derives from.
                out += differences(name, s, as_table(others[base]["options"]), f"{base}'s table (above)")
                continue
            out += [f"### {name}", "", f"`{s['path']}`: {len(s['options'])} options.", ""]
            if kind == "ensemble":
                out += ["Every other `-name value` pair goes unchanged to each run of `sleeve-random-threshold`",
                        "(its options: above); run it with `ff-mpirun` (`make ensemble ARGS='-help'` prints these).", ""]
            out += full_table(s["options"]) + [""]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=OUTPUT)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    try:
        all_scripts = collect()
    except ValueError as e:
        sys.exit(f"error: {e}")
    if args.json:
        json.dump(all_scripts, sys.stdout, indent=1)
        return
    text = markdown(all_scripts)
    if args.out == "-":
        sys.stdout.write(text)
        return
    with open(args.out + ".partial", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(args.out + ".partial", args.out)
    undocumented = sum(1 for s in all_scripts.values() for o in s["options"] if not o["meaning"])
    print(f"wrote {os.path.relpath(args.out, ROOT)}: {sum(len(s['options']) for s in all_scripts.values())} "
          f"options of {len(all_scripts)} scripts ({undocumented} undocumented)")


if __name__ == "__main__":
    main()
