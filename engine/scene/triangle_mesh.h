// engine/scene/triangle_mesh.h — every mesh instance of a model, in world space.
//
// Input:  a validated `Model` and world transforms per node (rest pose or animated).
// Output: `TriangleMesh` — one indexed triangle list holding every node's mesh transformed
//         to world space, with per-vertex normals (the file's, or area-weighted face normals
//         when it has none). This is what the shading pass draws; the line stages weld it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/model.h"

namespace lw {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // same size as positions, unit length
    std::vector<uint32_t> indices;    // 3 per triangle

    size_t triangle_count() const { return indices.size() / 3; }
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    float radius() const { return 0.5f * glm::length(max - min); }  // bounding-sphere radius of the box
};

[[nodiscard]] TriangleMesh flatten(const Model& model, const std::vector<glm::mat4>& world);
[[nodiscard]] Bounds compute_bounds(const std::vector<glm::vec3>& positions);

// Area-weighted vertex normals of an indexed triangle list (zero-area faces ignored).
[[nodiscard]] std::vector<glm::vec3> vertex_normals(const std::vector<glm::vec3>& positions,
                                                    const std::vector<uint32_t>& indices);

}  // namespace lw
