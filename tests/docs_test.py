#!/usr/bin/python3
"""The documentation stands alone: a student who clones the repository can follow every reference.

  * no tracked text file refers to the paper digest or the paper outside the repository (the
    `../shared` directory, its `SPEC.md`, "SPEC section n"): docs/model.md states the model and the
    paper's results instead;
  * every relative link of README.md and docs/*.md ([text](target), ![alt](target), outside code)
    names an existing file, and its #anchor an existing heading of that file;
  * every `docs/<page>.md#anchor` (or `README.md#anchor`) written as text in a tracked file (the
    scripts' comments, tests, tools, the pages' prose) names an existing heading of that page;
  * the anchor rule is GitHub's: the heading's text lowercased, every character that is not a
    letter, digit, space, hyphen or underscore dropped, each space turned into a hyphen, and a
    repeated anchor suffixed -1, -2, ...; checked first on headings whose GitHub anchors are known;
  * every page is a handout: each line of README.md and docs/*.md outside fenced code (prose,
    lists, table rows) at most 400 characters, the evidence in docs/measurements.md (a row of 405
    slipped into docs/parameters.md unnoticed); a failure names file:line and the length;
  * no page but docs/measurements.md (the evidence page) names an issue number ("issue 27"):
    the pages say what the code is and does.
Writes results/checks/docs.json.
"""
import os
import re
import subprocess
import sys
import unicodedata
from urllib.parse import unquote

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, check, finish, record  # noqa: E402

THIS = os.path.relpath(os.path.abspath(__file__), ROOT)
# References a reader of the repository cannot follow (the project's working notes live outside it).
OUTSIDE = re.compile(r"\.\./shared|shared/paper|SPEC\.md|\bSPEC\b")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^ {0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"")
LINK = re.compile(r"\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_DEFINITION = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)")
INLINE_CODE = re.compile(r"(`+)(?:(?!\1).)+?\1")
PAGE_ANCHOR = re.compile(r"\b(docs/[\w.-]+\.md|README\.md)#([\w-]+)")


def slug(text):
    """GitHub's anchor of a heading's text (github-slugger): the rendered text, lowercased, with
    punctuation and symbols dropped and each space turned into a hyphen."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link's or an image's text
    text = text.lower()
    kept = [ch for ch in text
            if ch.isalnum() or ch in " -_" or unicodedata.category(ch).startswith("M")]
    return "".join(kept).replace(" ", "-")


def prose_lines(text):
    """The lines of a Markdown text outside fenced code blocks, with (1-based number, line)."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def anchors_of(path, cache={}):
    """The anchors of a Markdown file: its headings' slugs (repeats numbered as GitHub does) and
    explicit <a id/name> anchors."""
    if path not in cache:
        seen, found = {}, set()
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for _, line in prose_lines(text):
            m = HEADING.match(line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                found.add(base if n == 0 else f"{base}-{n}")
                seen[base] = n + 1
            found.update(HTML_ANCHOR.findall(line))
        cache[path] = found
    return cache[path]


def tracked_files():
    """The repository's tracked files (git), or, outside a git checkout, its source tree."""
    try:
        out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True)
        return [p for p in out.stdout.decode().split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        paths = []
        for top, dirs, files in os.walk(ROOT):
            dirs[:] = [d for d in dirs if d not in (".git", "build", "results")]
            paths += [os.path.relpath(os.path.join(top, f), ROOT) for f in files]
        return paths


def read_text(rel):
    """A tracked file's text, or None for a binary file (or one that is not there)."""
    try:
        with open(os.path.join(ROOT, rel), "rb") as f:
            data = f.read()
    except OSError:
        return None
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


# ---- The anchor rule, on headings whose GitHub anchors are known ----
KNOWN = {"Fig. 9-10: beam": "fig-9-10-beam",
         "The paper's sections": "the-papers-sections",
         "alpha(T) and c(T)": "alphat-and-ct",
         "Sleeve variants (one file each)": "sleeve-variants-one-file-each",
         "1. An asymmetric tension/compression law (`beam-asymmetric`)":
             "1-an-asymmetric-tensioncompression-law-beam-asymmetric",
         "Frémond's law": "frémonds-law",
         "Heat (§2.3 [38], [41]-[44])": "heat-23-38-41-44",
         "snake_case and  two spaces": "snake_case-and--two-spaces",
         "[a link](other.md) in a heading": "a-link-in-a-heading"}
for heading, expected in KNOWN.items():
    check(slug(heading) == expected, f"anchor rule: {heading!r} -> {slug(heading)!r} (GitHub: {expected!r})")

files = tracked_files()
texts = {rel: read_text(rel) for rel in files}
texts = {rel: text for rel, text in texts.items() if text is not None}

# ---- No reference outside the repository ----
outside = []
for rel, text in sorted(texts.items()):
    if rel == THIS:
        continue
    for number, line in enumerate(text.split("\n"), 1):
        if OUTSIDE.search(line):
            outside.append(f"{rel}:{number}: {line.strip()[:100]}")
check(not outside, f"no tracked file refers to ../shared or SPEC ({len(texts)} text files): "
      + ("; ".join(outside[:10]) or "none"))

# ---- Links of README.md and docs/*.md ----
pages = sorted(rel for rel in texts
               if rel == "README.md" or (rel.startswith("docs/") and rel.endswith(".md")
                                         and rel.count("/") == 1))
check(len(pages) >= 2 and "docs/model.md" in pages, f"pages checked: {', '.join(pages)}")
broken, links = [], 0
for rel in pages:
    for number, line in prose_lines(texts[rel]):
        line = INLINE_CODE.sub("", line)
        targets = LINK.findall(line) + REFERENCE_DEFINITION.findall(line)
        for target in targets:
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):  # http:, mailto:, ...
                continue
            links += 1
            path, _, anchor = unquote(target).partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(rel), path)) if path else rel
            where = f"{rel}:{number}: ({target})"
            if resolved.startswith("..") or not os.path.exists(os.path.join(ROOT, resolved)):
                broken.append(f"{where} no file {resolved}")
            elif anchor and resolved.endswith(".md") and \
                    anchor not in anchors_of(os.path.join(ROOT, resolved)):
                broken.append(f"{where} no heading #{anchor} in {resolved}")
check(links > 0 and not broken, f"{links} relative links of README.md and docs/*.md resolve: "
      + ("; ".join(broken[:10]) or "all"))

# ---- page.md#anchor written in the scripts, tests and tools ----
mentions, unresolved = 0, []
for rel, text in sorted(texts.items()):
    if rel == THIS:
        continue
    for number, line in enumerate(text.split("\n"), 1):
        for page, anchor in PAGE_ANCHOR.findall(line):
            mentions += 1
            target = os.path.join(ROOT, page)
            if not os.path.exists(target):
                unresolved.append(f"{rel}:{number}: no file {page}")
            elif anchor not in anchors_of(target):
                unresolved.append(f"{rel}:{number}: no heading #{anchor} in {page}")
check(mentions > 0 and not unresolved, f"{mentions} docs/<page>.md#anchor references in the "
      "tracked files resolve: " + ("; ".join(unresolved[:10]) or "all"))

# ---- every page a handout: no line a reader must scroll ----
# Every line of README.md and docs/*.md outside fenced code (prose, list items, headings, table
# rows; the generated pages as their tools write them) at most ROW_LIMIT characters: prose wrapped
# (Markdown joins the lines of a paragraph), a table's long cells shortened with the detail below
# the table or in docs/measurements.md (a row of 405 slipped into docs/parameters.md unnoticed).
ROW_LIMIT = 400
long_lines = [f"{rel}:{number} ({len(line)} characters)" for rel in pages
              for number, line in prose_lines(texts[rel]) if len(line) > ROW_LIMIT]
check(not long_lines, f"every line of README.md and docs/*.md outside fenced code at most {ROW_LIMIT} "
      f"characters ({len(pages)} pages): " + (", ".join(long_lines) or "all"))

# ---- the pages say what the code is, not its history: issue numbers only on the evidence page ----
ISSUE = re.compile(r"\bissues?\s+#?[0-9]+", re.I)
HISTORY_PAGE = "docs/measurements.md"
issue_mentions = [f"{rel}:{number}: {m.group(0)!r}" for rel in pages if rel != HISTORY_PAGE
                  for number, line in enumerate(texts[rel].split("\n"), 1) for m in ISSUE.finditer(line)]
check(not issue_mentions, f"no page but {HISTORY_PAGE} names an issue number: "
      + (", ".join(issue_mentions) or "none"))

# ---- docs/hooks.md shows each hook's default body as the sources define it ----
hooks = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools", "docs", "hook_defaults.py"), "--check"],
                       capture_output=True, text=True)
check(hooks.returncode == 0, "docs/hooks.md's default bodies are the sources' (tools/docs/hook_defaults.py --check)"
      + (": " + hooks.stderr.strip() if hooks.returncode else ""))

record("docs", {"text_files": len(texts), "pages": pages, "links": links, "broken_links": broken,
                "anchor_references": mentions, "unresolved_references": unresolved,
                "outside_references": outside, "long_lines": long_lines, "issue_mentions": issue_mentions})
finish()
