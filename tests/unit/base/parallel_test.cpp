#include "base/parallel.h"

#include <doctest/doctest.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
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
