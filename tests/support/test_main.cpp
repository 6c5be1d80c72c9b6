// SPDX-License-Identifier: MIT
// Test main: seeds every random generator the tests may use, so runs are reproducible.
#include <gtest/gtest.h>

#include <cstdlib>
#include <opencv2/core.hpp>

#include "util/log.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  std::srand(12345);
  cv::theRNG().state = 12345;
  // Keep test output readable: the core's warnings are asserted on, not printed.
  layermod::SetLogSink([](layermod::LogLevel, std::string_view) {});
  return RUN_ALL_TESTS();
}
