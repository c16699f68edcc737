// SPDX-License-Identifier: GPL-3.0-or-later
// The few operating-system calls fracterra makes, behind one interface (as
// sqlite keeps os_unix.c and os_win.c apart): files by UTF-8 path, atomic
// replacement, flushing to disk, temporary files, process ids, spawning a
// helper program, aligned memory and its huge-page hint, available memory.
// Everything else in the library is portable C++ (the memory calls are in
// platform_memory.hpp, which the buffers include everywhere without
// <filesystem>). platform_posix.cpp and
// platform_windows.cpp implement it; each compiles to nothing on the other
// system.
//
// Paths are UTF-8 std::strings everywhere in fracterra. On Windows the C
// runtime's narrow calls (fopen, std::filesystem::path(std::string)) read
// them in the ANSI code page, which mangles "Dossier été"; so every path
// that reaches the system goes through fs_path() or open_file(), which
// convert UTF-8 to UTF-16 there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ft::platform {

// A UTF-8 path as a std::filesystem::path, and back.
std::filesystem::path fs_path(std::string_view utf8);
std::string utf8_of(const std::filesystem::path& p);

// Path arithmetic on UTF-8 paths, by way of fs_path() and utf8_of(): never
// std::filesystem::path(std::string) or .string(), the ANSI code page on
// Windows. `name` (a file or folder name, or a relative path) in folder `dir`.
inline std::string join_path(std::string_view dir, std::string_view name) {
  return utf8_of(fs_path(dir) / fs_path(name));
}
// The last part of a path: "b.pov" of "a/b.pov".
inline std::string file_name_of(std::string_view path) { return utf8_of(fs_path(path).filename()); }
// A file beside `path` named after its stem: ("a/b.pov", "_height.png") gives "a/b_height.png".
inline std::string sibling_path(std::string_view path, std::string_view suffix) {
  const std::filesystem::path p = fs_path(path);
  return utf8_of(p.parent_path() / fs_path(utf8_of(p.stem()) + std::string(suffix)));
}

// fopen of a UTF-8 path; nullptr and errno set on failure.
FILE* open_file(const std::string& utf8_path, const char* mode);
// Creates and opens ("wb") a new file from `path_template`, whose last six
// characters are "XXXXXX" and are replaced by the name actually made; the
// file gets the usual permissions (0666 less the umask on POSIX). nullptr and
// errno set on failure.
FILE* create_temp_file(std::string& path_template);
// Flushes the C buffer and the operating system's cache to the disk (fsync;
// FlushFileBuffers on Windows). False on failure, errno set.
bool sync_file(FILE* f);
// Renames `from` over `to`, replacing it in one step (rename; MoveFileExW
// with MOVEFILE_REPLACE_EXISTING on Windows). "" on success, else the reason.
std::string replace_file(const std::string& from, const std::string& to);
// Size in bytes of an open file as the system sees it (writes by a child
// process included); -1 on failure.
int64_t file_size(FILE* f) noexcept;
// Appends `bytes` to a file (made if missing) in one write and syncs it to
// the disk, for journals whose lines must survive a kill. "" on success,
// else the reason.
std::string append_synced(const std::string& utf8_path, std::string_view bytes);
// Removes a file, ignoring any failure (a temporary file being cleaned up).
void remove_file(const std::string& utf8_path) noexcept;

long process_id() noexcept;
// True only when no process of that id runs on this machine now.
bool process_gone(long pid) noexcept;

// Runs `argv` (argv[0] looked up on PATH), stdin empty, stdout into
// `stdout_to` (or inherited when nullptr), in folder `cwd` ("" = this one).
struct ProcessResult {
  bool started = false;
  std::string start_error;  // why it could not start
  int exit_code = -1;       // when it exited normally
  bool signalled = false;   // killed by a signal (POSIX)
  std::string errors;       // what it wrote to stderr
};
ProcessResult run_process(const std::vector<std::string>& argv, FILE* stdout_to, const std::string& cwd);

// The program's arguments as UTF-8 (Windows hands main() the ANSI code page;
// they are taken from the wide command line instead).
std::vector<std::string> utf8_arguments(int argc, char** argv);

// A shared library opened at run time (dlopen; LoadLibraryW on Windows), for
// optional libraries the system may have (GDAL): `name` is a path or a name
// the system's loader searches for. nullptr on failure, with the loader's
// reason in `error`. Never closed: what it hands out stays valid.
void* open_library(const std::string& name, std::string& error);
// The address of `symbol` in a library open_library() opened (nullptr if absent).
void* library_symbol(void* library, const char* symbol) noexcept;

}  // namespace ft::platform
