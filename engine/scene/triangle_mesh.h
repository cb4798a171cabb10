// engine/scene/triangle_mesh.h — every mesh instance of a model, in world space.
//
// Input:  a validated `Model` and world transforms per node (rest pose or animated), and
//         optionally the joint matrices of its skins (scene/animation.h computes them).
// Output: `TriangleMesh` — one indexed triangle list holding every node's mesh transformed
//         to world space, with per-vertex normals (the file's, or area-weighted face normals
//         when it has none). This is what the shading pass draws; the line stages weld it.
//
// Vertex and triangle order depend only on the model (nodes depth-first from the roots,
// children and primitives in file order), never on the transforms: every frame of an
// animation has the same vertex numbering, so a mesh welded once can be updated in place.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/model.h"

namespace lw {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // same size as positions, unit length
    // Base colour texture coordinates (KHR_texture_transform applied): empty when no
    // primitive has a textured material, else one per position (zero where it has none).
    std::vector<glm::vec2> texcoords;
    std::vector<uint32_t> indices;    // 3 per triangle
    std::vector<int32_t> face_material;  // per triangle: its primitive's glTF material, -1 for none
    // Per triangle: which primitive instance (a node's primitive; numbered over the scene's
    // models in mesh order) it comes from. Material and object boundaries are drawn
    // between faces of different parts (lines/line_mesh.h).
    std::vector<uint32_t> face_part;
    uint32_t part_count = 0;
    std::vector<uint32_t> face_model;  // per triangle: the scene's model it comes from (empty: one)
    // Midpoint subdivisions made (geometry/subdivide.h): triangle t is then one of the 4^n
    // pieces of the input's triangle t / 4^n.
    uint32_t subdivisions = 0;

    size_t triangle_count() const { return indices.size() / 3; }
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    float radius() const { return 0.5f * glm::length(max - min); }  // bounding-sphere radius of the box
};

// Every mesh instance rigidly transformed by its node's world transform; skins ignored.
[[nodiscard]] TriangleMesh flatten(const Model& model, const std::vector<glm::mat4>& world);

// As above, but primitives with JOINTS_0/WEIGHTS_0 on a node with a skin are deformed by
// linear blend skinning (glTF 2.0 §3.7.3 "Skins"): `joint_matrices[skin][j]` is
// world(joint j) × inverse bind matrix j, one list per skin of the model (or empty for no
// skinning at all). Weights are renormalized to sum 1; a vertex whose weights are all zero
// stays rigid at its node's world transform. As the spec requires, the skinned node's own
// transform is otherwise ignored. Skinned triangles keep the file's winding (bind-space
// orientation), so their index order never depends on the pose; a rigid instance's winding
// is flipped back where its world transform mirrors.
[[nodiscard]] TriangleMesh flatten(const Model& model, const std::vector<glm::mat4>& world,
                                   const std::vector<std::vector<glm::mat4>>& joint_matrices);
[[nodiscard]] Bounds compute_bounds(const std::vector<glm::vec3>& positions);

// Pads `texcoords` with zeros to one per position (a mesh gaining a textured part).
void pad_texcoords(TriangleMesh& mesh);

// Area-weighted vertex normals of an indexed triangle list (zero-area faces ignored).
[[nodiscard]] std::vector<glm::vec3> vertex_normals(const std::vector<glm::vec3>& positions,
                                                    const std::vector<uint32_t>& indices);

}  // namespace lw
