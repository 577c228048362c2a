"""Child processes that end with their parent (issue 26: a SIGTERM to `make run` or to a sweep left
FreeFEM running; a Python script driving sma_driver.run, killed, left its FreeFEM to finish and
publish). run() is subprocess.run for the suite's tools; once install() has run, a TERM,
INT or HUP to this process is passed on to every child still running, their end awaited (10 s,
then SIGKILL), no new child is started (a sweep's queued runs), and this process exits 128 + the
signal's number, as the shell would. GNU make passes a TERM on to the recipe it runs, tools/ff to
FreeFEM: a TERM to `make run` reaches every process of the run.
"""
import contextlib
import ctypes
import os
import signal
import subprocess
import sys
import threading
import time

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
# Set by stop_running (an interrupted or failed sweep stops its runs): a worker thread that was
# starting a child when the others were stopped stops it too, and none starts another, until the
# next sweep's pool clears it (allow_running). A KeyboardInterrupt is not a forwarded signal: without
# this, a run whose child started just after stop_running ran to its end and published.
_stop_requested = []


def _forward(signum, frame):
    with _lock:
        _stopped_by.append(signum)
        procs = list(_running)
    # Never Popen.wait here: the handler runs in the main thread, which may be inside that very
    # Popen's wait, holding its lock (a self-deadlock only SIGKILL ended). The children's ends are
    # watched without reaping them; each Popen reaps its own once this exception unwinds its wait.
    _end(procs, signum, reap=False)
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


@contextlib.contextmanager
def terminable():
    """While the block runs in the main thread, a TERM or HUP that would end this process without a
    word (Python's default: a script or a notebook that set no handler of its own) stops the
    children as install() does, says so and exits 128 + the signal's number. A handler the caller
    set is left alone; elsewhere than in the main thread (where Python runs handlers) nothing."""
    saved = {}
    if threading.current_thread() is threading.main_thread():
        for s in (signal.SIGTERM, signal.SIGHUP):
            if signal.getsignal(s) == signal.SIG_DFL:
                saved[s] = signal.signal(s, _forward)
    try:
        yield
    finally:
        for s, handler in saved.items():
            signal.signal(s, handler)


def run(args, **kwargs):
    """subprocess.run(args, **kwargs) whose process is stopped with this one (see install). After
    a forwarded signal it starts nothing: it returns exit 128 + that signal's number at once."""
    capture = kwargs.pop("capture_output", False)
    if capture:
        kwargs.setdefault("stdout", subprocess.PIPE)
        kwargs.setdefault("stderr", subprocess.PIPE)
    with _lock:
        stopped = _stopped_by[0] if _stopped_by else (signal.SIGINT if _stop_requested else 0)
    if stopped:
        return subprocess.CompletedProcess(args, 128 + stopped, "" if capture else None, "" if capture else None)
    kwargs.setdefault("preexec_fn", _die_with_parent)
    with terminable(), subprocess.Popen(args, **kwargs) as p:
        with _lock:
            _running.add(p)
            late = bool(_stopped_by) or bool(_stop_requested)  # stopped while this child was starting
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


def _exited(p):
    """Whether p's process has ended, without reaping it (waitid with WNOWAIT): the Popen that owns
    it still collects its status."""
    if p.returncode is not None:
        return True
    try:
        return os.waitid(os.P_PID, p.pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is not None
    except ChildProcessError:  # reaped already (by the thread that runs it)
        return True


def _end(procs, signum=signal.SIGTERM, reap=True, grace=10.0):
    """Sends signum to each process still running and awaits each end (grace seconds, then
    SIGKILL). reap=False: watches the ends without Popen.wait (see _forward)."""
    for p in procs:
        if not _exited(p):
            try:
                os.kill(p.pid, signum)
            except OSError:
                pass
    deadline = time.monotonic() + grace
    for p in procs:
        while not _exited(p) and time.monotonic() < deadline:
            time.sleep(0.02)
        if not _exited(p):
            try:
                os.kill(p.pid, signal.SIGKILL)
            except OSError:
                pass
            while not _exited(p):
                time.sleep(0.02)
        if reap:
            p.wait()


def stop_running():
    """Stops every child still running (a TERM, then SIGKILL after 10 s) and awaits them: an
    interrupted sweep in a notebook, whose runs wait in other threads, stops them all; a child that
    was starting meanwhile is stopped as it starts, and none starts after (until allow_running)."""
    with _lock:
        _stop_requested.append(True)
        procs = list(_running)
    _end(procs)


def allow_running():
    """Children may start again (a new sweep's pool, after an earlier one was stopped)."""
    with _lock:
        _stop_requested.clear()
