// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/subdiv.h
/// Fractalize any polygon mesh: Voss midpoint displacement generalised to
/// arbitrary topology with OpenSubdiv. The mesh is refined uniformly
/// (Catmull-Clark, Loop or bilinear) `levels` times; after each refinement
/// step k the new vertices (Voss) or all vertices (Feder's successive random
/// additions) move along the vertex normal of that level by
///
///     sigma * 2^(-k H) * w * g,   g ~ N(0, 1),
///
/// where w is 1, or the interpolated per-vertex weight, times the local base
/// edge length when asked for. g is a counter-based random number keyed by
/// (seed, level, vertex index), so the result is the same on any thread count.
///
/// Typical use from ctypes (Blender): build an ft_mesh from the object's
/// vertices (foreach_get "co", float32), polygon loop totals and loop vertex
/// indices (and edge creases), call ft_fractalize, then read the result with
/// ft_mesh_positions / ft_mesh_face_sizes / ft_mesh_face_indices straight into
/// foreach_set, and free both handles.
#ifndef FRACTERRA_SUBDIV_H
#define FRACTERRA_SUBDIV_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------
 * Meshes: shared vertices (float32 xyz) and polygonal faces given as a size
 * per face and the faces' vertex indices one after another (the OpenSubdiv
 * and Blender loop layout). Faces are counter-clockwise seen from outside.
 * ------------------------------------------------------------------------- */
typedef struct ft_mesh ft_mesh;

/// A new mesh, validated: vertex indices in range, faces of 3 or more distinct
/// vertices with non-zero area, finite positions, each directed edge used by
/// at most one face (consistent orientation, at most two faces per edge).
/// The error message names the offending face or edge.
///
/// @param positions       3 * vertex_count floats (xyz); copied. Not NULL if vertex_count > 0.
/// @param vertex_count    0 .. 2^31 - 1 (no fracterra result is larger)
/// @param face_sizes      face_count ints, each >= 3; copied.
/// @param face_count      1 .. 2^31 - 1
/// @param face_indices    sum(face_sizes) vertex indices; copied.
/// @param crease_pairs    2 * crease_count vertex indices naming edges of the
///                        mesh (NULL when crease_count is 0); copied.
/// @param crease_sharpness crease_count sharpness values in [0, 10]
///                        (10 = infinitely sharp; Blender's edge crease c in
///                        [0, 1] maps to 10 c^2, as in Blender's own
///                        BKE_subdiv_crease_to_sharpness_f); copied.
/// @param crease_count    0 or more
/// @param out             receives the handle (free with ft_mesh_free); NULL on failure.
FT_API ft_status ft_mesh_create(const float* positions, int64_t vertex_count,
                                const int32_t* face_sizes, int64_t face_count,
                                const int32_t* face_indices,
                                const int32_t* crease_pairs, const float* crease_sharpness,
                                int64_t crease_count, ft_mesh** out);
/// Sets corner (vertex) sharpness, [0, 10] each, for `count` vertices; replaces
/// earlier corners. NULL vertices/sharpness only with count 0.
FT_API ft_status ft_mesh_set_corners(ft_mesh* mesh, const int32_t* vertices,
                                     const float* sharpness, int64_t count);
/// Number of vertices (0 for NULL).
FT_API int64_t ft_mesh_vertex_count(const ft_mesh* mesh);
/// 3 * vertex_count contiguous float32 xyz, owned by the handle, valid until
/// it is freed. NULL for a NULL handle.
FT_API const float* ft_mesh_positions(const ft_mesh* mesh);
/// Number of faces (0 for NULL).
FT_API int64_t ft_mesh_face_count(const ft_mesh* mesh);
/// face_count int32 face sizes, owned by the handle (all 4 after Catmull-Clark
/// or bilinear fractalization, all 3 after Loop). NULL for a NULL handle.
FT_API const int32_t* ft_mesh_face_sizes(const ft_mesh* mesh);
/// Length of the face index array: sum of the face sizes (0 for NULL).
FT_API int64_t ft_mesh_face_index_count(const ft_mesh* mesh);
/// face_index_count int32 vertex indices, owned by the handle. NULL for NULL.
FT_API const int32_t* ft_mesh_face_indices(const ft_mesh* mesh);
/// Frees the handle; NULL is a harmless no-op.
FT_API void ft_mesh_free(ft_mesh* mesh);

/// Subdivision schemes (ft_fractalize_params.scheme).
enum {
  FT_SCHEME_CATMARK = 0,   ///< Catmull-Clark: any polygons in, quads out
  FT_SCHEME_LOOP = 1,      ///< Loop: triangles in (only), triangles out
  FT_SCHEME_BILINEAR = 2   ///< bilinear: any polygons in, quads out, no smoothing
};

/// Displacement modes (ft_fractalize_params.mode).
enum {
  FT_FRACTALIZE_MIDPOINT = 0,      ///< midpoint displacement: only the vertices new at level k move
  FT_FRACTALIZE_ADDITIONS = 1  ///< Feder's successive random additions: every vertex moves
};

/// Parameters of ft_fractalize. Fill with ft_fractalize_params_init, then
/// change what you need.
typedef struct ft_fractalize_params {
  uint32_t struct_size;      ///< sizeof(ft_fractalize_params); set by _init
  int32_t levels;            ///< refinement steps L; 1..10, default 4 (faces grow 4^L)
  double hurst;              ///< Hurst exponent H in [0, 1]; default 0.8
  double sigma;              ///< displacement scale in mesh units: level k moves by
                             ///< sigma 2^(-kH) g (with scale_by_edge_length: a fraction of
                             ///< the local base edge length); >= 0 (0: plain subdivision);
                             ///< default 0.1
  uint64_t seed;             ///< any 64-bit value; default 1
  int32_t scheme;            ///< FT_SCHEME_*; default FT_SCHEME_CATMARK
  int32_t mode;              ///< FT_FRACTALIZE_*; default FT_FRACTALIZE_MIDPOINT
  int32_t fix_boundary;      ///< non-zero: vertices on a boundary (open edge) never move; default 0
  int32_t scale_by_edge_length; ///< non-zero: multiply by the base mesh's mean edge length at
                             ///< each vertex, interpolated over the surface; default 0
  const float* weights;      ///< NULL, or one weight per base vertex (a painted mask, any
                             ///< finite value, typically 0..1), interpolated like positions
  int32_t threads;           ///< 0: all cores; otherwise 1..1024. Output never depends on it.
  ft_progress_fn progress;   ///< NULL or called once per level; may cancel
  void* progress_user;
} ft_fractalize_params;

/// Fills `p` with the defaults documented above. `p` must not be NULL.
FT_API ft_status ft_fractalize_params_init(ft_fractalize_params* p);
/// Fractalizes `mesh`. On success `*out` owns a new mesh (free with
/// ft_mesh_free); on failure `*out` is NULL and ft_last_error() says why
/// (e.g. FT_ERR_INVALID_ARGUMENT naming a face that is not a triangle for
/// Loop, FT_ERR_TOO_LARGE when the result exceeds the memory cap).
/// The input is not modified; the creases and corners of the input are
/// honoured by the refinement. The result has no creases.
FT_API ft_status ft_fractalize(const ft_mesh* mesh, const ft_fractalize_params* p, ft_mesh** out);

#ifdef __cplusplus
}
#endif
#endif
