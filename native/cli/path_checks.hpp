// SPDX-License-Identifier: GPL-3.0-or-later
// CLI11's ExistingFile and ExistingDirectory, with the path read as UTF-8:
// CLI11 2.1 hands the string to std::filesystem as is, which on Windows reads
// it in the ANSI code page, so "Dossier été\terrain.png" would not exist.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "core/platform.hpp"

namespace ft::cli {

inline const CLI::Validator existing_file(
    [](std::string& path) {
      std::error_code ec;
      const auto status = std::filesystem::status(platform::fs_path(path), ec);
      if (!std::filesystem::exists(status)) return "File does not exist: " + path;
      if (std::filesystem::is_directory(status)) return "File is actually a directory: " + path;
      return std::string();
    },
    "FILE");

inline const CLI::Validator existing_directory(
    [](std::string& path) {
      std::error_code ec;
      const auto status = std::filesystem::status(platform::fs_path(path), ec);
      if (!std::filesystem::exists(status)) return "Directory does not exist: " + path;
      if (!std::filesystem::is_directory(status)) return "Directory is actually a file: " + path;
      return std::string();
    },
    "DIR");

}  // namespace ft::cli
