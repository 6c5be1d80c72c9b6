// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace layermod::test {

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs the layermod binary with `args` (no shell), waits, captures its output.
CliResult RunCli(const std::vector<std::string>& args);

// A running layermod process whose output is read through a pipe.
class CliProcess {
 public:
  explicit CliProcess(const std::vector<std::string>& args);
  ~CliProcess();
  CliProcess(const CliProcess&) = delete;
  CliProcess& operator=(const CliProcess&) = delete;

  // Reads output until it contains `text` or the process closes its output. True if found.
  bool WaitForOutput(const std::string& text);
  void Signal(int signal_number);
  CliResult Wait();  // reads the rest of the output and reaps the process

 private:
  int pid_ = -1;
  int fd_ = -1;
  std::string output_;
};

// Splits a command line on spaces; "double quotes" keep spaces.
std::vector<std::string> SplitArgs(const std::string& line);

}  // namespace layermod::test
