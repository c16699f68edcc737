// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/gdal_session.hpp"

#include <atomic>
#include <mutex>

#include "core/error.hpp"

namespace ft::io {
namespace {
// The session of this thread's current call; GDAL's per-thread handler stack
// has no slot we could read back from a plain handler, so keep our own.
thread_local GdalSession* current = nullptr;

void CPL_STDCALL handler(CPLErr error_class, CPLErrorNum /*code*/, const char* message) {
  // Warnings and debug messages are dropped: they are not failures, and the
  // promise is that nothing is printed. (CE_Fatal still aborts inside GDAL
  // after the handler returns; GDAL raises it only when it cannot allocate
  // its own small structures.)
  if (error_class >= CE_Failure && current != nullptr) current->note_error(message);
}
}  // namespace

GdalSession::GdalSession() {
  static std::once_flag registered;
  std::call_once(registered, [] { gdal().GDALAllRegister(); });
  gdal().CPLPushErrorHandler(handler);
  // No ".aux.xml" beside files we only read, nor beside files we write.
  gdal().CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");
  outer_ = current;
  current = this;
}

GdalSession::~GdalSession() {
  current = outer_;
  if (outer_ == nullptr) gdal().CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", nullptr);
  gdal().CPLPopErrorHandler();
}

void GdalSession::note_error(const char* message) {
  if (first_error_.empty() && message) first_error_ = message;
}

void GdalSession::fail(ft_status status, const std::string& what) const {
  ft::fail(status, first_error_.empty() ? what : what + ": " + first_error_);
}

void GdalCloser::operator()(void* ds) const { gdal().GDALClose(ds); }

GdalMemFile::GdalMemFile(const std::string& extension) {
  static std::atomic<unsigned long> serial{0};
  name_ = "/vsimem/fracterra_" + std::to_string(serial++) + extension;
}

GdalMemFile::~GdalMemFile() { gdal().VSIUnlink(name_.c_str()); }

}  // namespace ft::io
