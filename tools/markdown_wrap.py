"""Markdown pages a reader need not scroll: wrap() breaks the long prose lines of a generated page
(paragraphs and list items outside fenced code) at about 100 columns, as the hand-written pages
are; Markdown joins the lines of a paragraph, so the page renders as before. Tables, headings,
fenced code and HTML lines are left as they are (tests/docs_test.py holds every line of
README.md and docs/*.md to 400 characters). Used by the generators of docs/benchmarks.md,
docs/figures.md and docs/paper-scale.md; `python3 tools/markdown_wrap.py FILE...` wraps pages in place."""
import re
import sys

WIDTH = 100
FENCE = re.compile(r"^\s*(```|~~~)")
# A list item's marker (its continuation lines are indented past it) or a blockquote's.
LEAD = re.compile(r"^(\s*)((?:[-*+]|\d{1,9}[.)])\s+|(?:>\s?)+)?")
# Spans a line break must not cut: code spans and a link's target (kept on one line for the tools
# that read the pages line by line: tests/docs_test.py's links and anchors).
UNBREAKABLE = re.compile(r"(`+)(?:(?!\1).)+?\1|\]\([^)]*\)")


def starts_block(word):
    """True when a line beginning with `word` would not continue the paragraph (a list item, a
    heading, a quote, a table row, HTML, a fence, a rule or a setext underline)."""
    return (word in ("-", "+", "*") or re.fullmatch(r"\d{1,9}[.)]", word) is not None
            or word.startswith(("#", ">", "|", "<", "```", "~~~", "="))
            or re.fullmatch(r"[-*_]{3,}", word) is not None)


def wrap_line(line, width=WIDTH):
    """The line as one or more lines of at most `width` columns where it can be broken."""
    if len(line) <= width or line.lstrip().startswith(("|", "#", "<", "!")):
        return [line]
    lead = LEAD.match(line)
    head = lead.group(0)
    quote = (lead.group(2) or "").strip().startswith(">")
    indent = head if quote else " " * len(head)
    body = line[len(head):]
    trail = body[len(body.rstrip(" ")):] if body.endswith("  ") else ""  # a hard line break
    body = body.rstrip(" ") if trail else body
    protected = set()
    for m in UNBREAKABLE.finditer(body):
        protected.update(range(m.start(), m.end()))
    # The spaces a break may replace: outside the spans, not before a word that starts a block.
    breaks = [i for i, ch in enumerate(body) if ch == " " and i not in protected and 0 < i < len(body) - 1
              and body[i - 1] != " " and body[i + 1] != " "
              and not starts_block(body[i + 1:].split(" ", 1)[0]) and body[i + 1] != "%"]  # 2.6 % on one line
    out, start, prefix = [], 0, head
    while True:
        room = width - len(prefix)
        fits = [i for i in breaks if start < i <= start + room]
        if start + room >= len(body) or not (fits or [i for i in breaks if i > start]):
            out.append(prefix + body[start:] + trail)
            return out
        cut = fits[-1] if fits else next(i for i in breaks if i > start)
        out.append(prefix + body[start:cut])
        start, prefix = cut + 1, indent


def wrap(text, width=WIDTH):
    """The page's text with its long prose lines wrapped (fenced code untouched)."""
    out, fenced = [], False
    for line in text.split("\n"):
        if FENCE.match(line):
            fenced = not fenced
            out.append(line)
        else:
            out.extend([line] if fenced else wrap_line(line, width))
    return "\n".join(out)


if __name__ == "__main__":
    for path in sys.argv[1:]:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        with open(path, "w", encoding="utf-8") as f:
            f.write(wrap(text))
