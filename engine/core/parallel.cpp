#include "core/parallel.h"

#include <pthread.h>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace lw {

// Read once: std::thread::hardware_concurrency() reads /sys/devices/system/cpu/online with
// three system calls each time (5.8 us a call on the 2-core VM), and every parallel_for and
// team asked for it, which was most of a team's fork on a 0.1 ms pass (docs/BENCHMARKS.md,
// "Two threads against one").
size_t worker_count() {
    static const size_t count = std::max<size_t>(1, std::thread::hardware_concurrency());
    return count;
}

namespace {

// A hint to the CPU that this thread spins (it frees the core's other hyperthread).
inline void pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
}

// Waits while `busy()`: first spinning on the CPU (the next phase of a pass comes within
// microseconds), then yielding it, for 5 ms in all, and only then returns for the caller
// to sleep: a thread woken by the kernel takes tens of microseconds (more in a virtual
// machine), as long as a whole pass over a small mesh, and a renderer's next frame
// comes within milliseconds.
template <class Busy>
void spin_while(Busy&& busy) {
    for (int i = 0; i < 1000; ++i) {
        if (!busy()) return;
        pause();
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(5);
    while (busy() && std::chrono::steady_clock::now() < until) std::this_thread::yield();
}

// worker_count() − 1 threads started on first use and kept: a per-view pass of a
// millisecond cannot repay starting threads per call (~0.1 ms, docs/BENCHMARKS.md). The
// caller works too; chunks are taken from a shared counter, so any chunk count runs on any
// number of threads and each chunk still writes only its own output.
class Pool {
public:
    explicit Pool(size_t workers) {
        for (size_t i = 0; i < workers; ++i) std::thread([this] { work(); }).detach();  // they live as long as the process
    }

    // Runs `body` on chunks [0, chunks) of [0, count); false when another parallel_for is
    // using the pool (a nested call from a chunk, or another thread): the caller then runs
    // every chunk itself.
    // `one_each`: no thread runs two chunks (a team, whose members wait for each other).
    bool run(size_t count, size_t chunks, const std::function<void(size_t, size_t, size_t)>& body, bool one_each = false) {
        std::unique_lock busy(busy_, std::try_to_lock);
        if (!busy.owns_lock()) return false;
        std::vector<std::exception_ptr> errors(chunks);
        Job job{.body = &body, .count = count, .chunks = chunks, .errors = &errors, .one_each = one_each};
        {
            std::lock_guard lock(mutex_);
            current_ = &job;
            generation_.fetch_add(1);
        }
        // Sleeping workers need a system call to wake, spinning ones do not: in a virtual
        // machine the call (an interrupt to a halted CPU) costs tens of microseconds.
        if (sleepers_.load() > 0) wake_.notify_all();
        job.finished.fetch_add(take_chunks(job));
        // The job lives on this stack: wait until every chunk ran and no worker holds it.
        // Workers join and leave under the mutex, so the last check is made holding it.
        const auto over = [&] { return job.finished.load() == chunks && job.users.load() == 0; };
        spin_while([&] { return !over(); });
        {
            std::unique_lock lock(mutex_);
            finished_.wait(lock, over);
            current_ = nullptr;
        }
        for (auto& e : errors)
            if (e) std::rethrow_exception(e);
        return true;
    }

private:
    struct Job {
        const std::function<void(size_t, size_t, size_t)>* body = nullptr;
        size_t count = 0, chunks = 0;
        std::vector<std::exception_ptr>* errors = nullptr;
        bool one_each = false;
        std::atomic<size_t> next{0};      // the next chunk to take
        std::atomic<size_t> finished{0};  // chunks run
        std::atomic<size_t> users{0};     // workers inside (changed under the mutex)
    };

    // Chunks until none is left; returns how many this thread ran.
    static size_t take_chunks(Job& job) {
        size_t ran = 0;
        for (size_t c = job.next.fetch_add(1); c < job.chunks; c = job.next.fetch_add(1)) {
            try {
                (*job.body)(job.count * c / job.chunks, job.count * (c + 1) / job.chunks, c);
            } catch (...) {
                (*job.errors)[c] = std::current_exception();
            }
            ++ran;
            if (job.one_each) break;
        }
        return ran;
    }

    void work() {
        uint64_t seen = 0;
        for (;;) {
            Job* job = nullptr;
            spin_while([&] { return generation_.load() == seen; });
            {
                std::unique_lock lock(mutex_);
                sleepers_.fetch_add(1);
                wake_.wait(lock, [&] { return generation_.load() != seen; });
                sleepers_.fetch_sub(1);
                seen = generation_.load();
                job = current_;
                if (!job) continue;  // it ended before this thread woke
                job->users.fetch_add(1);
            }
            job->finished.fetch_add(take_chunks(*job));
            std::lock_guard lock(mutex_);
            job->users.fetch_sub(1);
            finished_.notify_all();  // no system call unless the caller sleeps
        }
    }

    std::mutex busy_;   // held by the one parallel_for using the pool
    std::mutex mutex_;  // guards current_ and the start and end of each worker's part in a job
    std::condition_variable wake_, finished_;
    Job* current_ = nullptr;
    std::atomic<uint64_t> generation_{0};
    std::atomic<int> sleepers_{0};  // workers waiting on wake_ (changed under the mutex)
};

// The process's pool. A fork()ed child (a Python multiprocessing worker, say) has none of
// its parent's threads: it leaves the parent's pool untouched (its mutexes may be held) and
// starts its own on first use.
std::atomic<Pool*> g_pool{nullptr};
std::mutex g_pool_start;

void forget_pool_after_fork() { g_pool.store(nullptr); }

Pool* pool() {
    if (Pool* p = g_pool.load()) return p;
    std::lock_guard lock(g_pool_start);
    if (Pool* p = g_pool.load()) return p;
    static const bool registered = [] { return pthread_atfork(nullptr, nullptr, forget_pool_after_fork) == 0; }();
    (void)registered;
    // Never deleted: its threads run until the process ends, and a static's destructor could
    // run while one of them still waits on its condition variable.
    auto* p = new Pool(worker_count() - 1);
    g_pool.store(p);
    return p;
}

}  // namespace

size_t parallel_for(size_t count, size_t min_chunk,
                    const std::function<void(size_t begin, size_t end, size_t chunk)>& body, size_t max_chunks) {
    const size_t chunks =
        std::clamp<size_t>(count / std::max<size_t>(min_chunk, 1), 1, max_chunks > 0 ? max_chunks : worker_count());
    if (chunks == 1 || worker_count() == 1 || !pool()->run(count, chunks, body)) {
        for (size_t c = 0; c < chunks; ++c) body(count * c / chunks, count * (c + 1) / chunks, c);
    }
    return chunks;
}

namespace {

// Thrown out of a wait once a member has left the team by an exception: the others stop
// where they wait instead of running on into a phase over data the failed member never
// wrote. parallel_team catches it; the caller gets the failed member's exception.
struct TeamAbandoned {};

}  // namespace

void TeamSync::arrive_and_wait() {
    // The phase before the flag: an abandon after this load changes the phase (so the wait
    // below ends and sees the flag), one before it is seen here.
    const uint32_t phase = phase_.load(std::memory_order_acquire);
    if (abandoned_.load(std::memory_order_acquire)) throw TeamAbandoned{};
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == members_) {  // the last: open it
        arrived_.store(0, std::memory_order_relaxed);
        phase_.fetch_add(1, std::memory_order_release);
        phase_.notify_all();  // a system call only when a member sleeps
        return;
    }
    const auto closed = [&] { return phase_.load(std::memory_order_acquire) == phase; };
    spin_while(closed);
    while (closed()) phase_.wait(phase, std::memory_order_acquire);
    if (abandoned_.load(std::memory_order_acquire)) throw TeamAbandoned{};
}

void TeamSync::abandon() {
    abandoned_.store(true, std::memory_order_release);
    phase_.fetch_add(1, std::memory_order_release);  // opens the barrier members wait at now
    phase_.notify_all();
}

size_t parallel_team(size_t size, const std::function<void(size_t member, size_t members, TeamSync& sync)>& body) {
    const size_t members = std::clamp<size_t>(size, 1, worker_count());
    if (members > 1) {
        TeamSync sync(members);
        const std::function<void(size_t, size_t, size_t)> member = [&](size_t, size_t, size_t m) {
            try {
                body(m, members, sync);
            } catch (const TeamAbandoned&) {
                // Stopped at a barrier by another member's exception, which the caller gets.
            } catch (...) {
                sync.abandon();
                throw;  // the pool rethrows it in the caller once every member is done
            }
        };
        if (pool()->run(members, members, member, true)) return members;
    }
    TeamSync alone(1);
    body(0, 1, alone);
    return 1;
}

}  // namespace lw
