// SPDX-License-Identifier: GPL-3.0-or-later
// GeoJSON and GeoPackage through OGR (see vector_io.hpp): features built
// with OGR's geometry API, never hand-written JSON.

#include <string_view>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_session.hpp"
#include "io/vector_io.hpp"

namespace ft::io {
namespace {

struct Geometry {
  OGRGeometryH h;
  ~Geometry() {
    if (h) gdal().OGR_G_DestroyGeometry(h);
  }
};
struct Feature {
  OGRFeatureH h;
  ~Feature() { gdal().OGR_F_Destroy(h); }
};
struct Srs {
  OGRSpatialReferenceH h = nullptr;
  ~Srs() {
    if (h) gdal().OSRRelease(h);
  }
};

}  // namespace

void write_vector_layers(const std::vector<VectorLayer>& layers, const GeoReference& geo, double spacing,
                         const std::string& path) {
  const std::string ext = extension_of(path);
  const bool gpkg = ext == ".gpkg";
  if (!gpkg && ext != ".geojson" && ext != ".json")
    invalid("'" + path + "': unsupported vector format (use .geojson or .gpkg)");
  if (layers.empty()) invalid("'" + path + "': nothing to write");
  gdal("writing '" + path + "' (GeoJSON or GeoPackage; .csv and .json need nothing)");
  GdalSession session;
  GDALDriverH driver = gdal().GDALGetDriverByName(gpkg ? "GPKG" : "GeoJSON");
  if (!driver) fail(FT_ERR_UNSUPPORTED, std::string("this GDAL has no ") + (gpkg ? "GPKG" : "GeoJSON") + " driver");
  Srs srs;
  if (!geo.crs_wkt.empty()) {
    srs.h = gdal().OSRNewSpatialReference(geo.crs_wkt.c_str());
    if (srs.h) gdal().OSRSetAxisMappingStrategy(srs.h, OAMS_TRADITIONAL_GIS_ORDER);
  }
  auto to_map = [&](const Vec3& p, double& X, double& Y) {
    if (!geo.has_transform) {
      X = p[0], Y = p[1];
      return;
    }
    const auto& t = geo.transform;
    const double col = p[0] / spacing + 0.5, row = p[1] / spacing + 0.5;  // sample centres
    X = t[0] + col * t[1] + row * t[2];
    Y = t[3] + col * t[4] + row * t[5];
  };
  GdalMemFile file(gpkg ? ".gpkg" : ".geojson");
  {
    GdalDataset ds(gdal().GDALCreate(driver, file.name().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) session.fail(FT_ERR_IO, "GDAL could not create '" + path + "'");
    for (const VectorLayer& L : layers) {
      OGRLayerH layer = gdal().GDALDatasetCreateLayer(ds.get(), L.name.c_str(), srs.h,
                                               L.polygons ? wkbPolygon25D : wkbLineString25D, nullptr);
      if (!layer) session.fail(FT_ERR_IO, "GDAL could not create the layer '" + L.name + "' in '" + path + "'");
      for (size_t f = 0; f < L.fields.size(); ++f) {
        OGRFieldDefnH def = gdal().OGR_Fld_Create(L.fields[f].c_str(), L.integer[f] ? OFTInteger64 : OFTReal);
        gdal().OGR_L_CreateField(layer, def, TRUE);
        gdal().OGR_Fld_Destroy(def);
      }
      for (const std::string& name : L.string_fields) {
        OGRFieldDefnH def = gdal().OGR_Fld_Create(name.c_str(), OFTString);
        gdal().OGR_L_CreateField(layer, def, TRUE);
        gdal().OGR_Fld_Destroy(def);
      }
      for (size_t k = 0; k < L.geometry.size(); ++k) {
        Feature feat{gdal().OGR_F_Create(gdal().OGR_L_GetLayerDefn(layer))};
        for (size_t f = 0; f < L.fields.size(); ++f) {
          if (L.integer[f]) gdal().OGR_F_SetFieldInteger64(feat.h, int(f), GIntBig(L.values[k][f]));
          else gdal().OGR_F_SetFieldDouble(feat.h, int(f), L.values[k][f]);
        }
        for (size_t s = 0; s < L.string_fields.size(); ++s)
          gdal().OGR_F_SetFieldString(feat.h, int(L.fields.size() + s), L.strings[k][s].c_str());
        Geometry g{gdal().OGR_G_CreateGeometry(L.polygons ? wkbPolygon25D : wkbLineString25D)};
        for (const auto& ring : L.geometry[k]) {
          OGRGeometryH target = g.h;
          Geometry r{nullptr};
          if (L.polygons) r.h = gdal().OGR_G_CreateGeometry(wkbLinearRing), target = r.h;
          for (const Vec3& p : ring) {
            double X, Y;
            to_map(p, X, Y);
            gdal().OGR_G_AddPoint(target, X, Y, p[2]);
          }
          if (L.polygons) gdal().OGR_G_AddGeometry(g.h, r.h);  // copies the ring
          if (!L.polygons) break;
        }
        gdal().OGR_F_SetGeometry(feat.h, g.h);  // copies
        if (gdal().OGR_L_CreateFeature(layer, feat.h) != OGRERR_NONE)
          session.fail(FT_ERR_IO, "GDAL could not write a feature of '" + L.name + "' to '" + path + "'");
      }
      if (!gpkg) break;  // GeoJSON holds one layer
    }
  }
  vsi_l_offset length = 0;
  GByte* bytes = gdal().VSIGetMemFileBuffer(file.name().c_str(), &length, FALSE);
  if (bytes == nullptr || !session.first_error().empty())
    session.fail(FT_ERR_IO, "GDAL could not write '" + path + "'");
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes), size_t(length)));
}

}  // namespace ft::io
