// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/plot_writer.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"

namespace ft::cli {

void write_plot(const std::string& path, const io::SvgFigure& fig) {
  const std::string ext = io::extension_of(path);
  if (ext == ".svg") return io::write_svg(path, fig);
  if (ext != ".png") invalid("--plot '" + path + "': use a .svg or .png file name");
  const std::string svg = path + ".tmp.svg", png = path + ".tmp.png";
  io::write_svg(svg, fig);
  const platform::ProcessResult run =
      platform::run_process({"rsvg-convert", "-b", "white", "-o", png, svg}, nullptr, "");
  platform::remove_file(svg);
  if (!run.started || run.signalled || run.exit_code != 0) {
    platform::remove_file(png);
    fail(FT_ERR_IO, "--plot '" + path + "': PNG plots need rsvg-convert (Debian package librsvg2-bin); "
                    "it is missing or failed: write a .svg instead");
  }
  const std::string why = platform::replace_file(png, path);
  if (!why.empty()) fail(FT_ERR_IO, "--plot '" + path + "': " + why);
}

}  // namespace ft::cli
