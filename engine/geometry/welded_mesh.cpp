// engine/geometry/welded_mesh.cpp — weld split vertices and build edge adjacency.
//
// Files split vertices at UV and normal seams; the line stages need the surface's real
// connectivity, so vertices at bit-identical positions become one. Exact equality (not a
// tolerance) keeps the result independent of scale and of vertex order.
#include "geometry/welded_mesh.h"

#include <algorithm>
#include <bit>
#include <string>
#include <unordered_map>

#include "core/error.h"

namespace lw {

namespace {

struct PositionKey {
    uint32_t bits[3];
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    size_t operator()(const PositionKey& key) const {
        // 64-bit mix of the three words (splitmix64-style finaliser).
        uint64_t h = (uint64_t{key.bits[0]} << 32 | key.bits[1]) ^ (uint64_t{key.bits[2]} * 0x9E3779B97F4A7C15ull);
        h ^= h >> 31;
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 29;
        return static_cast<size_t>(h);
    }
};

PositionKey key_of(const glm::vec3& p) {
    PositionKey key;
    for (int c = 0; c < 3; ++c) {
        // -0.0 and 0.0 are the same point but differ in their sign bit.
        const float v = p[c] == 0.0f ? 0.0f : p[c];
        key.bits[c] = std::bit_cast<uint32_t>(v);
    }
    return key;
}

uint64_t edge_key(uint32_t a, uint32_t b) { return uint64_t{std::min(a, b)} << 32 | std::max(a, b); }

}  // namespace

size_t WeldedMesh::border_edge_count() const {
    return static_cast<size_t>(
        std::count_if(edges.begin(), edges.end(), [](const MeshEdge& e) { return e.face_count == 1; }));
}

WeldedMesh weld(const TriangleMesh& mesh) {
    WeldedMesh out;

    // Welded vertices are numbered in order of first use by the faces (then the unused ones):
    // the numbering, and with it each edge's direction and where chains start, depends on the
    // triangles only, not on how a file orders its vertex buffer. A glTF and the OBJ written
    // from it (whose vertices a reader numbers by first use) give the same lines.
    std::unordered_map<PositionKey, uint32_t, PositionKeyHash> welded_of;
    welded_of.reserve(mesh.positions.size());
    constexpr uint32_t kUnassigned = ~0u;
    out.welded_index.assign(mesh.positions.size(), kUnassigned);
    const auto assign = [&](size_t v) {
        if (out.welded_index[v] != kUnassigned) return;
        const auto [it, inserted] =
            welded_of.try_emplace(key_of(mesh.positions[v]), static_cast<uint32_t>(out.positions.size()));
        if (inserted) {
            out.positions.push_back(mesh.positions[v]);
            out.source_vertex.push_back(static_cast<uint32_t>(v));
        }
        out.welded_index[v] = it->second;
    };
    for (uint32_t v : mesh.indices)
        if (v < mesh.positions.size()) assign(v);
    for (size_t v = 0; v < mesh.positions.size(); ++v) assign(v);

    // Faces whose corners collapsed onto each other have no area and no well-defined edges.
    out.faces.reserve(mesh.triangle_count());
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        for (size_t k = t; k < t + 3; ++k)
            if (mesh.indices[k] >= mesh.positions.size())
                throw Error("weld: index " + std::to_string(mesh.indices[k]) + " is past the vertex count " +
                            std::to_string(mesh.positions.size()));
        const glm::uvec3 face(out.welded_index[mesh.indices[t]], out.welded_index[mesh.indices[t + 1]],
                              out.welded_index[mesh.indices[t + 2]]);
        if (face[0] == face[1] || face[1] == face[2] || face[2] == face[0]) continue;
        out.faces.push_back(face);
        out.source_face.push_back(static_cast<uint32_t>(t / 3));
    }

    // Edges in order of first appearance (faces in order, corners 0..2), each with the first
    // two faces that use it and how many use it in all.
    std::unordered_map<uint64_t, uint32_t> edge_of;
    edge_of.reserve(out.faces.size() * 2);
    out.face_edges.resize(out.faces.size());
    for (size_t f = 0; f < out.faces.size(); ++f) {
        for (int i = 0; i < 3; ++i) {
            const uint32_t a = out.faces[f][(i + 1) % 3];
            const uint32_t b = out.faces[f][(i + 2) % 3];
            const auto [it, inserted] = edge_of.try_emplace(edge_key(a, b), static_cast<uint32_t>(out.edges.size()));
            if (inserted) {
                out.edges.push_back(MeshEdge{{std::min(a, b), std::max(a, b)}, {static_cast<int32_t>(f), -1}, 1});
            } else {
                MeshEdge& edge = out.edges[it->second];
                if (edge.face_count == 1) edge.f[1] = static_cast<int32_t>(f);
                ++edge.face_count;
            }
            out.face_edges[f][i] = static_cast<int>(it->second);
        }
    }

    // Only a manifold edge (exactly two faces) has a well-defined face across it.
    out.face_neighbors.assign(out.faces.size(), glm::ivec3(-1));
    for (size_t f = 0; f < out.faces.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            const MeshEdge& edge = out.edges[static_cast<size_t>(out.face_edges[f][i])];
            if (edge.face_count != 2) continue;
            out.face_neighbors[f][i] = edge.f[0] == static_cast<int32_t>(f) ? edge.f[1] : edge.f[0];
        }
    return out;
}

void update_positions(WeldedMesh& welded, const TriangleMesh& deformed) {
    if (deformed.positions.size() != welded.welded_index.size())
        throw Error("update_positions: the deformed mesh has " + std::to_string(deformed.positions.size()) +
                    " vertices, the welded mesh was built from " + std::to_string(welded.welded_index.size()));
    // Each welded vertex moves with the input vertex weld took its position from (the first
    // used by the faces), whatever the other seam copies do.
    if (welded.source_vertex.size() != welded.positions.size())
        throw Error("update_positions: the welded mesh has " + std::to_string(welded.positions.size()) +
                    " vertices but " + std::to_string(welded.source_vertex.size()) + " sources");
    for (size_t w = 0; w < welded.positions.size(); ++w) welded.positions[w] = deformed.positions[welded.source_vertex[w]];
}

}  // namespace lw
