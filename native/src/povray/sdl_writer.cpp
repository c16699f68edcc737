// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/sdl_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.hpp"
#include "core/platform.hpp"

namespace ft::pov {

std::string number(double v) {
  if (!std::isfinite(v)) invalid("a scene coordinate must be finite, got " + format_number(v));
  if (v == 0.0) return "0";  // no "-0"
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string vec(const Vec3& v) {
  // Appended piece by piece: GCC 12's -Wrestrict misfires on the chained "+".
  std::string s = "<";
  s.append(number(v[0])).append(", ").append(number(v[1])).append(", ").append(number(v[2]));
  return s.append(">");
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c < 0x20 || c == 0x7f)
      invalid("text written into a POV-Ray scene must not contain control characters: '" +
              comment_text(text) + "'");
    // POV-Ray 3.7 turns \" into " in file names but keeps \\ as two
    // backslashes, so a backslash cannot be written faithfully: refuse it
    // (and with it any way to pair our escapes with one of the caller's).
    if (c == '\\')
      invalid("a path written into a POV-Ray scene must not contain a backslash: '" + comment_text(text) + "'");
    if (c == '"') out += '\\';
    out += char(c);
  }
  return out + "\"";
}

const std::string& identifier(const std::string& name, const char* what) {
  bool ok = !name.empty() && name.size() <= 40 &&
            ((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z'));
  bool capital = false;
  for (char c : name) {
    ok = ok && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_');
    capital = capital || (c >= 'A' && c <= 'Z');
  }
  if (!ok || !capital)
    invalid(std::string(what) + " '" + comment_text(name) +
            "' is not a usable POV-Ray identifier: use 1 to 40 letters, digits or '_', starting "
            "with a letter and with at least one capital letter (e.g. 'Terrain')");
  return name;
}

std::string comment_text(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return out;
}

std::string relative_path(const std::string& target, const std::string& from_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path t = fs::weakly_canonical(fs::absolute(platform::fs_path(target)), ec);
  const fs::path d = fs::weakly_canonical(fs::absolute(platform::fs_path(from_dir.empty() ? "." : from_dir)), ec);
  fs::path rel = t.lexically_relative(d);
  if (rel.empty()) rel = t;  // different roots: keep it absolute
  std::string s = platform::utf8_of(rel);
  // POV-Ray reads '/' on every system; a backslash would start an escape.
  if constexpr (fs::path::preferred_separator == '\\') std::replace(s.begin(), s.end(), '\\', '/');
  return s;
}

std::string folder_of(const std::string& path) {
  const auto parent = platform::fs_path(path).parent_path();
  return parent.empty() ? std::string(".") : platform::utf8_of(parent);
}

}  // namespace ft::pov
