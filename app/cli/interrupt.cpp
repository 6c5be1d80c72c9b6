// SPDX-License-Identifier: MIT
#include "cli/interrupt.h"

#include <csignal>

namespace layermod::cli {
namespace {

CancelToken* g_token = nullptr;

extern "C" void OnInterrupt(int signal_number) {
  if (g_token != nullptr) g_token->Cancel();
  std::signal(signal_number, SIG_DFL);  // a second signal ends the process
}

}  // namespace

InterruptScope::InterruptScope(CancelToken& token) {
  g_token = &token;
  std::signal(SIGINT, OnInterrupt);
  std::signal(SIGTERM, OnInterrupt);
}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_token = nullptr;
}

}  // namespace layermod::cli
