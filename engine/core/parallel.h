// engine/core/parallel.h — a plain parallel-for over index ranges.
//
// Splits [0, count) into at most `max_chunks` contiguous chunks (default: the hardware's
// cores) and runs `body(begin, end, chunk)` on each: on the calling thread and a pool of
// worker_count() − 1 threads started once per process (again in a fork()ed child). The
// chunks depend on the count alone, so results stay deterministic when each chunk writes
// only its own slots (or its own output, concatenated in chunk order afterwards). Small
// counts, nested calls and calls while another thread uses the pool run inline, in order.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace lw {

size_t worker_count();  // std::thread::hardware_concurrency, at least 1, read once per process

// Returns the number of chunks used (≤ max_chunks, 0: ≤ worker_count()).
size_t parallel_for(size_t count, size_t min_chunk,
                    const std::function<void(size_t begin, size_t end, size_t chunk)>& body, size_t max_chunks = 0);

// Where the members of a team wait for each other: `arrive_and_wait()`. The members spin
// first, as the pool's workers do: a team's phases are tens of microseconds apart, and
// std::barrier sleeps in the kernel at once, which costs ~20 us a wait in a virtual machine
// (measured: 3 of the 20 us lost per barrier on a 0.65 ms two-thread extraction).
class TeamSync {
public:
    explicit TeamSync(size_t members) : members_(uint32_t(members)) {}
    void arrive_and_wait();
    // A member left by an exception: the others stop at their next (or current) wait, which
    // would otherwise last for ever, and parallel_team throws the member's exception once
    // they have stopped. Members never run on past a barrier the failed member missed.
    void abandon();

private:
    const uint32_t members_;
    std::atomic<uint32_t> arrived_{0};
    std::atomic<uint32_t> phase_{0};  // passed barriers
    std::atomic<bool> abandoned_{false};
};

// A team of threads that run `body(member, members, sync)` at the same time, one member
// each, so that they may wait for each other at `sync` (each member as often as the
// others): one fork and join for work in phases (a pass, then a pass over its results).
// `members` is at most `size` and the cores; 1 (the caller alone, `sync` then a no-op
// wait) when the pool is in use. Returns `members`.
size_t parallel_team(size_t size, const std::function<void(size_t member, size_t members, TeamSync& sync)>& body);

}  // namespace lw
