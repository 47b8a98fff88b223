// Giving freed heap pages back to the system between the stages of a large run.
#pragma once

namespace sm {

/// Returns the free pages of the heap to the system (glibc's malloc_trim; nothing
/// elsewhere). Large arrays freed in the middle of the heap otherwise stay resident
/// beside everything allocated after them: once the import has freed its arrays,
/// glibc's mmap threshold has risen to 32 MiB, so the mesher's arrays come from the heap
/// too and each freed one adds to the peak of the stages after it (docs/kernel.md,
/// "Memory"). The output never depends on it.
void release_free_memory();

}  // namespace sm
