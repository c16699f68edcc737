// SPDX-License-Identifier: GPL-3.0-or-later
// Small pieces the subcommands share: name <-> enum tables for CLI11 options,
// and a stopwatch.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <map>
#include <string>

namespace ft::cli {

// A CLI11 transformer that maps names to enum values; --help lists them.
inline CLI::Transformer choice(const std::map<std::string, int>& names) {
  return CLI::Transformer(names, CLI::ignore_case);
}

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace ft::cli
