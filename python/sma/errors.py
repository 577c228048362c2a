"""The package's one error type, and the guard that makes every failure of the package one.

Every public function and method of the package goes through `guarded` (applied in __init__.py):
a SceneError passes as it is; an exhausted resource (memory, the disk, a file-size limit), a
library that cannot load, a bad argument or a bad matplotlib backend becomes a SceneError naming
the call, the file or the limit (a user met raw tracebacks: sma.plot(None), a full disk in a
sweep's figures, a memory limit while importing VTK). `tool_errors` does the same for the
command-line tools: one `error:` line and exit 1 instead of a traceback, for those causes only (a
bug keeps its traceback).
"""
import errno
import functools
import os
import resource
import sys


class SceneError(RuntimeError):
    """A scene that does not exist, an option it does not read, a value it does not take, a run
    that failed, or a results file that is missing or damaged: the message names which."""


def _limit_text():
    """The address-space limit, if one is set ("under ulimit -v N kB"), else ""."""
    soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    return "" if soft == resource.RLIM_INFINITY else f" under the address-space limit (ulimit -v {soft // 1024} kB)"


def reason(e):
    """A sentence for an exception of the environment (memory, disk, loading, backend), or None
    for any other (a bug, or a wrong argument: the caller words those)."""
    if isinstance(e, MemoryError):
        return f"out of memory{_limit_text()}: raise the limit or free memory"
    if isinstance(e, ImportError):
        mapped = "failed to map segment" in str(e) or "cannot allocate memory" in str(e).lower()
        return (f"cannot load {e.name or 'a library'} ({e}): "
                + (f"out of memory{_limit_text()}" if mapped else "reinstall it ('make deps')"))
    if isinstance(e, OSError) and e.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG):
        where = f" writing {e.filename}" if e.filename else ""
        return f"{os.strerror(e.errno)}{where}: free space or raise the file-size limit (ulimit -f)"
    if isinstance(e, OSError):
        return f"{e.strerror or e}{': ' + str(e.filename) if e.filename else ''}"
    if isinstance(e, ValueError) and "backend" in str(e).lower():
        return f"{e} (MPLBACKEND={os.environ.get('MPLBACKEND', '')!r}: unset it, or name a backend matplotlib has)"
    return None


def guarded(call, name):
    """`call` with every failure a SceneError naming `name` (sma.plot, Results.frame, ...)."""
    @functools.wraps(call)
    def checked(*args, **kwargs):
        try:
            return call(*args, **kwargs)
        except SceneError:
            raise
        except (TypeError, AttributeError, KeyError, IndexError, ValueError) as e:
            why = reason(e)
            if why is None:
                shown = ", ".join([repr(a)[:60] for a in args] + [f"{k}={v!r}"[:60] for k, v in kwargs.items()])
                why = f"{type(e).__name__}: {e} (called with {shown}; docs/python-api.md says what it takes)"
            raise SceneError(f"{name}: {why}") from e
        except (MemoryError, ImportError, OSError) as e:
            raise SceneError(f"{name}: {reason(e)}") from e
    return checked


def tool_errors(tool):
    """For a command-line tool: an exception of the environment (memory, disk, loading, backend)
    or a SceneError that reaches the top ends the tool with one `error:` line and exit 1; any
    other keeps Python's traceback (a bug)."""
    def hook(kind, value, traceback):
        why = str(value) if isinstance(value, SceneError) else reason(value)
        if why is None:
            sys.__excepthook__(kind, value, traceback)
            return
        try:
            print(f"error: {tool}: {why}", file=sys.stderr)
        except Exception:  # noqa: BLE001 (a console that cannot print: the exit code says it)
            pass
        os._exit(1)
    sys.excepthook = hook


def tool_errors_when_run_from(shim):
    """tool_errors for the running program when it is one of the tools, a script in the folder of
    `shim` (tools/, where the command-line names of the package's modules are) or below it."""
    tools = os.path.dirname(os.path.abspath(shim))
    program = os.path.abspath(sys.argv[0]) if sys.argv and sys.argv[0] else ""
    if program.startswith(tools + os.sep):
        tool_errors(os.path.relpath(program, os.path.dirname(tools)))
        # A console that cannot print a character (LC_ALL=C, PYTHONIOENCODING=ascii) gets it
        # escaped: printing a folder named with an accent raised, and a plot tool blamed the
        # results it had just read ("an edited or foreign summary.json?").
        for stream in (sys.stdout, sys.stderr):
            if hasattr(stream, "reconfigure"):
                stream.reconfigure(errors="backslashreplace")
