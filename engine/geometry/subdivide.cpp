#include "geometry/subdivide.h"

#include <unordered_map>

namespace lw {

namespace {

TriangleMesh subdivide_once(const TriangleMesh& in) {
    TriangleMesh out;
    out.positions = in.positions;
    out.normals = in.normals;
    out.texcoords = in.texcoords;
    out.part_count = in.part_count;
    out.subdivisions = in.subdivisions + 1;
    const bool textured = in.texcoords.size() == in.positions.size();
    out.indices.reserve(in.indices.size() * 4);
    std::unordered_map<uint64_t, uint32_t> midpoints;
    midpoints.reserve(in.indices.size());
    auto midpoint = [&](uint32_t a, uint32_t b) {
        const uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
        auto [it, inserted] = midpoints.try_emplace(key, static_cast<uint32_t>(out.positions.size()));
        if (inserted) {
            out.positions.push_back(0.5f * (in.positions[a] + in.positions[b]));
            const glm::vec3 n = in.normals[a] + in.normals[b];
            const float len = glm::length(n);
            out.normals.push_back(len > 0.0f ? n / len : in.normals[a]);
            if (textured) out.texcoords.push_back(0.5f * (in.texcoords[a] + in.texcoords[b]));
        }
        return it->second;
    };
    for (size_t t = 0; t + 2 < in.indices.size(); t += 3) {
        const uint32_t a = in.indices[t], b = in.indices[t + 1], c = in.indices[t + 2];
        const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        // Four triangles with the parent's winding.
        for (uint32_t i : {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca}) out.indices.push_back(i);
        // The four children keep the parent's per-triangle values.
        const auto children = [&](const auto& parent, auto& child) {
            if (t / 3 < parent.size()) child.insert(child.end(), 4, parent[t / 3]);
        };
        children(in.face_material, out.face_material);
        children(in.face_part, out.face_part);
        children(in.face_model, out.face_model);
    }
    return out;
}

}  // namespace

TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int levels) {
    TriangleMesh result = mesh;
    for (int i = 0; i < levels; ++i) result = subdivide_once(result);
    return result;
}

}  // namespace lw
