// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/atomic_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/platform.hpp"

namespace ft::io {
namespace {
std::string folder_of(const std::string& path) {
  auto parent = platform::fs_path(path).parent_path();
  return parent.empty() ? std::string(".") : platform::utf8_of(parent);
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
  for (const auto& e : std::filesystem::directory_iterator(platform::fs_path(folder), ec)) {
    const std::string name = platform::utf8_of(e.path().filename());
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
    if (pid <= 0 || *end != '.' || pid == platform::process_id()) continue;
    if (platform::process_gone(pid)) platform::remove_file(platform::utf8_of(e.path()));
  }
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) invalid("output path must not be empty");
  const std::string folder = folder_of(path_);
  std::error_code ec;
  if (!std::filesystem::is_directory(platform::fs_path(folder), ec))
    fail(FT_ERR_IO, "cannot write '" + path_ + "': folder '" + folder + "' does not exist");
  if (std::filesystem::is_directory(platform::fs_path(path_), ec))
    fail(FT_ERR_IO, "cannot write '" + path_ + "': it is a folder");
  const std::string prefix = "." + platform::utf8_of(platform::fs_path(path_).filename()) + ".tmp.";
  remove_stale_temps(folder, prefix);
  temp_ = platform::utf8_of(platform::fs_path(folder) /
                            platform::fs_path(prefix + std::to_string(platform::process_id()) + ".XXXXXX"));
  file_ = platform::create_temp_file(temp_);
  if (!file_) fail(FT_ERR_IO, "cannot write in folder '" + folder + "': " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_) platform::remove_file(temp_);
}

void AtomicFile::write(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail(FT_ERR_IO, "writing '" + path_ + "' failed: " + std::strerror(errno));
}

void AtomicFile::commit() {
  bool ok = platform::sync_file(file_);
  const int err = errno;
  ok = (std::fclose(file_) == 0) && ok;
  file_ = nullptr;
  if (!ok) fail(FT_ERR_IO, "writing '" + path_ + "' failed: " + std::strerror(err));
  const std::string why = platform::replace_file(temp_, path_);
  if (!why.empty()) fail(FT_ERR_IO, "cannot move the finished file to '" + path_ + "': " + why);
  committed_ = true;
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
  AtomicFile f(path);
  f.write(bytes);
  f.commit();
}

std::string extension_of(const std::string& path) {
  std::string ext = platform::utf8_of(platform::fs_path(path).extension());
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string read_file(const std::string& path) {
  FILE* f = platform::open_file(path, "rb");
  if (!f) fail(FT_ERR_IO, "cannot read '" + path + "': " + std::strerror(errno));
  std::string data;
  std::error_code ec;
  if (std::filesystem::is_regular_file(platform::fs_path(path), ec)) {
    const int64_t size = platform::file_size(f);
    try {
      if (size > 0) check_allocation(uint64_t(size), "reading '" + path + "'");
    } catch (...) {
      std::fclose(f);
      throw;
    }
    if (size > 0) data.reserve(size_t(size));
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
