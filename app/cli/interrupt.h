// SPDX-License-Identifier: MIT
#pragma once

#include "util/job.h"

namespace layermod::cli {

// While alive, the first SIGINT/SIGTERM cancels `token` (the job stops cleanly and writes
// nothing); a second one ends the process at once.
class InterruptScope {
 public:
  explicit InterruptScope(CancelToken& token);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

}  // namespace layermod::cli
