"""tools/sma_driver.py: the command-line tools' name for sma.driver (python/sma/driver.py, where the code
and its documentation are). This checkout's package is put first on the path, so that the tools
run this checkout's code even when another checkout is the one installed for the user."""
import os
import sys

_PYTHON = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python")
if _PYTHON not in sys.path:
    sys.path.insert(0, _PYTHON)
from sma.driver import *  # noqa: E402,F401,F403
