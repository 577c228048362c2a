"""The rules of the claims table (tools/docs/claims.py), one for every row: how a measure becomes a
verdict, how the verdicts of the three runs of a row are written, and the table's state in one line.
tests/claims_rules_test.py pins them on made-up curves.

The verdict rule: "agrees" when the measure is within the row's tolerance of the paper's statement;
"partly" when the feature the paper describes is there but its number is outside the tolerance;
"disagrees" when the feature is absent. A worse result never gets a better word: no crossing at all
is "disagrees", a crossing far from the paper's temperature "partly".
"""
import math

WORDS = ("agrees", "partly", "disagrees")


def verdict(ok, partly=False):
    """The rule's word: ok (within the tolerance), else partly (the feature there, its number off)."""
    return "agrees" if ok else ("partly" if partly else "disagrees")


def crossing_verdict(crossing_C, paper_C=-30.0, tolerance_K=5.0):
    """Two curves that cross at crossing_C (nan: they never cross), where the paper says paper_C."""
    if math.isnan(crossing_C):
        return "disagrees"
    return verdict(abs(crossing_C - paper_C) < tolerance_K, True)


def first_sustained(values, threshold=0.0, run=2):
    """The 1-based step of the first `run` consecutive values above threshold (a single-step event,
    such as one step's touch, is not a start); 0 when there is none."""
    count = 0
    for i, v in enumerate(values):
        count = count + 1 if v > threshold else 0
        if count == run:
            return i - run + 2
    return 0


def settled_from(values, tolerance):
    """The 1-based step from which every value stays within tolerance of the last one (a force that
    no longer changes, a temperature spread that stays small); 1 when all do, 0 for no values."""
    if len(values) == 0:
        return 0
    off = [i for i, v in enumerate(values) if abs(v - values[-1]) > tolerance]
    return off[-1] + 2 if off else 1


def release_episodes(values, drop=0.1):
    """How many times a value (a node's contact pressure) falls from a peak by at least `drop` of the
    highest it ever reaches, each fall counted once however long it lasts: a further fall counts only
    after the value rose again by as much from its lowest. Each such fall is a contact then a release;
    smaller wiggles (a step's noise on a small force) are not."""
    values = list(values)
    if not values or max(values) <= 0:
        return 0
    size, count, peak, trough = drop * max(values), 0, values[0], None
    for v in values:
        if trough is not None:              # falling since the last release: wait for a rise as large
            trough = min(trough, v)
            if v >= trough + size:
                peak, trough = v, None
        elif v > peak:
            peak = v
        elif v <= peak - size:
            count, trough = count + 1, v
    return count


def joined(*texts):
    """The verdicts (or measures) of a row's runs, one word when they are all the same; the runs
    not measured ("") are left out of the comparison but keep their place, and a row the default
    does not measure is written in full (one word would read as the default's)."""
    given = [t for t in texts if t != ""]
    if not given:
        return ""
    if len(set(given)) == 1 and texts[0] != "":
        return given[0]
    return " / ".join(t if t != "" else "-" for t in texts)


def side_word(verdict_text, side):
    """The word of run `side` (0 default, 1 on/off, 2 replay) in a joined verdict; "" for "-"."""
    parts = verdict_text.split(" / ")
    word = parts[side] if len(parts) > 1 else parts[0]
    return "" if word == "-" else word


def steps(n):
    return "no step" if n == 0 else f"{n} step" + ("" if n == 1 else "s")


def pct(x):
    return f"{100 * x:+.1f} %"


def counts_line(verdicts, sides=("Default model", "On/off scheme", "The paper's algorithm replayed")):
    """The table's state in one line. verdicts: (joined verdict, explanation, measured on each side,
    fitted). Counts the statements no run measures (no output shows them), the words on each run,
    the rows where the default does not agree that are explained by a run and those open, and the
    agreements that were fitted."""
    parts = []
    unmeasured = sum(1 for _, _, measured, _ in verdicts if not any(measured))
    for side, name in enumerate(sides):
        words = [side_word(v, side) for v, _, measured, _ in verdicts if measured[side]]
        tally = ", ".join(f"{words.count(w)} {w}" for w in WORDS if words.count(w))
        parts.append(f"{name}: {tally}" + ("" if side == 0 and len(words) == len(verdicts) - unmeasured
                                           else f" (of the {len(words)} statements measured on it)"))
    rest = [e for v, e, measured, _ in verdicts if measured[0] and side_word(v, 0) != "agrees"]
    explained = sum(1 for e in rest if e.startswith("explained"))
    opened = sum(1 for e in rest if e.startswith("open"))
    agreeing = [f for v, _, _, f in verdicts if side_word(v, 0) == "agrees"]
    return (f"**In one line:** {len(verdicts)} statements"
            + (f", {unmeasured} of them not measured (no output of the runs shows them: the row names the "
               "output needed)" if unmeasured else "") + ". " + ". ".join(parts) + ". "
            f"Of the {len(rest)} where the default does not agree: {explained} explained by a run, {opened} open, "
            f"{len(rest) - explained - opened} with a note only. Of the default's {len(agreeing)} agreements, "
            f"{sum(agreeing)} fitted (a parameter chosen to meet that statement) and {len(agreeing) - sum(agreeing)} "
            "predicted.")
