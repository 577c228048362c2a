#!/usr/bin/python3
"""A resumed run reads its checkpoint's arrays in the plugin: the script's own reading of the state
does not grow with the mesh.

The checkpoint's strict reads (issue 26) first checked every value in the script, a loop over its
characters (IsNumberWord) for each of the state's numbers: about 70 us a value, 2.6 s before the
first step of an 18-layer sleeve-circular (39 000 values) whose 150 steps take 0.5 s. The plugin's
StreamReadNumbers now reads and checks each array (plugin/core/files.hpp read_numbers; its unit
tests check the rule and the messages). Without timing anything, for sleeve-circular on two meshes
(sleeve-coarse, 217 nodes; sleeve-nr9, 460), stopped after step 20 with a checkpoint and resumed,
the resumed run's console line (time-loop.idp SleeveLoadState) gives the state's bytes, the values
and bytes the plugin read, and the bytes the script read itself; checked here:
  - the state's bytes equal those between the checkpoint's "state" and "end" lines (counted here
    from the file), and the plugin's bytes plus the script's make them up;
  - the plugin read all of the state's number words (counted here from the file) but at most 64,
    the same number on both meshes (the lengths, the step, the counters);
  - from one mesh to the other the state grows by tens of kB, the script's own bytes by less than
    1 % of that (names, lengths, the step and counters): its work is per field, not per value.
A loop over the values in the script again (the regression) fails the last two checks.
Writes results/checks/resume_read.json.
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, REDUCED, check, finish, record  # noqa: E402

MESHES = ["meshes/sleeve-coarse.msh", "meshes/sleeve-nr9.msh"]
COMMON = ["edp/scenes/sleeve-circular.edp", "-steps", "40", "-vtkevery", "0", *REDUCED]
LINE = re.compile(r"resumed after step (\d+) from .* \(state: (\d+) bytes; (\d+) values, (\d+) bytes, read by "
                  r"the plugin; (-?\d+) bytes of names and lengths read by the script\)")
NUMBER = re.compile(rb"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


def ff(*args):
    return subprocess.run([os.path.join(ROOT, "tools", "ff"), *args], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)


def state_of(checkpoint):
    """(bytes, number words) of the state section: after the "state" line's word, up to its "end"."""
    text = open(checkpoint, "rb").read()
    start = text.index(b"\nstate\n") + len(b"\nstate")
    end = text.index(b"\nend\n") + len(b"\nend")
    words = text[start:end].split()
    return end - start, sum(1 for w in words if NUMBER.fullmatch(w))


def resumed(mesh, tmp):
    out = os.path.join(tmp, os.path.basename(mesh))
    stop = ff(*COMMON, "-mesh", mesh, "-checkpoint", "20", "-stopafter", "20", "-quiet", "1", "-out", out)
    if stop.returncode != 4:
        sys.exit(f"FAIL the run to stop after step 20 ended with exit {stop.returncode}: {stop.stderr[-500:]}")
    state_bytes, numbers = state_of(os.path.join(out, "checkpoint.txt"))
    run = ff(*COMMON, "-mesh", mesh, "-resume", "1", "-out", out)
    found = LINE.search(run.stdout)
    if run.returncode != 0 or not found:
        sys.exit(f"FAIL the resumed run (exit {run.returncode}) printed no 'resumed after step' line: "
                 f"{(run.stdout + run.stderr)[-800:]}")
    step, total, values, plugin, script = map(int, found.groups())
    return {"mesh": mesh, "step": step, "state_bytes": total, "state_bytes_in_file": state_bytes,
            "number_words_in_file": numbers, "plugin_values": values, "plugin_bytes": plugin,
            "script_bytes": script}


def main():
    with tempfile.TemporaryDirectory() as tmp:
        runs = [resumed(mesh, tmp) for mesh in MESHES]
    for r in runs:
        name = os.path.basename(r["mesh"])
        check(r["step"] == 20, f"{name}: resumed after step {r['step']} (20)")
        check(r["state_bytes"] == r["state_bytes_in_file"] and r["plugin_bytes"] + r["script_bytes"] == r["state_bytes"],
              f"{name}: state {r['state_bytes']} bytes (in the file: {r['state_bytes_in_file']}) = plugin "
              f"{r['plugin_bytes']} + script {r['script_bytes']}")
        r["numbers_left_to_script"] = r["number_words_in_file"] - r["plugin_values"]
        check(0 <= r["numbers_left_to_script"] <= 64,
              f"{name}: the plugin read {r['plugin_values']} of the state's {r['number_words_in_file']} number words "
              f"(the script {r['numbers_left_to_script']}: lengths, the step, counters; <= 64)")
    small, large = runs
    check(small["numbers_left_to_script"] == large["numbers_left_to_script"],
          f"the number words the script reads itself: {small['numbers_left_to_script']} and "
          f"{large['numbers_left_to_script']} on the two meshes (equal: one per field)")
    grown = large["state_bytes"] - small["state_bytes"]
    script_grown = large["script_bytes"] - small["script_bytes"]
    check(grown > 20000 and abs(script_grown) < 0.01 * grown,
          f"from {small['mesh']} to {large['mesh']} the state grows by {grown} bytes (> 20000), the script's own "
          f"reading by {script_grown} ({small['script_bytes']} -> {large['script_bytes']}; < 1 % of {grown})")
    record("resume_read", {"runs": runs})
    finish()


if __name__ == "__main__":
    main()
