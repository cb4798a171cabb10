#include "core/parallel.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace lw {

size_t worker_count() { return std::max<size_t>(1, std::thread::hardware_concurrency()); }

size_t parallel_for(size_t count, size_t min_chunk,
                    const std::function<void(size_t begin, size_t end, size_t chunk)>& body, size_t max_chunks) {
    const size_t chunks =
        std::clamp<size_t>(count / std::max<size_t>(min_chunk, 1), 1, max_chunks > 0 ? max_chunks : worker_count());
    if (chunks == 1) {
        body(0, count, 0);
        return 1;
    }
    std::vector<std::thread> threads;
    std::vector<std::exception_ptr> errors(chunks);
    auto run = [&](size_t c) {
        try {
            body(count * c / chunks, count * (c + 1) / chunks, c);
        } catch (...) {
            errors[c] = std::current_exception();
        }
    };
    for (size_t c = 1; c < chunks; ++c) threads.emplace_back(run, c);
    run(0);
    for (auto& t : threads) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
    return chunks;
}

}  // namespace lw
