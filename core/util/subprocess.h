// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace layermod {

struct ProcessResult {
  std::string out;         // everything the process wrote to stdout (binary)
  std::string err;         // and to stderr
  int exit_code = -1;      // when it exited
  int signal_number = 0;   // when a signal ended it (0: it exited)
  bool timed_out = false;  // it was still running at the deadline and was killed
};

// Runs `argv` (argv[0] an executable path; no shell) as a new process and collects its output.
// A fresh exec, not a bare fork: the child inherits no locks or threads of the caller. Throws
// Error when the process cannot be started.
ProcessResult RunProcess(const std::vector<std::string>& argv, std::chrono::seconds timeout);

}  // namespace layermod
