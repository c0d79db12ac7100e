#pragma once
/*!
  \file BatchPool.h
  Runs the items of a small batch (one RM-GA generation: ~20 fitness evaluations of a few
  microseconds) on the calling thread and one helper thread, for a machine that may be busy.

  Unlike an OpenMP loop, the caller never waits for the helper to *start*: both take items from
  one atomic counter, and the caller waits only for items the helper has already taken. When the
  helper is not scheduled (the cores are busy with other work), the caller simply does the whole
  batch itself, instead of waiting a scheduler time slice at a barrier, which made a frame of
  300 evaluations take 47 ms instead of 1 on a loaded machine. The helper spins briefly for the
  next batch, then sleeps. No allocation per batch; the results cannot depend on who ran an item.

  One batch at a time: a second caller that finds the pool busy runs its batch alone.
*/
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>

namespace pm::core {

/*!
  Runs the items of a small batch on the calling thread and one helper thread (see BatchPool.h).
  The fitness's batch evaluations and setImages() run on BatchPool::shared().

  \code
  std::vector<double> out(20);
  pm::core::BatchPool::shared().run(out.size(), [&](std::size_t i) { out[i] = std::sqrt(static_cast<double>(i)); });
  // every out[i] is set here, whichever thread computed it
  \endcode
*/
class BatchPool
{
public:
  //! \e helper: start the helper thread (false, or a single core: every batch on the caller).
  explicit BatchPool(bool helper = std::thread::hardware_concurrency() > 1);
  //! Stops and joins the helper thread.
  ~BatchPool();
  BatchPool(const BatchPool &) = delete;
  BatchPool &operator=(const BatchPool &) = delete;

  /*!
    Calls f(i) for every i in [0, n) once; \e f must not throw. Returns when all are done.
    \e f may run on two threads at once; the caller alone runs it when n < 2, without a helper, or
    while another caller's batch is running.
  */
  template <class F> void run(std::size_t n, F &&f)
  {
    auto call = [](void *ctx, std::size_t i) { (*static_cast<F *>(ctx))(i); };
    runErased(n, call, &f);
  }

  //! True when the helper thread runs (else every batch runs on the caller).
  bool hasHelper() const { return m_thread.joinable(); }
  //! The process's pool (one helper thread, started on first use).
  static BatchPool &shared();

private:
  using Fn = void (*)(void *, std::size_t);
  void runErased(std::size_t n, Fn fn, void *ctx);
  void helperLoop();
  //! Takes the next item of batch \e gen; false when the batch is exhausted or over.
  bool take(std::uint32_t gen, std::size_t n, std::size_t &item);

  std::mutex m_busy;                    //!< held by the caller of the running batch
  std::mutex m_mutex;                   //!< guards the job and the sleep
  std::condition_variable m_wake;
  std::atomic<std::uint64_t> m_next{0}; //!< (batch number << 32) | next item
  std::atomic<std::size_t> m_done{0};   //!< items of the current batch completed
  std::atomic<std::uint32_t> m_posted{0};
  Fn m_fn = nullptr;
  void *m_ctx = nullptr;
  std::size_t m_n = 0;
  bool m_stop = false;
  std::thread m_thread;
};

} // namespace pm::core
