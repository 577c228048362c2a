"""sma: run the SMA coupling-sleeve scenes of this repository from Python and read what they wrote.

    import sma
    out = sma.run("sleeve-radial", "results/x", g=1000, steps=300)   # the absolute folder
    r = sma.read(out)
    r.summary["final_pressure_mean"]          # summary.json as a dict
    r.frame("history")                        # history.csv as a DataFrame: t_s, pressure_mean_Pa, ...
    f = r.fields("3-end")                     # a VTU: f.points, f.triangles, f.point_data, f.cell_data
    table = sma.sweep("sleeve-radial", {"interference": [2e-4, 5e-4], "g": [250, 1000]},
                      fixed={"steps": 300}, out="results/sweeps/lab")
    sma.plot(table, "final_pressure_mean_Pa")

This checkout's python/ on the path (PYTHONPATH, as the tools, the tests and `make lab` do), or
installed editable for the user by `make python` when asked (docs/parameters.md says how and
why); it runs the scenes of the checkout it lives in (sma.ROOT) through tools/ff, whatever the
working directory. docs/python-api.md lists every public function (generated from these docstrings);
docs/outputs.md every file, column and unit.
"""
import os as _os
import sys as _sys

# OpenBLAS (numpy's BLAS) starts a worker thread per core at import; under an address-space limit
# (ulimit -v, about 300 MB) its allocation retries forever and the process, plot tool or sweep,
# spun without end, deaf to TERM (tools/ff sets the same for FreeFEM and says why). The figures and
# tables make no BLAS call worth a thread. Only before numpy is loaded, and never over a value the
# user chose.
if "numpy" not in _sys.modules:
    _os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from .driver import Results, check_option, options, read, read_csv, run, scenes, script
from .errors import SceneError
from .frames import frame
from .repository import FF, ROOT
from .sweeps import plot, read_sweep, sweep
from .vtu import Fields, read_pvd, read_vtu

from .errors import guarded as _guarded

# Every public function and method: its failures are SceneErrors naming it (errors.py says which).
# The guarded function replaces the plain one in its own module too: the tools' names for the
# modules (tools/sma_driver.py, ...) and the package's own calls get the same object.
for _name in ("run", "read", "options", "scenes", "script", "check_option", "read_csv", "frame", "read_vtu",
              "read_pvd", "sweep", "read_sweep", "plot"):
    _plain = globals()[_name]
    globals()[_name] = _guarded(_plain, "sma." + _name)
    setattr(_sys.modules[_plain.__module__], _name, globals()[_name])
for _cls in (Results, Fields):
    for _name, _member in list(vars(_cls).items()):
        if callable(_member) and not _name.startswith("_"):
            setattr(_cls, _name, _guarded(_member, f"{_cls.__name__}.{_name}"))

__all__ = ["run", "read", "Results", "options", "scenes", "script", "check_option", "read_csv", "frame",
           "read_vtu", "read_pvd", "Fields", "sweep", "read_sweep", "plot", "SceneError", "ROOT", "FF"]
