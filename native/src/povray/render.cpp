// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/render.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"

namespace ft::pov {
namespace {

// The lines of POV-Ray's report that say what went wrong, not its banner.
std::string error_lines(const std::string& messages) {
  std::istringstream in(messages);
  std::string line, out;
  bool keep = false;
  while (std::getline(in, line)) {
    if (line.find("Error") != std::string::npos || line.find("error") != std::string::npos ||
        line.find("File '") != std::string::npos)
      keep = true;
    if (keep) out += "  " + line + "\n";
  }
  return out.empty() ? messages : out;
}

}  // namespace

RenderResult render_scene(const std::string& pov_path, const std::string& out_png, const RenderOptions& o) {
  namespace fs = std::filesystem;
  check_int_range("width", o.width, 1, 16384);
  check_int_range("height", o.height, 1, 16384);
  check_range("antialias", o.antialias, 0, 3);
  if (!fs::is_regular_file(platform::fs_path(pov_path)))
    fail(FT_ERR_IO, "cannot render '" + pov_path + "': no such file");
  std::string program = o.povray;
  if (program.empty()) program = std::getenv("FT_POVRAY") ? std::getenv("FT_POVRAY") : "povray";

  const fs::path scene = fs::absolute(platform::fs_path(pov_path));
  // POV-Ray splits options at spaces unless the value is in double quotes,
  // and has no escape for a quote inside them.
  auto quote = [](const std::string& v) {
    if (v.find('"') != std::string::npos)
      invalid("povray cannot be given a path containing a double quote: '" + v + "'");
    return "\"" + v + "\"";
  };
  std::vector<std::string> args = {program,
                                   "+I" + quote(platform::utf8_of(scene.filename())),
                                   "+O-",  // the image comes to us on stdout
                                   "+FN",
                                   "-D",
                                   "+W" + std::to_string(o.width),
                                   "+H" + std::to_string(o.height)};
  if (o.antialias > 0) {
    char a[32];
    std::snprintf(a, sizeof a, "+A%.3g", o.antialias);
    args.push_back(a);
  } else {
    args.push_back("-A");
  }
  for (const auto& dir : o.include_paths)
    args.push_back("+L" + quote(platform::utf8_of(fs::absolute(platform::fs_path(dir)))));

  io::AtomicFile image(out_png);  // the rendered image goes to its temporary file
  const platform::ProcessResult run = platform::run_process(args, image.file(), platform::utf8_of(scene.parent_path()));
  if (!run.started)
    fail(FT_ERR_IO, "cannot run '" + program + "': " + run.start_error +
                        " (install POV-Ray 3.7: apt-get install povray, or set FT_POVRAY)");
  RenderResult result;
  result.messages = run.errors;
  std::istringstream in(result.messages);
  for (std::string line; std::getline(in, line);)
    if (line.find("Warning:") != std::string::npos) ++result.warnings;
  const bool ok = !run.signalled && run.exit_code == 0 && platform::file_size(image.file()) > 8;
  if (!ok)
    fail(FT_ERR_IO, "povray failed on '" + pov_path + "' (" +
                        (!run.signalled ? "exit code " + std::to_string(run.exit_code)
                                        : std::string("killed by a signal")) +
                        "):\n" + error_lines(result.messages));
  image.commit();
  return result;
}

}  // namespace ft::pov
