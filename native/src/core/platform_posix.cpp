// SPDX-License-Identifier: GPL-3.0-or-later
// platform.hpp on Linux (and any POSIX system with glibc's posix_spawn).
#ifndef _WIN32
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/platform.hpp"
#include "core/platform_memory.hpp"

extern char** environ;

namespace ft::platform {

std::filesystem::path fs_path(std::string_view utf8) { return std::filesystem::path(utf8); }
std::string utf8_of(const std::filesystem::path& p) { return p.string(); }

FILE* open_file(const std::string& utf8_path, const char* mode) { return std::fopen(utf8_path.c_str(), mode); }

FILE* create_temp_file(std::string& path_template) {
  const int fd = ::mkstemp(path_template.data());
  if (fd < 0) return nullptr;
  // mkstemp makes the file 0600; give it the usual permissions (respecting umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  FILE* f = ::fdopen(fd, "wb");
  if (!f) {
    const int err = errno;
    ::close(fd);
    ::unlink(path_template.c_str());
    errno = err;
  }
  return f;
}

bool sync_file(FILE* f) { return std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0; }

std::string replace_file(const std::string& from, const std::string& to) {
  return ::rename(from.c_str(), to.c_str()) == 0 ? std::string() : std::string(std::strerror(errno));
}

int64_t file_size(FILE* f) noexcept {
  struct stat st {};
  return ::fstat(::fileno(f), &st) == 0 ? int64_t(st.st_size) : -1;
}

std::string append_synced(const std::string& utf8_path, std::string_view bytes) {
  const int fd = ::open(utf8_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) return std::strerror(errno);
  // One write of a short line: O_APPEND puts it whole at the end.
  const bool ok = ::write(fd, bytes.data(), bytes.size()) == ssize_t(bytes.size()) && ::fdatasync(fd) == 0;
  const int err = errno;
  ::close(fd);
  return ok ? std::string() : std::string(std::strerror(err));
}

void remove_file(const std::string& utf8_path) noexcept { ::unlink(utf8_path.c_str()); }

long process_id() noexcept { return long(::getpid()); }
bool process_gone(long pid) noexcept { return ::kill(pid_t(pid), 0) != 0 && errno == ESRCH; }

ProcessResult run_process(const std::vector<std::string>& args, FILE* stdout_to, const std::string& cwd) {
  ProcessResult r;
  int err_pipe[2];
  if (::pipe(err_pipe) != 0) {
    r.start_error = std::strerror(errno);
    return r;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (stdout_to) posix_spawn_file_actions_adddup2(&fa, ::fileno(stdout_to), 1);
  posix_spawn_file_actions_adddup2(&fa, err_pipe[1], 2);
  posix_spawn_file_actions_addclose(&fa, err_pipe[0]);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&fa, cwd.c_str());
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(err_pipe[1]);
  if (rc != 0) {
    ::close(err_pipe[0]);
    r.start_error = std::strerror(rc);
    return r;
  }
  r.started = true;
  char buf[4096];
  ssize_t n;
  while ((n = ::read(err_pipe[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) r.errors.append(buf, size_t(n));
  ::close(err_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.signalled = !WIFEXITED(status);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

void* aligned_allocate(size_t align, size_t bytes) noexcept { return std::aligned_alloc(align, bytes); }
void aligned_free(void* p) noexcept { std::free(p); }
void advise_huge_pages(void* p, size_t bytes) noexcept { ::madvise(p, bytes, MADV_HUGEPAGE); }

uint64_t available_memory() noexcept {
  FILE* f = std::fopen("/proc/meminfo", "r");
  if (!f) return std::numeric_limits<uint64_t>::max();
  char line[256];
  unsigned long long kib = 0;
  bool found = false;
  while (std::fgets(line, sizeof line, f)) {
    if (std::strncmp(line, "MemAvailable:", 13) == 0) {
      found = std::sscanf(line + 13, "%llu", &kib) == 1;
      break;
    }
  }
  std::fclose(f);
  return found ? uint64_t(kib) * 1024 : std::numeric_limits<uint64_t>::max();
}

std::vector<std::string> utf8_arguments(int argc, char** argv) { return {argv, argv + argc}; }

void* open_library(const std::string& name, std::string& error) {
  // RTLD_LOCAL: its symbols stay out of the global namespace, where they
  // could bind a host application's (Blender's) own libraries to them.
  void* h = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) {
    const char* e = dlerror();
    error = e ? e : "dlopen failed";
  }
  return h;
}

void* library_symbol(void* library, const char* symbol) noexcept { return dlsym(library, symbol); }

}  // namespace ft::platform
#endif
