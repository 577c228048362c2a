"""The words that make a sleeve run take fixed steps, for the tools whose runs need them: the paper's
figures and claims (its 1500 increments: tools/docs) and the benchmarks' studies, which refine fixed
steps (tools/bench). The sleeve scenes' default chooses its steps by their error (-tol 1e-3,
edp/problems/sleeve/parameters.idp); -tol 0 takes the scene's -steps."""

STEP_OPTIONS = {"-steps", "-dt", "-tol"}


def fixed_steps(words):
    """["-tol", "0"] to add to a sleeve scene's command-line words, or [] when they choose the steps
    themselves (-steps, -dt or -tol among them; the words may be numbers)."""
    return [] if STEP_OPTIONS & {str(w) for w in words} else ["-tol", "0"]
