// ParallelFor (util/parallel_for.hpp), the loop the exporters, the matcher and the engines run their items on.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace {

TEST(ParallelFor, RunsEveryItemOnceAndReportsProgressInOrder) {
  for (int threads : {1, 2, 4}) {
    for (size_t count : {size_t{0}, size_t{1}, size_t{100}}) {
      SCOPED_TRACE(std::to_string(threads) + " threads, " + std::to_string(count) + " items");
      std::vector<std::atomic<int>> runs(count);
      std::vector<size_t> reported;
      ParallelFor(
          count, threads, [&](size_t i) { ++runs[i]; },
          [&](const std::string& stage, size_t done, size_t total) {
            EXPECT_EQ(stage, "work");
            EXPECT_EQ(total, count);
            reported.push_back(done);
          },
          "work");
      for (size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << i;
      if (count == 0) continue;
      ASSERT_EQ(reported.size(), count + 1);  // 0, then one report per finished item
      for (size_t k = 0; k < reported.size(); ++k) EXPECT_EQ(reported[k], k);
    }
  }
}

TEST(ParallelFor, RethrowsTheErrorOfTheFirstFailingItemWhateverTheThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    SCOPED_TRACE(threads);
    try {
      ParallelFor(60, threads, [](size_t i) {
        if (i == 7 || i == 40 || i == 41) throw std::runtime_error("item " + std::to_string(i));
      });
      FAIL() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "item 7");
    }
  }
}

}  // namespace
}  // namespace sfm_pruning
