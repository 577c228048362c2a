#!/usr/bin/python3
"""summary.json's count of the step solver's dense Newton moves (`step_dense_moves`, and
`step_dense_move_steps`: the steps that took one) against the solver's own trace
(SMA_STEP_TRACE=1 prints a line per move: "step iteration N: dense newton move (...), taken"),
through the plugin's stats array, the scripts' sums and a checkpoint (docs/outputs.md):

  - sleeve-circular at its defaults takes none: both counts 0, no such line in the trace;
  - sleeve-offset at its defaults finishes one step by a dense move (step 579,
    docs/measurements.md#m-dense-newton), run in two halves (-checkpoint 600 -stopafter 600, then
    -resume 1): the move is in the first half's trace, so the resumed run's summary.json carries
    it through the checkpoint; its counts equal the traces' accepted moves and the steps that
    took them (a step's lines: its iteration numbers rise; the next step starts again);
  - that step's dense move comes after two creeping iterations (gradient steps after Newton
    rounds dearer than the block's points: StepSettings::early_dense), at iteration 5 at most,
    not after the stall rule's 10 iterations without halving (iteration 22 before the rule).
Writes results/checks/step_counts.json.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import check, finish, record, run_scene_captured, summary_of  # noqa: E402

ITERATION = re.compile(r"step iteration (\d+): (.*)")


def dense_moves(trace):
    """The accepted dense moves of a trace and the steps that took at least one."""
    moves, steps, last, this_step = 0, 0, None, False
    for line in trace.splitlines():
        m = ITERATION.match(line)
        if not m:
            continue
        n = int(m.group(1))
        if last is not None and n <= last:  # a new step
            steps += this_step
            this_step = False
        last = n
        if m.group(2).startswith("dense newton move") and "), taken," in m.group(2):
            moves += 1
            this_step = True
    return moves, steps + this_step


def dense_move_iterations(trace):
    """The iteration numbers of a trace's accepted dense moves."""
    found = []
    for line in trace.splitlines():
        m = ITERATION.match(line)
        if m and m.group(2).startswith("dense newton move") and "), taken," in m.group(2):
            found.append(int(m.group(1)))
    return found


def traced(scene, name, *args):
    os.environ["SMA_STEP_TRACE"] = "1"
    try:
        # (the fixed steps, -tol 0: the counts are those of the scenes' 1500 steps)
        return run_scene_captured(scene, name, "-quiet", "1", "-tol", "0", *args)
    finally:
        del os.environ["SMA_STEP_TRACE"]


def main():
    figures = {}
    out, done = traced("sleeve-circular", "step-counts-circular")
    s = summary_of(out) if done.returncode == 0 else {}
    moves, steps = dense_moves(done.stderr)
    check(done.returncode == 0 and s.get("step_dense_moves") == 0 and s.get("step_dense_move_steps") == 0
          and moves == 0,
          f"sleeve-circular: step_dense_moves {s.get('step_dense_moves')}, step_dense_move_steps "
          f"{s.get('step_dense_move_steps')} (0 and 0), {moves} dense moves in the trace (exit {done.returncode})")
    figures["circular"] = {"step_dense_moves": s.get("step_dense_moves"), "trace_moves": moves}

    # (the polygonal mesh's heat measure, -curvedmeasure 0: the steps whose creeping these counts were
    # measured on; with the true annulus's, one step of the 1500 meets the stall rule's dense move)
    half = ["-vtkevery", "0", "-checkpoint", "600", "-curvedmeasure", "0"]
    out, first = traced("sleeve-offset", "step-counts-offset", *half, "-stopafter", "600")
    stopped = os.path.isfile(os.path.join(out, "checkpoint.txt"))
    out, second = traced("sleeve-offset", "step-counts-offset", *half, "-resume", "1")
    s = summary_of(out) if second.returncode == 0 else {}
    moves1, steps1 = dense_moves(first.stderr)
    moves2, steps2 = dense_moves(second.stderr)
    check(first.returncode != 0 and stopped and moves1 > 0,
          f"sleeve-offset stopped after step 600 (exit {first.returncode}, checkpoint written: {stopped}) with "
          f"{moves1} dense move(s) in "
          f"{steps1} step(s) before it (> 0: the count passes through the checkpoint)")
    at = dense_move_iterations(first.stderr)
    check(at and max(at) <= 5,
          f"sleeve-offset's dense moves before step 600 at step iterations {at} (<= 5: after two creeping "
          f"iterations, not the stall rule's 10 without halving)")
    figures["offset_dense_move_iterations"] = at
    check(second.returncode == 0 and s.get("resumed_from_step") == 600
          and s.get("step_dense_moves") == moves1 + moves2 and s.get("step_dense_move_steps") == steps1 + steps2,
          f"sleeve-offset resumed from step {s.get('resumed_from_step')}: step_dense_moves {s.get('step_dense_moves')}, "
          f"step_dense_move_steps {s.get('step_dense_move_steps')}; the traces: {moves1} + {moves2} moves in "
          f"{steps1} + {steps2} steps (exit {second.returncode})")
    figures["offset"] = {"step_dense_moves": s.get("step_dense_moves"),
                         "step_dense_move_steps": s.get("step_dense_move_steps"),
                         "trace_moves": [moves1, moves2], "trace_steps": [steps1, steps2]}
    record("step_counts", figures)
    finish()


if __name__ == "__main__":
    main()
