"""The sleeve's dimensions, read from meshes/sleeve-geometry.txt: the one place of them (the
meshes, the radial scene, tools/bench/oracles/radial_numpy.py and the tests all read it)."""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def sleeve_geometry():
    """The sleeve's dimensions (m): {"Ri": inner radius, "Hr": thickness, "pipe": pipe radius}."""
    values = {}
    with open(os.path.join(ROOT, "meshes", "sleeve-geometry.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                key, value = line.split()
                values[key] = float(value)
    return values
