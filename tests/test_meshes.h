// tests/test_meshes.h — analytic surfaces as meshes, for tests with known answers.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>

#include "scene/triangle_mesh.h"

namespace lw::test {

// A UV sphere of `radius` around `center` (poles welded), counter-clockwise from outside.
inline TriangleMesh uv_sphere(float radius, glm::vec3 center, int rings, int segments) {
    TriangleMesh m;
    const float pi = std::numbers::pi_v<float>;
    m.positions.push_back(center + glm::vec3(0, radius, 0));
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const float theta = pi * float(r) / float(rings), phi = 2.0f * pi * float(s) / float(segments);
            m.positions.push_back(center + radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                              -std::sin(theta) * std::sin(phi)));
        }
    m.positions.push_back(center - glm::vec3(0, radius, 0));
    const auto ring = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
    const auto bottom = uint32_t(m.positions.size() - 1);
    for (int s = 0; s < segments; ++s) {
        m.indices.insert(m.indices.end(), {0u, ring(1, s), ring(1, s + 1)});
        for (int r = 1; r + 1 < rings; ++r)
            m.indices.insert(m.indices.end(), {ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s),
                                               ring(r + 1, s + 1), ring(r, s + 1)});
        m.indices.insert(m.indices.end(), {ring(rings - 1, s), bottom, ring(rings - 1, s + 1)});
    }
    for (const auto& p : m.positions) m.normals.push_back(glm::normalize(p - center));
    return m;
}

// A height field z = h(x, y) over [-half, half]² sampled on an n×n grid.
inline TriangleMesh height_field(const std::function<float(float, float)>& h, float half, int n) {
    TriangleMesh m;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -half + 2.0f * half * float(i) / float(n - 1);
            const float y = -half + 2.0f * half * float(j) / float(n - 1);
            m.positions.push_back({x, y, h(x, y)});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = uint32_t(j * n + i);
            m.indices.insert(m.indices.end(), {v, v + 1, v + uint32_t(n) + 1, v, v + uint32_t(n) + 1, v + uint32_t(n)});
        }
    m.normals = vertex_normals(m.positions, m.indices);
    return m;
}

}  // namespace lw::test
