#include "lines/line_mesh.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace lw {

namespace {

uint64_t next_generation() {
    static std::atomic<uint64_t> counter{0};
    return ++counter;
}

// Unit face normals (zero for a zero-area face).
std::vector<glm::vec3> unit_face_normals(const WeldedMesh& mesh) {
    std::vector<glm::vec3> normals(mesh.faces.size());
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const glm::uvec3 c = mesh.faces[f];
        const glm::vec3 n = glm::cross(mesh.positions[c[1]] - mesh.positions[c[0]], mesh.positions[c[2]] - mesh.positions[c[0]]);
        const float len = glm::length(n);
        normals[f] = len > 0.0f ? n / len : glm::vec3(0.0f);
    }
    return normals;
}

}  // namespace

std::vector<uint32_t> feature_edge_masks(const WeldedMesh& mesh, float crease_angle_deg,
                                         const std::vector<uint32_t>& face_part) {
    const std::vector<glm::vec3> face_normals = unit_face_normals(mesh);
    const float cos_limit = std::cos(glm::radians(crease_angle_deg));
    std::vector<uint32_t> masks(mesh.faces.size(), 0u);
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            const MeshEdge& edge = mesh.edges[size_t(mesh.face_edges[f][i])];
            if (edge.f[0] != int32_t(f)) continue;  // owned by its first face
            if (edge.face_count == 1) {
                masks[f] |= kBorderBit << i;
            } else if (edge.face_count == 2) {
                // Creases where the face normals turn by more than the angle (dihedral test).
                const float d = glm::dot(face_normals[size_t(edge.f[0])], face_normals[size_t(edge.f[1])]);
                if (d < cos_limit) masks[f] |= kCreaseBit << i;
                if (!face_part.empty() && face_part[size_t(edge.f[0])] != face_part[size_t(edge.f[1])])
                    masks[f] |= kPartBoundaryBit << i;
            }
        }
    return masks;
}

LineMesh build_line_mesh(const TriangleMesh& mesh, float crease_angle_deg, const CurvatureOptions& curvature) {
    LineMesh line_mesh;
    line_mesh.mesh = weld(mesh);
    line_mesh.curvature_options = curvature;
    line_mesh.curvature = compute_curvature(line_mesh.mesh, curvature);
    line_mesh.feature_size = feature_size(line_mesh.mesh, line_mesh.curvature);
    // A per-triangle array per welded face (empty where the mesh has none).
    const auto per_face = [&](const std::vector<uint32_t>& per_triangle) {
        std::vector<uint32_t> out;
        if (per_triangle.size() == mesh.triangle_count())
            for (uint32_t source : line_mesh.mesh.source_face) out.push_back(per_triangle[source]);
        return out;
    };
    line_mesh.face_part = per_face(mesh.face_part);
    line_mesh.face_coarse = coarse_faces(line_mesh.mesh, per_face(mesh.face_model), mesh.subdivisions);
    line_mesh.feature_edges = feature_edge_masks(line_mesh.mesh, crease_angle_deg, line_mesh.face_part);
    line_mesh.vertex_arrays = line_vertex_arrays(line_mesh.mesh, line_mesh.curvature);
    vertex_face_lists(line_mesh.mesh, line_mesh.vertex_face_offsets, line_mesh.vertex_faces, line_mesh.vertex_ring);
    line_mesh.strip_corners = strip_corner_order(line_mesh.mesh, line_mesh.vertex_face_offsets, line_mesh.vertex_faces);
    line_mesh.generation = next_generation();
    return line_mesh;
}

void pose_line_mesh(LineMesh& line_mesh, const TriangleMesh& posed) {
    update_positions(line_mesh.mesh, posed);
    line_mesh.curvature = compute_curvature(line_mesh.mesh, line_mesh.curvature_options);
    line_mesh.vertex_arrays = line_vertex_arrays(line_mesh.mesh, line_mesh.curvature);
    line_mesh.generation = next_generation();
}

std::vector<uint8_t> coarse_faces(const WeldedMesh& mesh, const std::vector<uint32_t>& face_model,
                                  uint32_t subdivisions) {
    // Edges inside one triangle of the mesh before subdivision are flat by construction:
    // the model is judged on its own edges only.
    const auto original = [&](int32_t f) { return uint64_t(mesh.source_face[size_t(f)]) >> (2 * subdivisions); };
    const auto model_of = [&](size_t f) { return face_model.empty() ? 0u : face_model[f]; };
    uint32_t models = 1;
    for (uint32_t m : face_model) models = std::max(models, m + 1);
    const std::vector<glm::vec3> normals = unit_face_normals(mesh);
    // Per model, the angles across its interior edges; coarse where their median is large.
    std::vector<std::vector<float>> angles(models);
    for (const MeshEdge& e : mesh.edges) {
        if (e.face_count != 2 || model_of(size_t(e.f[0])) != model_of(size_t(e.f[1]))) continue;
        if (subdivisions > 0 && original(e.f[0]) == original(e.f[1])) continue;
        const float d = glm::dot(normals[size_t(e.f[0])], normals[size_t(e.f[1])]);
        angles[model_of(size_t(e.f[0]))].push_back(glm::degrees(std::acos(std::clamp(d, -1.0f, 1.0f))));
    }
    std::vector<uint8_t> coarse_model(models, 0);
    for (uint32_t m = 0; m < models; ++m) {
        std::vector<float>& a = angles[m];
        if (a.empty()) continue;
        std::nth_element(a.begin(), a.begin() + std::ptrdiff_t(a.size() / 2), a.end());
        coarse_model[m] = a[a.size() / 2] > kCoarseDihedralDeg;
    }
    std::vector<uint8_t> coarse(mesh.faces.size());
    for (size_t f = 0; f < coarse.size(); ++f) coarse[f] = coarse_model[model_of(f)];
    return coarse;
}

void vertex_face_lists(const WeldedMesh& mesh, std::vector<uint32_t>& offsets, std::vector<uint32_t>& faces,
                       std::vector<glm::uvec2>& ring) {
    // Counting sort by vertex: a face index goes to each corner's list in face order.
    offsets.assign(mesh.positions.size() + 1, 0u);
    for (const glm::uvec3& f : mesh.faces)
        for (int i = 0; i < 3; ++i) ++offsets[f[i] + 1];
    for (size_t v = 0; v < mesh.positions.size(); ++v) offsets[v + 1] += offsets[v];
    faces.resize(offsets.back());
    ring.resize(offsets.back());
    std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            const glm::uvec3 c = mesh.faces[f];
            const uint32_t j = fill[c[i]]++;
            faces[j] = uint32_t(f);
            ring[j] = {c[(i + 1) % 3], c[(i + 2) % 3]};
        }
}

LineVertexArrays line_vertex_arrays(const WeldedMesh& mesh, const SurfaceCurvature& curvature) {
    using F = LineVertexArrays::Field;
    LineVertexArrays out;
    out.count = mesh.positions.size();
    out.values.resize(size_t(F::kFields) * out.count);
    const auto put = [&](F f, size_t i, float v) { out.values[size_t(f) * out.count + i] = v; };
    for (size_t i = 0; i < out.count; ++i) {
        const glm::vec3 p = mesh.positions[i], n = curvature.normals[i], e1 = curvature.pdir1[i], e2 = curvature.pdir2[i];
        const glm::vec4 c = curvature.dcurv[i];
        for (int k = 0; k < 3; ++k) {
            put(F(F::Px + size_t(k)), i, p[k]);
            put(F(F::Nx + size_t(k)), i, n[k]);
            put(F(F::E1x + size_t(k)), i, e1[k]);
            put(F(F::E2x + size_t(k)), i, e2[k]);
        }
        put(F::K1, i, curvature.k1[i]);
        put(F::K2, i, curvature.k2[i]);
        for (int k = 0; k < 4; ++k) put(F(F::C0 + size_t(k)), i, c[k]);
    }
    return out;
}

}  // namespace lw
