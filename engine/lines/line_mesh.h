// engine/lines/line_mesh.h — everything view-independent the line stages need of a mesh.
//
// Input:  a world-space `TriangleMesh` (rest pose or deformed) and the crease angle.
// Output: `LineMesh` — the welded mesh with adjacency, its curvature and derivative
//         tensor, rtsc's feature size, and per face a mask of the feature edges (creases
//         and borders) that face owns. Rebuilt when the mesh deforms; the per-view work
//         (extract_reference.h, extract_gpu.h) reads it every frame.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/curvature.h"
#include "geometry/welded_mesh.h"
#include "lines/line_types.h"
#include "scene/triangle_mesh.h"

namespace lw {

// Bits of `LineMesh::feature_edges[f]`: bit i = edge i of face f (opposite corner i) is a
// crease, bit 3 + i = it is a border. A shared edge is owned by its first face only, so
// each feature edge is emitted once.
constexpr uint32_t kCreaseBit = 1u;
constexpr uint32_t kBorderBit = 8u;

struct LineMesh {
    WeldedMesh mesh;
    SurfaceCurvature curvature;
    float feature_size = 0.0f;
    std::vector<uint32_t> feature_edges;
};

[[nodiscard]] LineMesh build_line_mesh(const TriangleMesh& mesh, float crease_angle_deg);

// Recomputes the feature-edge masks for another crease angle.
[[nodiscard]] std::vector<uint32_t> feature_edge_masks(const WeldedMesh& mesh, float crease_angle_deg);

}  // namespace lw
