#!/usr/bin/python3
"""`-algorithm paper` replays the paper's algorithm: its on/off law and nested loops with the
iteration counts the paper reports as caps (3 heat-phase, 4 DC), the slip threshold lagged (one pass),
plain PSOR to a loose 1e-3; a loop at its cap ends there and the step goes on, as the paper's did.

Checked on sleeve-circular (paper scale, 150 steps: the caps bind at 5 steps) and
sleeve-elliptic-friction (reduced scale, 150 steps: the slip threshold lagged, caps at most steps):
  - the replay runs to the end (exit 0), says in one note how many loops stopped at their caps and
    prints no -keepgoing warning; summary.json says "algorithm": "paper", the on/off law, and counts
    the capped loops (> 0);
  - the caps hold: at most 3 heat-phase passes per step and at most 3 x 4 DC iterations, and some
    step reaches the 3 passes;
  - the replay is exactly those options: the same options written out with -keepgoing 1 give the
    same history.csv, byte for byte (no step taken again shorter in either), and without
    -keepgoing no loop passes at its cap: the run fails naming a loop and the option that raises
    its limit, or every capped step is taken again in halves until its loops converge (exit 0,
    steps_retried > 0, no loop left unconverged);
  - an option given on the command line wins: the replay with every loop's tolerance and limit set
    back to the converged model's gives the converged on/off run's history.csv;
  - the radial model refuses it, and an unknown algorithm is refused, each naming -algorithm.
Writes results/checks/paper_algorithm.json.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import check, finish, record, rows, run_scene_captured, summary_of  # noqa: E402

REPLAY = ["-phasemodel", "onoff", "-stepsolver", "fixedpoint", "-fpmaxit", "3", "-dcmaxit", "4",
          "-psorpolish", "0", "-psortol", "1e-3", "-slipmaxit", "1"]
# (no -slipmaxit: sleeve-circular has no friction, and refuses it as having no effect)
CONVERGED_LOOPS = ["-fpmaxit", "1000", "-dcmaxit", "100", "-psorpolish", "10", "-psortol", "1e-10"]


def history_text(out):
    with open(os.path.join(out, "history.csv")) as f:
        return f.read()


def main():
    measured = {}
    for scene, scale in (("sleeve-circular", "paper"), ("sleeve-elliptic-friction", "reduced")):
        base = ["-scale", scale, "-steps", "150", "-quiet", "1", "-vtkevery", "0"]
        # (-slipmaxit written out where there is friction: with mu = 0 it is refused as having no effect)
        replay = REPLAY if scene == "sleeve-elliptic-friction" else REPLAY[:-2]
        tag = f"paper-algorithm-{scene}"
        out, done = run_scene_captured(scene, tag, *base, "-algorithm", "paper")
        console = done.stdout + done.stderr
        check(done.returncode == 0, f"{scene} -algorithm paper: exit {done.returncode}: {console[-400:]}")
        if done.returncode != 0:
            continue
        s = summary_of(out)
        history = rows(os.path.join(out, "history.csv"))
        passes = [int(r["fixed_point_iterations"]) for r in history]
        dc = [int(r["dc_iterations"]) for r in history]
        capped = s["unconverged_loops"]
        measured[scene] = {"capped_loops": capped, "capped_steps": s["unconverged_steps"],
                           "passes_max": max(passes), "dc_max": max(dc), "steps": len(history)}
        check(s["parameters"]["algorithm"] == "paper" and s["parameters"]["phase_model"] == "onoff",
              f"{scene}: summary.json parameters say algorithm {s['parameters'].get('algorithm')}, "
              f"phase model {s['parameters'].get('phase_model')} (want paper, onoff)")
        check(capped > 0, f"{scene}: no loop reached its cap (summary.json unconverged_loops 0): the test "
              "does not exercise the caps")
        check("the paper's algorithm (-algorithm paper)" in console and "-keepgoing 1)" not in console,
              f"{scene}: the replay's note missing, or a -keepgoing warning printed: {console[-400:]}")
        check(max(passes) == 3 and max(dc) <= 12,
              f"{scene}: heat-phase passes at most {max(passes)} (want 3 reached), DC iterations at most "
              f"{max(dc)} per step (cap 3 x 4 = 12)")
        spelled, done2 = run_scene_captured(scene, tag + "-spelled", *base, *replay, "-keepgoing", "1")
        check(done2.returncode == 0 and history_text(spelled) == history_text(out)
              and summary_of(spelled)["step_splits"] == 0 == s["step_splits"],
              f"{scene}: the replay's options written out with -keepgoing 1 give another history.csv "
              f"(exit {done2.returncode}), or a step was split")
        strict_out, done3 = run_scene_captured(scene, tag + "-strict", *base, *replay)
        strict = done3.stdout + done3.stderr
        failed_named = done3.returncode != 0 and "did not converge" in strict and "raise -" in strict
        ss = summary_of(strict_out) if done3.returncode == 0 else {}
        converged_in_halves = (done3.returncode == 0 and ss.get("unconverged_loops") == 0
                               and ss.get("steps_retried", 0) > 0)
        check(failed_named or converged_in_halves,
              f"{scene}: the replay's options without -keepgoing: exit {done3.returncode}, "
              f"{ss.get('steps_retried')} step(s) taken again in halves, {ss.get('unconverged_loops')} loop(s) "
              f"unconverged; want a failure naming the loop and its limit option, or every loop converged in "
              f"shorter steps: {strict[-300:] if done3.returncode else ''}")
    # An option given wins: every loop set back to the converged model's is the converged on/off run.
    base = ["-scale", "reduced", "-steps", "150", "-quiet", "1", "-vtkevery", "0"]
    back, done = run_scene_captured("sleeve-circular", "paper-algorithm-back", *base, "-algorithm", "paper",
                                    *CONVERGED_LOOPS)
    onoff, done2 = run_scene_captured("sleeve-circular", "paper-algorithm-onoff", *base, "-phasemodel", "onoff",
                                      "-stepsolver", "fixedpoint")
    check(done.returncode == 0 == done2.returncode and history_text(back) == history_text(onoff),
          "-algorithm paper with every loop's tolerance and limit given back is not the converged on/off run "
          f"(exits {done.returncode}, {done2.returncode})")
    for scene, value in (("sleeve-radial", "paper"), ("sleeve-circular", "1998")):
        _, bad = run_scene_captured(scene, f"paper-algorithm-refused-{scene}", "-algorithm", value, "-quiet", "1")
        said = (bad.stdout + bad.stderr).strip()
        check(bad.returncode != 0 and said.startswith("error:") and "-algorithm" in said and "\n" not in said,
              f"{scene} -algorithm {value}: exit {bad.returncode}, want a one-line error naming -algorithm: {said[-300:]}")
    record("paper_algorithm", measured)
    finish()


if __name__ == "__main__":
    main()
