# SPDX-License-Identifier: GPL-3.0-or-later
"""Exceptions raised by the fracterra binding (no bpy here).

Every failed library call becomes a FracterraError (or a subclass chosen by
its status code) whose message is the library's own ft_last_error() text:
what was wrong and what is allowed. Operators turn these into reports.
"""

FT_OK = 0
FT_ERR_INVALID_ARGUMENT = 1
FT_ERR_OUT_OF_MEMORY = 2
FT_ERR_TOO_LARGE = 3
FT_ERR_IO = 4
FT_ERR_FORMAT = 5
FT_ERR_CANCELLED = 6
FT_ERR_UNSUPPORTED = 7
FT_ERR_INTERNAL = 8


class FracterraError(Exception):
    """A fracterra call failed; `status` is the ft_status code, str() the message."""

    def __init__(self, message, status=FT_ERR_INTERNAL):
        super().__init__(message)
        self.status = status


class LibraryNotFoundError(FracterraError):
    """libfracterra.so could not be found, loaded, or has another ABI major version."""

    def __init__(self, message):
        super().__init__(message, FT_ERR_UNSUPPORTED)


class InvalidArgumentError(FracterraError, ValueError):
    pass


class TooLargeError(FracterraError, MemoryError):
    pass


class CancelledError(FracterraError):
    pass


class UnsupportedError(FracterraError):
    pass


_BY_STATUS = {
    FT_ERR_INVALID_ARGUMENT: InvalidArgumentError,
    FT_ERR_OUT_OF_MEMORY: TooLargeError,
    FT_ERR_TOO_LARGE: TooLargeError,
    FT_ERR_CANCELLED: CancelledError,
    FT_ERR_UNSUPPORTED: UnsupportedError,
}


def error_for_status(status, message):
    """The exception for a non-zero ft_status with the library's message."""
    return _BY_STATUS.get(status, FracterraError)(message, status)
