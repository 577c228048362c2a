"""The package's one error type."""


class SceneError(RuntimeError):
    """A scene that does not exist, an option it does not read, a value it does not take, a run
    that failed, or a results file that is missing or damaged: the message names which."""
