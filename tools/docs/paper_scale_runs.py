"""The runs of tools/docs/paper_scale_fit.py: the paper's geometry as scene options, and run(), which
runs one scene at a time into the work folder, with its log, a fallback where its spec names one,
and a line of RUNLOG (the report's run table) per attempt."""
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from scene_steps import fixed_steps  # noqa: E402

INTERF = 0.0005            # the paper's interference: pipe 5.05 cm, ring 5 cm
OFFSET = 0.0005            # the paper's 0.05 cm: its offset equals its interference
ELLIPSE = ["-Ri", "0.05", "-pipeA", "0.0504", "-pipeB", "0.0505"]   # paper 4.4.1: 5.04 (x) x 5.05 (y)
INSULATED = ["-g", "0", "-gpipe", "500", "-gcontact", "500"]         # outer face insulated
LONG = ["-tend", "450", "-steps", "4500"]   # insulated outer face: warming through one face only
                                            # takes longer than the default 150 s (same dt 0.1 s)
# the heat-exchange choices of stage 2: (key, options of sleeve-circular; gvar: -gcontact 2000)
HEATS = [("both", []),
         ("outer g=100", ["-g", "100", "-gpipe", "500", "-gcontact", "500"] + LONG),
         ("outer insulated", INSULATED + LONG)]


def gvar_opts(o):
    """The variable-g run of a heat choice: -gcontact 2000, over the default 150 s (with g = 2000
    on the contact it reverts within 100 s whatever the outer face)."""
    o = list(o)
    for k in ("-tend", "-steps"):
        if k in o:
            i = o.index(k)
            del o[i:i + 2]
    if "-gcontact" in o:
        o[o.index("-gcontact") + 1] = "2000"
    return o
FALLBACK = ["-stepsolver", "fixedpoint"]

VTK = ["-vtkevery", "2"]    # frames every 2 steps: where the reversion starts

RUNLOG = []                 # (name, scene, options, status, seconds, log)
REUSE = False               # --reuse: keep a finished run whose log starts with the same command


class RunFailed(Exception):
    pass


def run(work, name, scene, opts, fallback=None):
    """Runs one scene (sequentially); returns its output directory."""
    out = os.path.join(work, name)
    attempts = [opts] + ([opts + fallback] if fallback else [])
    logs = []
    if REUSE and os.path.exists(out + ".done"):
        with open(out + ".done") as f:
            k, done, secs = (f.read().split("\n") + ["", ""])[:3]
        for kk, o in enumerate(attempts):
            if kk == int(k) and done.strip() == " ".join(o):
                if kk > 0:
                    RUNLOG.append((name, scene, " ".join(attempts[0]), "FAILED (reused)", 0.0,
                                   out + ".log"))
                RUNLOG.append((name, scene, " ".join(o), ("fallback " if kk else "") +
                               "ok (reused)", float(secs or 0),
                               out + (".log" if kk == 0 else ".fallback.log")))
                print("  %-34s reused" % name, flush=True)
                return out
    subprocess.run(["rm", "-f", out + ".done"])
    for k, o in enumerate(attempts):
        log = out + (".log" if k == 0 else ".fallback.log")
        logs.append(log)
        cmd = ["tools/ff", "edp/scenes/%s.edp" % scene, "-quiet", "1", "-out", out]
        if "-vtkevery" not in o:
            cmd += ["-vtkevery", "0"]
        cmd += list(o) + fixed_steps(o)  # (the paper's figures at its 1500 increments)
        subprocess.run(["rm", "-rf", out])
        t0 = time.time()
        with open(log, "w") as f:
            f.write("$ " + " ".join(cmd) + "\n")
            f.flush()
            rc = subprocess.run(cmd, cwd=ROOT, stdout=f, stderr=subprocess.STDOUT).returncode
        dt = time.time() - t0
        ok = rc == 0 and os.path.exists(os.path.join(out, "summary.json"))
        status = "ok" if ok else "FAILED (exit %d)" % rc
        if ok:
            with open(os.path.join(out, "summary.json")) as f:
                fb = json.load(f).get("step_fallbacks", 0)
            if fb:
                status += " (%d step%s by the nested loops: -stepfallback)" % (fb, "s" if fb > 1 else "")
        if k > 0:
            status = "fallback " + status
        RUNLOG.append((name, scene, " ".join(o), status, dt, log))
        if ok:
            with open(out + ".done", "w") as f:
                f.write("%d\n%s\n%.1f\n" % (k, " ".join(o), dt))
            print("  %-34s %-26s %5.1f s  %s" % (name, scene, dt, status), flush=True)
            return out
        err = ""
        with open(log) as f:
            for line in f:
                if line.startswith("error"):
                    err = line.strip()
                    break
        print("!!! RUN FAILED: %s (%s %s), exit %d: %s; log %s"
              % (name, scene, " ".join(o), rc, err, log), file=sys.stderr, flush=True)
    raise RunFailed("run %s failed in every attempt; logs: %s" % (name, ", ".join(logs)))

