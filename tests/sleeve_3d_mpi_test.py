#!/usr/bin/python3
"""sleeve-3d on MPI ranks (edp/mpi/sleeve-3d.edp through tools/ff-mpi; make run SCENE=sleeve-3d NP=2):
the scene's time loop and the paper's nested loops, every stiffness and heat solve through ffddm
(edp/solvers/distributed.idp; docs/model.md#the-scene-on-ffddm).

On a small mesh (-nr 2 -nt 4 -length 0.04: 75 nodes, 4 layers) and fixed steps (-tol 0 -steps 100,
so that every run takes the same instants), with the paper's nested loops (-stepsolver fixedpoint)
but where newton is named:
- the run's own error stated once (rank 0), the mesh's not estimated by default on ranks (its
  companion would run sequentially on rank 0), the summary's mesh_estimate_skipped saying so;
- MPI equality: the curves (mean pressure, the bore's mean temperature, the austenite fraction) on
  1 and 2 ranks equal the sequential scene's with the same nested loops (-stepsolver fixedpoint)
  to 1e-4 of their largest value (measured 7.7e-6, and 3.2e-5 with GenEO: the nested loops stop
  at -dctol 1e-3, and a solve's 1e-10 moves where they stop);
- the difference is the loops' tolerance, not the distribution: with -dctol 1e-7 -fptol 1e-11 (on 2
  ranks with GenEO's coarse space, -ddmgeneo 1) it falls below 5e-7 (measured 1.5e-7), and by more
  than 10 times; GenEO's coarse space has some vectors and takes fewer GMRES iterations a solve
  than one level (measured 6.6 against 9.1);
- the stages after the clamping on ranks (the cone's W from one distributed solve per contact row,
  the plugin's PsorCone on it: distributed.idp DistributedConeStep; the clamping's kept columns of
  the rows both share taken again: its normal rows on 2 ranks, none on 1): the runs above bend the
  clamped joint (-bend 1e-2 -bendsteps 2, frictionless: the clamping unchanged); on 1 and 2 ranks
  bend.csv is the sequential scene's (moment, normal force, to 1e-4 of the largest; open and
  sliding nodes equal), with the cone and complementarity at every node;
- a budget between the clamping's columns and the stage's (-ddmcolumnsmb 0.1): the stage takes the
  clamping's kept columns again and keeps none of its own, the same bending;
- the contact's columns S K^-1 S H': kept on 2 ranks (their product a global step), solved for on
  1 rank (-ddmcolumnsmb 0: a second solve a global step, about twice the solves), the same curves;
  each rank keeps a slice of their rows (on 2 ranks half the size a rank);
- the solves: every one within 100 x -ddmtol of the scene's matrix (summary.json "distributed"
  residual_max); on one rank the preconditioner is the exact inverse (at most one GMRES iteration
  a solve), on two more than one (the subdomains are used);
- the laws as the sequential scene reports them: gap >= -1e-6 of the interference, r gap <= 1e-6,
  equilibrium residual <= 1e-9; rank 0 alone prints the report (tools/ff-mpi);
- refusals, once, alone and without a hang (no rank left running): an unknown option, named by the
  sequential first step; 2 ranks for 3 layers (a slab of at least 2 layers each), named by rank 0
  (docs/errors.md's cases, run by bad_inputs_test, add Coulomb's cone and 3 ranks for 2 layers); an ffddm
  option this run does not set (-ffddm_overlap 2), by every rank; each exits non-zero within 60 s;
- an error of one rank alone (rank 1 of tests/mpi/rank_alone_error.edp) is said once, the run fails;
- checkpoints: a run stopped after step 50 (-checkpoint 20 -stopafter 50, said on its last line,
  exit 4) and resumed (-resume 1, from step 40) writes the uninterrupted run's history.csv and
  contact-final.csv byte for byte, on 2 ranks with newton;
- a TERM to tools/ff-mpi mid-run stops every rank (exit 143, said once, no summary.json published);
  a solve at its iteration limit (-ffddm_max_it 1) stops every rank (MPI_Abort), said; every run's
  temporary folders are gone after all of them (each run's own TMPDIR folder, removed by
  tools/ff-mpi even when MPI_Abort skipped the ranks' exit handlers);
- the newton step solver on the ranks (the default: plugin StepSolveFractionBy, its stiffness and
  heat solves the ranks' distributed ones): on 2 ranks the curves and the bore's forces at the end
  of the clamping equal the sequential newton run's to 1e-7 (measured 4.5e-9), on the round pipe
  and on Coulomb's cone (-nt 8 -mu 0.2 -pipeB 0.0504: the elliptic pipe with friction and free
  ends), with the laws (gap, complementarity, the cone) at every bore node; the contact's product
  C' z the ranks' slices' sum, or without kept columns (-ddmcolumnsmb 0) a distributed solve, the same;
- -meshestimate 1 -timeestimate 1 on 2 ranks (rank 0 runs the companions, the sequential scene):
  the mesh estimate equals the sequential run's to 1e-6 (relative), the time bound is made;
- make run SCENE=sleeve-3d NP=2 runs it into the folder it names and draws its figures, with the
  step control the sequential newton run's steps (instants to 1e-6 s) and curves (to 1e-7); there (the
  default mesh: more than 400 dofs a subdomain) -ddmgeneo -1 (auto) takes GenEO's coarse space, on the
  test mesh one level;
- the MPI entry sets the scene's name and defaults (sleeveScene, sleeveDefaults) as the scene does.
Writes results/checks/sleeve_3d_mpi.json.
"""
import glob
import os
import signal
import subprocess
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import ROOT, TEST_RESULTS, check, finish, ranks_alive, record, rows, summary_of  # noqa: E402

sys.path.insert(0, os.path.join(ROOT, "tools", "bench"))
from ffddm_scaling import run_in_session  # noqa: E402

# Every run's temporary folders go under this test's own TMPDIR (tools/ff-mpi makes a folder of
# the run's there and removes it), which must be empty at the end: after aborted runs too.
SCRATCH = tempfile.mkdtemp(prefix="sma-mpi-test-")
ENV = dict(os.environ, TMPDIR=SCRATCH)
SMALL = ["-nr", "2", "-nt", "4", "-length", "0.04", "-tol", "0", "-steps", "100", "-quiet", "1"]
TIGHT = ["-dctol", "1e-7", "-dcmaxit", "1000", "-fptol", "1e-11"]
FIXEDPOINT = ["-stepsolver", "fixedpoint"]  # (the paper's nested loops; newton is the default, on the ranks too)
CONE = ["-nt", "8", "-mu", "0.2", "-pipeB", "0.0504"]  # (an elliptic pipe, friction, free ends: the clamping on the cone)
BEND = ["-bend", "1e-2", "-bendsteps", "2"]  # (the stage after the clamping: the cone's rows, frictionless)
COLUMNS = ("pressure_mean", "T_inner_mean", "fraction_austenite")


def last_wins(args):
    """The -name value pairs with a later value of a name replacing the earlier one, in the first's
    place (SMALL's -nt 4, CONE's -nt 8): a scene refuses an option given twice."""
    pairs = {}
    for name, value in zip(args[0::2], args[1::2]):
        pairs[name] = value
    return [word for pair in pairs.items() for word in pair]


def ranks_run(ranks, out, *args, timeout=300):
    """tools/ff-mpi on `ranks` ranks into `out`, in a session of its own (stopped whole at the
    timeout: ffddm_scaling.run_in_session): (exit code or None, stdout + stderr, seconds, session)."""
    start = time.monotonic()
    code, output, session = run_in_session([os.path.join(ROOT, "tools", "ff-mpi"), str(ranks), "edp/mpi/sleeve-3d.edp",
                                            "-out", out, *last_wins(args)], timeout, cwd=ROOT, env=ENV)
    return code, output, time.monotonic() - start, session


def sequential(out, *args, solver="fixedpoint"):
    subprocess.run([os.path.join(ROOT, "tools", "ff"), "edp/scenes/sleeve-3d.edp", "-out", out, "-stepsolver",
                    solver, *last_wins(args)], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return out


def contact_difference(a, b):
    """The largest difference of the bore's forces at the end of the clamping (contact-final.csv:
    the normal force and each tangential one present) over the largest normal force; None when the
    nodes differ in number."""
    ra, rb = rows(os.path.join(a, "contact-final.csv")), rows(os.path.join(b, "contact-final.csv"))
    if len(ra) != len(rb) or not ra:
        return None
    forces = [c for c in ra[0] if c == "normal_force" or c.startswith("tangential_force")]
    scale = max(abs(float(r["normal_force"])) for r in ra)
    return max(abs(float(x[c]) - float(y[c])) for x, y in zip(ra, rb) for c in forces) / scale


def curve_difference(a, b):
    """The largest difference of the COLUMNS of two history.csv at the same instants, over each
    column's largest value; None when the instants differ."""
    ra, rb = rows(os.path.join(a, "history.csv")), rows(os.path.join(b, "history.csv"))
    if len(ra) != len(rb) or any(x["t"] != y["t"] for x, y in zip(ra, rb)):
        return None
    worst = 0.0
    for column in COLUMNS:
        scale = max(abs(float(r[column])) for r in ra) or 1.0
        worst = max(worst, max(abs(float(x[column]) - float(y[column])) for x, y in zip(ra, rb)) / scale)
    return worst


def scene_settings(path):
    """The sleeveScene and sleeveDefaults lines of a script."""
    return [line for line in open(os.path.join(ROOT, path)) if line.startswith(("string sleeveScene", "string sleeveDefaults"))]


def main():
    settings = scene_settings("edp/mpi/sleeve-3d.edp")
    check(len(settings) == 2 and settings == scene_settings("edp/scenes/sleeve-3d.edp"),
          f"edp/mpi/sleeve-3d.edp sets the scene's name and defaults as edp/scenes/sleeve-3d.edp does: {settings}")
    out = os.path.join(TEST_RESULTS, "sleeve-3d-mpi")
    seq = sequential(out + "-seq", *SMALL, *BEND)
    runs = {}
    for ranks in (1, 2):
        # (1 rank without the contact's kept columns, -ddmcolumnsmb 0: a solve a global step instead)
        columns = ["-ddmcolumnsmb", "0"] if ranks == 1 else []
        code, output, seconds, _ = ranks_run(ranks, f"{out}-np{ranks}", *SMALL, *BEND, *columns, *FIXEDPOINT)
        check(code == 0, f"{ranks} rank(s): exit {code} in {seconds:.1f} s")
        if code != 0:
            print(output[-3000:])
            finish()
        runs[ranks] = f"{out}-np{ranks}"
        reports = [line for line in output.splitlines() if line.startswith("sleeve-3d: L 0.04 m")]
        check(len(reports) == 1, f"{ranks} rank(s): the report printed {len(reports)} time(s) (rank 0's only: 1)")
        # the mesh's error not estimated by default on ranks (rank 0 would run the companion alone), said once
        owned = [line for line in output.splitlines() if "the run's own error" in line]
        skipped = summary_of(runs[ranks])["mesh_estimate_skipped"] or ""
        check(len(owned) == 1 and "MPI ranks" in owned[0] and "MPI ranks" in skipped,
              f"{ranks} rank(s): the run's own error stated once, the mesh's skipped on ranks: {skipped!r}")
    differences = {}
    for name, (a, b) in {"1 rank": (seq, runs[1]), "2 ranks": (seq, runs[2]), "2 ranks vs 1": (runs[1], runs[2])}.items():
        differences[name] = curve_difference(a, b)
        check(differences[name] is not None and differences[name] <= 1e-4,
              f"MPI equality, {name} against {'the sequential nested loops' if 'vs' not in name else '1 rank'}: the "
              f"curves within {differences[name]} of their largest values (<= 1e-4; the loops' -dctol 1e-3)")
    # The bending after the clamping (the same runs): 1 and 2 ranks against the sequential scene's
    for ranks in (1, 2):
        a, b = rows(os.path.join(seq, "bend.csv")), rows(os.path.join(runs[ranks], "bend.csv"))
        worst = max(max(abs(float(x[c]) - float(y[c])) for x, y in zip(a, b)) / max(abs(float(x[c])) for x in a)
                    for c in ("moment", "normal_force_total"))
        same = len(a) == len(b) == 2 and all(x[c] == y[c] for x, y in zip(a, b) for c in ("nodes_open", "nodes_sliding"))
        laws = summary_of(runs[ranks])["bending"]
        differences[f"bending, {ranks} rank(s)"] = worst
        # the clamping's kept columns (its normal rows, frictionless) serve the stage's W again: on 2
        # ranks, not on 1 (-ddmcolumnsmb 0 keeps none)
        reused, bore = summary_of(runs[ranks])["distributed"]["contact_columns_reused"], int(a[0]["nodes_open"]) + int(
            a[0]["nodes_pressing"])
        check(reused == (bore if ranks == 2 else 0), f"{ranks} rank(s): {reused} of the stage's {3 * bore} columns taken "
              f"from the clamping's kept ones ({bore if ranks == 2 else 0}: its normal rows when kept)")
        check(same and worst <= 1e-4 and laws["cone_excess_max"] <= 1e-8 and laws["complementarity_max"] <= 1e-8
              and laws["gap_min"] >= -1e-6,
              f"the bending on {ranks} rank(s): bend.csv's moment and normal force within {worst:.1e} of the sequential "
              f"scene's (<= 1e-4), open and sliding nodes equal: {same}; cone excess {laws['cone_excess_max']:.1e}, r gap "
              f"{laws['complementarity_max']:.1e}, gap min {laws['gap_min']:.1e}")
    # A budget between the clamping's columns and the stage's (-ddmcolumnsmb 0.1 MB: the clamping's
    # 45 normal columns kept, the stage's 135 not): the stage takes the kept ones again and solves
    # the others, keeping none; the same bending
    code, output, _, _ = ranks_run(2, out + "-np2-budget", *SMALL, *BEND, "-ddmcolumnsmb", "0.1", *FIXEDPOINT)
    budget = summary_of(out + "-np2-budget")["distributed"] if code == 0 else {}
    a, b = rows(os.path.join(seq, "bend.csv")), rows(os.path.join(out + "-np2-budget", "bend.csv")) if code == 0 else []
    worst = max((abs(float(x[c]) - float(y[c])) / max(abs(float(r[c])) for r in a)
                 for x, y in zip(a, b) for c in ("moment", "normal_force_total")), default=None) if b else None
    check(code == 0 and budget["contact_columns"] == "solved" and budget["contact_columns_reused"] > 0
          and len(a) == len(b) and worst is not None and worst <= 1e-4,
          f"-ddmcolumnsmb 0.1 on 2 ranks (the clamping's columns kept, the stage's not): exit {code}, "
          f"{budget.get('contact_columns_reused')} columns taken again, the stage's {budget.get('contact_columns')}; "
          f"bend.csv within {worst} of the sequential scene's (<= 1e-4)")
    if code != 0:
        print(output[-2000:])
    # The tight loops on 2 ranks with GenEO's coarse space (-ddmgeneo 1): the difference is the
    # loops' tolerance, and the two levels are at work.
    seq_tight = sequential(out + "-seq-tight", *SMALL, *TIGHT)
    code, output, _, _ = ranks_run(2, out + "-np2-geneo", *SMALL, *TIGHT, "-ddmgeneo", "1", *FIXEDPOINT)
    geneo = summary_of(out + "-np2-geneo")["distributed"] if code == 0 else None
    tight = curve_difference(seq_tight, out + "-np2-geneo") if code == 0 else None
    check(tight is not None and tight <= 5e-7 and tight * 10 < differences["2 ranks"],
          f"the difference is the loops' tolerance: with -dctol 1e-7 -fptol 1e-11, 2 ranks (GenEO) within {tight} of "
          f"the sequential curve (<= 5e-7, and 10 times below {differences['2 ranks']})")
    one_level = summary_of(runs[2])["distributed"]
    check(geneo is not None and geneo["geneo"] == 1 and geneo["coarse_space"] > 0
          and geneo["stiffness_iterations"] / geneo["stiffness_solves"]
          < one_level["stiffness_iterations"] / one_level["stiffness_solves"],
          f"GenEO on 2 ranks: exit {code}, coarse space {geneo and geneo['coarse_space']}, "
          f"{geneo and geneo['stiffness_iterations'] / geneo['stiffness_solves']:.2f} GMRES iterations a solve against one "
          f"level's {one_level['stiffness_iterations'] / one_level['stiffness_solves']:.2f}")
    kept, solved = summary_of(runs[2])["distributed"], summary_of(runs[1])["distributed"]
    check(kept["contact_columns"] == "kept" and solved["contact_columns"] == "solved"
          and solved["stiffness_solves"] > 1.6 * kept["stiffness_solves"],
          f"the contact's columns: kept on 2 ranks ({kept['contact_columns_mb']:.3f} MB), solved for on 1 rank with "
          f"-ddmcolumnsmb 0: {solved['stiffness_solves']} stiffness solves against {kept['stiffness_solves']} (a second a "
          "global step), the curves equal above")
    # each rank keeps a slice of their rows: half of the whole on 2 ranks (the largest slice, dofs
    # rounded up)
    share = kept["contact_columns_mb"] / solved["contact_columns_mb"]
    check(0.5 <= share <= 0.51, f"the contact's columns on 2 ranks: {kept['contact_columns_mb']:.4f} MB a rank against "
          f"{solved['contact_columns_mb']:.4f} MB on 1 (a share {share:.4f}: each rank a slice of their rows, 0.5 to 0.51)")
    # The newton step solver on the ranks (the default, as the sequential scene's): the plugin's
    # step solver with its stiffness and heat solves the ranks' (plugin StepSolveFractionBy), the
    # contact's problem the kept columns; the sequential newton run's curves and bore forces to the
    # solves' tolerance (measured 4.5e-9), on the round pipe and on Coulomb's cone (an elliptic
    # pipe with friction and free ends: the clamping the nested loops could not do on the ranks).
    # The contact's product C' z is the ranks' slices' sum; without kept columns (-ddmcolumnsmb 0) a
    # distributed solve instead.
    newton, sequential_newton = {}, {}
    cases = (("the round pipe", "round", []), ("Coulomb's cone", "cone", CONE),
             ("the round pipe, no kept columns", "round", ["-ddmcolumnsmb", "0"]))
    for name, tag, extra in cases:
        cone = extra == CONE
        if tag not in sequential_newton:
            sequential_newton[tag] = sequential(f"{out}-seq-newton-{tag}", *SMALL, *(CONE if cone else []), solver="newton")
        seq_newton = sequential_newton[tag]
        folder = f"{out}-np2-newton-{tag}" + ("-solved" if "-ddmcolumnsmb" in extra else "")
        code, output, seconds, _ = ranks_run(2, folder, *SMALL, *extra)
        if code != 0:
            print(output[-3000:])
        summary = summary_of(folder) if code == 0 else {}
        curves = curve_difference(seq_newton, folder) if code == 0 else None
        forces = contact_difference(seq_newton, folder) if code == 0 else None
        newton[name] = {"curves": curves, "bore_forces": forces, "seconds": seconds,
                        "distributed": summary.get("distributed")}
        columns = summary.get("distributed", {}).get("contact_columns")
        check(code == 0 and summary["step_solver"] == "newton" and summary["contact_tangent"] == ("cone" if cone else "e_z")
              and columns == ("solved" if "-ddmcolumnsmb" in extra else "kept")
              and curves is not None and curves <= 1e-7 and forces is not None and forces <= 1e-7,
              f"newton on 2 ranks, {name}: exit {code}, step solver {summary.get('step_solver')}, tangent "
              f"{summary.get('contact_tangent')}, columns {columns}; the curves within {curves} and the bore's forces within {forces} of the "
              "sequential newton run's (<= 1e-7: the solves' tolerance, not the nested loops')")
        if code == 0:
            check(summary["contact_gap_min"] >= -1e-6 and summary["contact_complementarity_max"] <= 1e-6
                  and summary.get("contact_cone_excess_max", 0) <= 1e-9 and summary["equilibrium_residual"] <= 1e-9
                  and summary["distributed"]["residual_max"] <= 100 * summary["distributed"]["tol"],
                  f"newton on 2 ranks, {name}: gap min {summary['contact_gap_min']:.1e}, r gap "
                  f"{summary['contact_complementarity_max']:.1e}, cone excess {summary.get('contact_cone_excess_max')}, "
                  f"equilibrium {summary['equilibrium_residual']:.1e}, largest solve residual "
                  f"{summary['distributed']['residual_max']:.1e}")
    # The estimates on the ranks: rank 0 runs their companions (the sequential scene) and makes
    # them; the mesh estimate equals the sequential run's to the solves' tolerance
    est_args = ["-nr", "2", "-nt", "4", "-length", "0.04", "-quiet", "1", "-meshestimate", "1", "-timeestimate", "1"]
    seq_est = sequential(out + "-seq-estimates", *est_args, solver="newton")
    code, output, _, _ = ranks_run(2, out + "-np2-estimates", *est_args)
    if code != 0:
        print(output[-2000:])
    mine, theirs = (summary_of(seq_est), summary_of(out + "-np2-estimates") if code == 0 else {})
    mesh_gap = (abs(theirs["mesh_error_estimate"] / mine["mesh_error_estimate"] - 1)
                if code == 0 and theirs.get("mesh_error_estimate") else None)
    bound = theirs.get("time_error_bound") or {}
    newton["estimates"] = {"mesh_relative_difference": mesh_gap, "time_bound": bound}
    check(code == 0 and mesh_gap is not None and mesh_gap <= 1e-6 and bound.get("companion_steps", 0) > 0
          and bound.get("pressure", 1) <= 1e-3,
          f"-meshestimate 1 -timeestimate 1 on 2 ranks: exit {code}; the mesh estimate {theirs.get('mesh_error_estimate')} "
          f"against the sequential run's {mine['mesh_error_estimate']} (relative difference {mesh_gap}, <= 1e-6); the "
          f"time bound {bound.get('pressure')} from a companion of {bound.get('companion_steps')} steps")
    record_runs = {"geneo": geneo}
    for ranks, folder in runs.items():
        summary = summary_of(folder)
        solves = summary["distributed"]
        record_runs[ranks] = solves
        check(solves["ranks"] == ranks and summary["step_solver"] == "fixedpoint",
              f"{ranks} rank(s): summary.json says {solves['ranks']} rank(s), step solver {summary['step_solver']}")
        check(solves["stiffness_solves"] > 0 and solves["heat_solves"] > 0 and solves["residual_max"] <= 100 * solves["tol"],
              f"{ranks} rank(s): {solves['stiffness_solves']} stiffness and {solves['heat_solves']} heat solves, the "
              f"largest residual against the scene's matrix {solves['residual_max']:.2e} (<= 100 x {solves['tol']})")
        if ranks == 1:
            check(solves["stiffness_iterations"] <= solves["stiffness_solves"],
                  f"1 rank: {solves['stiffness_iterations']} GMRES iterations for {solves['stiffness_solves']} solves "
                  "(the exact inverse: at most one each)")
        else:
            check(solves["stiffness_iterations"] > 2 * solves["stiffness_solves"],
                  f"2 ranks: {solves['stiffness_iterations']} GMRES iterations for {solves['stiffness_solves']} solves "
                  "(more than 2 each: two subdomains)")
        check(summary["contact_gap_min"] >= -1e-6 and summary["contact_complementarity_max"] <= 1e-6
              and summary["equilibrium_residual"] <= 1e-9,
              f"{ranks} rank(s): gap min {summary['contact_gap_min']:.1e}, r gap {summary['contact_complementarity_max']:.1e}, "
              f"equilibrium {summary['equilibrium_residual']:.1e}")
    refusals = {}
    for name, ranks, args, message in (
            ("2 ranks, 3 layers (one slab of one layer stopped ffddm on an assertion)", 2,
             ["-nr", "1", "-length", "0.04", "-nz", "3"],
             "error: sleeve-3d on MPI ranks: 2 ranks, a slab of at least 2 element layers along z each, for 3 element layers"),
            ("an unknown option", 2, ["-stpes", "30"], "error: sleeve-3d: unknown option -stpes (did you mean -steps?"),
            ("ffddm's overlap", 2, ["-ffddm_overlap", "2"], "error: sleeve-3d on MPI ranks: -ffddm_overlap 2: this run takes only ffddm's default 1")):
        code, output, seconds, session = ranks_run(ranks, out + "-refused", *args, timeout=60)
        errors = [line for line in output.splitlines() if line.startswith("error:")]
        alive = ranks_alive(session)
        # (and nothing besides: FreeFEM's call trace and mpiexec's banner of an aborted job, 17
        # lines after the error, are dropped as tools/ff drops the trace)
        others = [line for line in output.splitlines() if line.strip() and not line.startswith("error:")]
        refusals[name] = {"exit": code, "seconds": seconds, "errors": errors, "left_running": alive, "other_lines": others}
        check(code not in (None, 0) and len(errors) == 1 and errors[0].startswith(message) and not alive and not others,
              f"refused, {name}: exit {code} in {seconds:.1f} s, {len(errors)} error line(s) {errors[:1]}, a rank left "
              f"running: {alive}, other lines {others[:3]}")
    # A failure of one rank alone (FreeFem++-mpi writes a script's cerr to the standard output,
    # which tools/ff-mpi does not show for ranks but 0): said once, the run failed
    code, output, _ = run_in_session([os.path.join(ROOT, "tools", "ff-mpi"), "2", "tests/mpi/rank_alone_error.edp"], 60,
                                     cwd=ROOT, env=ENV)
    errors = [line for line in output.splitlines() if line.startswith("error:")]
    check(code == 1 and errors == ["error: rank 1 alone failed (tests/mpi/rank_alone_error.edp)"],
          f"an error of rank 1 alone: exit {code} (1), said {errors}")
    # Checkpoints on the ranks: a run stopped after step 50 (-checkpoint 20 -stopafter 50) and
    # resumed (-resume 1) writes the uninterrupted run's history.csv and final contact, byte for
    # byte (the checkpoint holds the solves' GMRES starts too), on 2 ranks with newton
    whole, parted = out + "-np2-newton-round", out + "-np2-resumed"
    shutil.rmtree(parted, ignore_errors=True)  # (an earlier test's complete run there adds a note after the stop's line)
    stop_code, stop_output, _, _ = ranks_run(2, parted, *SMALL, "-checkpoint", "20", "-stopafter", "50")
    resume_code, resume_output, _, _ = ranks_run(2, parted, *SMALL, "-resume", "1")
    same = {name: resume_code == 0 and open(os.path.join(whole, name), "rb").read() == open(os.path.join(parted, name), "rb").read()
            for name in ("history.csv", "contact-final.csv")}
    said = [line for line in stop_output.splitlines() if line.strip()]
    check(stop_code == 4 and said[-1:] == ["sleeve-3d: stopped after step 50 (-stopafter 50; -resume 1 continues from the "
                                          "checkpoint of step 40)"] and resume_code == 0 and all(same.values())
          and summary_of(parted).get("resumed_from_step") == 40,
          f"checkpoints on 2 ranks: stopped after step 50 (exit {stop_code}, 4; its last line {said[-1:]}), resumed "
          f"(exit {resume_code}) from step {summary_of(parted).get('resumed_from_step') if resume_code == 0 else None} "
          f"(40): the uninterrupted run's files byte for byte {same}")
    if resume_code != 0:
        print(resume_output[-2000:])
    # A TERM to tools/ff-mpi mid-run (a job manager's stop): every rank stopped, said once, nothing
    # of the run's summary published.
    stopped = out + "-stopped"
    # (2000 fixed steps: a run of minutes, which the TERM at 4 s must meet mid-run on any machine; the
    # defaults' 80 steps took 6.2 s with newton)
    run = subprocess.Popen([os.path.join(ROOT, "tools", "ff-mpi"), "2", "edp/mpi/sleeve-3d.edp", "-out", stopped, "-quiet", "1",
                            "-tol", "0", "-steps", "2000"],
                           cwd=ROOT, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           start_new_session=True)
    time.sleep(4)
    run.send_signal(signal.SIGTERM)
    start = time.monotonic()
    try:
        output, _ = run.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(run.pid, signal.SIGKILL)
        output, _ = run.communicate()
    seconds = time.monotonic() - start
    said = [line for line in output.splitlines() if line.startswith("error:")]
    alive = ranks_alive(run.pid)
    check(run.returncode == 143 and len(said) == 1 and "interrupted" in said[0] and not alive
          and not os.path.exists(os.path.join(stopped, "summary.json")),
          f"TERM mid-run: exit {run.returncode} (143) {seconds:.1f} s after it, {said}, a rank left running: {alive}, "
          f"summary.json {'published' if os.path.exists(os.path.join(stopped, 'summary.json')) else 'not published'}")
    # A solve at its iteration limit on every rank: each stops the others (MPI_Abort), said.
    code, output, seconds, session = ranks_run(2, out + "-aborted", *SMALL, "-ffddm_max_it", "1", timeout=60)
    errors = [line for line in output.splitlines() if line.startswith("error:")]
    alive = ranks_alive(session)
    # (each rank may say it before the abort stops the other; nothing else may be said: mpiexec,
    # given the out-of-memory guard, called its own nonsense allocation an out of memory)
    check(code == 1 and errors and all(e.startswith("error: distributed solve (the stiffness") for e in errors)
          and not alive,
          f"a distributed solve at its limit (-ffddm_max_it 1): exit {code} (1) in {seconds:.1f} s, {errors}, a rank "
          f"left running: {alive}")
    left = os.listdir(SCRATCH)
    check(not left, f"every run's temporary folders removed, the aborted and the stopped runs' too ({left} left in TMPDIR)")
    shutil.rmtree(SCRATCH, ignore_errors=True)
    folder = os.path.join(TEST_RESULTS, "sleeve-3d-mpi-make")
    # (the default mesh: subdomains of more than 400 dofs, where -ddmgeneo -1 (auto) takes GenEO)
    made = subprocess.run(["make", "-s", "run", "SCENE=sleeve-3d", "NP=2", f"ARGS=-tend 20 -quiet 1 -out {folder}"],
                          cwd=ROOT, capture_output=True, text=True)
    figures = glob.glob(os.path.join(folder, "*.png"))
    made_ddm = summary_of(folder)["distributed"] if made.returncode == 0 else {}
    check(made.returncode == 0 and made_ddm["ranks"] == 2 and figures,
          f"make run SCENE=sleeve-3d NP=2: exit {made.returncode}, {len(figures)} figure(s) in {folder}")
    # With the step control and newton the ranks take the sequential run's steps: the same rows,
    # instants and curve to the solves' tolerance (measured: 5.4e-8 s, 6.7e-10)
    seq_made = sequential(folder + "-seq", "-tend", "20", "-quiet", "1", solver="newton")
    a = rows(os.path.join(seq_made, "history.csv"))
    b = rows(os.path.join(folder, "history.csv")) if made.returncode == 0 else []
    instants = max((abs(float(x["t"]) - float(y["t"])) for x, y in zip(a, b)), default=None)
    # (row by row: the instants differ by round-off, which curve_difference does not allow)
    curve = max((max(abs(float(x[c]) - float(y[c])) for x, y in zip(a, b)) / (max(abs(float(r[c])) for r in a) or 1.0)
                 for c in COLUMNS), default=None) if b else None
    check(len(a) == len(b) and instants is not None and instants <= 1e-6 and curve is not None and curve <= 1e-7,
          f"make run SCENE=sleeve-3d NP=2 with the step control: {len(b)} steps against the sequential newton run's "
          f"{len(a)}, the instants within {instants} s (<= 1e-6), the curves within {curve} (<= 1e-7)")
    # -ddmgeneo -1 (auto, the default): GenEO where every subdomain holds at least 400 dofs, one level below
    small = summary_of(runs[2])["distributed"]
    check(made_ddm.get("geneo_option") == -1 and made_ddm.get("geneo") == 1 and made_ddm.get("coarse_space", 0) > 0
          and made_ddm.get("subdomain_dofs", 0) >= 400 and small["geneo_option"] == -1 and small["geneo"] == 0
          and small["subdomain_dofs"] < 400,
          f"-ddmgeneo -1 (auto): GenEO at the defaults' {made_ddm.get('subdomain_dofs')} dofs a subdomain (coarse space "
          f"{made_ddm.get('coarse_space')}), one level at the test mesh's {small['subdomain_dofs']}")
    record("sleeve_3d_mpi", {"curve_differences": differences, "tight_loops_difference": tight, "newton": newton,
                             "distributed": record_runs, "refusals": refusals})
    finish()


if __name__ == "__main__":
    main()
