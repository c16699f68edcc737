// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/gdal_library.hpp"

#include <cstdlib>
#include <vector>

#include "core/build_features.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"

// FT_GDAL_SONAME: the soname number of the GDAL this library was built with;
// FT_GDAL_PACKAGE: its Debian package (both from native/CMakeLists.txt).
#ifndef FT_GDAL_SONAME
#define FT_GDAL_SONAME 0
#endif
#ifndef FT_GDAL_PACKAGE
#define FT_GDAL_PACKAGE "libgdal"
#endif

namespace ft {
namespace {

// GDAL 3.x's library is libgdal.so.(26 + minor): 3.0 is .26, 3.6 .32, 3.10 .36;
// 45 leaves room for the 3.x releases to come.
constexpr int kOldestSoname = 26, kNewestSoname = 45;

std::vector<std::string> candidates() {
  if (const char* env = std::getenv("FRACTERRA_GDAL"); env && *env) return {env};
  std::vector<std::string> names;
  if (FT_GDAL_SONAME > 0) names.push_back("libgdal.so." + std::to_string(FT_GDAL_SONAME));
  for (int n = kNewestSoname; n >= kOldestSoname; --n)
    if (n != FT_GDAL_SONAME) names.push_back("libgdal.so." + std::to_string(n));
  return names;
}

struct Opened {
  void* library = nullptr;
  std::string why_not;  // the first candidate's failure
};

const Opened& opened() {
  static const Opened o = [] {
    Opened out;
    if (!kHaveGdal) {
      out.why_not = "this build of fracterra has no GDAL support: the Windows build goes without it, docs/windows.md";
      return out;
    }
    for (const std::string& name : candidates()) {
      std::string error;
      if ((out.library = platform::open_library(name, error))) return out;
      if (out.why_not.empty()) out.why_not = error;
    }
    return out;
  }();
  return o;
}

}  // namespace

void* gdal_library() { return opened().library; }

bool have_gdal() { return gdal_library() != nullptr; }

void needs_gdal(const std::string& what) {
  if (!kHaveGdal) needs(what, "GDAL");
  fail(FT_ERR_UNSUPPORTED,
       what + " needs GDAL, which fracterra loads from the system when it is installed, and none was found (" +
           opened().why_not + "). Install GDAL 3.1 or later: on Debian and Ubuntu `sudo apt install gdal-bin` " +
           "(it brings libgdal; this build was made with " FT_GDAL_PACKAGE "), on Fedora `sudo dnf install " +
           "gdal-libs`, on Arch `sudo pacman -S gdal`; or set FRACTERRA_GDAL to the path of a libgdal.so. " +
           "Without it fracterra reads and writes " + heightfield_formats());
}

}  // namespace ft
