# SPDX-License-Identifier: GPL-3.0-or-later
"""How operators talk to the user: the errors they report instead of raising
(progress bars and Esc are progress.JobOperator's).

A leaf module (it imports nothing else from the add-on but `core`), so every
operator module can use it without an import circle.
"""

from ... import core


class SettingsError(ValueError):
    """A setting or a scene object the add-on checks itself is unusable
    (reference object or image, curve base, nothing to export, ...)."""


# Errors an operator turns into self.report({'ERROR'}, ...) instead of a
# traceback: the library's own messages (bad parameters, missing library,
# memory cap, cancelled) and the add-on's checks.
REPORTED = (core.FracterraError, SettingsError)
