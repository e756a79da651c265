// Jobs on every core (compiler/common/Parallel.h): each index runs once, and a failure is
// rethrown only once every job has stopped, the lowest index's first.

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "compiler/common/Parallel.h"

namespace mxc {
namespace {

TEST(Parallel, EachIndexRunsOnce) {
  for (size_t count : {size_t{0}, size_t{1}, size_t{3}, size_t{1000}}) {
    std::vector<std::atomic<int>> runs(count);
    runOnEveryCore(count, [&](size_t i) { ++runs[i]; });
    for (size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << i << " of " << count;
  }
  EXPECT_GE(coreCount(), 1u);
}

TEST(Parallel, TheLowestFailureIsRethrownAfterEveryJobStopped) {
  std::atomic<int> finished{0};
  try {
    runOnEveryCore(64, [&](size_t i) {
      if (i == 40 || i == 17) throw std::runtime_error("job " + std::to_string(i));
      ++finished;
    });
    FAIL() << "no failure rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 17");
  }
  EXPECT_EQ(finished.load(), 62);
}

}  // namespace
}  // namespace mxc
