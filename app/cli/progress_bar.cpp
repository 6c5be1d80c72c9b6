// SPDX-License-Identifier: MIT
#include "cli/progress_bar.h"

#include <unistd.h>

#include <cstdio>

namespace layermod::cli {
namespace {

constexpr int kBarWidth = 30;

std::string FormatSeconds(double seconds) {
  char text[32];
  if (seconds < 60) {
    std::snprintf(text, sizeof(text), "%.0fs", seconds);
  } else {
    std::snprintf(text, sizeof(text), "%dm%02ds", static_cast<int>(seconds) / 60,
                  static_cast<int>(seconds) % 60);
  }
  return text;
}

}  // namespace

ProgressBar::ProgressBar()
    : terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void ProgressBar::Update(std::size_t done, std::size_t total, std::string_view stage) {
  if (total == 0) return;
  const auto now = std::chrono::steady_clock::now();
  const double fraction = static_cast<double>(done) / static_cast<double>(total);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  if (!terminal_) {
    const int decile = static_cast<int>(fraction * 10.0);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %3.0f%% (%zu/%zu), ETA %s\n", std::string(stage).c_str(),
                 fraction * 100.0, done, total, FormatSeconds(eta).c_str());
    return;
  }
  if (done < total && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const int filled = static_cast<int>(fraction * kBarWidth);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kBarWidth, ' ');
  std::fprintf(stderr, "\r%s [%s] %3.0f%% %zu/%zu ETA %s   ", std::string(stage).c_str(),
               bar.c_str(), fraction * 100.0, done, total, FormatSeconds(eta).c_str());
  drawn_ = true;
}

void ProgressBar::Finish() {
  if (drawn_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace layermod::cli
