// engine/lines/line_mesh.h — everything view-independent the line stages need of a mesh.
//
// Input:  a world-space `TriangleMesh` (rest pose or deformed) and the crease angle.
// Output: `LineMesh` — the welded mesh with adjacency, its curvature and derivative
//         tensor, rtsc's feature size, per face a mask of the feature edges (creases and
//         borders) that face owns, and the per-vertex inputs of the per-view pass laid out
//         for it. Posed again (`pose_line_mesh`) when the mesh deforms; the per-view work
//         (extract_reference.h, extract_gpu.h) reads it every frame.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/curvature.h"
#include "geometry/welded_mesh.h"
#include "lines/line_types.h"
#include "lines/strip_order.h"
#include "scene/triangle_mesh.h"

namespace lw {

// Bits of `LineMesh::feature_edges[f]`: bit i = edge i of face f (opposite corner i) is a
// crease, bit 3 + i = it is a border, bit 6 + i = its two faces come from different parts
// (primitives of the scene's nodes: a material or object boundary). A shared edge is owned
// by its first face only, so each feature edge is emitted once per kind.
constexpr uint32_t kCreaseBit = 1u;
constexpr uint32_t kBorderBit = 8u;
constexpr uint32_t kPartBoundaryBit = 64u;

// What the host's per-vertex pass reads, one array per component (structure of arrays), so
// that its loop over vertices is one the compiler vectorizes and reads nothing else: the
// position, normal, principal directions and curvatures and the derivative tensor of
// `LineMesh::curvature`, copied.
struct LineVertexArrays {
    enum Field : size_t { Px, Py, Pz, Nx, Ny, Nz, E1x, E1y, E1z, E2x, E2y, E2z, K1, K2, C0, C1, C2, C3, kFields };
    size_t count = 0;
    std::vector<float> values;  // field f of vertex i at f · count + i
    const float* field(Field f) const { return values.data() + size_t(f) * count; }
};

// Low-poly models (the glTF Fox 16°, RobotExpressive 22°, craft_speederD 24°) against smooth
// ones and scans (CesiumMan 0.6°, spot 5°, FlightHelmet 7°, LeePerrySmith 7°, Suzanne 8°).
constexpr float kCoarseDihedralDeg = 12.0f;

// Per face, whether its model is coarse (`face_model`: per face, or empty for one model),
// judged on the edges of the mesh before `subdivisions` midpoint subdivisions.
[[nodiscard]] std::vector<uint8_t> coarse_faces(const WeldedMesh& mesh, const std::vector<uint32_t>& face_model,
                                                uint32_t subdivisions);

struct LineMesh {
    WeldedMesh mesh;
    SurfaceCurvature curvature;
    float feature_size = 0.0f;
    std::vector<uint32_t> feature_edges;
    std::vector<uint32_t> face_part;  // per face, TriangleMesh::face_part of its source triangle (empty: one part)
    // Per face, 1 where its model is coarse: the median angle between the normals of
    // neighbouring faces over the model's edges is above kCoarseDihedralDeg. There the
    // smooth contour (interpolated n·v) strays from the polygon's outline and `auto`
    // contours take the mesh's own edges (types/line_type.h, ContourMode).
    std::vector<uint8_t> face_coarse;
    LineVertexArrays vertex_arrays;  // of mesh.positions and curvature, kept in step with them
    // The faces around each vertex, in face order (apparent ridges, ridge_lines.h): those of
    // vertex v are vertex_faces[vertex_face_offsets[v] .. vertex_face_offsets[v + 1]).
    std::vector<uint32_t> vertex_face_offsets, vertex_faces;
    // Beside each vertex_faces entry, that face's two other corners in its winding after v
    // (the opposite edge v1–v2): apparent ridges' derivative walks these on the host. (A
    // welded face has three distinct corners: weld drops the others.)
    std::vector<glm::uvec2> vertex_ring;
    std::vector<StripCorners> strip_corners;  // per face, the corner order rtsc sees (strip_order.h)
    CurvatureOptions curvature_options;       // what `curvature` was fitted with, in every pose
    // A number no other build or pose of any line mesh has had: what per-view caches of
    // view-independent lines (ExtractWorkspace) are keyed on.
    uint64_t generation = 0;
};

// Whether a per-pose cache filled from a line mesh of generation `cached` holds `mesh`'s
// pose. The one rule of every such cache (ridges, principal highlight shapes, mesh contours'
// face planes, intersection lines, the occlusion index): generation 0, a line mesh not made
// by build_line_mesh (tests build them by hand), never is.
inline bool holds_pose(uint64_t cached, const LineMesh& mesh) { return mesh.generation != 0 && cached == mesh.generation; }

[[nodiscard]] LineMesh build_line_mesh(const TriangleMesh& mesh, float crease_angle_deg,
                                       const CurvatureOptions& curvature = {});

// The curvature options of a LineParams::curvature choice.
inline CurvatureOptions curvature_options(CurvatureFit fit) {
    CurvatureOptions options;
    options.trimesh2_ldlt_shortcut = fit == CurvatureFit::Trimesh2;
    return options;
}

// Another pose of the same mesh (an animation frame, same vertex numbering): positions,
// curvature and the vertex arrays follow it; the feature size and the feature edges stay
// those of the pose the line mesh was built in.
void pose_line_mesh(LineMesh& line_mesh, const TriangleMesh& posed);

[[nodiscard]] LineVertexArrays line_vertex_arrays(const WeldedMesh& mesh, const SurfaceCurvature& curvature);

// The faces around each vertex, in face order, as `LineMesh::vertex_faces` holds them, and
// each one's opposite edge (`LineMesh::vertex_ring`).
void vertex_face_lists(const WeldedMesh& mesh, std::vector<uint32_t>& offsets, std::vector<uint32_t>& faces,
                       std::vector<glm::uvec2>& ring);

// The feature-edge masks for a crease angle; `face_part` (per face, or empty) marks the
// boundaries between parts.
[[nodiscard]] std::vector<uint32_t> feature_edge_masks(const WeldedMesh& mesh, float crease_angle_deg,
                                                       const std::vector<uint32_t>& face_part);

}  // namespace lw
