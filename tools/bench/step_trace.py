#!/usr/bin/python3
"""The step solver's counts per time step, from its trace (SMA_STEP_TRACE=1: plugin/core/step_newton.hpp
prints one line per active-set round and per iteration on stderr).

  SMA_STEP_TRACE=1 tools/ff edp/scenes/sleeve-circular.edp -mesh meshes/sleeve-nr72.msh -steps 150 \\
      -tend 150 -scale reduced -quiet 1 -vtkevery 0 -checkpoint 30 -stopafter 30 -out /tmp/t 2> /tmp/t.trace
  tools/bench/step_trace.py /tmp/t.trace [more traces...]

Per call of the step solver (a time step that transforms, in order): Newton iterations, active-set
rounds, GMRES iterations (and how many solves stopped unconverged at a cap), dense Newton moves,
evaluations (line-search trials beyond one per iteration: evaluations - iterations - 1), products
(each one heat and one stiffness back-solve), the unpinned points of each iteration's first round,
then the totals, the rounds of at least 15 GMRES iterations and the smallest Ritz value seen
(of the q-scaled linearisation, whose largest is about 1). An iteration's counts of evaluations
and products are cumulative over its step, so a step's are those of its last iteration.
"""
import re
import sys

ROUND = re.compile(r"\s+round (\d+): (\d+) unpinned, gmres (\d+) its \((\w+)\), smallest ritz ([^,]+)")
ITERATION = re.compile(r"step iteration (\d+): (.*)")
COUNTS = re.compile(r"(\d+) evaluations, (\d+) products")


def parse(path):
    """The trace's steps: lists of iterations, each a dict with its rounds."""
    iterations, pending = [], []
    for line in open(path):
        r, m = ROUND.match(line), ITERATION.match(line)
        if r:
            pending.append({"round": int(r.group(1)), "points": int(r.group(2)), "gmres": int(r.group(3)),
                            "converged": r.group(4) == "converged", "ritz": float(r.group(5))})
        elif m:
            c = COUNTS.search(line)
            iterations.append({"k": int(m.group(1)), "kind": m.group(2).split(",")[0],
                               "evaluations": int(c.group(1)), "products": int(c.group(2)), "rounds": pending})
            pending = []
    steps = []
    for it in iterations:  # a new step where the iteration number does not grow (dense moves repeat it)
        if not steps or (it["k"] <= steps[-1][-1]["k"] and not it["kind"].startswith("dense")):
            steps.append([])
        steps[-1].append(it)
    return steps


def summary(path):
    steps = parse(path)
    print(path)
    total = {"iterations": 0, "rounds": 0, "gmres": 0, "stopped": 0, "dense": 0, "evaluations": 0, "products": 0}
    hard, smallest = [], float("inf")
    for i, s in enumerate(steps):
        rounds = [r for it in s for r in it["rounds"]]
        dense = sum(it["kind"].startswith("dense") for it in s)
        row = {"iterations": len(s) - dense, "rounds": len(rounds), "gmres": sum(r["gmres"] for r in rounds),
               "stopped": sum(not r["converged"] for r in rounds), "dense": dense,
               "evaluations": s[-1]["evaluations"], "products": s[-1]["products"]}
        for k in total:
            total[k] += row[k]
        first = [it["rounds"][0]["points"] for it in s if it["rounds"]]
        print(f"  call {i}: {row['iterations']} iterations, {row['rounds']} rounds, gmres {row['gmres']} "
              f"({row['stopped']} stopped), {row['dense']} dense moves, {row['evaluations']} evaluations "
              f"({row['evaluations'] - row['iterations'] - 1} extra trials), {row['products']} products; "
              f"unpinned points {first}")
        hard += [(i, r) for r in rounds if r["gmres"] >= 15]
        smallest = min([smallest] + [r["ritz"] for r in rounds])
    print(f"  total over {len(steps)} calls: " + ", ".join(f"{k} {v}" for k, v in total.items())
          + f"; smallest Ritz value {smallest:.1e}")
    for i, r in hard:
        print(f"  hard round (call {i}): {r['points']} points, {r['gmres']} GMRES iterations "
              f"({'converged' if r['converged'] else 'stopped'}), smallest Ritz {r['ritz']:.1e}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for p in sys.argv[1:]:
        summary(p)
