// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/terrain.h
/// Terrain heightfields and 1D profiles: Voss midpoint displacement, Feder's
/// successive random additions, and (see the method list) fBm octave noise,
/// spectral synthesis and the interpolated (lacunarity) variant.
#ifndef FRACTERRA_TERRAIN_H
#define FRACTERRA_TERRAIN_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Terrain methods (ft_terrain_params.method).
enum {
  FT_TERRAIN_MIDPOINT = 0,     ///< Voss diamond-square, (2^levels + 1)^2 samples
  FT_TERRAIN_ADDITIONS = 1,    ///< Feder/Voss successive random additions, (2^levels + 1)^2
  FT_TERRAIN_FBM = 2,          ///< sum of noise octaves (Quilez), any width x height
  FT_TERRAIN_SPECTRAL = 3,     ///< inverse-FFT spectral synthesis, any width x height, periodic
  FT_TERRAIN_INTERPOLATED = 4, ///< Saupe's InterpolatedFM, scale factor `lacunarity` per cycle
  FT_TERRAIN_MANDELBROT = 5    ///< the Mandelbrot set's smooth escape time, any width x height
};

/// Noise bases for FT_TERRAIN_FBM (ft_terrain_params.basis).
enum {
  FT_BASIS_VALUE = 0,          ///< lattice values, quintic interpolation; [-1, 1], mean 0
  FT_BASIS_GRADIENT = 1,       ///< Perlin gradient noise; [-1, 1], mean 0
  FT_BASIS_SIMPLEX = 2,        ///< simplex noise; [-1, 1], mean 0; not periodic
  FT_BASIS_CELLULAR_F1 = 3,    ///< Voronoi distance to the nearest feature point, in cells; [0, 1.17]
  FT_BASIS_CELLULAR_F2F1 = 4   ///< Voronoi F2 - F1, in cells; >= 0
};

/// Octave combinations for FT_TERRAIN_FBM (ft_terrain_params.variant).
enum {
  FT_FBM_STANDARD = 0,
  FT_FBM_RIDGED = 1,
  FT_FBM_HYBRID = 2,           ///< Musgrave's hybrid multifractal
  FT_FBM_HETERO = 3            ///< Musgrave's heterogeneous terrain
};

/// How the displacement scale is chosen when refining from reference points.
enum {
  FT_REFSCALE_SIGMA = 0,       ///< use `sigma` as given
  FT_REFSCALE_MEAN = 1,        ///< use the mean of |reference values| (seed 000, fig. 7b)
  FT_REFSCALE_STD = 2          ///< use the standard deviation of the reference values
};

/// Edge falloff of a terrain (ft_terrain_params.falloff, ABI 2.6).
enum {
  FT_FALLOFF_NONE = 0,         ///< heights run to the edge as generated
  FT_FALLOFF_SQUARE = 1,       ///< fall to edge_level along all four edges
  FT_FALLOFF_RADIAL = 2,       ///< fall to edge_level towards the inscribed ellipse (an island)
  FT_FALLOFF_CUSTOM = 3        ///< a mask grid (falloff_mask, ABI 2.9): 1 keeps the height, 0 gives edge_level
};

/// Sea of a terrain (ft_terrain_params.sea, ABI 2.6): heights below it are flattened to it.
enum {
  FT_SEA_NONE = 0,             ///< no sea
  FT_SEA_HEIGHT = 1,           ///< at sea_level, in scene units
  FT_SEA_FRACTION = 2          ///< at the height with sea_fraction of the samples below it (whole terrains only)
};

/// Parameters of ft_terrain_generate. Fill with ft_terrain_params_init, then
/// change what you need. Fields a method does not use are ignored. Every
/// field's default, range and documentation is also given at run time by
/// ft_params_field(FT_PARAMS_TERRAIN, ...) (params.h): that table is the
/// definition; the comments here repeat it for readers.
typedef struct ft_terrain_params {
  uint32_t struct_size;      ///< sizeof(ft_terrain_params); set by _init
  int32_t method;            ///< FT_TERRAIN_*; default FT_TERRAIN_MIDPOINT
  int32_t levels;            ///< midpoint/additions: size is 2^levels + 1 per side; 1..15, default 9
  int32_t width;             ///< other methods: samples in x; 2..65536, default 513
  int32_t height;            ///< other methods: samples in y; 2..65536, default 513
  double hurst;              ///< Hurst exponent H in [0, 1]; default 0.8
  double sigma;              ///< vertical scale (std of the first displacement), > 0; default 1
  uint64_t seed;             ///< any 64-bit value; default 1
  int32_t periodic;          ///< non-zero: the terrain tiles (wrap-around neighbours; fbm: whole
                             ///< cells per period, no rotation, not simplex); default 0.
                             ///< FT_TERRAIN_SPECTRAL always tiles.
  int32_t threads;           ///< 0: all cores; otherwise 1..1024. Output never depends on it.
  /* Reference points (midpoint and additions): a coarse (2^m + 1)^2 grid,
     row-major, taken as steps 1..m; the values survive exactly at their nodes. */
  const float* reference;    ///< NULL: none
  int32_t reference_size;    ///< 2^m + 1 with 1 <= m <= levels; ignored when reference is NULL
  int32_t reference_scale;   ///< FT_REFSCALE_*; default FT_REFSCALE_SIGMA
  /* fBm (FT_TERRAIN_FBM) and the interpolated variant. */
  int32_t octaves;           ///< 1..30, and the finest octave must stay within float
                             ///< resolution (lattice coordinates <= 2^17); default 8
  double lacunarity;         ///< frequency ratio between octaves (> 1; default 2), or the
                             ///< scale factor 1/r per cycle of FT_TERRAIN_INTERPOLATED
  double gain;               ///< amplitude ratio G between octaves, (0, 1]; <= 0 means
                             ///< lacunarity^-H, i.e. 2^-H at lacunarity 2 (default 0)
  int32_t basis;             ///< FT_BASIS_*; default FT_BASIS_GRADIENT
  int32_t variant;           ///< FT_FBM_*; default FT_FBM_STANDARD
  double frequency;          ///< base-octave lattice cells across the width, > 0; default 4
  double offset;             ///< ridged/hybrid/hetero offset; default 1
  double octave_rotation;    ///< domain rotation per octave in radians (not with periodic); default 0.5
  double warp;               ///< domain-warp displacement in base cells, 0 (off)..64; default 0
  /* Progress and cancellation; both may be NULL. */
  ft_progress_fn progress;
  void* progress_user;
  /* Added in ABI 1.1 (trailing fields). */
  double world_size;         ///< extent of the terrain along x in scene units (> 0; default 10);
                             ///< y follows the aspect ratio; heights are in the same units
  /* Added in ABI 1.2: the Mandelbrot set (FT_TERRAIN_MANDELBROT; docs/terrain.md). Heights are
     sigma (1 - (1 + s)^-1/2), s = log2(1 + 2^nu), nu the continuous escape time (capped at
     `iterations`); the set itself is the plateau at the cap's height, just below sigma. */
  double center_x;           ///< real part of the centre of the view, in [-4, 4]; default -0.5
  double center_y;           ///< imaginary part of the centre (row 0 is the top), in [-4, 4]; default 0
  double zoom;               ///< the width spans 4 / zoom of the complex plane; >= 1e-3 and at most
                             ///< where double runs out (neighbouring samples >= 64 ulp apart: about
                             ///< 1e11 at 1025 samples across); default 1
  int32_t iterations;        ///< maximum iterations; a point that has not escaped is inside the set;
                             ///< 1..2^24, default 64 (fewer: a lower wall where slopes meet the set)
  int32_t supersample;       ///< k x k points of the plane averaged per sample (anti-aliasing the
                             ///< boundary), 1..8; default 2
  /* Added in ABI 2.6: landforms, applied to the method's heights in this order (docs/terrain.md).
     Each depends only on the sample's position in the whole terrain, so windows stay equal to
     the whole; a sea given as a fraction needs the whole and is refused for windows. */
  double levelling;          ///< 0..1: the part of the tilt removed, the bilinear surface through the
                             ///< whole terrain's four corners (1: every corner at 0); default 0
  double height_offset;      ///< added to every height, scene units; default 0
  int32_t falloff;           ///< FT_FALLOFF_*; default FT_FALLOFF_NONE
  double falloff_width;      ///< (0, 1]: the band over which heights fall, as a fraction of the half
                             ///< width (1: from the centre); default 0.3
  double edge_level;         ///< height at the edge after the falloff, scene units; default 0
  int32_t sea;               ///< FT_SEA_*; default FT_SEA_NONE
  double sea_level;          ///< FT_SEA_HEIGHT: the sea's height, scene units; default 0
  double sea_fraction;       ///< FT_SEA_FRACTION: the fraction of samples under the sea, [0, 1); default 0.3
  /* Added in ABI 2.9: the mask of FT_FALLOFF_CUSTOM. It spans the whole terrain corner to corner
     (mask sample (0, 0) at terrain sample (0, 0), (mw - 1, mh - 1) at the last) and is resampled
     bilinearly at each sample's position in the whole, so windows stay equal to the whole. A height
     z becomes edge_level + m (z - edge_level); falloff_width is not used (blur the mask instead). */
  const float* falloff_mask; ///< falloff_mask_width x falloff_mask_height values in [0, 1], row-major
                             ///< (row 0 at terrain row 0); the caller keeps it alive; default NULL
  int32_t falloff_mask_width;  ///< 2..65536 with FT_FALLOFF_CUSTOM; default 0
  int32_t falloff_mask_height; ///< 2..65536 with FT_FALLOFF_CUSTOM; default 0
} ft_terrain_params;

/// Fills `p` with the defaults documented above. `p` must not be NULL.
FT_API ft_status ft_terrain_params_init(ft_terrain_params* p);
/// Generates a terrain. On success `*out` owns a new heightfield (free with
/// ft_heightfield_free); on failure `*out` is NULL and ft_last_error() says why.
FT_API ft_status ft_terrain_generate(const ft_terrain_params* p, ft_heightfield** out);
/// Windows of a terrain that need not fit in memory (ABI 1.3).
/// The whole terrain's samples per side at level of detail `lod` (0: every
/// sample; k: every 2^k-th, midpoint and additions only). Windows accept
/// midpoint and additions up to levels 24 and the other methods (except
/// spectral, a global FFT, which is refused) up to 2^24 + 1 samples a side.
/// `width` and `height` must not be NULL.
FT_API ft_status ft_terrain_extent(const ft_terrain_params* p, int32_t lod, int64_t* width, int64_t* height);
/// The samples [x0, x0 + width) x [y0, y0 + height) of the terrain `p`
/// defines, bit-identical to the same samples of ft_terrain_generate
/// wherever the whole fits. Memory: the window plus a thin halo, whatever
/// the whole's size. On success `*out` owns a new width x height heightfield
/// whose world size is the window's share of p->world_size.
FT_API ft_status ft_terrain_generate_window(const ft_terrain_params* p, int64_t x0, int64_t y0, int32_t width,
                                            int32_t height, ft_heightfield** out);
/// The same at level of detail `lod`: sample (i, j) is sample
/// ((x0 + i) 2^lod, (y0 + j) 2^lod) of the whole; x0, y0, width and height
/// count samples at that lod (see ft_terrain_extent). For midpoint this is
/// exactly the coarser stage and costs 4^-lod of the full window.
FT_API ft_status ft_terrain_generate_window_lod(const ft_terrain_params* p, int32_t lod, int64_t x0, int64_t y0,
                                                int32_t width, int32_t height, ft_heightfield** out);
/// Samples per side of a midpoint/additions terrain of `levels` levels
/// (2^levels + 1), or -1 when levels is out of range.
FT_API int32_t ft_terrain_side(int32_t levels);
/// The height that FT_TERRAIN_MANDELBROT gives the continuous escape time
/// `iterations` (nu >= 0; any real) with vertical scale `p->sigma`: contour
/// the terrain at this height (ft_coastline) to get the set's level curve of
/// that escape time (an equipotential). Fails on a non-finite `iterations` or a bad sigma.
FT_API ft_status ft_mandelbrot_level_height(const ft_terrain_params* p, double iterations, double* height);

/// Parameters of ft_profile_generate: Voss 1D midpoint displacement.
typedef struct ft_profile_params {
  uint32_t struct_size;      ///< sizeof(ft_profile_params); set by _init
  int32_t levels;            ///< 2^levels + 1 samples; 1..28, default 10
  double hurst;              ///< H in [0, 1]; default 0.8
  double sigma;              ///< vertical scale, > 0; default 1
  uint64_t seed;             ///< default 1
  const float* reference;    ///< NULL or 2^m + 1 values taken as steps 1..m
  int32_t reference_size;    ///< 2^m + 1 with 1 <= m <= levels
  int32_t reference_scale;   ///< FT_REFSCALE_*; default FT_REFSCALE_SIGMA
  ft_progress_fn progress;
  void* progress_user;
} ft_profile_params;

FT_API ft_status ft_profile_params_init(ft_profile_params* p);
/// Generates a profile X(k / 2^levels), k = 0..2^levels, into `dst`, which
/// holds `count` floats (at least 2^levels + 1; see ft_profile_length).
FT_API ft_status ft_profile_generate(const ft_profile_params* p, float* dst, size_t count);
/// 2^levels + 1, or -1 when levels is out of range.
FT_API int64_t ft_profile_length(int32_t levels);

#ifdef __cplusplus
}
#endif
#endif
