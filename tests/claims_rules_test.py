#!/usr/bin/python3
"""The claims table's verdict rule (tools/docs/claims_rules.py), pinned on made-up measures:

  - one ordering for every row: agrees (within the tolerance) above partly (the feature there, its
    number off) above disagrees (the feature absent); a worse result never gets a better word. For
    the g = 2000 crossing (Fig. 17-18): a crossing at -31 C agrees, one at -71 C is partly, none at all
    disagrees (the earlier rule gave "partly" to none and "disagrees" to one far away); the word never
    improves as the crossing moves away from -30 C;
  - the first contact is robust to a single-step event: a one-step touch at step 2 (the on/off
    path's lag did that) followed by contact from step 12 starts contact at step 12; a contact from
    the first step starts at 1; none gives 0;
  - a value settles from the step after the last one off its final value by more than the
    tolerance (a force constant once austenite, a temperature spread that stays small);
  - a contact-release episode is a fall of a tenth of the highest value, counted once however long
    it lasts: a steady fall to a low is one, a fall, a rise as large and a fall again are two, and
    a wiggle smaller than a tenth is none;
  - the three runs' verdicts are written once when they agree, each in its place otherwise ("-" for
    a run that does not measure the row; in full when the default does not), and read back by
    position; a row no run measures is
    written "" (its measure cells say what output it needs);
  - the one-line state counts each run's words over the rows it measures, the rows the default does
    not meet as explained / open / note only, and the default's agreements as fitted / predicted.
Writes results/checks/claims_rules.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, check, finish, record  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tools", "docs"))
from claims_rules import (WORDS, counts_line, crossing_verdict, first_sustained, joined, release_episodes,  # noqa: E402
                          settled_from, side_word, verdict)

RANK = {w: i for i, w in enumerate(WORDS)}  # 0 best


def main():
    nan = float("nan")
    check(verdict(True) == "agrees" and verdict(False, True) == "partly" and verdict(False) == "disagrees"
          and verdict(True, False) == "agrees", "verdict(ok, partly): agrees / partly / disagrees")
    words = {x: crossing_verdict(x) for x in (-30.0, -31.0, -34.9, -35.1, -50.0, -71.2, 0.0)}
    check(words[-31.0] == "agrees" and words[-71.2] == "partly" and crossing_verdict(nan) == "disagrees",
          f"crossings: -31 C {words[-31.0]}, -71.2 C {words[-71.2]}, none {crossing_verdict(nan)} "
          "(want agrees, partly, disagrees)")
    ordered = [crossing_verdict(x) for x in (-30.0, -31.0, -34.9, -35.1, -50.0, -71.2, -120.0)] + [crossing_verdict(nan)]
    check(all(RANK[a] <= RANK[b] for a, b in zip(ordered, ordered[1:])),
          f"a crossing farther from -30 C, then none, never gets a better word: {ordered}")
    touch = [0, 7, 0, 0, 0, 0, 0, 0, 0, 0, 0, 91, 91, 91]   # contact_nodes per step: a touch at step 2
    check(first_sustained(touch) == 12, f"one step's touch at step 2, contact from 12: first contact "
          f"{first_sustained(touch)} (want 12)")
    check(first_sustained([5, 5, 5]) == 1 and first_sustained([0, 0, 3]) == 0 and first_sustained([]) == 0,
          "contact from the first step starts at 1; a last-step touch or none gives 0")
    check(settled_from([0, 5, 9, 10, 10, 10], 0.5) == 4 and settled_from([3, 3], 0.1) == 1
          and settled_from([], 1) == 0 and settled_from([10, 10, 12, 10], 1) == 4,
          f"settled: from step {settled_from([0, 5, 9, 10, 10, 10], 0.5)} (want 4); a late bump postpones it "
          f"to {settled_from([10, 10, 12, 10], 1)} (want 4)")
    falls = {"one long fall": release_episodes([0, 1, 2, 3, 2.6, 2.2, 1.8, 1.4, 1, 1.2, 1.5]),
             "fall, rise, fall": release_episodes([0, 3, 1, 3, 1]),
             "wiggles of 5 %": release_episodes([0, 2, 3, 2.85, 3, 2.86, 3.1]),
             "none rising": release_episodes([0, 1, 2, 3]), "empty": release_episodes([])}
    check(falls == {"one long fall": 1, "fall, rise, fall": 2, "wiggles of 5 %": 0, "none rising": 0, "empty": 0},
          f"contact-release episodes: {falls} (want 1, 2, 0, 0, 0)")
    check(joined("", "", "") == "", f"a row no run measures: verdict {joined('', '', '')!r} (want '')")
    check(joined("agrees", "agrees", "agrees") == "agrees" and joined("agrees", "", "agrees") == "agrees"
          and joined("agrees", "", "partly") == "agrees / - / partly"
          and joined("disagrees", "agrees", "agrees") == "disagrees / agrees / agrees"
          and joined("", "partly", "partly") == "- / partly / partly",
          "three runs' verdicts: one word when the measured ones agree, each in its place otherwise")
    check(side_word("agrees / - / partly", 1) == "" and side_word("agrees / - / partly", 2) == "partly"
          and side_word("agrees", 2) == "agrees", "a joined verdict read back by position")
    rows = [("agrees", "", [True, True, True], True),
            ("agrees / partly / agrees", "", [True, True, True], False),
            ("disagrees / - / agrees", "explained: an artefact", [True, False, True], False),
            ("partly", "open: tried this", [True, True, True], False),
            ("disagrees / disagrees / -", "a note", [True, True, False], False),
            ("", "", [False, False, False], False)]
    line = counts_line(rows)
    want = ("6 statements, 1 of them not measured", "Default model: 2 agrees, 1 partly, 2 disagrees.",
            "On/off scheme: 1 agrees, 2 partly, 1 disagrees (of the 4 statements measured on it)",
            "replayed: 3 agrees, 1 partly (of the 4 statements measured on it)",
            "Of the 3 where the default does not agree: 1 explained by a run, 1 open, 1 with a note only",
            "Of the default's 2 agreements, 1 fitted")
    missing = [w for w in want if w not in line]
    check(not missing, f"counts line on made-up rows lacks {missing}: {line}")
    record("claims_rules", {"crossing_words": {str(k): v for k, v in words.items()}, "counts_line": line})
    finish()


if __name__ == "__main__":
    main()
