// SPDX-License-Identifier: GPL-3.0-or-later
// GDAL's C API, bound at run time to the system's GDAL that
// core/gdal_library.hpp opens: every call into GDAL goes through gdal().
#pragma once

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <string>

namespace ft::io {

// Every GDAL function the library calls; a new call adds its name here.
#define FT_GDAL_FUNCTIONS(X)                                                                                        \
  X(GDALAllRegister) X(GDALOpen) X(GDALOpenEx) X(GDALClose) X(GDALCreate) X(GDALCreateCopy)                          \
  X(GDALGetDriverByName) X(GDALGetRasterBand) X(GDALGetRasterCount) X(GDALGetRasterXSize) X(GDALGetRasterYSize)     \
  X(GDALRasterIO) X(GDALGetRasterNoDataValue) X(GDALSetRasterNoDataValue) X(GDALGetRasterOffset)                    \
  X(GDALSetRasterOffset) X(GDALGetRasterScale) X(GDALSetRasterScale) X(GDALGetProjectionRef) X(GDALSetProjection)   \
  X(GDALGetGeoTransform) X(GDALSetGeoTransform) X(GDALGetMetadataItem) X(GDALSetMetadataItem) X(GDALFillNodata)    \
  X(GDALBuildOverviews) X(GDALBuildVRT) X(GDALBuildVRTOptionsNew) X(GDALBuildVRTOptionsFree)                        \
  X(GDALDatasetCreateLayer) X(OGR_L_CreateField) X(OGR_L_GetLayerDefn) X(OGR_L_CreateFeature) X(OGR_Fld_Create)     \
  X(OGR_Fld_Destroy) X(OGR_F_Create) X(OGR_F_Destroy) X(OGR_F_SetFieldInteger64) X(OGR_F_SetFieldDouble)            \
  X(OGR_F_SetFieldString) X(OGR_F_SetGeometry) X(OGR_G_CreateGeometry) X(OGR_G_DestroyGeometry) X(OGR_G_AddPoint)  \
  X(OGR_G_AddGeometry) X(OSRNewSpatialReference) X(OSRRelease) X(OSRDestroySpatialReference)                       \
  X(OSRSetAxisMappingStrategy) X(OSRIsGeographic) X(OSRGetSemiMajor) X(OSRGetLinearUnits) X(CPLPushErrorHandler)   \
  X(CPLPopErrorHandler) X(CPLGetConfigOption) X(CPLSetConfigOption) X(CPLSetThreadLocalConfigOption)               \
  X(CSLAddString) X(CSLCount) X(CSLDestroy) X(CSLSetNameValue) X(VSIFileFromMemBuffer) X(VSIFCloseL)                \
  X(VSIGetMemFileBuffer) X(VSIStatL) X(VSIUnlink)

struct GdalApi {
#define FT_GDAL_POINTER(name) decltype(&::name) name = nullptr;
  FT_GDAL_FUNCTIONS(FT_GDAL_POINTER)
#undef FT_GDAL_POINTER
};

// The bound API; throws FT_ERR_UNSUPPORTED "<what> needs GDAL, ..." (what
// was tried, which package brings GDAL) when there is none or it lacks a
// function. Each entry point calls it first, naming what it does; the code
// it calls then uses gdal().
const GdalApi& gdal(const std::string& what);
const GdalApi& gdal();

}  // namespace ft::io
