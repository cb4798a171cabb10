// engine/geometry/face_pairs.h — pairs of faces that may meet, from a spatial search.
//
// Input:  a `WeldedMesh` (any pose).
// Output: each pair of its faces whose bounding boxes overlap and that share no vertex
//         (neighbours touch by construction), handed to a callback as (a, b) with a < b, in
//         the search's own order. Faces with no area (corners on one line) and faces with a
//         corner that is not finite are left out: they cross nothing.
//
// CGAL's `box_self_intersection_d` is the search (the spatial index the line-family issue
// gives to a library); `triangles_meet` is its exact triangle–triangle predicate. Users:
// intersection lines (lines/intersections.h) and the self-intersection test of closed
// surfaces (geometry/closed_surfaces.h).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "geometry/welded_mesh.h"

namespace lw {

// With `neighbours`, pairs that share a vertex or an edge are visited too.
void for_each_box_pair(const WeldedMesh& mesh, const std::function<void(uint32_t, uint32_t)>& visit,
                       bool neighbours = false);

// Do faces a and b have any point in common besides the corners they share (touching
// counts)? Exact predicates. Faces that share a vertex v meet beyond it when an edge of one
// meets the other's edge opposite v, or an edge of each at v run the same way; faces that
// share an edge meet beyond it when they are coplanar on the same side of it.
[[nodiscard]] bool triangles_meet(const WeldedMesh& mesh, uint32_t a, uint32_t b);

// The segment faces a and b have in common, when they meet along one (not at a point, not
// in a coplanar overlap): its ends, constructed in doubles.
[[nodiscard]] std::optional<std::array<glm::dvec3, 2>> common_segment(const WeldedMesh& mesh, uint32_t a, uint32_t b);

}  // namespace lw
