// engine/lines/intersections.h — intersection lines: where surfaces cut through each other.
//
// Input:  a `LineMesh` (any pose).
// Output: `LineSegment`s of type Intersection: for each pair of faces that share no vertex
//         and cross (two primitives, two models, or a mesh and itself), the segment the two
//         triangles have in common. The segment belongs to the pair's lower-numbered face
//         (its barycentric coordinates are in that face). An endpoint lies where the curve
//         crosses an edge of one of the two faces into the next pair; endpoints at the same
//         point share a chaining key, so the segments of one crossing curve chain into one
//         path (a closed loop where the curve is closed, e.g. two spheres).
//
// Not view-dependent: found once per pose (LineMesh::generation) and kept in an
// `IntersectionCache`; a still model costs nothing per frame, an animated one a search per
// pose. CGAL does the geometry: `box_self_intersection_d` finds the pairs of faces whose
// bounding boxes overlap (the spatial index), `intersection(Triangle_3, Triangle_3)` the
// common segment (exact predicates, so touching, parallel and coplanar pairs are told
// apart reliably). Pairs that only touch — at a point, or along an edge of one of them (a
// seam of two parts that are not welded) — and coplanar overlaps give no line.
//
// This is the reference and the only implementation: there is no GPU pass. The work is the
// spatial search, which the brief gives to a library; both extraction paths (host and
// device, render/frame_renderer.cpp) append the same cached segments.
#pragma once

#include <cstdint>
#include <vector>

#include "lines/line_mesh.h"
#include "lines/line_types.h"

namespace lw {

struct IntersectionCache {
    uint64_t generation = 0;  // LineMesh::generation of `segments` (0: none)
    std::vector<LineSegment> segments;
    size_t candidate_pairs = 0;  // pairs of non-degenerate faces sharing no vertex whose boxes overlap (benchmarks)
};

// All intersection segments of `mesh`, in a deterministic order (by face pair).
[[nodiscard]] std::vector<LineSegment> find_intersection_lines(const LineMesh& mesh, size_t* candidate_pairs = nullptr);

// The segments of `mesh`'s pose: from the cache when it holds that pose, else found again.
const std::vector<LineSegment>& intersection_lines(const LineMesh& mesh, IntersectionCache& cache);

}  // namespace lw
