#include "povray/render.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

extern char** environ;

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
  if (!fs::is_regular_file(pov_path)) fail(FT_ERR_IO, "cannot render '" + pov_path + "': no such file");
  std::string program = o.povray;
  if (program.empty()) program = std::getenv("FT_POVRAY") ? std::getenv("FT_POVRAY") : "povray";

  const fs::path scene = fs::absolute(pov_path);
  // POV-Ray splits options at spaces unless the value is in double quotes,
  // and has no escape for a quote inside them.
  auto quote = [](const std::string& v) {
    if (v.find('"') != std::string::npos)
      invalid("povray cannot be given a path containing a double quote: '" + v + "'");
    return "\"" + v + "\"";
  };
  std::vector<std::string> args = {program,
                                   "+I" + quote(scene.filename().string()),
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
  for (const auto& dir : o.include_paths) args.push_back("+L" + quote(fs::absolute(dir).string()));

  io::AtomicFile image(out_png);  // the rendered image goes to its temporary file
  int err_pipe[2];
  if (::pipe(err_pipe) != 0) fail(FT_ERR_IO, std::string("cannot start povray: ") + std::strerror(errno));
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, ::fileno(image.file()), 1);
  posix_spawn_file_actions_adddup2(&fa, err_pipe[1], 2);
  posix_spawn_file_actions_addclose(&fa, err_pipe[0]);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addchdir_np(&fa, scene.parent_path().c_str());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, program.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(err_pipe[1]);
  if (rc != 0) {
    ::close(err_pipe[0]);
    fail(FT_ERR_IO, "cannot run '" + program + "': " + std::strerror(rc) +
                        " (install POV-Ray 3.7: apt-get install povray, or set FT_POVRAY)");
  }
  RenderResult result;
  char buf[4096];
  ssize_t n;
  while ((n = ::read(err_pipe[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) result.messages.append(buf, size_t(n));
  ::close(err_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::istringstream in(result.messages);
  for (std::string line; std::getline(in, line);)
    if (line.find("Warning:") != std::string::npos) ++result.warnings;
  struct stat st {};
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                  ::fstat(::fileno(image.file()), &st) == 0 && st.st_size > 8;
  if (!ok)
    fail(FT_ERR_IO, "povray failed on '" + pov_path + "' (" +
                        (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                           : std::string("killed by a signal")) +
                        "):\n" + error_lines(result.messages));
  image.commit();
  return result;
}

}  // namespace ft::pov
