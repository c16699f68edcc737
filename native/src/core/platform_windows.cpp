// SPDX-License-Identifier: GPL-3.0-or-later
// platform.hpp on Windows (built with mingw-w64; see docs/windows.md).
#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
// windows.h first: shellapi.h needs its types.
#include <fcntl.h>
#include <io.h>
#include <malloc.h>
#include <shellapi.h>
#include <sys/stat.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/platform.hpp"
#include "core/platform_memory.hpp"

namespace ft::platform {
namespace {

std::wstring wide(std::string_view utf8) {
  if (utf8.empty()) return {};
  const int n = MultiByteToWideChar(CP_UTF8, 0, utf8.data(), int(utf8.size()), nullptr, 0);
  std::wstring w(size_t(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, utf8.data(), int(utf8.size()), w.data(), n);
  return w;
}

std::string narrow(std::wstring_view w) {
  if (w.empty()) return {};
  const int n = WideCharToMultiByte(CP_UTF8, 0, w.data(), int(w.size()), nullptr, 0, nullptr, nullptr);
  std::string s(size_t(n), '\0');
  WideCharToMultiByte(CP_UTF8, 0, w.data(), int(w.size()), s.data(), n, nullptr, nullptr);
  return s;
}

std::string windows_error(DWORD code) {
  wchar_t* text = nullptr;
  FormatMessageW(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
                 nullptr, code, 0, reinterpret_cast<wchar_t*>(&text), 0, nullptr);
  std::string s = text ? narrow(text) : std::string();
  LocalFree(text);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ' || s.back() == '.')) s.pop_back();
  return s.empty() ? "Windows error " + std::to_string(code) : s;
}

// One argument of a command line as the C runtime's parser reads it back
// (backslashes are literal except before a double quote).
std::wstring quoted(const std::wstring& a) {
  if (!a.empty() && a.find_first_of(L" \t\n\v\"") == std::wstring::npos) return a;
  std::wstring out = L"\"";
  size_t backslashes = 0;
  for (wchar_t c : a) {
    if (c == L'\\') {
      ++backslashes;
      continue;
    }
    out.append(c == L'"' ? backslashes * 2 + 1 : backslashes, L'\\');
    backslashes = 0;
    out.push_back(c);
  }
  out.append(backslashes * 2, L'\\');
  out.push_back(L'"');
  return out;
}

HANDLE inheritable_copy(HANDLE h) {
  HANDLE copy = nullptr;
  if (h == nullptr || h == INVALID_HANDLE_VALUE) return nullptr;
  DuplicateHandle(GetCurrentProcess(), h, GetCurrentProcess(), &copy, 0, TRUE, DUPLICATE_SAME_ACCESS);
  return copy;
}

}  // namespace

std::filesystem::path fs_path(std::string_view utf8) { return std::filesystem::path(wide(utf8)); }
std::string utf8_of(const std::filesystem::path& p) { return narrow(p.native()); }

FILE* open_file(const std::string& utf8_path, const char* mode) {
  return _wfopen(wide(utf8_path).c_str(), wide(mode).c_str());
}

FILE* create_temp_file(std::string& path_template) {
  // What mkstemp does: six random letters, O_EXCL so an existing file is
  // never opened, a few tries.
  static std::atomic<uint64_t> counter{0};
  const size_t at = path_template.size() - 6;
  const char* letters = "abcdefghijklmnopqrstuvwxyz0123456789";
  for (int attempt = 0; attempt < 100; ++attempt) {
    uint64_t x = (uint64_t(GetTickCount64()) << 20) ^ (uint64_t(GetCurrentProcessId()) << 40) ^
                 (counter.fetch_add(1) * 0x9E3779B97F4A7C15ull);
    for (size_t i = 0; i < 6; ++i, x /= 36) path_template[at + i] = letters[x % 36];
    const int fd = _wopen(wide(path_template).c_str(), _O_CREAT | _O_EXCL | _O_WRONLY | _O_BINARY,
                          _S_IREAD | _S_IWRITE);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      return nullptr;
    }
    FILE* f = _fdopen(fd, "wb");
    if (!f) {
      const int err = errno;
      _close(fd);
      _wunlink(wide(path_template).c_str());
      errno = err;
    }
    return f;
  }
  errno = EEXIST;
  return nullptr;
}

bool sync_file(FILE* f) {
  if (std::fflush(f) != 0) return false;
  if (FlushFileBuffers(reinterpret_cast<HANDLE>(_get_osfhandle(_fileno(f))))) return true;
  errno = EIO;
  return false;
}

std::string replace_file(const std::string& from, const std::string& to) {
  if (MoveFileExW(wide(from).c_str(), wide(to).c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH))
    return {};
  return windows_error(GetLastError());
}

int64_t file_size(FILE* f) noexcept {
  LARGE_INTEGER n{};
  return GetFileSizeEx(reinterpret_cast<HANDLE>(_get_osfhandle(_fileno(f))), &n) ? int64_t(n.QuadPart) : -1;
}

std::string append_synced(const std::string& utf8_path, std::string_view bytes) {
  const int fd = _wopen(wide(utf8_path).c_str(), _O_WRONLY | _O_CREAT | _O_APPEND | _O_BINARY, _S_IREAD | _S_IWRITE);
  if (fd < 0) return std::strerror(errno);
  // One write of a short line: _O_APPEND puts it whole at the end; _commit
  // is FlushFileBuffers.
  const bool ok = _write(fd, bytes.data(), unsigned(bytes.size())) == int(bytes.size()) && _commit(fd) == 0;
  const int err = errno;
  _close(fd);
  return ok ? std::string() : std::string(std::strerror(err));
}

void remove_file(const std::string& utf8_path) noexcept { _wunlink(wide(utf8_path).c_str()); }

long process_id() noexcept { return long(GetCurrentProcessId()); }

bool process_gone(long pid) noexcept {
  HANDLE h = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, DWORD(pid));
  if (!h) return GetLastError() == ERROR_INVALID_PARAMETER;  // no such process
  DWORD code = 0;
  const bool exited = GetExitCodeProcess(h, &code) && code != STILL_ACTIVE;
  CloseHandle(h);
  return exited;
}

ProcessResult run_process(const std::vector<std::string>& args, FILE* stdout_to, const std::string& cwd) {
  ProcessResult r;
  std::wstring command;
  for (const auto& a : args) command += (command.empty() ? L"" : L" ") + quoted(wide(a));
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  HANDLE err_read = nullptr, err_write = nullptr;
  if (!CreatePipe(&err_read, &err_write, &inherit, 0)) {
    r.start_error = windows_error(GetLastError());
    return r;
  }
  SetHandleInformation(err_read, HANDLE_FLAG_INHERIT, 0);
  if (stdout_to) std::fflush(stdout_to);
  HANDLE out = inheritable_copy(stdout_to ? reinterpret_cast<HANDLE>(_get_osfhandle(_fileno(stdout_to)))
                                          : GetStdHandle(STD_OUTPUT_HANDLE));
  HANDLE in = CreateFileW(L"NUL", GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit, OPEN_EXISTING, 0,
                          nullptr);
  STARTUPINFOW si{};
  si.cb = sizeof si;
  si.dwFlags = STARTF_USESTDHANDLES;
  si.hStdInput = in;
  si.hStdOutput = out;
  si.hStdError = err_write;
  PROCESS_INFORMATION pi{};
  const std::wstring folder = wide(cwd);
  const BOOL ok = CreateProcessW(nullptr, command.data(), nullptr, nullptr, TRUE, CREATE_NO_WINDOW, nullptr,
                                 folder.empty() ? nullptr : folder.c_str(), &si, &pi);
  const DWORD start_error = ok ? 0 : GetLastError();
  CloseHandle(err_write);
  if (out) CloseHandle(out);
  if (in != INVALID_HANDLE_VALUE) CloseHandle(in);
  if (!ok) {
    CloseHandle(err_read);
    r.start_error = windows_error(start_error);
    return r;
  }
  r.started = true;
  char buf[4096];
  DWORD n = 0;
  while (ReadFile(err_read, buf, sizeof buf, &n, nullptr) && n > 0) r.errors.append(buf, n);
  CloseHandle(err_read);
  WaitForSingleObject(pi.hProcess, INFINITE);
  DWORD code = 0;
  GetExitCodeProcess(pi.hProcess, &code);
  r.exit_code = int(code);
  CloseHandle(pi.hThread);
  CloseHandle(pi.hProcess);
  return r;
}

void* aligned_allocate(size_t align, size_t bytes) noexcept { return _aligned_malloc(bytes, align); }
void aligned_free(void* p) noexcept { _aligned_free(p); }
void advise_huge_pages(void*, size_t) noexcept {}

uint64_t available_memory() noexcept {
  MEMORYSTATUSEX m{};
  m.dwLength = sizeof m;
  return GlobalMemoryStatusEx(&m) ? uint64_t(m.ullAvailPhys) : std::numeric_limits<uint64_t>::max();
}

std::vector<std::string> utf8_arguments(int argc, char** argv) {
  int n = 0;
  wchar_t** w = CommandLineToArgvW(GetCommandLineW(), &n);
  if (!w || n != argc) {
    if (w) LocalFree(w);
    return {argv, argv + argc};
  }
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i) out.push_back(narrow(w[i]));
  LocalFree(w);
  return out;
}

void* open_library(const std::string& name, std::string& error) {
  HMODULE h = LoadLibraryW(wide(name).c_str());
  if (!h) error = "LoadLibrary failed with error " + std::to_string(GetLastError());
  return reinterpret_cast<void*>(h);
}

void* library_symbol(void* library, const char* symbol) noexcept {
  return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(library), symbol));
}

}  // namespace ft::platform
#endif
