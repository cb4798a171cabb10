// engine/geometry/test_meshes.h — analytic surfaces as triangle meshes.
//
// For tests and benchmarks that need a surface with known normals and curvatures. Each
// returns a `TriangleMesh` (positions, area-weighted unit normals, indices) with shared
// vertices along seams (`weld` keeps them as they are, in the same order), vertices on the
// analytic surface up to float rounding, and counter-clockwise faces seen from outside (or
// from +z for a height field). Positions are evaluated in double and rounded once.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/triangle_mesh.h"

namespace lw {

// Icosahedron split 1→4 `levels` times, projected onto the sphere: 20·4^levels faces,
// 10·4^levels + 2 vertices, nearly equilateral faces everywhere.
[[nodiscard]] TriangleMesh make_icosphere(float radius, int levels, glm::vec3 center = glm::vec3(0.0f));

// Latitude–longitude sphere about z: `slices` ≥ 3 around, `stacks` ≥ 2 from pole to pole,
// each pole a single vertex (fans of thin triangles there).
[[nodiscard]] TriangleMesh make_uv_sphere(float radius, int slices, int stacks);

// Open cylinder about z for z in [0, height], `around` ≥ 3 × `along` ≥ 1 quads, each split in
// two: vertex (i around, j along) has index j·around + i; the borders are rings j = 0, along.
[[nodiscard]] TriangleMesh make_open_cylinder(float radius, float height, int around, int along);

// Torus about z: vertex (i, j) at ring angle u = 2πi/ring_segments and tube angle
// v = 2πj/tube_segments has index i·tube_segments + j and position
// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v); outward normal (cos v cos u, cos v sin u, sin v).
[[nodiscard]] TriangleMesh make_torus(float ring_radius, float tube_radius, int ring_segments, int tube_segments);

// Height field z = height(x, y) on a regular grid of nx × ny cells over [lo, hi]: vertex
// (i, j) at x = lo.x + (hi.x − lo.x)·i/nx, y likewise, has index j·(nx + 1) + i.
[[nodiscard]] TriangleMesh make_height_field(const std::function<double(double, double)>& height, glm::vec2 lo,
                                             glm::vec2 hi, int nx, int ny);

// z = Σ amplitude · exp(−|p − center|² / width²).
struct GaussianBump {
    glm::dvec2 center{0.0};
    double amplitude = 1.0;
    double width = 1.0;
};
[[nodiscard]] double gaussian_bumps_height(const std::vector<GaussianBump>& bumps, double x, double y);

}  // namespace lw
