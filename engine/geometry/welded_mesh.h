// engine/geometry/welded_mesh.h — a welded, indexed mesh with edge adjacency.
//
// Input:  a `TriangleMesh` whose vertices may be split at UV or normal seams.
// Output: `WeldedMesh` — vertices at identical positions merged, degenerate faces dropped,
//         and for every face its three edges and the face across each of them. The line
//         stages (curvature, contours, chaining) walk this structure.
//
// Conventions: face f has corners faces[f][0..2]; edge i of a face is the one opposite
// corner i, i.e. (faces[f][(i+1)%3], faces[f][(i+2)%3]). An edge shared by one face is a
// border; an edge shared by more than two faces is non-manifold and has no neighbour.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/triangle_mesh.h"

namespace lw {

struct MeshEdge {
    uint32_t v[2];        // v[0] < v[1]
    int32_t f[2];         // incident faces; f[1] = -1 on a border
    uint32_t face_count;  // 1 border, 2 manifold interior, > 2 non-manifold
};

struct WeldedMesh {
    std::vector<glm::vec3> positions;        // numbered in order of first use by the faces
    std::vector<glm::uvec3> faces;
    std::vector<MeshEdge> edges;
    std::vector<glm::ivec3> face_edges;      // edge index opposite each corner
    std::vector<glm::ivec3> face_neighbors;  // face across each edge, -1 if border/non-manifold
    std::vector<uint32_t> welded_index;      // input vertex -> welded vertex
    std::vector<uint32_t> source_vertex;     // welded vertex -> the input vertex it was taken from
    std::vector<uint32_t> source_face;       // welded face -> input triangle (degenerate ones are dropped)

    size_t border_edge_count() const;
};

[[nodiscard]] WeldedMesh weld(const TriangleMesh& mesh);

// Animation: refreshes the positions of a mesh welded once (from the rest pose) from a
// deformed mesh of the same vertex numbering (flatten_posed of another pose), keeping the
// faces, edges and adjacency. Each welded vertex takes the position of the first input
// vertex welded into it. The topology stays that of the weld: vertices that meet only in
// the deformed pose are not merged, and faces that collapse in it are not dropped.
// Throws lw::Error when the vertex counts differ.
void update_positions(WeldedMesh& welded, const TriangleMesh& deformed);

}  // namespace lw
