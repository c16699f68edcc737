// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/gdal_api.hpp"

#include "core/error.hpp"
#include "core/gdal_library.hpp"
#include "core/platform.hpp"

namespace ft::io {
namespace {

struct Bound {
  GdalApi api;
  std::string missing;  // the functions this GDAL lacks ("" when all are there)
};

const Bound& bound() {
  static const Bound b = [] {
    Bound out;
    void* lib = gdal_library();
    if (!lib) return out;
#define FT_GDAL_BIND(fn)                                                                 \
  out.api.fn = reinterpret_cast<decltype(&::fn)>(platform::library_symbol(lib, #fn)); \
  if (!out.api.fn) out.missing += (out.missing.empty() ? "" : ", ") + std::string(#fn);
    FT_GDAL_FUNCTIONS(FT_GDAL_BIND)
#undef FT_GDAL_BIND
    return out;
  }();
  return b;
}

}  // namespace

const GdalApi& gdal(const std::string& what) {
  if (!have_gdal()) needs_gdal(what);
  const Bound& b = bound();
  if (!b.missing.empty())
    fail(FT_ERR_UNSUPPORTED, what + " needs GDAL 3.1 or later; the GDAL found lacks " + b.missing);
  return b.api;
}

const GdalApi& gdal() { return gdal("a call into GDAL"); }

}  // namespace ft::io
