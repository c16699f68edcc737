# SPDX-License-Identifier: GPL-3.0-or-later
"""The base of every Python object that owns a library handle."""

from .binding import library


class LibraryHandle:
    """Owns one library handle, freed by the C function named `_free`.

    Use as a context manager or call close(); __del__ is only a safety net
    (the glTF add-on's flaw to avoid is an early return that skips the release).
    """

    _free = None  # name of the NULL-safe ft_*_free function, set by subclasses

    def __init__(self, handle):
        self._lib = library()
        self.handle = handle

    def close(self):
        if self.handle:
            getattr(self._lib, self._free)(self.handle)
            self.handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass
