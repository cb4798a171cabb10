// core/memory.h: after keep_freed_memory(), a large block that is freed and allocated again
// comes back without fresh pages — what keeps lavapipe's per-draw reallocations from
// faulting in thousands of pages a frame.
#include <sys/resource.h>

#include <cstdlib>

#include <gtest/gtest.h>

#include "core/memory.h"

namespace lw {
namespace {

long minor_faults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// Writes every page of a fresh `bytes` block, then frees it.
void touch_and_free(size_t bytes) {
    auto* p = static_cast<volatile char*>(std::malloc(bytes));
    ASSERT_NE(p, nullptr);
    for (size_t i = 0; i < bytes; i += 4096) p[i] = char(i);
    std::free(const_cast<char*>(p));
}

TEST(Memory, FreedLargeBlocksAreReusedWithoutPageFaults) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "the sanitizers' allocator replaces glibc's malloc";
#else
    ASSERT_TRUE(keep_freed_memory());
    constexpr size_t kBytes = 24u << 20;  // 6,144 pages; glibc's default would mmap it anew
    touch_and_free(kBytes);               // the first use may fault its pages in
    const long before = minor_faults();
    for (int i = 0; i < 4; ++i) touch_and_free(kBytes);
    const long faults = minor_faults() - before;
    std::printf("  page faults for 4 more uses of a 24 MiB block: %ld (of %zu pages each)\n", faults, kBytes / 4096);
    EXPECT_LT(faults, 100);
#endif
}

}  // namespace
}  // namespace lw
