// SPDX-License-Identifier: GPL-3.0-or-later
// Every call into GDAL runs inside a GdalSession: GDAL's drivers are
// registered once, and GDAL's errors go to a handler of ours for the time of
// the call (pushed on this thread only, so a host application's own GDAL
// handler is left alone). Nothing is printed to stderr behind the caller's
// back; the first error GDAL reports becomes the message of our exception.
#pragma once

#include <memory>
#include <string>

#include "core/error.hpp"
#include "io/gdal_api.hpp"

namespace ft::io {

class GdalSession {
 public:
  GdalSession();
  ~GdalSession();
  GdalSession(const GdalSession&) = delete;
  GdalSession& operator=(const GdalSession&) = delete;

  // Throws `status` with "<what>: <GDAL's message>" (or just `what` when GDAL
  // said nothing).
  [[noreturn]] void fail(ft_status status, const std::string& what) const;
  // The first failure GDAL reported in this session ("" if none).
  const std::string& first_error() const noexcept { return first_error_; }
  // Called by the handler for each failure GDAL reports on this thread.
  void note_error(const char* message);

 private:
  std::string first_error_;
  GdalSession* outer_ = nullptr;  // a session this one runs inside, restored at the end
};

// An open GDALDatasetH, closed by GDALClose.
struct GdalCloser {
  void operator()(void* ds) const;
};
using GdalDataset = std::unique_ptr<void, GdalCloser>;

// A unique in-memory file name ("/vsimem/fracterra_<n><extension>"),
// unlinked when this goes out of scope.
class GdalMemFile {
 public:
  explicit GdalMemFile(const std::string& extension);
  ~GdalMemFile();
  GdalMemFile(const GdalMemFile&) = delete;
  GdalMemFile& operator=(const GdalMemFile&) = delete;
  const std::string& name() const noexcept { return name_; }

 private:
  std::string name_;
};

}  // namespace ft::io
