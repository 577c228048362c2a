"""Figures: matplotlib on a file backend when no other was chosen, and PNGs written whole."""
import os
import sys

from . import results_io


def save(fig, path, dpi, tight=False):
    """Writes a figure's PNG under a temporary name, then renames it (never a half-drawn file),
    listed first in the results folder's manifest; closes the figure. tight: crop to the drawn
    area (bbox_inches="tight"). Every plot tool's figures go through here."""
    import matplotlib.pyplot as plt
    with results_io.publishing(path, path[:-len(".png")] + ".partial.png") as partial:
        fig.savefig(partial, dpi=dpi, **({"bbox_inches": "tight"} if tight else {}))
        plt.close(fig)


def pyplot():
    """matplotlib.pyplot, on the Agg backend (files only) unless pyplot is in use already or
    MPLBACKEND names one (a notebook keeps its inline figures)."""
    import matplotlib
    if "matplotlib.pyplot" not in sys.modules and not os.environ.get("MPLBACKEND"):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt
