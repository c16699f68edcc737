// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/polyline.h
/// Fractal polylines: Nikulin's FPL (random orthogonal midpoint displacement,
/// seed 003) in 2D and 3D with optional branching (lightning), the Voss
/// profile as a curve, the classic Koch, Harter-Heighway dragon and
/// Sierpinski arrowhead curves, IFS point sets by random iteration (seed 002),
/// and the measures of seed 003 (eta, chi, gamma, box-counting and mass
/// dimensions). Results come back as ft_polylines handles (see core.h).
#ifndef FRACTERRA_POLYLINE_H
#define FRACTERRA_POLYLINE_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Polyline methods (ft_polyline_params.method).
enum {
  FT_POLYLINE_FPL = 0,        ///< FPLrec on every base segment, x,y plane (z interpolated)
  FT_POLYLINE_FPL3D = 1,      ///< FPL with 3D displacements (random direction or in a plane)
  FT_POLYLINE_KOCH = 2,       ///< Koch curve on every base segment, 4^depth segments each
  FT_POLYLINE_DRAGON = 3,     ///< Harter-Heighway dragon: FPL rule +-1/2 alternating, 2^depth each
  FT_POLYLINE_SIERPINSKI = 4, ///< Sierpinski arrowhead curve, 3^depth segments each
  FT_POLYLINE_IFS = 5,        ///< IFS attractor points by random iteration (one vertex per line)
  FT_POLYLINE_PROFILE = 6     ///< Voss 1D profile laid across every base segment (a horizon)
};

/// Random generators rf of the FPL (ft_polyline_params.rng).
enum {
  FT_POLYLINE_RNG_UNIFORM = 0, ///< urf(s): uniform on [-s, s]
  FT_POLYLINE_RNG_NORMAL = 1   ///< nrf(sigma): normal, standard deviation sigma
};

/// Built-in IFS tables (seed 002), used when ifs_table is NULL.
enum {
  FT_IFS_FERN = 0,   ///< Barnsley's fern, 4 maps, p = 0.01, 0.85, 0.07, 0.07
  FT_IFS_DRAGON = 1, ///< Harter-Heighway dragon, 2 maps (640 x 350 screen units)
  FT_IFS_KOCH = 2,   ///< Koch curve, 4 maps (640 x 350 screen units)
  FT_IFS_SIERPINSKI_GASKET = 3 ///< Sierpinski gasket, 3 maps of ratio 1/2 towards the corners of the
                               ///< unit equilateral triangle, p = 1/3 each; dimension log 3 / log 2
};

/// Parameters of ft_polyline_generate. Fill with ft_polyline_params_init,
/// then change what you need; fields a method does not use are ignored.
typedef struct ft_polyline_params {
  uint32_t struct_size;        ///< sizeof(ft_polyline_params); set by _init
  int32_t method;              ///< FT_POLYLINE_*; default FT_POLYLINE_FPL
  int32_t rng;                 ///< FT_POLYLINE_RNG_*; default uniform
  int32_t depth;               ///< recursion depth r: FPL/dragon 0..34 (memory cap
                               ///< permitting; profile 1..28), Koch 0..15, Sierpinski 0..19; default 8
  double spread;               ///< s or sigma, displacement per unit segment length, >= 0; default 0.1.
                               ///< Profile: the vertical scale sigma (> 0)
  double min_length;           ///< delta: segments shorter than this are not split, >= 0; default 0
  uint64_t seed;               ///< any 64-bit value; default 1
  const double* base;          ///< base polyline p1..pn as n xyz triples (not copied); NULL: the
                               ///< unit segment (0,0,0)-(1,0,0). Unused by IFS
  int64_t base_count;          ///< n >= 2 when base is given; consecutive nodes must differ
  double plane_normal[3];      ///< FPL3D: displacements lie in the plane with this normal;
                               ///< all zero (default): a random direction per midpoint
  double branch_prob;          ///< FPL/FPL3D: probability that a midpoint of recursion level l forks
                               ///< a side branch is branch_prob * 2^(-l/2); 0..1, default 0 (none)
  double branch_decay;         ///< length and radius factor per branch generation, (0, 1); default 0.5
  int32_t branch_generations;  ///< deepest branch generation, 1..8; default 3
  int32_t ifs_preset;          ///< FT_IFS_*; default FT_IFS_FERN
  double radius;               ///< vertex radius of the main line, >= 0; default 0.01.
                               ///< With branches every line tapers to branch_decay x its start radius
  double hurst;                ///< profile: Hurst exponent H in [0, 1]; default 0.8
  const double* ifs_table;     ///< NULL: ifs_preset; else ifs_maps rows of 7 doubles
                               ///< (a, b, c, d, e, f, p): x' = a x + b y + e, y' = c x + d y + f,
                               ///< chosen with probability p (p >= 0, normalised by their sum)
  int32_t ifs_maps;            ///< rows in ifs_table, 1..64
  int32_t threads;             ///< FPL worker threads, 0 = all cores, 1..1024; output never depends on it
  int64_t ifs_points;          ///< IFS points to return, 1..2^28; default 100000
  ft_progress_fn progress;     ///< may be NULL
  void* progress_user;
} ft_polyline_params;

/// Fills `p` with the defaults documented above. `p` must not be NULL.
FT_API ft_status ft_polyline_params_init(ft_polyline_params* p);
/// Generates polylines. Line 0 is the main line through the base nodes (which
/// survive exactly); branches follow. IFS returns one single-vertex line per
/// point. On success `*out` owns a new set (free with ft_polylines_free); on
/// failure `*out` is NULL and ft_last_error() says why.
FT_API ft_status ft_polyline_generate(const ft_polyline_params* p, ft_polylines** out);

/// Measures of a polyline set (seed 003). eta, chi, gamma and the mass
/// dimension describe line 0 (the main line), relative to its chord p1 -> pn
/// (so a line on the unit horizontal segment gives the paper's numbers);
/// they are NaN when the line has fewer than 2 vertices or a zero chord.
/// The box-counting dimension covers all lines together in the x,y plane
/// (box sizes: see docs/polyline.md); NaN fields when it cannot be measured.
typedef struct ft_polyline_stats {
  uint32_t struct_size;        ///< set by the caller to sizeof(ft_polyline_stats)
  int32_t reserved0;
  int64_t line_count;
  int64_t vertex_count;
  double eta;                  ///< max |deviation| from the chord / chord length (eq. 1a)
  double chi;                  ///< mean |deviation| over the vertices / chord length (eq. 1a)
  double gamma;                ///< line length / chord length (eq. 1b)
  double length;               ///< total length of all lines
  double mass_dimension;       ///< 1 / (1 - log2(M_r / M_{r-1})), M_{r-1} the length through every
                               ///< second vertex (eq. 4g with N ratio 2, as eq. 6)
  double box_dimension;        ///< box-counting D (slope of log N against log 1/eps)
  double box_dimension_std_error;        ///< standard error of that slope
  double box_min_size;         ///< smallest box side used
  double box_max_size;         ///< largest box side used
  int32_t box_sizes;           ///< number of box sizes in the fit
  int32_t reserved1;
} ft_polyline_stats;

/// Measures `p` into `out` (out->struct_size must be set). Returns
/// FT_ERR_INVALID_ARGUMENT for NULL pointers or a too small struct_size.
FT_API ft_status ft_polyline_measure(const ft_polylines* p, ft_polyline_stats* out);

/// One (spread, depth) of the FPL ensemble study (seed 003, `fracterra study fpl`; ABI 2.27): the
/// ensemble means and standard errors (sd / sqrt(K), over the finite values) of eta, chi, gamma, the
/// mass and box-counting dimensions over K lines on the unit horizontal segment, and the paper's
/// fitted values at the same spread and depth.
typedef struct ft_fpl_study_row {
  double spread;
  int32_t depth;
  int32_t count;              ///< K, lines per (spread, depth)
  double eta_mean;            ///< max |deviation| / chord (eq. 1a)
  double eta_se;
  double chi_mean;            ///< mean |deviation| / chord (eq. 1a)
  double chi_se;
  double gamma_mean;          ///< length / chord (eq. 1b)
  double gamma_se;
  double mass_dimension_mean; ///< eq. 4g / 6
  double mass_dimension_se;
  double box_dimension_mean;  ///< NaN below depth 6 or at spread 0
  double box_dimension_se;
  double paper_eta;           ///< the paper's fits at this spread and depth
  double paper_chi;
  double paper_gamma;
  double paper_dimension;     ///< NaN where the fit has none
} ft_fpl_study_row;

/// The FPL ensemble study (ABI 2.27), as `fracterra study fpl` runs it: for each spread (>= 0) and
/// each depth (1..20), `count` (2..100000) FPL lines of generator `rng` (FT_POLYLINE_RNG_*) with
/// seeds seed, seed + 1, ...; box counting (depth >= 6, spread > 0) when `box_counting` is non-zero.
/// `out` receives spread_count x depth_count rows, spreads outer (out_count must be that). The
/// result never depends on the thread count. `progress` may be NULL.
FT_API ft_status ft_fpl_study(int32_t rng, const double* spreads, int32_t spread_count, const int32_t* depths,
                              int32_t depth_count, int32_t count, uint64_t seed, int32_t box_counting,
                              ft_progress_fn progress, void* progress_user, ft_fpl_study_row* out, int64_t out_count);

#ifdef __cplusplus
}
#endif
#endif
