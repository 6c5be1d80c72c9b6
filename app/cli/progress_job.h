// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string_view>

#include "cli/interrupt.h"
#include "cli/progress_bar.h"
#include "util/job.h"

namespace layermod::cli {

// Runs `work(job)` with its progress drawn on stderr and Ctrl-C cancelling the job; the bar's
// line is ended however the work ends. Returns what the work returns.
template <typename Work>
auto RunWithProgress(Work&& work) {
  CancelToken cancel;
  InterruptScope interrupt(cancel);
  ProgressBar bar;
  struct FinishOnExit {
    ProgressBar& bar;
    ~FinishOnExit() { bar.Finish(); }
  } finish{bar};
  const JobControl job([&bar](std::size_t done, std::size_t total,
                              std::string_view stage) { bar.Update(done, total, stage); },
                       &cancel);
  return work(job);
}

}  // namespace layermod::cli
