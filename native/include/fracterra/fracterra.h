// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/fracterra.h
/// The fracterra C ABI: fractal terrains and polylines, and their measures.
/// Include this one header; it pulls in every capability's declarations.
/// Conventions (see core.h): every call returns ft_status; ft_last_error()
/// says what went wrong; parameter structs start with struct_size and are
/// filled by ft_*_params_init; result handles are freed by NULL-safe *_free.
#ifndef FRACTERRA_H
#define FRACTERRA_H

#include "core.h"
#include "terrain.h"
#include "analysis.h"
#include "subdiv.h"
#include "mesh.h"
#include "polyline.h"
#include "povray.h"
#include "params.h"
#include "erosion.h"
#include "hydrology.h"
#include "raster.h"
#include "tiles.h"
#include "pipeline.h"
#include "planet.h"
#include "splat.h"

#endif
