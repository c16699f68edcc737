# SPDX-License-Identifier: GPL-3.0-or-later
"""Huge pages for a new mesh's large arrays, asked for before they are first
written (Linux only; elsewhere a no-op).

Blender's allocator hands out a large array as untouched memory that the
kernel maps a 4 kB page at a time as foreach_set first writes it. On a
virtual machine such a fault costs 15-25 us, so a 1025^2 grid's arrays spent
more time in faults than in copying (docs/measurements/speed.md).
madvise(MADV_HUGEPAGE) on an array not yet written, which numpy does for its
own large arrays, has the kernel map it in 2 MB pages instead. It is advice
only: no byte changes, and a kernel without transparent huge pages ignores it.
"""

import ctypes
import mmap
import sys

MADV_HUGEPAGE = 14  # <sys/mman.h> on Linux
# As numpy: smaller arrays would not fill a 2 MB page.
MIN_BYTES = 4 << 20

_madvise = None


def _libc_madvise():
    global _madvise  # pylint: disable=global-statement
    if _madvise is None:
        try:
            fn = ctypes.CDLL(None, use_errno=True).madvise
            fn.argtypes, fn.restype = (ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int), ctypes.c_int
            _madvise = fn
        except (OSError, AttributeError):
            _madvise = False
    return _madvise


def array_span(collection):
    """(start, end) addresses of the array behind a Blender collection whose
    items lie at one stride (mesh vertices, edges, loops, polygons, a UV
    layer's or an attribute's data), or None when its items do not."""
    n = len(collection)
    if n < 3:
        return None
    first, second = collection[0].as_pointer(), collection[1].as_pointer()
    stride = second - first
    if not 0 < stride <= 64 or collection[n // 2].as_pointer() != first + (n // 2) * stride:
        return None
    last = collection[n - 1].as_pointer()
    if last != first + (n - 1) * stride:
        return None
    return first, last + stride


def advise(*collections):
    """Asks for huge pages under each collection's array (see the module doc);
    returns how many arrays were advised (0 off Linux)."""
    if not sys.platform.startswith("linux"):
        return 0
    fn = _libc_madvise()
    if not fn:
        return 0
    page = mmap.PAGESIZE
    advised = 0
    for collection in collections:
        span = array_span(collection)
        if span is None:
            continue
        start = -(-span[0] // page) * page  # whole pages inside the array only
        end = span[1] // page * page
        if end - start >= MIN_BYTES and fn(start, end - start, MADV_HUGEPAGE) == 0:
            advised += 1
    return advised
