// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string_view>

#include "util/error.h"

namespace layermod {

// Set from any thread (GUI button, SIGINT handler); polled by long jobs.
class CancelToken {
 public:
  void Cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
  bool IsCancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
};

// Progress callback: `done` of `total` work units finished in `stage`. May be called from worker
// threads, but never concurrently (JobControl serialises calls).
using ProgressFn = std::function<void(std::size_t done, std::size_t total, std::string_view stage)>;

// What a long job receives: an optional progress sink and an optional cancel token. Null-safe.
class JobControl {
 public:
  JobControl() = default;
  JobControl(ProgressFn progress, const CancelToken* cancel)
      : progress_(std::move(progress)), cancel_(cancel) {}

  bool IsCancelled() const noexcept { return cancel_ != nullptr && cancel_->IsCancelled(); }
  void ThrowIfCancelled() const {
    if (IsCancelled()) throw Cancelled();
  }
  void Report(std::size_t done, std::size_t total, std::string_view stage) const;

 private:
  ProgressFn progress_;
  const CancelToken* cancel_ = nullptr;
};

}  // namespace layermod
