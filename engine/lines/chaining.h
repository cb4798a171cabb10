// engine/lines/chaining.h — segments to brush paths.
//
// Input:  `LineSegment`s in any order (the GPU appends them with atomics).
// Output: `LinePath`s: per line type, segments whose endpoints share a chaining key (the
//         mesh edge a contour crosses, or the mesh vertex a crease passes) are linked into
//         polylines. A key shared by exactly two endpoints joins them; a key seen once, or
//         more than twice (a non-manifold junction), ends the path there. Paths whose ends
//         meet are closed loops and keep no duplicate end vertex. Each path vertex keeps its
//         face and barycentric position, which the coherence stage needs.
//
// Deterministic: the result depends only on the multiset of segments, not on their order
// (segments are sorted first), so GPU and CPU extraction chain identically.
#pragma once

#include <vector>

#include "lines/line_types.h"

namespace lw {

[[nodiscard]] std::vector<LinePath> chain_segments(const std::vector<LineSegment>& segments);

// Sorts segments into a canonical order (type, face, key0, key1): GPU output made comparable.
void sort_segments(std::vector<LineSegment>& segments);

}  // namespace lw
