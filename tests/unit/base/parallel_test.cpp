#include "base/parallel.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace sm;

TEST_CASE("parallel_for_chunks covers every item once, whatever the thread count") {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<int> hits(10007, 0);
    parallel_for_chunks(threads, hits.size(), 100, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ++hits[i];
    });
    CHECK(std::accumulate(hits.begin(), hits.end(), 0) == 10007);
    CHECK(*std::min_element(hits.begin(), hits.end()) == 1);
  }
}

TEST_CASE("parallel_for_chunks: chunk boundaries depend on the item count only") {
  auto bounds = [](int threads) {
    std::vector<std::size_t> starts(11, 99);
    parallel_for_chunks(threads, 1001, 100, [&](std::size_t b, std::size_t e) { starts[b / 100] = e - b; });
    return starts;
  };
  CHECK(bounds(1) == bounds(4));
  CHECK(bounds(4).back() == 1);
}

TEST_CASE("parallel_for_chunks rethrows the first exception by chunk order") {
  std::atomic<int> ran{0};
  auto f = [&](std::size_t b, std::size_t) {
    ++ran;
    if (b == 300) throw std::runtime_error("chunk 3");
    if (b == 700) throw std::runtime_error("chunk 7");
  };
  for (int threads : {1, 4}) {
    CHECK_THROWS_WITH(parallel_for_chunks(threads, 1000, 100, f), "chunk 3");
  }
  parallel_for_chunks(2, 0, 10, f);  // nothing to do: no call
  CHECK(resolve_thread_count(3) == 3);
  CHECK(resolve_thread_count(0) >= 1);
}

TEST_CASE("parallel_for_chunks with progress: reports on the calling thread, non-decreasing, ending at the count") {
  for (int threads : {1, 2, 4}) {
    CAPTURE(threads);
    std::vector<int> hits(64, 0);
    std::vector<std::size_t> reports;
    const std::thread::id caller = std::this_thread::get_id();
    bool other_thread = false;
    parallel_for_chunks(
        threads, hits.size(), 1,
        [&](std::size_t b, std::size_t e) {
          // Slow chunks, so the caller also reports while it waits for the others.
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
          for (std::size_t i = b; i < e; ++i) ++hits[i];
        },
        [&](std::size_t done) {
          other_thread = other_thread || std::this_thread::get_id() != caller;
          reports.push_back(done);
        },
        0.001);
    CHECK(std::accumulate(hits.begin(), hits.end(), 0) == 64);
    CHECK_FALSE(other_thread);
    REQUIRE(!reports.empty());
    CHECK(std::is_sorted(reports.begin(), reports.end()));
    CHECK(std::adjacent_find(reports.begin(), reports.end()) == reports.end());   // each count once
    CHECK(reports.back() == 64);
    if (threads == 1) CHECK(reports.size() == 64);
  }
}
