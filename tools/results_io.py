"""tools/results_io.py: the command-line tools' name for sma.results_io (python/sma/results_io.py, where the code
and its documentation are). This checkout's package is put first on the path, so that the tools
run this checkout's code even when another checkout is the one installed for the user."""
import os
import sys

_PYTHON = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "python")
if _PYTHON not in sys.path:
    sys.path.insert(0, _PYTHON)
from sma.results_io import *  # noqa: E402,F401,F403
from sma.errors import tool_errors_when_run_from  # noqa: E402

tool_errors_when_run_from(__file__)
