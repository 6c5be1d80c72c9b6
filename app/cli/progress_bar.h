// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace layermod::cli {

// Draws job progress on stderr: a redrawn bar with ETA on a terminal, a line per 10 % otherwise.
class ProgressBar {
 public:
  ProgressBar();
  void Update(std::size_t done, std::size_t total, std::string_view stage);
  void Finish();  // ends the bar's line

 private:
  bool terminal_;
  bool drawn_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace layermod::cli
