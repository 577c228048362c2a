"""Where the repository is: the scenes (edp/), tools/ff and plugin/build of the checkout this
package is part of.

The package is installed editable (`make python`): its files stay in <repository>/python/sma/, so
the repository is two folders above this file, wherever the package is imported from (a notebook
elsewhere, another working directory). A copy of the package outside a checkout (a non-editable
install) has no scenes to run: importing it fails, saying so.
"""
import os

PACKAGE = os.path.dirname(os.path.realpath(__file__))  # the physical folder (make python compares pwd -P)
ROOT = os.path.dirname(os.path.dirname(PACKAGE))
FF = os.path.join(ROOT, "tools", "ff")
FF_MPI = os.path.join(ROOT, "tools", "ff-mpi")  # a scene's run on MPI ranks (edp/mpi)

if not (os.path.isfile(FF) and os.path.isdir(os.path.join(ROOT, "edp", "scenes"))):
    raise ImportError(f"the sma package at {PACKAGE} is not inside a checkout of the SMA sleeves repository "
                      f"(no tools/ff and edp/scenes in {ROOT}): install it editable from the checkout "
                      "with `make python` (pip install --user -e python/), not as a copy")
