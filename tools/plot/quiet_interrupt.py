"""Imported first by every plot tool (tools/plot/plot_*.py), for its effect: a Ctrl-C ends the tool
at once, by the signal, without a traceback, even during its imports (numpy, matplotlib: a 60-line
KeyboardInterrupt traceback under make run). The process that started it, make's, says it was
stopped. (Not the package's: a notebook keeps Python's KeyboardInterrupt.)"""
import signal

signal.signal(signal.SIGINT, signal.SIG_DFL)
