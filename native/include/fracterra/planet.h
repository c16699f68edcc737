// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/planet.h
/// Fractal planets (ABI 2.18): fBm on the sphere, sampled as a cube-sphere,
/// a patch of one cube face at any level, an equirectangular map, or a
/// closed cube-sphere mesh. The height is a function of the 3D point on the
/// unit sphere (the noise bases of terrain.h in three dimensions), so there
/// are no seams and no poles, and every layout and patch gives the bits of
/// the same planet. Heights are in metres above the radius (float32).
/// 2.23: midpoint displacement on the cube-sphere (FT_PLANET_MIDPOINT), the
/// icosphere mesh, the spherical-harmonic power spectrum and H from it.
///
/// Cube faces follow the OpenGL cube-map convention. Face f in 0..5 is
/// +X, -X, +Y, -Y, +Z, -Z. At level n a face has (2^n + 1)^2 samples;
/// sample (i, j) (column i, row j, 0..2^n) with s = (2i - 2^n) / 2^n and
/// t = (2j - 2^n) / 2^n lies on the cube at
///   +X: ( 1, -t, -s)   -X: (-1, -t,  s)   +Y: ( s,  1,  t)
///   -Y: ( s, -1, -t)   +Z: ( s, -t,  1)   -Z: (-s, -t, -1)
/// and on the sphere at that point divided by its length. Samples on the
/// cube's edges and corners belong to two or three faces and are equal bit
/// for bit on each (they are computed from the same integer cube point).
///
/// Equirectangular maps: pixel (i, j) of W x H is the centre of its cell,
/// longitude -180 + (i + 0.5) 360 / W degrees, latitude 90 - (j + 0.5) 180 / H;
/// the point is (cos lat cos lon, cos lat sin lon, sin lat). Row 0 is north.
#ifndef FRACTERRA_PLANET_H
#define FRACTERRA_PLANET_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// How a planet is made (ft_planet_params.method).
enum {
  FT_PLANET_FBM = 0,        ///< octave noise on the sphere (Quilez; the bases of terrain.h in 3D)
  FT_PLANET_MIDPOINT = 1    ///< (2.23) Voss's midpoint displacement by subdivision of the cube-sphere: its
                            ///< heights are the cube-sphere's samples (ft_planet_heights refuses it; the
                            ///< equirect and icosphere layouts interpolate them). Uses sigma, hurst, seed, sea.
};

/// Where a planet's sea is (ft_planet_params.sea); heights below it are
/// raised to it, as for terrains (the values of terrain.h's FT_SEA_*).
enum {
  FT_PLANET_SEA_NONE = 0,
  FT_PLANET_SEA_HEIGHT = 1,   ///< at sea_level, metres
  FT_PLANET_SEA_FRACTION = 2  ///< at the height with sea_fraction of the planet's area below it
};

/// Fill with ft_planet_params_init; ranges in params.h (FT_PARAMS_PLANET).
typedef struct ft_planet_params {
  uint32_t struct_size;     ///< sizeof(ft_planet_params)
  int32_t method;           ///< FT_PLANET_*; default FT_PLANET_FBM
  double radius;            ///< metres (> 0); default 6371000 (the Earth)
  double sigma;             ///< height scale, metres (> 0); default 4000
  double hurst;             ///< H in 0..1; the octave gain is lacunarity^-H; default 0.8
  int32_t octaves;          ///< 1..30; default 12
  double lacunarity;        ///< frequency ratio between octaves (> 1); default 2
  double frequency;         ///< base-octave noise cells per radius (> 0); default 1.5
  int32_t basis;            ///< FT_BASIS_* of terrain.h; default FT_BASIS_GRADIENT
  int32_t variant;          ///< FT_FBM_* of terrain.h; default FT_FBM_STANDARD
  double offset;            ///< ridged / hybrid / hetero offset; default 1
  uint64_t seed;
  int32_t sea;              ///< FT_PLANET_SEA_*; default FT_PLANET_SEA_NONE
  double sea_level;         ///< FT_PLANET_SEA_HEIGHT: metres above the radius
  double sea_fraction;      ///< FT_PLANET_SEA_FRACTION: share of the area under the sea, [0, 1); default 0.7
  int32_t threads;          ///< 0: all cores; the output never depends on it
  ft_progress_fn progress;  ///< may be NULL; return non-zero to cancel
  void* progress_user;
} ft_planet_params;

FT_API ft_status ft_planet_params_init(ft_planet_params* p);

/// The largest cube-face level (a patch's; whole faces are limited by the memory cap).
#define FT_PLANET_MAX_LEVEL 26

/// Samples (x0 .. x0 + width - 1, y0 .. y0 + height - 1) of face `face`
/// (0..5) at level `level` (0..FT_PLANET_MAX_LEVEL): a new heightfield whose
/// world size is the patch's width along the face's middle, in metres. The
/// patch must lie inside the face's (2^level + 1)^2 samples. The whole face is
/// the patch (0, 0, 2^level + 1, 2^level + 1).
FT_API ft_status ft_planet_face(const ft_planet_params* p, int32_t level, int32_t face, int64_t x0, int64_t y0,
                                int32_t width, int32_t height, ft_heightfield** out);

/// An equirectangular map of width x height (2..65536 each), georeferenced
/// in EPSG:4326 (written so by the GeoTIFF writer of raster.h).
FT_API ft_status ft_planet_equirect(const ft_planet_params* p, int32_t width, int32_t height,
                                    ft_heightfield** out);

/// Heights at `count` unit vectors xyz (3 * count doubles; they are
/// normalised first) into `heights` (count floats).
FT_API ft_status ft_planet_heights(const ft_planet_params* p, const double* xyz, int64_t count, float* heights);

/// The sea's height in metres (NaN without a sea). A sea given as a fraction
/// is the area-weighted quantile of the planet's heights over 2^16 points of
/// a Fibonacci sphere, the same for every layout and patch.
FT_API ft_status ft_planet_sea_height(const ft_planet_params* p, double* out);

/// Counts of the closed cube-sphere mesh of level `level`: 6 4^level + 2
/// vertices and 6 4^level quads.
FT_API ft_status ft_planet_mesh_counts(int32_t level, int64_t* vertices, int64_t* faces);

/// The closed cube-sphere mesh of level `level` (0..12 and within the memory
/// cap): every cube-face sample once (no duplicates at edges and corners),
/// at radius + vertical_scale x height along its direction, in metres.
/// `xyz` holds `xyz_count` floats (at least 3 x vertices), `quads` holds
/// `quad_count` int32 (at least 4 x faces, counter-clockwise seen from
/// outside); either may be NULL to skip it. `heights` (NULL to skip) gets one
/// float per vertex (metres, before the vertical scale). Written in place, no
/// copy made; `progress` is called all along (after every 2^16 samples or
/// fewer of each pass), so a cancel returns FT_ERR_CANCELLED at that call (the
/// arrays then hold part of the mesh).
FT_API ft_status ft_planet_mesh(const ft_planet_params* p, int32_t level, double vertical_scale, float* xyz,
                                size_t xyz_count, int32_t* quads, size_t quad_count, float* heights,
                                size_t height_count);

/// (2.23) Counts of the icosphere of level `level` (0..10): 10 4^level + 2
/// vertices and 20 4^level triangles.
FT_API ft_status ft_planet_icosphere_counts(int32_t level, int64_t* vertices, int64_t* triangles);

/// (2.23) The icosphere mesh of level `level` (0..10 and within the memory
/// cap): a regular icosahedron whose triangles are split in four `level`
/// times (new vertices the normalised middles of their edges), closed, no
/// duplicate vertices, at radius + vertical_scale x height, in metres.
/// An fBm planet's heights are the field's at the vertices; a midpoint
/// planet's are its cube-sphere of level + 1 bilinearly interpolated.
/// Arrays as ft_planet_mesh's, with 3 int32 a triangle (counter-clockwise
/// seen from outside).
FT_API ft_status ft_planet_icosphere(const ft_planet_params* p, int32_t level, double vertical_scale, float* xyz,
                                     size_t xyz_count, int32_t* triangles, size_t triangle_count, float* heights,
                                     size_t height_count);

/// (2.23) The angular power spectrum C_l = sum_m |a_lm|^2 / (2l + 1) of the
/// heights (metres^2, orthonormal spherical harmonics), l = 0..lmax
/// (2..512), into `power` (at least lmax + 1 doubles). A direct transform on
/// a Gauss-Legendre grid of 4 (lmax + 1) x 8 (lmax + 1) points; a midpoint
/// planet is interpolated from the cube-sphere level as fine as the grid.
FT_API ft_status ft_planet_power_spectrum(const ft_planet_params* p, int32_t lmax, double* power,
                                          size_t power_count);

/// (2.23) H from the slope of log C_l against log l over l_min..l_max
/// (1 <= l_min < l_max <= 512): fBm on the sphere has C_l ~ l^-(2H + 2), so
/// H = (-slope - 2) / 2. `std_error` (may be NULL) gets the slope's
/// standard error / 2. Choose l_min above the planet's largest features
/// (a few continents: l ~ 8) and l_max below its finest detail.
FT_API ft_status ft_planet_spectrum_hurst(const ft_planet_params* p, int32_t l_min, int32_t l_max, double* hurst,
                                          double* std_error);

#ifdef __cplusplus
}
#endif
#endif
