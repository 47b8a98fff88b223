// parallel_for_chunks: a shared chunk counter and std::threads made per call. Calls are
// coarse (a face's parts, a smoothing pass over millions of vertices), so making threads
// per call costs microseconds against milliseconds of work and needs no pool to shut down.
#include "base/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
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
  if (n == 0) return;
  chunk = std::max<std::size_t>(chunk, 1);
  const std::size_t chunks = (n + chunk - 1) / chunk;
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), chunks);
  if (workers <= 1) {
    for (std::size_t b = 0; b < n; b += chunk) fn(b, std::min(n, b + chunk));
    return;
  }
  std::atomic<std::size_t> next{0};
  // One slot per chunk so that the exception reported is the first by chunk order,
  // whatever the timing.
  std::vector<std::exception_ptr> errors(chunks);
  // Chunks after the first failed one are skipped; chunks before it still run, so the
  // exception rethrown is the one a serial loop would have met first.
  std::atomic<std::size_t> first_failed{chunks};
  auto work = [&] {
    for (;;) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks || c > first_failed.load(std::memory_order_relaxed)) return;
      const std::size_t b = c * chunk;
      try {
        fn(b, std::min(n, b + chunk));
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
  for (std::size_t i = 1; i < workers; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace sm
