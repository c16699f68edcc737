// SPDX-License-Identifier: GPL-3.0-or-later
// Files are never written in place: the content goes to a temporary file in
// the destination's folder and is renamed over the destination only once it
// is complete and flushed, so a failed or interrupted write leaves the old
// file untouched and no partial file behind. The temporary file is
// ".<name>.tmp.<pid>.XXXXXX"; one left by a writer that was killed is
// removed by the next write of the same file (see atomic_file.cpp).
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace ft::io {

class AtomicFile {
 public:
  // Creates the temporary file; throws FT_ERR_IO naming the folder when it
  // does not exist or is not writable.
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary file unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  FILE* file() noexcept { return file_; }
  const std::string& path() const noexcept { return path_; }
  void write(std::string_view bytes);
  // Flushes, syncs and renames into place; throws FT_ERR_IO on any failure.
  void commit();

 private:
  std::string path_, temp_;
  FILE* file_ = nullptr;
  bool committed_ = false;
};

// Writes `bytes` to `path` atomically.
void write_file_atomically(const std::string& path, std::string_view bytes);
// Lower-case extension of a path including the dot (".png"), or "".
std::string extension_of(const std::string& path);
// Whole file as bytes; throws FT_ERR_IO with the path and the reason.
std::string read_file(const std::string& path);

}  // namespace ft::io
