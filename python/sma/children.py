"""Child processes that end with their parent (issue 26: a SIGTERM to `make run` or to a sweep left
FreeFEM running; a Python script driving sma_driver.run, killed, left its FreeFEM to finish and
publish). run() is subprocess.run for the suite's tools; once install() has run, a TERM,
INT or HUP to this process is passed on to every child still running, their end awaited (10 s,
then SIGKILL), no new child is started (a sweep's queued runs), and this process exits 128 + the
signal's number, as the shell would. GNU make passes a TERM on to the recipe it runs, tools/ff to
FreeFEM: a TERM to `make run` reaches every process of the run.
"""
import ctypes
import signal
import subprocess
import sys
import threading

_PR_SET_PDEATHSIG = 1
try:
    _libc = ctypes.CDLL(None, use_errno=True)
except OSError:
    _libc = None


def _die_with_parent():
    """In the child, before exec: the kernel sends it a TERM when the thread that started it ends
    (this process killed outright, or a notebook's kernel restarted), which no handler can
    forward. Linux only; elsewhere nothing."""
    if _libc is not None:
        _libc.prctl(_PR_SET_PDEATHSIG, signal.SIGTERM)

_running = set()
# Reentrant: the handler runs in the main thread, which may hold the lock when the signal comes.
_lock = threading.RLock()
_stopped_by = []  # the signal that stopped this process, once one has


def _forward(signum, frame):
    with _lock:
        _stopped_by.append(signum)
        procs = list(_running)
    _end(procs, signum)
    print(f"error: stopped by signal {signal.Signals(signum).name}: {len(procs)} running child process(es) "
          "stopped with it", file=sys.stderr)
    sys.stderr.flush()
    raise SystemExit(128 + signum)


def install():
    """Forward TERM, INT and HUP to the running children (call once, from the main thread); and
    take a TERM when this process's own parent dies (make killed outright: this tool would run on,
    re-parented, with its children)."""
    for s in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(s, _forward)
    _die_with_parent()


def run(args, **kwargs):
    """subprocess.run(args, **kwargs) whose process is stopped with this one (see install). After
    a forwarded signal it starts nothing: it returns exit 128 + that signal's number at once."""
    capture = kwargs.pop("capture_output", False)
    if capture:
        kwargs.setdefault("stdout", subprocess.PIPE)
        kwargs.setdefault("stderr", subprocess.PIPE)
    if _stopped_by:
        return subprocess.CompletedProcess(args, 128 + _stopped_by[0], "" if capture else None, "" if capture else None)
    kwargs.setdefault("preexec_fn", _die_with_parent)
    with subprocess.Popen(args, **kwargs) as p:
        with _lock:
            _running.add(p)
            late = bool(_stopped_by)  # the signal came while this child was starting
        if late:
            p.terminate()
        try:
            out, err = p.communicate()
        except BaseException:  # a KeyboardInterrupt (a notebook's interrupt): the child stops with the call
            _end([p])
            raise
        finally:
            with _lock:
                _running.discard(p)
    return subprocess.CompletedProcess(args, p.returncode, out, err)


def _end(procs, signum=signal.SIGTERM):
    """Sends signum to each process, awaits each (10 s, then SIGKILL)."""
    for p in procs:
        try:
            p.send_signal(signum)
        except OSError:
            pass
    for p in procs:
        try:
            p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()


def stop_running():
    """Stops every child still running (a TERM, then SIGKILL after 10 s) and awaits them: an
    interrupted sweep in a notebook, whose runs wait in other threads, stops them all."""
    with _lock:
        procs = list(_running)
    _end(procs)
