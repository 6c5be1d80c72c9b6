// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace layermod::test {

// The message of the `E` that `call` throws, or "" when it throws none.
template <typename E, typename F>
std::string ThrownMessage(F&& call) {
  try {
    call();
  } catch (const E& error) {
    return error.what();
  }
  return "";
}

}  // namespace layermod::test
