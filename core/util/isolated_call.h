// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace layermod {

// Runs `work` in a forked child process and returns the bytes it produced. Third-party readers
// fed a hostile file can crash or hang; in a child they cannot take the CLI or the studio (and
// its unsaved work) down with them.
// - an Error thrown by `work` is rethrown here with its type (Error, IoError, FormatError) and
//   message; std::bad_alloc and other exceptions become FormatError;
// - a child that dies by a signal, or is still running after `timeout` (it is then killed),
//   gives FormatError: "<failure_prefix> crashed (signal N) ..." / "... took longer than ...".
// The child runs only `work` and leaves with _exit: no destructors, no atexit handlers.
std::string RunIsolated(const std::function<std::string()>& work, std::chrono::seconds timeout,
                        const std::string& failure_prefix);

}  // namespace layermod
