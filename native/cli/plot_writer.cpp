#include "cli/plot_writer.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace ft::cli {

void write_plot(const std::string& path, const io::SvgFigure& fig) {
  const std::string ext = io::extension_of(path);
  if (ext == ".svg") return io::write_svg(path, fig);
  if (ext != ".png") invalid("--plot '" + path + "': use a .svg or .png file name");
  const std::string svg = path + ".tmp.svg", png = path + ".tmp.png";
  io::write_svg(svg, fig);
  const char* argv[] = {"rsvg-convert", "-b", "white", "-o", png.c_str(), svg.c_str(), nullptr};
  pid_t pid;
  int status = -1;
  const int rc = posix_spawnp(&pid, "rsvg-convert", nullptr, nullptr, const_cast<char* const*>(argv), environ);
  if (rc == 0) waitpid(pid, &status, 0);
  std::error_code ec;
  std::filesystem::remove(svg, ec);
  if (rc != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(png, ec);
    fail(FT_ERR_IO, "--plot '" + path + "': PNG plots need rsvg-convert (Debian package librsvg2-bin); "
                    "it is missing or failed: write a .svg instead");
  }
  std::filesystem::rename(png, path, ec);
  if (ec) fail(FT_ERR_IO, "--plot '" + path + "': " + ec.message());
}

}  // namespace ft::cli
