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
_malloc = None


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


def _libc_malloc():
    """(malloc, free) of the process (Blender's allocator), or False."""
    global _malloc  # pylint: disable=global-statement
    if _malloc is None:
        try:
            libc = ctypes.CDLL(None)
            malloc, free = libc.malloc, libc.free
            malloc.argtypes, malloc.restype = (ctypes.c_size_t,), ctypes.c_void_p
            free.argtypes, free.restype = (ctypes.c_void_p,), None
            _malloc = (malloc, free)
        except (OSError, AttributeError):
            _malloc = False
    return _malloc


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


def _advise_range(fn, start, end):
    page = mmap.PAGESIZE
    start = -(-start // page) * page
    end = end // page * page
    return end - start >= MIN_BYTES and fn(start, end - start, MADV_HUGEPAGE) == 0


def _copy_sizes(mesh):
    """The bytes of each array that Blender 3.x's depsgraph copies of a new
    mesh, in the order it copies them (vertex layers, edge, loop, then face
    layers), then the vertex and face normals it computes for the copy."""
    def size(collection):
        span = array_span(collection)
        return span[1] - span[0] if span else 0
    vertex_layers = [a.data for a in mesh.attributes if a.domain == "POINT"]
    corner_layers = [a.data for a in mesh.attributes if a.domain == "CORNER"]
    face_layers = [a.data for a in mesh.attributes if a.domain == "FACE"]
    sizes = [size(mesh.vertices)] + [size(d) for d in vertex_layers] + [size(mesh.edges)]
    sizes += [size(mesh.loops)] + [size(layer.data) for layer in mesh.uv_layers] + [size(d) for d in corner_layers]
    sizes += [size(mesh.polygons)] + [size(d) for d in face_layers]
    return [n for n in sizes if n] + [12 * len(mesh.vertices), 12 * len(mesh.polygons)]


def advise_copy_of(mesh):
    """Huge pages for the copy of new mesh `mesh` that Blender 3.x's depsgraph
    makes right after the operator (Blender 3.6 and later share the arrays
    instead of copying them): 20 000 page faults, 0.2-0.3 s of a 1025^2 add.
    Blender's allocator (jemalloc) gives requests of the same sizes in the
    same order the same free address ranges, so those ranges are taken here
    (one malloc per array, in Blender's order), advised, and given back
    untouched: no memory is used. Where the copy lands elsewhere nothing
    changes. Returns how many ranges were advised (0 off Linux)."""
    if not sys.platform.startswith("linux") or bpy_version() >= (3, 6, 0):
        return 0
    fn, alloc = _libc_madvise(), _libc_malloc()
    if not fn or not alloc:
        return 0
    malloc, free = alloc
    taken, advised = [], 0
    try:
        for n in _copy_sizes(mesh):
            if n < MIN_BYTES:
                continue
            p = malloc(n + 16)  # 16: Blender's allocation header
            if not p:
                break
            taken.append(p)
            advised += _advise_range(fn, p, p + n + 16)
    finally:
        for p in reversed(taken):
            free(p)
    return advised


def bpy_version():
    import bpy  # pylint: disable=import-outside-toplevel (the rest of this module needs no bpy)
    return tuple(bpy.app.version)
