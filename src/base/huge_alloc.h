// Allocator for large working arrays read at random: 2 MiB aligned and, on Linux,
// advised to use transparent huge pages.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sm {

/// An array jumping across tens of MiB (a triangulation's triangles, a hash table of the
/// coast's vertices) with 4 KiB pages takes a TLB miss on nearly every jump besides the
/// cache miss, and a fault at the first touch of each page; arrays of 4 MiB and more are
/// given whole 2 MiB pages. Small arrays take the ordinary path.
template <class T>
struct HugeAlloc {
  using value_type = T;
  HugeAlloc() = default;
  template <class U>
  HugeAlloc(const HugeAlloc<U>&) {}
  static constexpr std::size_t kHuge = std::size_t{2} << 20;
  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T) < 2 * kHuge ? n * sizeof(T) : (n * sizeof(T) + kHuge - 1) / kHuge * kHuge;
    void* p = bytes < 2 * kHuge ? std::malloc(bytes ? bytes : 1) : std::aligned_alloc(kHuge, bytes);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes >= 2 * kHuge) madvise(p, bytes, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) { std::free(p); }
  template <class U>
  friend bool operator==(const HugeAlloc&, const HugeAlloc<U>&) { return true; }
};

}  // namespace sm
