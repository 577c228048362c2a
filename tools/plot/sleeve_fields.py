"""fields-<instant>.png of the sleeve scenes (tools/plot/plot_sleeve.py): radial stress, temperature
and phases at the three instants, from the fields CSVs and the VTU mesh."""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tools/: results_io, units
import results_io  # noqa: E402,F401
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sleeve_curves import fields_time, read_csv  # noqa: E402
from units import celsius  # noqa: E402
from sma.plotting import save  # noqa: E402

PHASE_NAMES = ("A", "M1", "M2")  # the phase labels 0, 1, 2 of the fields
PHASE_COLOURS = ("0.75", "tab:red", "tab:blue")  # A, M1, M2


def phase_map(ax, fig, tri, phases, flat=False):
    """The phase field in the colours of PHASE_COLOURS, its colour bar naming only the phases
    present (a bar with an M2 colour where no point is M2 misleads). flat: one colour per
    triangle of `tri` (the mesh's own), else contours over the points of `tri`."""
    present = sorted({int(round(v)) for v in phases})
    index = {p: k for k, p in enumerate(present)}
    cmap = mcolors.ListedColormap([PHASE_COLOURS[p] for p in present])
    levels = [k - 0.5 for k in range(len(present) + 1)]
    values = [index[int(round(v))] for v in phases]
    if flat:
        mappable = ax.tripcolor(tri, facecolors=values, cmap=cmap, vmin=-0.5, vmax=len(present) - 0.5)
    else:
        mappable = ax.tricontourf(tri, values, levels=levels, cmap=cmap)
    bar = fig.colorbar(mappable, ax=ax, shrink=0.8, ticks=range(len(present)))
    bar.ax.set_yticklabels([PHASE_NAMES[p] for p in present])
    bar.set_label("phase")
    return mappable


def mesh_fields(vtu):
    """The triangles of a fields VTU (matplotlib Triangulation, mm) with its per-triangle arrays
    and nodal temperature, or None when the VTU is absent."""
    if not os.path.isfile(vtu):
        return None
    fields = results_io.read_vtu(vtu)  # (a cut or damaged VTU: an error line naming it)
    tri = mtri.Triangulation(fields.points[:, 0] * 1e3, fields.points[:, 1] * 1e3, fields.triangles)
    return tri, {name: fields.cell_data[name] for name in ("sigma_rr", "phase")}, fields.point_data["temperature"]


def fields(outdir, summary):
    for path in sorted(glob.glob(os.path.join(outdir, "fields-*.csv"))):
        when = fields_time(path)
        mesh = mesh_fields(path[:-4] + ".vtu")
        if mesh is not None:
            # The mesh's own triangles, one colour each for the stress and the phase (P1
            # displacements give one stress per triangle): contours through the triangles'
            # centres drew periodic blobs that were the mesh's pattern, not the solution's.
            tri, cell, T_nodes = mesh
            fig, axes = plt.subplots(1, 3, figsize=(13, 4))
            sigma = axes[0].tripcolor(tri, facecolors=cell["sigma_rr"] / 1e6)
            fig.colorbar(sigma, ax=axes[0], shrink=0.8).set_label("sigma_rr (MPa), one value per triangle")
            temp = axes[1].tricontourf(tri, [celsius(v) for v in T_nodes], levels=20)
            fig.colorbar(temp, ax=axes[1], shrink=0.8).set_label("T (°C)")
            phase_map(axes[2], fig, tri, cell["phase"], flat=True)
            decorate_fields(fig, axes, summary, path, when)
            continue
        d = read_csv(path)
        x_mm, y_mm = [v * 1e3 for v in d["x"]], [v * 1e3 for v in d["y"]]
        tri = mtri.Triangulation(x_mm, y_mm)
        # Delaunay of the centroids also fills the hole of the ring: mask those triangles.
        radius = [math.hypot(x, y) for x, y in zip(x_mm, y_mm)]
        inner = min(radius)
        tri.set_mask([math.hypot(sum(x_mm[k] for k in t) / 3, sum(y_mm[k] for k in t) / 3) < inner * 0.999
                      for t in tri.triangles])
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
        sigma = axes[0].tricontourf(tri, [v / 1e6 for v in d["sigma_rr"]], levels=20)
        fig.colorbar(sigma, ax=axes[0], shrink=0.8).set_label("sigma_rr (MPa)")
        temp = axes[1].tricontourf(tri, [celsius(v) for v in d["T"]], levels=20)
        fig.colorbar(temp, ax=axes[1], shrink=0.8).set_label("T (°C)")
        phase_map(axes[2], fig, tri, d["phase"])
        decorate_fields(fig, axes, summary, path, when)


def decorate_fields(fig, axes, summary, path, when):
    """Titles and axes of a fields figure, then fields-<instant>.png beside the CSV."""
    for ax, label in zip(axes, ("radial stress", "temperature", "phase (A austenite, M1 and M2 martensite)")):
        ax.set_aspect("equal")
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
    instant = os.path.basename(path)[len("fields-"):-len(".csv")]
    fig.suptitle(f"{summary['scene']}: {instant} ({when})")
    fig.tight_layout()
    save(fig, path[:-4] + ".png", 110)

