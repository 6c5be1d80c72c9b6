// SPDX-License-Identifier: MIT
#include "util/job.h"

#include <gtest/gtest.h>

namespace layermod {
namespace {

TEST(JobControlTest, DefaultIsNullSafe) {
  JobControl job;
  EXPECT_FALSE(job.IsCancelled());
  EXPECT_NO_THROW(job.ThrowIfCancelled());
  EXPECT_NO_THROW(job.Report(1, 2, "stage"));
}

TEST(JobControlTest, ForwardsProgressAndCancellation) {
  CancelToken token;
  std::size_t last_done = 0;
  std::string last_stage;
  JobControl job(
      [&](std::size_t done, std::size_t, std::string_view stage) {
        last_done = done;
        last_stage = stage;
      },
      &token);
  job.Report(7, 10, "render");
  EXPECT_EQ(last_done, 7u);
  EXPECT_EQ(last_stage, "render");
  token.Cancel();
  EXPECT_TRUE(job.IsCancelled());
  EXPECT_THROW(job.ThrowIfCancelled(), Cancelled);
}

}  // namespace
}  // namespace layermod
