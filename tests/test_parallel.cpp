// The thread pool's team: its members meet at each barrier, every write made before it
// seen by every member after it, however often the same barrier is passed.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <vector>

#include "core/parallel.h"

namespace lw {
namespace {

TEST(ParallelTeam, MembersSeeEachOthersWritesAfterEveryBarrier) {
    constexpr int kPhases = 2000;  // enough rounds for a member to lap a slow one if it could
    std::vector<std::atomic<int>> slot(worker_count());
    std::atomic<int> mismatches{0};
    const size_t members = parallel_team(worker_count(), [&](size_t member, size_t count, TeamSync& sync) {
        for (int phase = 1; phase <= kPhases; ++phase) {
            slot[member].store(phase, std::memory_order_relaxed);
            sync.arrive_and_wait();
            for (size_t other = 0; other < count; ++other)
                if (slot[other].load(std::memory_order_relaxed) != phase) mismatches.fetch_add(1);
            sync.arrive_and_wait();  // nobody writes the next phase before all have read this one
        }
    });
    EXPECT_GE(members, 1u);
    EXPECT_EQ(mismatches.load(), 0);
    for (size_t m = 0; m < members; ++m) EXPECT_EQ(slot[m].load(), kPhases);
}

// A member that arrives long after the others (past their spinning) still wakes them.
TEST(ParallelTeam, ASlowMemberWakesTheSleepers) {
    std::atomic<int> passed{0};
    parallel_team(worker_count(), [&](size_t member, size_t, TeamSync& sync) {
        if (member == 0) {
            const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(30);
            while (std::chrono::steady_clock::now() < until) {
            }
        }
        sync.arrive_and_wait();
        passed.fetch_add(1);
    });
    EXPECT_GE(passed.load(), 1);
}

// A member that throws does not leave the others waiting for it, and they do not run on
// past a barrier it never reached: the team ends and the caller gets the exception. Many
// rounds, since the throw may land before, during or after the others' wait begins.
TEST(ParallelTeam, AMemberThatThrowsEndsTheTeam) {
    for (int round = 0; round < 500; ++round) {
        std::atomic<int> past_barrier{0};
        EXPECT_THROW(parallel_team(worker_count(), [&](size_t member, size_t members, TeamSync& sync) {
                         if (member + 1 == members) throw std::runtime_error("member failed");
                         sync.arrive_and_wait();
                         past_barrier.fetch_add(1);
                     }),
                     std::runtime_error);
        ASSERT_EQ(past_barrier.load(), 0) << "round " << round;
    }
}

}  // namespace
}  // namespace lw
