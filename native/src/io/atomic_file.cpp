#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace ft::io {
namespace {
std::string folder_of(const std::string& path) {
  std::filesystem::path p(path);
  auto parent = p.parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// A writer killed outright (SIGKILL, power loss) cannot remove its temporary
// file. Temporary names carry the writer's pid, so the next write of the same
// file removes those whose writer no longer runs on this machine, before
// making its own (a stale multi-GiB temp may be what filled the disk).
// Temps of live writers, and of other machines sharing the folder whose pid
// happens to be free here (their rename then fails with FT_ERR_IO; their
// destination stays intact), are the only ones touched or left.
void remove_stale_temps(const std::string& folder, const std::string& prefix) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
    if (pid <= 0 || *end != '.' || pid == long(::getpid())) continue;
    if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH) ::unlink(e.path().c_str());
  }
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) invalid("output path must not be empty");
  const std::string folder = folder_of(path_);
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    fail(FT_ERR_IO, "cannot write '" + path_ + "': folder '" + folder + "' does not exist");
  if (::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    fail(FT_ERR_IO, "cannot write '" + path_ + "': it is a folder");
  const std::string prefix = "." + std::filesystem::path(path_).filename().string() + ".tmp.";
  remove_stale_temps(folder, prefix);
  temp_ = (std::filesystem::path(folder) / (prefix + std::to_string(::getpid()) + ".XXXXXX")).string();
  int fd = ::mkstemp(temp_.data());
  if (fd < 0)
    fail(FT_ERR_IO, "cannot write in folder '" + folder + "': " + std::strerror(errno));
  // mkstemp makes the file 0600; give it the usual permissions (respecting umask).
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    ::close(fd);
    ::unlink(temp_.c_str());
    fail(FT_ERR_IO, "cannot open a temporary file for '" + path_ + "'");
  }
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_) ::unlink(temp_.c_str());
}

void AtomicFile::write(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail(FT_ERR_IO, "writing '" + path_ + "' failed: " + std::strerror(errno));
}

void AtomicFile::commit() {
  bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  const int err = errno;
  ok = (std::fclose(file_) == 0) && ok;
  file_ = nullptr;
  if (!ok) fail(FT_ERR_IO, "writing '" + path_ + "' failed: " + std::strerror(err));
  if (::rename(temp_.c_str(), path_.c_str()) != 0)
    fail(FT_ERR_IO, "cannot move the finished file to '" + path_ + "': " + std::strerror(errno));
  committed_ = true;
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  AtomicFile f(path);
  f.write(bytes);
  f.commit();
}

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string read_file(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) fail(FT_ERR_IO, "cannot read '" + path + "': " + std::strerror(errno));
  std::string data;
  struct stat st {};
  if (::fstat(::fileno(f), &st) == 0 && S_ISREG(st.st_mode)) {
    try {
      check_allocation(uint64_t(st.st_size), "reading '" + path + "'");
    } catch (...) {
      std::fclose(f);
      throw;
    }
    data.reserve(size_t(st.st_size));
  }
  char buf[1 << 16];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) data.append(buf, n);
  const bool err = std::ferror(f);
  std::fclose(f);
  if (err) fail(FT_ERR_IO, "reading '" + path + "' failed");
  return data;
}

}  // namespace ft::io
