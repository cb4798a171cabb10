#include "core/memory.h"

// A C library header first: glibc defines __GLIBC__ in it, and the #if below needs it (without
// one the settings were silently skipped).
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lw {

bool keep_freed_memory() {
#if defined(__GLIBC__)
    // Blocks below this size come from the heaps, never from their own mmap: 32 MiB is the
    // largest value glibc accepts on 64-bit systems (its default grows from 128 KiB as blocks
    // are freed, but the heap top is still trimmed back to the kernel).
    constexpr int kMmapThreshold = 32 << 20;
    // Free memory at the top of a heap is returned to the kernel only past this much.
    constexpr int kTrimThreshold = 512 << 20;
    const bool mmap_ok = mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1;
    const bool trim_ok = mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
    return mmap_ok && trim_ok;
#else
    return false;
#endif
}

}  // namespace lw
