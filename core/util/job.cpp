// SPDX-License-Identifier: MIT
#include "util/job.h"

#include <mutex>

namespace layermod {

void JobControl::Report(std::size_t done, std::size_t total, std::string_view stage) const {
  if (!progress_) return;
  static std::mutex report_mutex;
  std::lock_guard lock(report_mutex);
  progress_(done, total, stage);
}

}  // namespace layermod
