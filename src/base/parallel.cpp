// parallel_for_chunks: a shared chunk counter and std::threads made per call. Calls are
// coarse (a face's parts, a smoothing pass over millions of vertices), so making threads
// per call costs microseconds against milliseconds of work and needs no pool to shut down.
#include "base/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace sm {

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

void parallel_for_chunks(int threads, std::size_t n, std::size_t chunk,
                         const std::function<void(std::size_t, std::size_t)>& fn) {
  parallel_for_chunks(threads, n, chunk, fn, nullptr);
}

void parallel_for_chunks(int threads, std::size_t n, std::size_t chunk,
                         const std::function<void(std::size_t, std::size_t)>& fn,
                         const std::function<void(std::size_t)>& progress, double poll_seconds) {
  if (n == 0) return;
  chunk = std::max<std::size_t>(chunk, 1);
  const std::size_t chunks = (n + chunk - 1) / chunk;
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), chunks);
  if (workers <= 1) {
    std::size_t done = 0;
    for (std::size_t b = 0; b < n; b += chunk) {
      fn(b, std::min(n, b + chunk));
      if (progress) progress(++done);
    }
    return;
  }
  std::atomic<std::size_t> next{0};
  // One slot per chunk so that the exception reported is the first by chunk order,
  // whatever the timing.
  std::vector<std::exception_ptr> errors(chunks);
  // Chunks after the first failed one are skipped; chunks before it still run, so the
  // exception rethrown is the one a serial loop would have met first.
  std::atomic<std::size_t> first_failed{chunks};
  // Progress: chunks finished, and workers stopped (the caller waits on `stopped_cv`
  // between reports instead of joining at once).
  std::atomic<std::size_t> finished{0};
  std::mutex stopped_mutex;
  std::condition_variable stopped_cv;
  std::size_t stopped = 0;
  std::size_t reported = 0;   // the caller's last report
  const auto report = [&](std::size_t done) {
    if (progress && done > reported) progress(reported = done);
  };
  auto work = [&](bool caller) {
    for (;;) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks || c > first_failed.load(std::memory_order_relaxed)) return;
      const std::size_t b = c * chunk;
      try {
        fn(b, std::min(n, b + chunk));
        const std::size_t done = finished.fetch_add(1, std::memory_order_relaxed) + 1;
        if (caller) report(done);
      } catch (...) {
        errors[c] = std::current_exception();
        std::size_t seen = first_failed.load(std::memory_order_relaxed);
        while (c < seen && !first_failed.compare_exchange_weak(seen, c, std::memory_order_relaxed)) {
        }
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (std::size_t i = 1; i < workers; ++i)
    pool.emplace_back([&] {
      work(false);
      if (!progress) return;
      const std::lock_guard<std::mutex> lock(stopped_mutex);
      ++stopped;
      stopped_cv.notify_one();
    });
  work(true);
  if (progress) {
    const auto poll = std::chrono::duration<double>(std::max(poll_seconds, 1e-3));
    std::unique_lock<std::mutex> lock(stopped_mutex);
    while (stopped + 1 < workers) {
      stopped_cv.wait_for(lock, poll);
      lock.unlock();
      report(finished.load(std::memory_order_relaxed));
      lock.lock();
    }
  }
  for (auto& t : pool) t.join();
  report(finished.load(std::memory_order_relaxed));
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace sm
