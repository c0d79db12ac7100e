#include "pm/core/BatchPool.h"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace pm::core {

namespace {
//! How long the helper looks for the next batch before it sleeps: longer than the gap between
//! two generations (selection, crossover, sorting), far shorter than the gap between frames.
constexpr std::chrono::microseconds kSpin(200);
constexpr std::uint64_t kIndexMask = 0xffffffffu;

//! A short wait: the CPU's spin hint (a yield is a system call, about a microsecond in a VM).
inline void relax()
{
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

//! Waits until \e done(): spinning first (most waits here are a few microseconds), then yielding.
template <class Done> void waitUntil(Done done)
{
  for (int k = 0; !done(); ++k)
    if (k < 256)
      relax();
    else
      std::this_thread::yield();
}
} // namespace

BatchPool::BatchPool(bool helper)
{
  if (helper)
    m_thread = std::thread([this] { helperLoop(); });
}

BatchPool::~BatchPool()
{
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stop = true;
  }
  m_wake.notify_all();
  if (m_thread.joinable())
    m_thread.join();
}

BatchPool &BatchPool::shared()
{
  static BatchPool pool;
  return pool;
}

bool BatchPool::take(std::uint32_t gen, std::size_t n, std::size_t &item)
{
  std::uint64_t v = m_next.load(std::memory_order_acquire);
  for (;;) {
    if ((v >> 32) != gen || (v & kIndexMask) >= n)
      return false;
    if (m_next.compare_exchange_weak(v, v + 1, std::memory_order_acq_rel, std::memory_order_acquire)) {
      item = static_cast<std::size_t>(v & kIndexMask);
      return true;
    }
  }
}

void BatchPool::runErased(std::size_t n, Fn fn, void *ctx)
{
  std::unique_lock<std::mutex> busy(m_busy, std::try_to_lock);
  if (n < 2 || n > kIndexMask || !hasHelper() || !busy.owns_lock()) {
    for (std::size_t i = 0; i < n; ++i)
      fn(ctx, i);
    return;
  }
  std::uint32_t gen;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    gen = m_posted.load(std::memory_order_relaxed) + 1;
    m_fn = fn;
    m_ctx = ctx;
    m_n = n;
    m_done.store(0, std::memory_order_relaxed);
    m_next.store(static_cast<std::uint64_t>(gen) << 32, std::memory_order_release);
    m_posted.store(gen, std::memory_order_release);
  }
  m_wake.notify_one();
  std::size_t item, mine = 0;
  while (take(gen, n, item)) {
    fn(ctx, item);
    ++mine;
  }
  m_done.fetch_add(mine, std::memory_order_acq_rel);
  // Every item is taken; wait only for those the helper is still running.
  waitUntil([&] { return m_done.load(std::memory_order_acquire) >= n; });
}

void BatchPool::helperLoop()
{
  std::uint32_t seen = 0;
  for (;;) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; m_posted.load(std::memory_order_acquire) == seen; ++k) {
      relax();
      if ((k & 63) == 63 && std::chrono::steady_clock::now() - t0 >= kSpin)
        break;
    }
    Fn fn;
    void *ctx;
    std::size_t n;
    std::uint32_t gen;
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_wake.wait(lock, [&] { return m_stop || m_posted.load(std::memory_order_relaxed) != seen; });
      if (m_stop)
        return;
      // The job as one snapshot: if it is already over, take() refuses its items.
      gen = m_posted.load(std::memory_order_relaxed);
      fn = m_fn;
      ctx = m_ctx;
      n = m_n;
    }
    seen = gen;
    std::size_t item;
    while (take(gen, n, item)) {
      fn(ctx, item);
      m_done.fetch_add(1, std::memory_order_acq_rel);
    }
  }
}

} // namespace pm::core
