#!/usr/bin/python3
"""-help on every script, and docs/parameter-reference.md generated from it
(tools/docs/param_reference.py, edp/lib/errors.idp).

  * the reference regenerated from the scripts' `-help tsv` equals docs/parameter-reference.md
    byte for byte (else: make docs);
  * every option of every script (found, not listed) has a meaning, except the options of PENDING (read
    by library files not converted yet), and each PENDING entry is still needed;
  * probe run per script: every option -help printed, given at its printed default, then one
    unknown option last: CheckOptions must refuse only the probe (so every default parses as the
    printed type), and the names it says the script reads must be the printed ones, in order; a
    scene or variant names itself (the refusal's "error: <name>:") after its file and its -out
    default is results/<name> or results/variants/<name> (where make run reads);
  * the printed defaults are the values the scenes use: beam, ring-lame and free-ring are run (on
    one mesh level, a short programme) and their summary.json parameters compared with -help;
  * -help anywhere among the options (alone, with "text", after -name value pairs, beside an
    unknown option or a malformed value) prints the same text, in the format errors.idp documents,
    agreeing with -help tsv, without FreeFEM's exit trailer, exits 0 and writes nothing;
  * errors.idp's own rules, on small scripts: a two-argument getARGV is listed "(undocumented)",
    an option read twice once, a real default with more than 6 digits reads back exactly, normal
    runs still parse values, and an option read after CheckOptions fails the run.
Writes results/checks/param_reference.json.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools", "docs"))

from checklib import ROOT, TEST_RESULTS, check, finish, record  # noqa: E402
import param_reference  # noqa: E402

# Every script's every option must have a meaning (getARGV's third argument): a new scene or
# variant is checked as soon as its file exists, without being listed anywhere.
# Options read by library files that are not converted yet: allowed without a meaning, for now.
# Delete an entry once its file gives the meaning (the test fails while an entry is not needed).
PENDING = {}
PROBE = "-paramreferenceprobe"
FF = os.path.join(ROOT, "tools", "ff")
# A line of -help text (errors.idp's header): name, type, default (a string in quotes), meaning.
HELP_LINE = re.compile(r'^  (?P<name>-\S+) +(?P<type>int|real|string) +(?P<default>"[^"]*"|\S+) +(?P<meaning>\S.*)$')


def ff(*args, timeout=120):
    return subprocess.run([FF, *args], cwd=ROOT, capture_output=True, text=True, timeout=timeout)


def generated(scripts):
    current_path = os.path.join(ROOT, "docs", "parameter-reference.md")
    current = open(current_path, encoding="utf-8").read() if os.path.exists(current_path) else ""
    fresh = param_reference.markdown(scripts)
    stale = ""
    if fresh != current:
        old, new = param_reference.sections_of(current), param_reference.sections_of(fresh)
        changed = [f"{n} (new)" for n in new if n not in old] + [f"{n} (gone)" for n in old if n not in new] \
            + [n for n in new if n in old and new[n] != old[n]]
        stale = f": it is stale for {', '.join(changed) or 'its shared sleeve table or headings'}; run `make docs`"
    check(fresh == current, "docs/parameter-reference.md is what the scripts' -help gives" + stale)


def documented(scripts):
    still_pending = set()
    for name, s in scripts.items():
        empty = [o["name"] for o in s["options"] if not o["meaning"]]
        still_pending |= set(empty) & set(PENDING)
        missing = [o for o in empty if o not in PENDING]
        check(not missing, f"{name}: every option has a meaning ({len(s['options'])} options; "
              f"without: {missing or 'none'}; pending library options: "
              f"{sorted(set(empty) & set(PENDING)) or 'none'})")
    for option, where in sorted(PENDING.items()):
        check(option in still_pending, f"{option} ({where}) is still undocumented somewhere (else delete it "
              "from PENDING)")


def probe(name, s):
    argv = [s["path"]]
    for o in s["options"]:
        argv += [o["name"], o["default"]]
    run = ff(*argv, PROBE, "1", timeout=60)
    message = next((line for line in (run.stdout + run.stderr).splitlines() if "unknown option" in line), "")
    check(run.returncode != 0 and f"unknown option {PROBE} " in message,
          f"{name}: all {len(s['options'])} options accepted at their printed defaults, the probe refused"
          + ("" if message else f" (exit {run.returncode}: {(run.stdout + run.stderr).strip()[-300:]})"))
    if s["kind"] in OWN_FOLDER:
        own_names(name, s, message)
    read = re.search(r" reads (.*)\)\s*$", message)
    registered = read.group(1).split() if read else []
    printed = [o["name"] for o in s["options"]]
    check(registered == printed, f"{name}: -help lists the {len(registered)} options the script reads, "
          f"in order (missed {sorted(set(registered) - set(printed))}, invented "
          f"{sorted(set(printed) - set(registered))})")
    return {"options": len(printed), "registered": len(registered),
            "undocumented": sum(1 for o in s["options"] if not o["meaning"])}


# A scene's or a variant's results folder, where make run looks for them (the Makefile's RUN_RESULTS).
OWN_FOLDER = {"scene": "results/{}", "variant": "results/variants/{}"}


def own_names(name, s, message):
    """A scene or variant names itself after its file, and writes by default where make run reads
    (a copied variant that kept the original's name wrote into the original's folder, and make run
    then found no summary.json in its own)."""
    said = re.match(r"error: (\S+): unknown option", message)
    out = next((o["default"] for o in s["options"] if o["name"] == "-out"), None)
    folder = OWN_FOLDER[s["kind"]].format(name)
    check(said and said.group(1) == name and out == folder,
          f"{s['path']}: names itself {said.group(1) if said else '?'} (messages, summary.json) and writes to "
          f"-out {out} by default: both must be its file's name, {name} and {folder} (a copied script keeps "
          "the original's: set them, as docs/variants.md says)")


def same_value(printed, used):
    """A -help default against the value a summary.json reports (12 significant digits)."""
    if isinstance(used, str):
        return printed == used
    return abs(float(printed) - used) <= 1e-11 * max(abs(used), 1e-300)


def used_defaults(scripts):
    """Runs beam, ring-lame and free-ring at their defaults (but for a shorter run) and compares
    the parameters their summary.json reports with the defaults -help prints."""
    runs = {
        "beam": (["-levels", "coarse", "-quiet", "1"], lambda j: j["parameters"],
                 {"-E": "E", "-nu": "nu", "-alpha": "alpha", "-c": "c", "-F": "F", "-plane": "plane",
                  "-dctol": "dc_tol", "-dcmaxit": "dc_maxit"}),
        "ring-lame": (["-levels", "l1", "-quiet", "1"], lambda j: dict(j, **j["levels"][0]),
                      {"-psormode": "psor_mode", "-mu": "mu", "-omega": "omega", "-psortol": "psor_tol",
                       "-psorpolish": "psor_polish", "-E": "E", "-nu": "nu", "-Ri": "Ri", "-Ro": "Ro",
                       "-Rp": "Rp", "-plane": "plane"}),
        "free-ring": (["-tcool", "4", "-thold", "2", "-theat", "4", "-quiet", "1"], lambda j: j["parameters"],
                      {"-E": "E", "-nu": "nu", "-rho": "rho", "-a": "a", "-latent": "latent", "-T0": "T0",
                       "-Tc": "Tc", "-C0": "C0", "-k": "k", "-g": "g", "-plane": "plane", "-Tinit": "Tinit",
                       "-Tlow": "Tlow", "-Thigh": "Thigh", "-dt": "dt", "-theta": "theta",
                       "-rannacher": "rannacher", "-dctol": "dc_tol", "-fptol": "fp_tol", "-mesh": "mesh"}),
    }
    compared = {}
    for name, (args, parameters, keys) in runs.items():
        out = os.path.join(TEST_RESULTS, f"param-reference-{name}")
        run = ff(scripts[name]["path"], "-out", out, *args)
        check(run.returncode == 0, f"{name}: the short run at the defaults succeeds (exit {run.returncode})")
        if run.returncode != 0:
            print((run.stdout + run.stderr)[-600:])
            continue
        used = parameters(json.load(open(os.path.join(out, "summary.json"))))
        printed = {o["name"]: o["default"] for o in scripts[name]["options"]}
        wrong = {option: (printed.get(option), used.get(key)) for option, key in keys.items()
                 if option not in printed or key not in used or not same_value(printed[option], used[key])}
        check(not wrong, f"{name}: the {len(keys)} defaults -help prints are the values summary.json reports "
              f"(differing: {wrong or 'none'})")
        compared[name] = sorted(keys)
    return compared


def help_modes(scripts):
    """beam's -help in every position gives the same documented text, agreeing with -help tsv."""
    beam = scripts["beam"]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "never-written")
        variants = [["-help"], ["-help", "text"], ["-out", out, "-help"], ["-help", "-out", out],
                    ["-help", "-stpes", "abc"], ["-dcmaxit", "1e3", "-help"], ["-quiet", "1", "-help", "-levels"]]
        texts = []
        for args in variants:
            run = ff(beam["path"], *args)
            check(run.returncode == 0, f"beam {' '.join(args)}: exit 0 (exit {run.returncode})")
            texts.append(run.stdout)
        check(all(t == texts[0] for t in texts), f"beam: the same -help text in all {len(variants)} positions")
        check(not os.path.exists(out), "beam -help writes nothing (stops in CheckOptions)")
    lines = texts[0].rstrip("\n").split("\n")
    check("exit(0)" not in texts[0] and "err code" not in texts[0], "tools/ff drops FreeFEM's exit trailer")
    check(lines[0].startswith(f"beam: {len(beam['options'])} options ("),
          f"title line 'beam: {len(beam['options'])} options (...': {lines[0]!r}")
    rows = [HELP_LINE.match(line) for line in lines[1:]]
    check(len(rows) == len(beam["options"]) and all(rows),
          f"one line per option in the documented format ({len(rows)} lines, {len(beam['options'])} options)")
    if all(rows):
        as_tsv = [{"name": m["name"], "type": m["type"],
                   "default": m["default"][1:-1] if m["type"] == "string" else m["default"],
                   "meaning": "" if m["meaning"] == param_reference.UNDOCUMENTED else m["meaning"]} for m in rows]
        check(as_tsv == beam["options"], "-help text and -help tsv give the same names, types, defaults, meanings")
        widths = {len(line) - len(m["meaning"]) for line, m in zip(lines[1:], rows)}
        check(len(widths) == 1, f"-help text: the meanings start in one column ({sorted(widths)})")


def errors_rules():
    """errors.idp on small scripts of its own."""
    with tempfile.TemporaryDirectory() as tmp:
        both = os.path.join(tmp, "both.edp")
        with open(both, "w") as f:
            f.write('include "errors.idp"\n'
                    'real a = getARGV("-a", 1.23456789, "m: a length");\n'
                    'int b = getARGV("-b", 3);\n'
                    'real again = getARGV("-a", 1.23456789);\n'
                    'string s = getARGV("-s", "", "an empty default");\n'
                    'CheckOptions("both");\n'
                    'cout << "values " << a << " " << b << " [" << s << "]" << endl;\n')
        run = ff(both, "-help", "tsv")
        check(run.returncode == 0, f"a two- and three-argument script: -help tsv exits 0 (exit {run.returncode})")
        try:
            options = param_reference.parse_tsv("both", run.stdout)
        except ValueError as e:
            options = []
            print(e)
        check([o["name"] for o in options] == ["-a", "-b", "-s"], f"-a read twice, listed once: {options}")
        if len(options) == 3:
            check(options[0]["type"] == "real" and float(options[0]["default"]) == 1.23456789
                  and options[0]["meaning"] == "m: a length",
                  f"a real default with 9 digits reads back exactly ({options[0]['default']}), the first meaning kept")
            check(options[1] == {"name": "-b", "type": "int", "default": "3", "meaning": ""},
                  "a two-argument getARGV: an int option with an empty meaning")
            check(options[2]["default"] == "" and options[2]["type"] == "string", "an empty string default")
        text = ff(both, "-help").stdout
        check("-b" in text and "(undocumented)" in text.split("-b", 1)[1].split("\n")[0],
              "-help text lists the two-argument option as (undocumented)")
        run = ff(both, "-a", "2.5", "-b", "5", "-s", "x")
        check(run.returncode == 0 and "values 2.5 5 [x]" in run.stdout,
              f"without -help the values are parsed: {run.stdout.strip()[:80]!r}")
        late = os.path.join(tmp, "late.edp")
        with open(late, "w") as f:
            f.write('include "errors.idp"\nreal a = getARGV("-a", 1., "m: a");\nCheckOptions("late");\n'
                    'int b = getARGV("-b", 2, "read too late");\n')
        run = ff(late)
        check(run.returncode != 0 and "error: option -b is read after CheckOptions" in run.stdout + run.stderr,
              f"an option read after CheckOptions fails the run (exit {run.returncode})")


def main():
    scripts = param_reference.collect()
    generated(scripts)
    documented(scripts)
    measured = {}
    for name, s in scripts.items():
        # ensemble: no CheckOptions, it passes unknown options on to its children; mpi: its
        # options are its scene's (probed here) and ffddm's and its own, which
        # tests/sleeve_3d_mpi_test.py gives (its sequential first step refuses an unknown one)
        if s["kind"] in ("ensemble", "mpi"):
            measured[name] = {"options": len(s["options"]),
                              "undocumented": sum(1 for o in s["options"] if not o["meaning"])}
            continue
        measured[name] = probe(name, s)
    compared = used_defaults(scripts)
    help_modes(scripts)
    errors_rules()
    record("param_reference", {"test": "param_reference", "documented": sorted(scripts), "pending": PENDING,
                               "scripts": measured, "defaults_compared_with_summary": compared})
    finish()


if __name__ == "__main__":
    main()
