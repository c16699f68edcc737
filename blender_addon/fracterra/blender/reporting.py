"""How operators talk to the user: the errors they report instead of raising,
and the window's progress bar around a library call.

A leaf module (it imports nothing else from the add-on but `core`), so every
operator module can use it without an import circle.
"""

from .. import core


class SettingsError(ValueError):
    """A setting or a scene object the add-on checks itself is unusable
    (reference object or image, curve base, nothing to export, ...)."""


# Errors an operator turns into self.report({'ERROR'}, ...) instead of a
# traceback: the library's own messages (bad parameters, missing library,
# memory cap, cancelled) and the add-on's checks.
REPORTED = (core.FracterraError, SettingsError)


class WindowProgress:
    """wm.progress_begin/update/end around a library call, as its progress callback."""

    def __init__(self, context):
        self.wm = getattr(context, "window_manager", None)

    def __enter__(self):
        if self.wm:
            self.wm.progress_begin(0, 1000)
        return self

    def __call__(self, fraction):
        if self.wm:
            self.wm.progress_update(int(fraction * 1000))
        return False  # never cancels on its own; the binding supports it for scripts

    def __exit__(self, *exc):
        if self.wm:
            self.wm.progress_end()
