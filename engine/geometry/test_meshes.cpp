// engine/geometry/test_meshes.cpp — analytic surfaces as triangle meshes.
#include "geometry/test_meshes.h"

#include <cmath>
#include <numbers>
#include <unordered_map>

namespace lw {

namespace {

constexpr double kTau = 2.0 * std::numbers::pi;

void add_triangle(TriangleMesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// Quad a-b-c-d (counter-clockwise from outside) as triangles a-b-c and a-c-d.
void add_quad(TriangleMesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    add_triangle(mesh, a, b, c);
    add_triangle(mesh, a, c, d);
}

TriangleMesh finish(TriangleMesh mesh) {
    mesh.normals = vertex_normals(mesh.positions, mesh.indices);
    return mesh;
}

}  // namespace

TriangleMesh make_icosphere(float radius, int levels, glm::vec3 center) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> dirs = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& d : dirs) d = glm::normalize(d);
    std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::unordered_map<uint64_t, uint32_t> midpoint_of;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const uint64_t key = uint64_t{std::min(a, b)} << 32 | std::max(a, b);
            const auto [it, inserted] = midpoint_of.try_emplace(key, static_cast<uint32_t>(dirs.size()));
            if (inserted) dirs.push_back(glm::normalize(dirs[a] + dirs[b]));
            return it->second;
        };
        std::vector<glm::uvec3> finer;
        finer.reserve(faces.size() * 4);
        for (const glm::uvec3& f : faces) {
            const uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
        }
        faces = std::move(finer);
    }
    TriangleMesh mesh;
    for (const auto& d : dirs) mesh.positions.push_back(glm::vec3(glm::dvec3(center) + double(radius) * d));
    for (const glm::uvec3& f : faces) add_triangle(mesh, f[0], f[1], f[2]);
    return finish(std::move(mesh));
}

TriangleMesh make_uv_sphere(float radius, int slices, int stacks) {
    TriangleMesh mesh;
    const double r = radius;
    mesh.positions.push_back(glm::vec3(0.0f, 0.0f, radius));  // north pole: index 0
    for (int k = 1; k < stacks; ++k) {
        const double theta = std::numbers::pi * k / stacks;
        for (int i = 0; i < slices; ++i) {
            const double phi = kTau * i / slices;
            mesh.positions.push_back(glm::vec3(glm::dvec3(r * std::sin(theta) * std::cos(phi),
                                                          r * std::sin(theta) * std::sin(phi), r * std::cos(theta))));
        }
    }
    const auto south = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(glm::vec3(0.0f, 0.0f, -radius));
    auto ring = [&](int k, int i) { return static_cast<uint32_t>(1 + (k - 1) * slices + (i % slices)); };
    for (int i = 0; i < slices; ++i) {
        add_triangle(mesh, 0, ring(1, i), ring(1, i + 1));
        for (int k = 1; k + 1 < stacks; ++k) add_quad(mesh, ring(k, i), ring(k + 1, i), ring(k + 1, i + 1), ring(k, i + 1));
        add_triangle(mesh, ring(stacks - 1, i), south, ring(stacks - 1, i + 1));
    }
    return finish(std::move(mesh));
}

TriangleMesh make_open_cylinder(float radius, float height, int around, int along) {
    TriangleMesh mesh;
    for (int j = 0; j <= along; ++j)
        for (int i = 0; i < around; ++i) {
            const double phi = kTau * i / around;
            mesh.positions.push_back(glm::vec3(glm::dvec3(radius * std::cos(phi), radius * std::sin(phi),
                                                          double(height) * j / along)));
        }
    auto index = [&](int i, int j) { return static_cast<uint32_t>(j * around + (i % around)); };
    for (int j = 0; j < along; ++j)
        for (int i = 0; i < around; ++i) add_quad(mesh, index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
    return finish(std::move(mesh));
}

TriangleMesh make_torus(float ring_radius, float tube_radius, int ring_segments, int tube_segments) {
    TriangleMesh mesh;
    const double big = ring_radius, small = tube_radius;
    for (int i = 0; i < ring_segments; ++i) {
        const double u = kTau * i / ring_segments;
        for (int j = 0; j < tube_segments; ++j) {
            const double v = kTau * j / tube_segments;
            const double w = big + small * std::cos(v);
            mesh.positions.push_back(glm::vec3(glm::dvec3(w * std::cos(u), w * std::sin(u), small * std::sin(v))));
        }
    }
    auto index = [&](int i, int j) {
        return static_cast<uint32_t>((i % ring_segments) * tube_segments + (j % tube_segments));
    };
    for (int i = 0; i < ring_segments; ++i)
        for (int j = 0; j < tube_segments; ++j)
            add_quad(mesh, index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
    return finish(std::move(mesh));
}

TriangleMesh make_height_field(const std::function<double(double, double)>& height, glm::vec2 lo, glm::vec2 hi,
                               int nx, int ny) {
    TriangleMesh mesh;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const double x = lo.x + (double(hi.x) - lo.x) * i / nx;
            const double y = lo.y + (double(hi.y) - lo.y) * j / ny;
            mesh.positions.push_back(glm::vec3(glm::dvec3(x, y, height(x, y))));
        }
    auto index = [&](int i, int j) { return static_cast<uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) add_quad(mesh, index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
    return finish(std::move(mesh));
}

double gaussian_bumps_height(const std::vector<GaussianBump>& bumps, double x, double y) {
    double z = 0.0;
    for (const GaussianBump& b : bumps) {
        const double dx = x - b.center.x, dy = y - b.center.y;
        z += b.amplitude * std::exp(-(dx * dx + dy * dy) / (b.width * b.width));
    }
    return z;
}

}  // namespace lw
