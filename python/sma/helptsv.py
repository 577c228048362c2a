"""The format every script prints with `-help tsv` (edp/lib/errors.idp): a header line, then one
tab-separated row per option (name, type, default, meaning). The one parser of it: the driver's
option checks and tools/docs/param_reference.py (docs/parameter-reference.md) both read it here."""
import re

HEADER = "option\ttype\tdefault\tmeaning"
TYPES = ("int", "real", "string")
# FreeFEM's exit(0) trailer (tools/ff drops it; mpiexec does not).
TRAILER = re.compile(r"^(  current line = \d+( mpirank \d+ / \d+)?| call .* at  line \d+|exit\(0\)|"
                     r" err code 0 ,  mpirank \d+)$")


def parse_tsv(name, text):
    """The options of one `-help tsv` output: [{"name", "type", "default", "meaning"}]. Fails
    (ValueError naming the script) on anything but the header, rows, and FreeFEM's exit trailer."""
    lines = text.split("\n")
    while lines and lines[-1] == "":
        lines.pop()
    if not lines or lines[0] != HEADER:
        raise ValueError(f"{name}: -help tsv did not start with the header line {HEADER!r}: "
                         f"{text.strip()[-400:]!r}")
    options, seen = [], set()
    i = 1
    while i < len(lines) and not TRAILER.match(lines[i]):
        fields = lines[i].split("\t")
        if len(fields) != 4 or not fields[0].startswith("-") or fields[1] not in TYPES:
            raise ValueError(f"{name}: -help tsv line {i + 1} is not 'option<TAB>type<TAB>default"
                             f"<TAB>meaning': {lines[i]!r}")
        if fields[0] in seen:
            raise ValueError(f"{name}: option {fields[0]} listed twice")
        seen.add(fields[0])
        options.append(dict(zip(("name", "type", "default", "meaning"), fields)))
        i += 1
    rest = [line for line in lines[i:] if not TRAILER.match(line)]
    if rest:
        raise ValueError(f"{name}: unexpected lines after the options: {rest[:5]!r}")
    return options
