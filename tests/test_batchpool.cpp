// BatchPool: every item of every batch runs exactly once, whoever runs it, with or without the
// helper, and with two callers at once (the second runs alone).
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "pm/core/BatchPool.h"

namespace {

//! Runs \e batches batches of sizes 0..40 and checks that every item ran once.
void runBatches(pm::core::BatchPool &pool, int batches)
{
  std::vector<std::atomic<int>> hits(40);
  for (int b = 0; b < batches; ++b) {
    const std::size_t n = static_cast<std::size_t>(b % 41);
    for (auto &h : hits)
      h.store(0);
    pool.run(n, [&](std::size_t i) { hits[i].fetch_add(1); });
    for (std::size_t i = 0; i < hits.size(); ++i)
      ASSERT_EQ(hits[i].load(), i < n ? 1 : 0) << "batch " << b << " of " << n << " items, item " << i;
  }
}

} // namespace

TEST(BatchPool, EveryItemOnceWithTheHelper)
{
  pm::core::BatchPool pool(true);
  ASSERT_TRUE(pool.hasHelper());
  runBatches(pool, 20000);
}

TEST(BatchPool, EveryItemOnceWithoutTheHelper)
{
  pm::core::BatchPool pool(false);
  EXPECT_FALSE(pool.hasHelper());
  runBatches(pool, 2000);
}

TEST(BatchPool, TwoCallersAtOnce)
{
  pm::core::BatchPool pool(true);
  std::thread other([&] { runBatches(pool, 5000); });
  runBatches(pool, 5000);
  other.join();
}

TEST(BatchPool, TheHelperDoesShareTheWork)
{
  // Items slow enough for the helper to wake: some must run on another thread.
  pm::core::BatchPool pool(true);
  const std::thread::id me = std::this_thread::get_id();
  std::atomic<int> elsewhere{0};
  for (int b = 0; b < 200 && elsewhere.load() == 0; ++b)
    pool.run(16, [&](std::size_t) {
      const auto t0 = std::chrono::steady_clock::now();
      while (std::chrono::steady_clock::now() - t0 < std::chrono::microseconds(50)) {
      }
      if (std::this_thread::get_id() != me)
        elsewhere.fetch_add(1);
    });
  EXPECT_GT(elsewhere.load(), 0);
}
