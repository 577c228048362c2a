"""make bench, section 5 (tools/bench/bench.py): PSOR modes full / condensed (plain, with
active-set polish) for omega in 1.0 .. 1.95, and the polish interval. figure() and doc() draw and
write their part of docs/benchmarks.md."""
import os

from common import OUT, QUICK, run, save

OMEGAS = [1.0, 1.2, 1.4, 1.6, 1.8, 1.88, 1.95]
POLISH = [1, 2, 5, 10, 20, 50]
if QUICK:
    OMEGAS = [1.0, 1.88]
    POLISH = [1, 10]


def measure(results):
    """PSOR modes and omega (coarse mesh, 150 steps: contact from step 2 on), the polish interval."""
    psor_rows = []
    psor_args = ["-mesh", "meshes/sleeve-coarse.msh", "-steps", 150, "-quiet", 1]
    for mode, extra in (("full", []), ("condensed-plain", ["-psorpolish", 0]), ("condensed", [])):
        for omega in OMEGAS:
            print(f"bench: PSOR {mode} omega {omega}", flush=True)
            out = os.path.join(OUT, f"psor-{mode}-{omega}")
            wall, s, failure = run("edp/scenes/sleeve-circular.edp", out, *psor_args, "-omega", omega,
                                   "-psormode", "full" if mode == "full" else "condensed", *extra,
                                   allow_failure=True)
            psor_rows.append({"mode": mode, "omega": omega, "wall_seconds": wall,
                              "failure": failure or None,
                              "sweeps_mean": s["psor_sweeps_mean"] if s else None,
                              "sweeps_max": s["psor_sweeps_max"] if s else None,
                              "loop_seconds_per_step": s["wall_seconds"] / 150 if s else None,
                              "first_contact_step": s["first_contact_step"] if s else None,
                              "final_pressure_mean": s["final_pressure_mean"] if s else None})
    results["psor_modes"] = psor_rows
    polish_rows = []
    for every in POLISH:
        print(f"bench: PSOR condensed, polish every {every}", flush=True)
        out = os.path.join(OUT, f"polish-{every}")
        wall, s, _ = run("edp/scenes/sleeve-circular.edp", out, "-psorpolish", every, "-quiet", 1,
                         *(["-mesh", "meshes/sleeve-coarse.msh", "-steps", 150] if QUICK else []))
        polish_rows.append({"polish": every, "wall_seconds": wall, "loop_seconds": s["wall_seconds"],
                            "sweeps_mean": s["psor_sweeps_mean"], "sweeps_max": s["psor_sweeps_max"],
                            "final_pressure_mean": s["final_pressure_mean"]})
    results["psor_polish"] = polish_rows


def figure(r, plt):
    """psor-modes.png; returns {"psor": its path from docs/}."""
    pngs = {}
    # PSOR modes.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for mode in ("full", "condensed-plain", "condensed"):
        rows = [x for x in r["psor_modes"] if x["mode"] == mode and x["sweeps_mean"] is not None]
        axes[0].semilogy([x["omega"] for x in rows], [x["sweeps_mean"] for x in rows], "o-", label=mode)
        axes[1].semilogy([x["omega"] for x in rows], [x["loop_seconds_per_step"] * 1e3 for x in rows], "o-",
                         label=mode)
    axes[0].set(xlabel="omega", ylabel="PSOR sweeps per step (mean)")
    axes[1].set(xlabel="omega", ylabel="ms per step (loop)")
    axes[0].legend(fontsize=8)
    pngs["psor"] = save(fig, "psor-modes.png")
    return pngs


def doc(r, w, pngs):
    """PSOR: full system against condensed, and omega."""
    w("## PSOR: full system against condensed, and omega")
    w("")
    w(f"![PSOR modes]({pngs['psor']})")
    w("")
    w("sleeve-circular on the coarse mesh, 150 steps. *full*: the paper's sweeps over every dof of "
      "K u = f + B s; *condensed-plain*: sweeps on the Delassus problem of the contact nodes; "
      "*condensed*: the same with an exact active-set solve tried every 10 sweeps (the default).")
    w("")
    w("| mode | omega | PSOR sweeps per step (mean / max) | loop ms per step | first contact step | final pressure (MPa) |")
    w("|---|---|---|---|---|---|")
    for x in r["psor_modes"]:
        if x["sweeps_mean"] is None:
            w(f"| {x['mode']} | {x['omega']} | failed: {x['failure']} | | | |")
        else:
            w(f"| {x['mode']} | {x['omega']} | {x['sweeps_mean']:.1f} / {x['sweeps_max']:.0f} | "
              f"{1e3 * x['loop_seconds_per_step']:.2f} | {x['first_contact_step']} | {x['final_pressure_mean'] / 1e6:.6f} |")
    w("")
    w("Polish interval (condensed, omega 1.88, default mesh and steps):")
    w("")
    w("| polish every | sweeps per step (mean / max) | loop (s) | final pressure (MPa) |")
    w("|---|---|---|---|")
    for x in r["psor_polish"]:
        w(f"| {x['polish']} | {x['sweeps_mean']:.2f} / {x['sweeps_max']:.0f} | {x['loop_seconds']:.2f} | "
          f"{x['final_pressure_mean'] / 1e6:.6f} |")
    w("")
