// engine/core/parallel.h — a plain parallel-for over index ranges.
//
// Splits [0, count) into at most `threads` contiguous chunks (default: the hardware's
// cores) and runs `body(begin, end, chunk)` on each, the first on the calling thread.
// Results stay deterministic when each chunk writes only its own slots (or its own
// output, concatenated in chunk order afterwards). Small counts run inline.
#pragma once

#include <cstddef>
#include <functional>

namespace lw {

size_t worker_count();  // std::thread::hardware_concurrency, at least 1

// Returns the number of chunks used (≤ max_chunks, 0: ≤ worker_count()).
size_t parallel_for(size_t count, size_t min_chunk,
                    const std::function<void(size_t begin, size_t end, size_t chunk)>& body, size_t max_chunks = 0);

}  // namespace lw
