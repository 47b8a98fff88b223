// Deterministic fork-join parallelism for the kernel (`-nt`): work is cut into
// chunks whose boundaries depend only on the item count, never on the thread count, so a
// result written per item or per chunk is the same bytes with 1 or 16 threads.
#pragma once

#include <cstddef>
#include <functional>

namespace sm {

/// The number of threads to use for `requested` (General.NumThreads / -nt): values <= 0
/// mean the hardware concurrency (at least 1).
int resolve_thread_count(int requested);

/// Calls fn(begin, end) for consecutive chunks [begin, end) of [0, n) of `chunk` items
/// (the last one shorter), on up to `threads` threads (the calling thread included), and
/// returns when every chunk is done. Chunks are handed out in order from a shared counter;
/// fn must not depend on which thread runs it. An exception thrown by fn is rethrown here
/// (the first one, by chunk order) after every thread has stopped.
void parallel_for_chunks(int threads, std::size_t n, std::size_t chunk,
                         const std::function<void(std::size_t begin, std::size_t end)>& fn);

/// parallel_for_chunks that also tells the calling thread how far it is: progress(done)
/// with the number of chunks finished so far (non-decreasing), called on the calling
/// thread only (never by a worker), after each chunk it ran itself and about every
/// `poll_seconds` while it waits for the others; last with the final count. fn reports
/// nothing itself, so a Progress sink needs no locking. progress must not throw.
void parallel_for_chunks(int threads, std::size_t n, std::size_t chunk,
                         const std::function<void(std::size_t begin, std::size_t end)>& fn,
                         const std::function<void(std::size_t chunks_done)>& progress, double poll_seconds = 0.1);

}  // namespace sm
