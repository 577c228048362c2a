"""The runs of the claims table (tools/docs/claims.py) besides the figure scenes at their defaults (all
at the paper's 1500 fixed increments, -tol 0, unless a run gives its steps):
each figure scene with the paper's on/off scheme (its quarter mesh), each with the paper's algorithm
replayed (`-algorithm paper`: docs/model.md#the-papers-algorithm-replayed), and the explanation runs
that change one choice the paper leaves open. Results in results/claims/<name>/.

Usage: tools/docs/claims.py --run (make figures; about 6 min), one run at a time, each failure named
with its log.
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_io  # noqa: E402
from paper_scale_metrics import curve, reversion_start  # noqa: E402
from scene_steps import fixed_steps  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RESULTS = os.path.join(ROOT, "results")
CLAIMS = os.path.join(RESULTS, "claims")
QUARTER = ["-phasemodel", "onoff", "-mesh", "meshes/sleeve-quarter.msh"]
# name: (scene, options); the on/off runs on the quarter mesh the paper's scheme is tested on (the
# offset scene on its own half-ring mesh), the explanation runs change one choice the paper leaves open.
RUNS = {
    "onoff-sleeve-circular": ("sleeve-circular", QUARTER),
    "onoff-sleeve-circular-gvar": ("sleeve-circular-gvar", QUARTER),
    "onoff-sleeve-offset": ("sleeve-offset", ["-phasemodel", "onoff"]),
    "onoff-sleeve-elliptic": ("sleeve-elliptic", QUARTER),
    "onoff-sleeve-elliptic-friction": ("sleeve-elliptic-friction", QUARTER),
    "onoff-sleeve-random-threshold": ("sleeve-random-threshold", QUARTER),
    # where the reversion starts: frames every 2 steps (dt 0.1 s as the default) up to past the
    # onset, both faces exchanging (the default: onset near step 580) ...
    "circular-frames": ("sleeve-circular", ["-vtkevery", "2", "-tend", "65", "-steps", "650"]),
    # ... and the outer face insulated (the ring warms through the pipe only: onset near step 1270)
    "circular-outer-insulated": ("sleeve-circular", ["-vtkevery", "2", "-g", "0", "-gpipe", "500",
                                                     "-gcontact", "500", "-tend", "140", "-steps", "1400"]),
    # Fig. 17-18: the pipe's temperature (not in the paper; the default: the air's, 20 C), both
    # scenes on the same mesh: a pipe at -25 C and at -30 C
    "circular-pipe-25C": ("sleeve-circular", ["-mesh", "meshes/sleeve-quarter.msh", "-Tpipe", "248.15"]),
    "gvar-pipe-25C": ("sleeve-circular-gvar", ["-Tpipe", "248.15"]),
    "circular-pipe-30C": ("sleeve-circular", ["-mesh", "meshes/sleeve-quarter.msh", "-Tpipe", "243.15"]),
    "gvar-pipe-30C": ("sleeve-circular-gvar", ["-Tpipe", "243.15"]),
    # Fig. 21-24: point A where the offset ring touches the pipe (the offset equals the
    # interference), held rigidly: the ring dilates about it (paper 4.3: "the deformed ring
    # coincides at one instant with the pipe, and contact occurs then at every point")
    "offset-tangent-anchor": ("sleeve-offset", ["-anchorpoint", "tangent", "-anchor", "1e3"]),
    # Fig. 30-31: the slip threshold lagged (one DC solve per pass, the paper's "diagonal
    # process" [RAO 88]) on the on/off scheme's path
    "onoff-friction-diagonal": ("sleeve-elliptic-friction", QUARTER + ["-slipmaxit", "1", "-keepgoing", "1"]),
    # ... the time step (5 times the default's) and the outer face insulated (the paper does not
    # say which faces exchange heat; the runs with a weaker outer face go over 450 s)
    "onoff-friction-300-steps": ("sleeve-elliptic-friction", QUARTER + ["-steps", "300"]),
    "onoff-friction-outer-insulated": ("sleeve-elliptic-friction", QUARTER + ["-g", "0", "-gpipe", "500", "-gcontact",
                                                                              "500", "-tend", "450", "-steps", "4500"]),
    # Fig. 34-35: the threshold's law (uniform, the same standard deviation) and a coarser mesh
    "random-uniform": ("sleeve-random-threshold", ["-cdist", "uniform"]),
    "random-coarse": ("sleeve-random-threshold", ["-mesh", "meshes/sleeve-coarse.msh"]),
    # ... and the printed a = 300 on the interference it can open (-scale reduced, spread 5 K)
    "random-printed-a": ("sleeve-random-threshold", ["-scale", "reduced"]),
}
# The paper's algorithm replayed on each figure scene, on the scene's own mesh (the paper's quarter
# ring; the offset scene's half ring): what of the paper's figures its unconverged iterations make.
FIGURE_SCENES = ("sleeve-circular", "sleeve-circular-gvar", "sleeve-circular-single", "sleeve-offset",
                 "sleeve-elliptic", "sleeve-elliptic-friction", "sleeve-random-threshold")
RUNS.update({f"replay-{scene}": (scene, ["-algorithm", "paper"]) for scene in FIGURE_SCENES})
START = "reversion-start.json"  # a frames run's measure; its frames (60 MB) are removed once read


def out_of(name):
    return os.path.join(CLAIMS, name)


def run_all():
    for name, (scene, options) in RUNS.items():
        out = out_of(name)
        log = out + ".log"
        os.makedirs(CLAIMS, exist_ok=True)
        cmd = [os.path.join(ROOT, "tools", "ff"), f"edp/scenes/{scene}.edp", "-quiet", "1", "-out", out]
        if "-vtkevery" not in options:
            cmd += ["-vtkevery", "0"]
        cmd += list(options) + fixed_steps(options)
        with open(log, "w") as f:
            rc = subprocess.run(cmd, cwd=ROOT, stdout=f, stderr=subprocess.STDOUT).returncode
        if rc != 0 or not os.path.exists(os.path.join(out, "summary.json")):
            sys.exit(f"error: claims run {name} ({' '.join(cmd[1:])}) failed with exit {rc}: see {log}")
        if "-vtkevery" in options:
            where, step = reversion_start(out, curve(out)["onset_step"])
            results_io.record(os.path.join(out, START))  # in the folder's manifest: a rerun replaces it
            with open(os.path.join(out, START), "w") as f:
                json.dump({"fraction_of_thickness": where, "frame_step": step}, f)
            shutil.rmtree(os.path.join(out, "frames"))
            for vtu in os.listdir(out):
                if vtu.endswith(".vtu") or vtu.endswith(".pvd"):
                    os.remove(os.path.join(out, vtu))
        print(f"  claims run {name}: ok")


def default(scene):
    return os.path.join(RESULTS, scene)
