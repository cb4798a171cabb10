// engine/pattern/lloyd.h — seed distributions by Lloyd's method (Barla et al. 2006, §3.2).
//
// Input:  the number of seeds, the target (a path length, or a region polygon), the iteration
//         count and a seeded generator.
// Output: seed positions: arc lengths along the path, or points inside the region.
//
// "Lloyd's method […] starts with a random distribution of seeds. Then, at each step, a Voronoi
// diagram of the seeds is computed, and each seed is moved to the center of its Voronoi region.
// It converges to a centroidal Voronoi tessellation, close to regular."
//  - 1D: the Voronoi cell of a seed is the interval between the midpoints to its neighbours
//    (clipped to [0, L] on an open path, wrapped on a closed one); the seed moves to its centre.
//    1D Lloyd converges slowly, so it runs on after `iterations` until it has converged.
//  - 2D: the region is sampled on a regular grid (about 32 samples per seed); each sample goes
//    to its nearest seed (a bucket grid of the seeds keeps that local), and each seed moves to
//    the mean of its samples — the discrete centroid of its Voronoi cell clipped to the region.
//    A seed with no samples stays.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "core/random.h"

namespace lw {

// Shoelace area (absolute) and even–odd point-in-polygon test of a closed polygon.
[[nodiscard]] float polygon_area(const std::vector<glm::vec2>& polygon);
[[nodiscard]] bool inside_polygon(const std::vector<glm::vec2>& polygon, glm::vec2 p);
// No two edges meet but neighbours at their shared corner (repeated consecutive points are
// one corner). A figure eight's lobes cancel in the shoelace sum (its area read 2e-12 and
// Lloyd's sample grid went on for ever): a region must be simple. CGAL's sweep
// (engine/pattern/delaunay.cpp, with the other CGAL call).
[[nodiscard]] bool polygon_is_simple(const std::vector<glm::vec2>& polygon);

// Sorted arc lengths in [0, length] (closed: [0, length)).
[[nodiscard]] std::vector<float> lloyd_1d(int count, float length, bool closed, int iterations, Rng& rng);

// Points inside `polygon` (at least 3 vertices, non-zero area).
[[nodiscard]] std::vector<glm::vec2> lloyd_2d(const std::vector<glm::vec2>& polygon, int count, int iterations, Rng& rng);

// Distance from each point to its nearest other point (a bucket grid).
[[nodiscard]] std::vector<float> nearest_neighbour_distances(const std::vector<glm::vec2>& points);

}  // namespace lw
