// SPDX-License-Identifier: GPL-3.0-or-later
// Runs the real `povray` on a scene: in the scene's folder (POV-Ray's file
// restrictions allow reading there, and the scene's relative paths start
// there), image to a temporary file renamed into place only on success,
// POV-Ray's own messages passed on when it fails.
#pragma once

#include <string>
#include <vector>

namespace ft::pov {

struct RenderOptions {
  int width = 800, height = 600;      // pixels, 1..16384
  double antialias = 0.3;             // +A threshold (0 = no anti-aliasing), 0..3
  std::vector<std::string> include_paths;  // extra +L folders (e.g. povray_macros)
  std::string povray = "";            // program; "" = $FT_POVRAY or "povray"
  bool verbose = false;               // pass all of POV-Ray's messages on, not only warnings
};

struct RenderResult {
  std::string messages;  // POV-Ray's stderr
  int warnings = 0;      // "Warning" lines in it (parse warnings and the like)
};

// Renders `pov_path` to the PNG `out_png` (atomically). Throws FT_ERR_IO
// with POV-Ray's error lines when it cannot be started or fails.
RenderResult render_scene(const std::string& pov_path, const std::string& out_png, const RenderOptions& o);

}  // namespace ft::pov
