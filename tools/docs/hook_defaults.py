#!/usr/bin/python3
"""Writes the default body of every hook of docs/hooks.md's main table into that page.

A variant author replaces a hook by defining its macro first; to write one, the default is what to
start from (a heating-ramp variant needed ContactHeatExchange, gContact and gPipe, found by reading
time-loop.idp). For each row of the table under "## The hooks", the hook's `macro` in the file(s)
its row names, as written there (to its closing `//` or `// EOM`), and the `func` that macro calls
when the same file defines it. The section between the markers below is replaced; the rest of the
page is the authors'.

Usage: tools/docs/hook_defaults.py           rewrite the section of docs/hooks.md
       tools/docs/hook_defaults.py --check   exit 1 when the section is not what the sources give
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAGE = os.path.join(ROOT, "docs", "hooks.md")
BEGIN, END = "<!-- hook defaults: written by tools/docs/hook_defaults.py -->", "<!-- end of hook defaults -->"


def table_hooks(text):
    """[(hook name, [files])] of the main table (the section "## The hooks")."""
    section = text.split("\n## The hooks\n", 1)[1].split("\n## ", 1)[0]
    hooks = []
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if not line.startswith("| `") or len(cells) < 2:
            continue
        name = re.match(r"`(\w+)", cells[0]).group(1)
        files = [f for f in re.findall(r"`(edp/[^`]+\.(?:idp|edp))`", cells[1])]
        hooks.append((name, files))
    return hooks


def default_of(name, path):
    """The default macro of `name` in `path` and the func it calls there (text), or None."""
    lines = open(os.path.join(ROOT, path), encoding="utf-8").read().split("\n")
    start = next((i for i, ln in enumerate(lines) if re.match(rf"macro {name}\b", ln)), None)
    if start is None:
        return None
    end = start
    while not (lines[end].rstrip().endswith("//") or "// EOM" in lines[end]):
        end += 1
    block = lines[start:end + 1]
    called = re.match(rf"macro {name}(\([^)]*\))?\s+(\w+)\(", lines[start])
    if called:
        func = called.group(2)
        head = next((i for i, ln in enumerate(lines) if re.match(rf"func \w+(\[int\])? {func}\(", ln)), None)
        if head is not None:
            tail = next(i for i in range(head, len(lines)) if lines[i].startswith("}"))
            block = lines[head:tail + 1] + [""] + block
        else:  # a macro of the file's own (its lines to its closing // or // EOM)
            head = next((i for i, ln in enumerate(lines) if re.match(rf"macro {func}\b", ln)), None)
            if head is not None:
                tail = head
                while not (lines[tail].rstrip().endswith("//") or "// EOM" in lines[tail]):
                    tail += 1
                block = lines[head:tail + 1] + [""] + block
    return "\n".join(block)


def section(text):
    parts = [BEGIN, "", "## The default bodies", "",
             "Each hook's default as its file defines it (generated from the sources: "
             "`tools/docs/hook_defaults.py`, checked by tests/docs_test.py), to start a variant's own from.", ""]
    for name, files in table_hooks(text):
        for path in files:
            body = default_of(name, path)
            if body is None:
                continue
            parts += [f"### `{name}` ({path})", "", "```", body, "```", ""]
    return "\n".join(parts + [END])


def main(argv):
    text = open(PAGE, encoding="utf-8").read()
    new_section = section(text)
    if BEGIN in text:
        before, rest = text.split(BEGIN, 1)
        after = rest.split(END, 1)[1]
        new = before + new_section + after
    else:
        new = text.rstrip("\n") + "\n\n" + new_section + "\n"
    if argv[1:] == ["--check"]:
        if new != text:
            print("docs/hooks.md's default bodies are not the sources': run tools/docs/hook_defaults.py",
                  file=sys.stderr)
            return 1
        return 0
    with open(PAGE, "w", encoding="utf-8") as f:
        f.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
