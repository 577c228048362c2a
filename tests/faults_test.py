#!/usr/bin/python3
"""Faults while writing results: nothing silent, nothing lost, nothing mixed (edp/lib/output.idp,
plugin/core/files.hpp).

1. A full disk. A small tmpfs is mounted as the output folder where the machine allows it (root),
   at several sizes; and, everywhere, the process's file-size limit (RLIMIT_FSIZE, SIGXFSZ
   ignored: writes beyond it fail with EFBIG) at several sizes. Each run either ends with exit 0
   and complete files (summary.json valid JSON, history.csv with every step, every VTU closed),
   or with exit 1, one "error: cannot write <file>" line and no summary.json. At least one size
   must fail (or the test proves nothing) and the largest must pass.
2. Two runs into one folder: the second, started while the first holds the folder, fails naming
   the first's process; the first completes undisturbed, and its lock is gone after. Ten pairs
   started at once: one runs, one is refused, each time (the lock appears whole: files.hpp).
3. A killed run (SIGKILL, no exit handler) leaves its lock; the next run takes it (the process is
   dead) and completes.
4. A folder of the user's (a frames/ folder and notes) given as -out: refused, nothing in it touched;
   a second scene into a first scene's folder: the first's files all go (the manifest lists them).
5. Names with shell syntax: -out and -mesh with a quote, double quotes, spaces, a semicolon,
   $(...), backquotes and UTF-8 run normally; summary.json is valid JSON and holds the mesh path
   exactly; no command in them ran.
6. Out of memory: sleeve-circular, sleeve-radial and beam at their defaults under address-space
   limits (RLIMIT_AS, as `ulimit -v`) from 60 to 400 MB. Each run ends within the timeout, either
   with exit 0 and complete files, or with a non-zero exit and one `error:` line that says out of
   memory and names the limit (before: 100-230 MB wrote the results and never exited, in
   OpenBLAS's thread shutdown; 92-100 MB an exit 1 without an error line, a segmentation fault or
   an exec error called a bug). At least one limit fails and the largest completes, per scene.
7. The results folder removed during the run (tests/hooks/folder-removed*.edp remove it at step 20):
   the next write (an instant's fields, a frame, a checkpoint; sleeve-circular and sleeve-radial)
   fails with exit 1 and one error line naming the missing folder (it ended in a segmentation
   fault after the line, or FreeFEM's "Exec error" naming no cause). And the form that keeps a
   failure there from crashing FreeFEM (edp/lib/output.idp, PartialPath), checked in every script:
   no Partial or PartialVtu as a string's initializer, no call in a stream's argument.
8. A folder's last complete run is kept whole while the next one runs: sleeve-radial (with its
   default mesh-error companion in mesh-estimate/) completes, then a run stopped after step 30
   (-stopafter) leaves previous-run/ holding every file and folder its manifest lists, the
   companion's history.csv the same bytes (the companion was removed: previous-run/ lacked it);
   a third run that completes leaves no previous-run/.
Writes results/checks/faults.json.
"""
import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from checklib import ROOT, check, finish, record  # noqa: E402

FF = os.path.join(ROOT, "tools", "ff")
SCENE = os.path.join(ROOT, "edp", "scenes", "sleeve-circular.edp")
# A short run that still writes every kind of file: 300 steps, frames every 50, three instants.
SHORT = ["-mesh", "meshes/sleeve-coarse.msh", "-steps", "300", "-vtkevery", "50", "-quiet", "1"]


def run(out, *extra, limit=None, wait=True):
    def preexec():
        if limit is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    command = [FF, SCENE] + SHORT + ["-out", out] + list(extra)
    if not wait:
        return subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True, start_new_session=True)
    return subprocess.run(command, cwd=ROOT, capture_output=True, text=True, preexec_fn=preexec, timeout=300)


def errors_of(result):
    return [ln for ln in (result.stdout + result.stderr).splitlines() if ln.startswith("error:")]


def complete(out, steps=300):
    """Why the folder is not a complete run's, or "" when it is. steps: the run's fixed steps, or
    "adaptive" for a run whose steps the error chose (the sleeve scenes' default): as many as its
    summary.json says, the last row of history.csv at -tend."""
    try:
        summary = json.load(open(os.path.join(out, "summary.json")))
    except (OSError, ValueError) as e:
        return f"summary.json: {e}"
    adaptive = steps == "adaptive"
    if adaptive:
        steps = summary.get("n_steps")
        if summary.get("time_steps") != "adaptive" or not isinstance(steps, int) or steps < 1:
            return f"summary.json time_steps {summary.get('time_steps')}, n_steps {steps}"
    if summary.get("n_steps") != steps:
        return f"summary.json n_steps {summary.get('n_steps')}"
    lines = open(os.path.join(out, "history.csv")).read().splitlines()
    if len(lines) != steps + 1:
        return f"history.csv has {len(lines)} lines"
    if adaptive:
        t_last = float(lines[-1].split(",")[lines[0].split(",").index("t")])
        if abs(t_last - summary["parameters"]["tend"]) > 1e-9 * summary["parameters"]["tend"]:
            return f"history.csv ends at t {t_last}, not -tend {summary['parameters']['tend']}"
    vtus = [os.path.join(d, f) for d, _, fs in os.walk(out) for f in fs if f.endswith(".vtu")]
    for vtu in vtus:
        if not open(vtu).read().rstrip().endswith("</VTKFile>"):
            return f"{vtu} is not closed"
    partial = [f for _, _, fs in os.walk(out) for f in fs if ".partial" in f]
    return f"left {partial}" if partial else ""


def judge(label, result, out):
    """One run under a full disk: complete, or a clean failure."""
    errors = errors_of(result)
    if result.returncode == 0:
        why = complete(out)
        check(why == "", f"{label}: exit 0 and every file complete{': ' + why if why else ''}")
        return "complete"
    clean = (result.returncode == 1 and len(errors) == 1 and errors[0].startswith("error: cannot write ")
             and not os.path.exists(os.path.join(out, "summary.json")))
    check(clean, f"{label}: exit {result.returncode}, one 'error: cannot write' line, no summary.json "
          f"({errors[:2] or result.stdout[-300:]})")
    return errors[0] if errors else f"exit {result.returncode}"


def full_disk(tmp, measured):
    outcomes = []
    # The file-size limit: the largest file of the short run is a VTU of about 60 kB.
    for limit in (2000, 20000, 50000, 10 ** 7):
        out = os.path.join(tmp, f"fsize-{limit}")
        outcome = judge(f"file size limit {limit} B", run(out, limit=limit), out)
        outcomes.append({"fault": "RLIMIT_FSIZE", "bytes": limit, "outcome": outcome})
    # A small file system, where one can be mounted.
    mount = os.path.join(tmp, "tmpfs")
    os.makedirs(mount)
    mounted = False
    if os.geteuid() == 0:
        for size in ("64k", "256k", "600k", "8m"):
            if subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", mount],
                              capture_output=True).returncode != 0:
                break
            mounted = True
            try:
                out = os.path.join(mount, "out")
                outcome = judge(f"a {size} file system", run(out), out)
                outcomes.append({"fault": "tmpfs", "size": size, "outcome": outcome})
            finally:
                subprocess.run(["umount", mount], check=True)
    measured["full_disk"] = outcomes
    measured["tmpfs_mounted"] = mounted
    failed = [o for o in outcomes if o["outcome"] != "complete"]
    check(failed and outcomes[-1]["outcome"] == "complete",
          f"full disk: {len(failed)} of {len(outcomes)} runs failed cleanly, the largest completed "
          f"(tmpfs {'mounted' if mounted else 'not available: RLIMIT_FSIZE only'})")


def wait_for(path, seconds=60):
    end = time.time() + seconds
    while time.time() < end and not os.path.exists(path):
        time.sleep(0.02)
    return os.path.exists(path)


def concurrent(tmp, measured):
    out = os.path.join(tmp, "shared")
    # the paper's 1500 fixed steps (-tol 0): a few seconds, where the default's adaptive steps take 0.1 s
    first = subprocess.Popen([FF, SCENE, "-quiet", "1", "-tol", "0", "-out", out], cwd=ROOT, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
    locked = wait_for(os.path.join(out, ".sma-lock"))
    # The first run is held (SIGSTOP) while the second tries the folder, then let go: the second
    # meets it holding the folder however loaded the machine (it could finish first, and the
    # second then overwrote its folder).
    held = [int(p) for p in subprocess.run(["pgrep", "-P", str(first.pid), "FreeFem"], capture_output=True,
                                           text=True).stdout.split()]
    for pid in held:
        os.kill(pid, signal.SIGSTOP)
    second = run(out)
    for pid in held:
        os.kill(pid, signal.SIGCONT)
    first_output, _ = first.communicate(timeout=300)
    errors = errors_of(second)
    owner_named = bool(errors) and "in use by another run (process " in errors[0]
    check(locked and held and second.returncode == 1 and len(errors) == 1 and owner_named,
          f"a second run into a folder in use fails naming the first's process: {errors[:1]}")
    why = complete(out, steps=1500)
    check(first.returncode == 0 and why == "" and not os.path.exists(os.path.join(out, ".sma-lock")),
          f"the first run completed undisturbed and released the folder (exit {first.returncode}{', ' + why if why else ''})")
    measured["concurrent"] = {"second_error": errors[0] if errors else None, "first_exit": first.returncode}


def started_together(tmp, measured):
    """Ten pairs of runs started at once into one folder: each time one runs and the other is refused
    as in use, or, where the machine's load let the first end before the second began, both run one
    after the other (the first's whole run in previous-run/). Never both at once. (The lock was
    created empty, then written: a second run that read it in between saw no owner, judged it stale
    and took the folder too, in 6 of 20 pairs; one failed renaming a file the other had moved, the
    other on a FreeFEM assertion.)"""
    outcomes = []
    for i in range(10):
        out = os.path.join(tmp, f"together-{i}")
        args = [FF, "edp/scenes/sleeve-radial.edp", "-quiet", "1", "-tol", "0", "-steps", "2000", "-meshestimate", "0",
                "-out", out]
        pair = [subprocess.Popen(args, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                for _ in range(2)]
        texts = [p.communicate(timeout=300)[0] for p in pair]
        codes = sorted(p.returncode for p in pair)
        refused = sum("in use by another run" in t for t in texts)
        whole = complete(out, steps=2000) == ""
        one_after = codes == [0, 0] and refused == 0 and whole and os.path.exists(os.path.join(out, "previous-run", "summary.json"))
        outcomes.append({"exits": codes, "refused": refused, "complete": whole, "one_after_the_other": one_after})
    bad = [o for o in outcomes if not ((o["exits"] == [0, 1] and o["refused"] == 1 and o["complete"]) or o["one_after_the_other"])]
    together = sum(o["refused"] == 1 for o in outcomes)
    check(not bad and together >= 1, f"ten pairs started together into one folder: one runs and one is refused as in use "
                                     f"({together} pairs), or one after the other: never both at once (otherwise: {bad or 'none'})")
    measured["started_together"] = {"pairs": len(outcomes), "refused": together, "bad": len(bad)}


def killed(tmp, measured):
    out = os.path.join(tmp, "killed")
    victim = subprocess.Popen([FF, SCENE, "-quiet", "1", "-out", out], cwd=ROOT, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL, start_new_session=True)
    locked = wait_for(os.path.join(out, ".sma-lock"))
    os.killpg(victim.pid, signal.SIGKILL)
    victim.wait()
    stale = os.path.exists(os.path.join(out, ".sma-lock"))
    again = run(out)
    why = complete(out)
    check(locked and stale and again.returncode == 0 and why == "",
          f"a killed run's lock stays (stale: {stale}) and the next run takes it and completes "
          f"(exit {again.returncode}{', ' + why if why else ''})")
    measured["killed"] = {"stale_lock_left": stale, "next_exit": again.returncode}


def causes(tmp, measured):
    """tools/ff names why FreeFEM stopped: a SIGTERM of the FreeFEM process (interrupted), a
    file-size limit (SIGXFSZ), an execution error of a script (exit 8): one error line each."""
    out = os.path.join(tmp, "terminated")
    victim = subprocess.Popen([FF, SCENE, "-quiet", "1", "-steps", "30000", "-out", out], cwd=ROOT,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wait_for(os.path.join(out, ".sma-lock"))
    pid = subprocess.run(["pgrep", "-P", str(victim.pid), "FreeFem"], capture_output=True, text=True).stdout.split()
    for p in pid:
        os.kill(int(p), signal.SIGTERM)
    _, err = victim.communicate(timeout=60)
    lines = [ln for ln in err.splitlines() if ln.startswith("error:")]
    check(victim.returncode == 143 and len(lines) == 1 and "SIGTERM" in lines[0] and "interrupted" in lines[0],
          f"FreeFEM stopped by SIGTERM: exit {victim.returncode}, {lines[0] if lines else err[-200:]}")
    script = os.path.join(tmp, "divide.edp")
    with open(script, "w") as f:
        f.write("int a = 1 / 0;\n")
    divide = subprocess.run([FF, script], cwd=ROOT, capture_output=True, text=True)
    lines = [ln for ln in (divide.stdout + divide.stderr).splitlines() if ln.startswith("error:")]
    check(divide.returncode == 8 and len(lines) == 1 and "execution error (exit 8)" in lines[0],
          f"an execution error of a script: exit {divide.returncode}, {lines[0] if lines else divide.stderr[-200:]}")
    measured["causes"] = {"sigterm_exit": victim.returncode, "exec_error_exit": divide.returncode}


def foreign(tmp, measured):
    out = os.path.join(tmp, "my papers")
    os.makedirs(os.path.join(out, "frames"))
    mine = {os.path.join(out, "frames", "step-000050.vtu"): "my own frame\n",
            os.path.join(out, "notes.txt"): "do not lose\n"}
    for path, text in mine.items():
        with open(path, "w") as f:
            f.write(text)
    result = run(out)
    errors = errors_of(result)
    untouched = all(open(p).read() == t for p, t in mine.items())
    left = sorted(os.listdir(out))
    check(result.returncode == 1 and len(errors) == 1 and "holds files this suite did not write" in errors[0]
          and untouched and left == ["frames", "notes.txt"],
          f"a folder of the user's is refused and left as it was ({left}): {errors[:1]}")
    measured["foreign"] = {"error": errors[0] if errors else None, "left": left}


def second_scene(tmp, measured):
    """A second scene into a first scene's folder: the first's files go as a whole (its frames,
    fields and points.csv are no output of the radial model) and the manifest names the second."""
    out = os.path.join(tmp, "two scenes")
    first = run(out)
    radial = subprocess.run([FF, os.path.join(ROOT, "edp", "scenes", "sleeve-radial.edp"), "-steps", "100",
                             "-quiet", "1", "-out", out], cwd=ROOT, capture_output=True, text=True, timeout=300)
    alone = os.path.join(tmp, "radial alone")
    subprocess.run([FF, os.path.join(ROOT, "edp", "scenes", "sleeve-radial.edp"), "-steps", "100", "-quiet", "1",
                    "-out", alone], cwd=ROOT, capture_output=True, text=True, timeout=300)
    left, expected = sorted(os.listdir(out)), sorted(os.listdir(alone))
    with open(os.path.join(out, ".sma-results")) as f:
        scene_line = f.read().splitlines()[1]
    check(first.returncode == 0 and radial.returncode == 0 and left == expected and scene_line == "scene sleeve-radial",
          f"sleeve-radial into sleeve-circular's folder leaves only its own files ({len(left)} entries, alone "
          f"{len(expected)}; extra: {sorted(set(left) - set(expected))}), its manifest's '{scene_line}'")
    measured["second_scene"] = {"entries": left, "expected": expected}


# Address-space limits in kB (ulimit -v): below what FreeFEM's libraries need, the start-up, the
# plugin's first arrays, OpenBLAS's 128 MB buffer (beam's UMFPACK solves), and enough.
MEMORY_LIMITS_KB = (60000, 92000, 96000, 100000, 150000, 200000, 250000, 400000)
MEMORY_SCENES = (("sleeve-circular", "adaptive"), ("sleeve-radial", None), ("beam", None))


def under_memory_limit(scene, out, limit_kb, timeout=60):
    """Runs a scene at its defaults under RLIMIT_AS = limit_kb kB; kills its process group when it
    outlives the timeout (a FreeFEM stuck at exit would stay behind tools/ff otherwise)."""
    def preexec():
        resource.setrlimit(resource.RLIMIT_AS, (limit_kb * 1024, limit_kb * 1024))
    start = time.time()
    p = subprocess.Popen([FF, os.path.join(ROOT, "edp", "scenes", scene + ".edp"), "-quiet", "1", "-out", out],
                         cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         preexec_fn=preexec, start_new_session=True)
    try:
        stdout, stderr = p.communicate(timeout=timeout)
        code = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        stdout, stderr = p.communicate()
        code = None
    return code, stdout + stderr, time.time() - start


def memory(tmp, measured):
    outcomes = []
    for scene, steps in MEMORY_SCENES:
        ends = []
        for limit_kb in MEMORY_LIMITS_KB:
            out = os.path.join(tmp, f"memory-{scene}-{limit_kb}")
            code, output, seconds = under_memory_limit(scene, out, limit_kb)
            errors = [ln for ln in output.splitlines() if ln.startswith("error:")]
            label = f"{scene} under ulimit -v {limit_kb}"
            if code == 0:
                if steps:
                    why = complete(out, steps)
                else:
                    try:
                        json.load(open(os.path.join(out, "summary.json")))
                        why = ""
                    except (OSError, ValueError) as e:
                        why = f"summary.json: {e}"
                check(why == "" and not errors, f"{label}: exit 0 and complete files{': ' + why if why else ''} "
                      f"({seconds:.1f} s)")
                outcome = "complete"
            else:
                clean = (code is not None and len(errors) == 1 and "out of memory" in errors[0]
                         and f"(ulimit -v {limit_kb} kB)" in errors[0])
                check(clean, f"{label}: " + ("no end within 60 s" if code is None else f"exit {code}") +
                      f", one 'error:' line saying out of memory under that limit ({errors[:2] or output[-300:]})")
                outcome = errors[0] if errors else ("timeout" if code is None else f"exit {code}")
            ends.append(outcome)
            outcomes.append({"scene": scene, "limit_kb": limit_kb, "exit": code, "seconds": round(seconds, 2),
                             "outcome": outcome})
        check(ends[-1] == "complete" and any(e != "complete" for e in ends),
              f"{scene}: {sum(e != 'complete' for e in ends)} of {len(ends)} limits failed cleanly, "
              f"the largest ({MEMORY_LIMITS_KB[-1]} kB) completed")
    measured["memory"] = outcomes


def shell_syntax(tmp, measured):
    name = "it's a \"dir\"; touch PWNED $(touch PWNED) `touch PWNED` r\u00e9sultats \u2713"
    folder = os.path.join(tmp, name)
    os.makedirs(folder)
    mesh = os.path.join(folder, "ring; touch PWNED 'q'.msh")
    shutil.copyfile(os.path.join(ROOT, "meshes", "sleeve-coarse.msh"), mesh)
    out = os.path.join(folder, "out $(touch PWNED)")
    result = subprocess.run([FF, SCENE, "-mesh", mesh, "-steps", "300", "-quiet", "1", "-out", out],
                            cwd=ROOT, capture_output=True, text=True, timeout=300)
    # A PWNED made by a shell would land in the working directory (ROOT) or next to the files.
    injected = [p for p in (os.path.join(tmp, "PWNED"), os.path.join(ROOT, "PWNED"), os.path.join(folder, "PWNED"))
                if os.path.exists(p)]
    try:
        summary = json.load(open(os.path.join(out, "summary.json")))
        mesh_recorded = summary["parameters"]["mesh"]
    except (OSError, ValueError, KeyError) as e:
        mesh_recorded = f"unreadable: {e}"
    check(result.returncode == 0 and mesh_recorded == mesh and not injected,
          f"paths with quotes, spaces, ;, $(...), backquotes and UTF-8 are names: exit {result.returncode}, "
          f"summary.json records the mesh path exactly ({mesh_recorded == mesh}), nothing ran ({injected})"
          + ("" if result.returncode == 0 else f": {errors_of(result)[:1] or result.stdout[-300:]}"))
    measured["shell_syntax"] = {"exit": result.returncode, "mesh_recorded_exactly": mesh_recorded == mesh}


def folder_removed(tmp, measured):
    cases = [("tests/hooks/folder-removed.edp", ["-vtkevery", "0"], "fields-2-contact.csv"),
             ("tests/hooks/folder-removed.edp", ["-vtkevery", "21"], "frames/step-000021.vtu"),
             ("tests/hooks/folder-removed.edp", ["-vtkevery", "0", "-checkpoint", "10"], ".csv"),
             ("tests/hooks/folder-removed-radial.edp", [], "fields-2-contact.csv")]
    for k, (script, extra, named) in enumerate(cases):
        out = os.path.join(tmp, f"removed-{k}")
        result = subprocess.run([FF, script, "-steps", "300", "-quiet", "1", *extra, "-out", out], cwd=ROOT,
                                capture_output=True, text=True, timeout=300)
        lines = errors_of(result)
        label = f"{os.path.basename(script)} {' '.join(extra)}".strip()
        check(result.returncode == 1 and len(lines) == 1 and "is missing (removed while the run wrote" in lines[0]
              and named in lines[0] and not os.path.exists(out),
              f"{label}: the folder removed at step 20: exit {result.returncode} (1), one error line naming it "
              f"({len(lines)}): {lines[:2]}")
        measured[f"folder_removed {label}"] = {"exit": result.returncode, "errors": lines}
    # The form, in every script (edp/lib/output.idp, PartialPath; its own definitions apart)
    bad = []
    for folder, _, names in os.walk(os.path.join(ROOT, "edp")):
        for name in sorted(names):
            if not name.endswith((".edp", ".idp")):
                continue
            path = os.path.join(folder, name)
            for number, line in enumerate(open(path), 1):
                code = line.split("//")[0]
                if (re.search(r"\bstring\s+\w+\s*=[^;]*\bPartial(Vtu)?\(", code)
                        or re.search(r"\bofstream\s+\w+\([^;]*\(", code)):
                    bad.append(f"{os.path.relpath(path, ROOT)}:{number}")
    check(not bad, f"no script opens a result file's stream on a call, or declares a string with Partial as its "
          f"initializer (output.idp, PartialPath): {bad or 'none'}")


def previous_run_whole(tmp, measured):
    out = os.path.join(tmp, "previous-whole")
    radial = [FF, "edp/scenes/sleeve-radial.edp", "-out", out]
    first = subprocess.run(radial, cwd=ROOT, capture_output=True, text=True, timeout=300)
    companion = os.path.join(out, "mesh-estimate", "history.csv")
    kept = open(companion, "rb").read() if os.path.isfile(companion) else None
    stopped = subprocess.run(radial + ["-stopafter", "30"], cwd=ROOT, capture_output=True, text=True, timeout=300)
    previous = os.path.join(out, "previous-run")
    with open(os.path.join(previous, ".sma-results")) as f:
        listed = [ln.strip() for ln in f.read().splitlines()[2:] if ln.strip()]
    missing = [e for e in listed if not os.path.exists(os.path.join(previous, e.rstrip("/")))]
    again = os.path.join(previous, "mesh-estimate", "history.csv")
    same = kept is not None and os.path.isfile(again) and open(again, "rb").read() == kept
    check(first.returncode == 0 and stopped.returncode == 4 and "mesh-estimate/" in listed and not missing and same,
          f"a complete run, then one stopped after step 30 (exit {first.returncode}, {stopped.returncode}): previous-run/ "
          f"holds all {len(listed)} entries its manifest lists (missing: {missing or 'none'}), the companion's "
          f"history.csv {'the same bytes' if same else 'CHANGED OR MISSING'}")
    third = subprocess.run(radial, cwd=ROOT, capture_output=True, text=True, timeout=300)
    check(third.returncode == 0 and not os.path.exists(previous),
          f"the next complete run (exit {third.returncode}) removes previous-run/")
    measured["previous_run_whole"] = {"listed": listed, "missing": missing, "companion_same": same}


def main():
    measured = {}
    with tempfile.TemporaryDirectory(prefix="faults-") as tmp:
        full_disk(tmp, measured)
        concurrent(tmp, measured)
        started_together(tmp, measured)
        killed(tmp, measured)
        causes(tmp, measured)
        foreign(tmp, measured)
        second_scene(tmp, measured)
        shell_syntax(tmp, measured)
        folder_removed(tmp, measured)
        previous_run_whole(tmp, measured)
        memory(tmp, measured)
    record("faults", {"test": "faults", **measured})
    finish()


if __name__ == "__main__":
    main()
