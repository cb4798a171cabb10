// engine/vector/fill.h — filled regions of vector-art layers, as triangles.
//
// Input:  closed polylines (a layer's closed strokes), in any units; they may nest, touch
//         and cross.
// Output: a triangle list covering the even-odd interior: a point is filled when a ray from
//         it crosses the outlines an odd number of times (SVG's fill-rule="evenodd"), so
//         an inner loop cuts a hole.
//
// A constrained Delaunay triangulation of all outline edges (CGAL, with intersecting
// constraints split at their crossings) is walked from the outside; a face is inside when
// reaching it crossed an odd number of constrained edges. CGAL lives in fill.cpp alone.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace lw {

[[nodiscard]] std::vector<glm::vec2> triangulate_even_odd(const std::vector<std::vector<glm::vec2>>& loops);

}  // namespace lw
