// SPDX-License-Identifier: GPL-3.0-or-later
// The fracterra CLI (FT_CLI_PATH) run as a user runs it: its exit code,
// stdout and stderr, for the suites that test a subcommand end to end.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "io/atomic_file.hpp"

namespace ft::test {

struct CliRun {
  int code;
  std::string out, err;
};

inline CliRun run_cli(const std::string& args) {
  namespace fs = std::filesystem;
  const fs::path err = fs::temp_directory_path() / ("ft_cli_err_" + std::to_string(::getpid()));
  const std::string cmd = std::string(FT_CLI_PATH) + " " + args + " 2>" + err.string();
  CliRun r{};
  FILE* p = ::popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = io::read_file(err.string());
  fs::remove(err);
  return r;
}

}  // namespace ft::test
