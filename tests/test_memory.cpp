// core/memory.h: after keep_freed_memory(), large blocks that are freed and allocated again
// come back without fresh pages — what keeps lavapipe's per-draw reallocations from
// faulting in thousands of pages a frame.
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "core/memory.h"

#if defined(__SANITIZE_ADDRESS__)
#define LW_REPLACED_MALLOC 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LW_REPLACED_MALLOC 1
#endif
#endif

namespace lw {
namespace {

long minor_faults_of_this_thread() {
    rusage usage{};
    getrusage(RUSAGE_THREAD, &usage);
    return usage.ru_minflt;
}

// Three blocks held at once, every page written, then all freed: 48 MiB of free heap top,
// more than glibc's default trim threshold grows to (twice the largest freed mmap block), so
// with the defaults every round gets fresh pages from the kernel (49,024 faults in four
// rounds, measured), however many rounds came before.
void use_three_blocks(size_t bytes) {
    volatile char* blocks[3];
    for (volatile char*& p : blocks) {
        p = static_cast<volatile char*>(std::malloc(bytes));
        ASSERT_NE(p, nullptr);
        for (size_t i = 0; i < bytes; i += 4096) p[i] = char(i);
    }
    for (volatile char* p : blocks) std::free(const_cast<char*>(p));
}

TEST(Memory, FreedLargeBlocksAreReusedWithoutPageFaults) {
#if defined(LW_REPLACED_MALLOC) || !defined(__GLIBC__)
    GTEST_SKIP() << "not glibc's malloc (a sanitizer's allocator replaces it, or another C library)";
#else
    ASSERT_TRUE(keep_freed_memory());
    constexpr size_t kBytes = 16u << 20;  // 4,096 pages a block
    use_three_blocks(kBytes);             // the first use may fault its pages in
    const long before = minor_faults_of_this_thread();
    for (int i = 0; i < 4; ++i) use_three_blocks(kBytes);
    const long faults = minor_faults_of_this_thread() - before;
    std::printf("  page faults for 4 more rounds of three 16 MiB blocks: %ld (12,288 pages a round)\n", faults);
    EXPECT_LT(faults, 100);
#endif
}

}  // namespace
}  // namespace lw
