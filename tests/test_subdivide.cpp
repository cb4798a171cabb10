// Midpoint subdivision (the benchmark meshes) keeps the surface and its topology.
#include "geometry/subdivide.h"
#include "geometry/welded_mesh.h"
#include "scene/model.h"
#include "scene/triangle_mesh.h"
#include "test_support.h"

namespace lw {
namespace {

double surface_area(const TriangleMesh& m) {
    double area = 0.0;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

TEST(Subdivide, QuadruplesTrianglesAndKeepsArea) {
    const Model model = load_gltf(test::data_dir() / "models/spot/spot.glb");
    const TriangleMesh mesh = flatten(model, world_transforms(model));
    const TriangleMesh fine = subdivide_midpoint(mesh, 2);
    EXPECT_EQ(fine.triangle_count(), mesh.triangle_count() * 16);
    EXPECT_NEAR(surface_area(fine), surface_area(mesh), 1e-5 * surface_area(mesh));
    EXPECT_EQ(fine.normals.size(), fine.positions.size());
    for (const auto& n : fine.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
}

TEST(Subdivide, KeepsAClosedMeshClosed) {
    const Model model = load_gltf(test::data_dir() / "models/spot/spot.glb");
    const TriangleMesh mesh = flatten(model, world_transforms(model));
    const WeldedMesh coarse = weld(mesh);
    const WeldedMesh fine = weld(subdivide_midpoint(mesh, 1));
    EXPECT_EQ(fine.border_edge_count(), coarse.border_edge_count());
    // Euler characteristic is a topological invariant: V − E + F unchanged.
    auto euler = [](const WeldedMesh& m) {
        return int64_t(m.positions.size()) - int64_t(m.edges.size()) + int64_t(m.faces.size());
    };
    EXPECT_EQ(euler(fine), euler(coarse));
}

}  // namespace
}  // namespace lw
