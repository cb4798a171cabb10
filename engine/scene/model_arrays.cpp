// A mesh given as arrays, made a Model so that every later stage treats it as a loaded file.
#include <cmath>

#include "core/error.h"
#include "scene/model.h"

namespace lw {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Model model_from_arrays(const std::string& name, std::vector<glm::vec3> positions, std::vector<uint32_t> indices,
                        std::vector<glm::vec3> normals) {
    if (indices.empty() || indices.size() % 3 != 0)
        throw Error(name + ": faces: expected at least one triangle (M×3 vertex indices)");
    for (size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= positions.size())
            throw Error(name + ": faces: index " + std::to_string(indices[i]) + " of triangle " + std::to_string(i / 3) +
                        " is past the " + std::to_string(positions.size()) + " vertices");
    for (size_t v = 0; v < positions.size(); ++v)
        if (!finite(positions[v])) throw Error(name + ": vertices: vertex " + std::to_string(v) + " is not finite");
    if (!normals.empty()) {
        if (normals.size() != positions.size())
            throw Error(name + ": normals: " + std::to_string(normals.size()) + " normals for " +
                        std::to_string(positions.size()) + " vertices");
        for (size_t v = 0; v < normals.size(); ++v)
            if (!finite(normals[v])) throw Error(name + ": normals: normal " + std::to_string(v) + " is not finite");
    }
    Model model;
    model.path = name;
    Primitive primitive{.positions = std::move(positions), .normals = std::move(normals), .indices = std::move(indices)};
    model.meshes.push_back({.name = name, .primitives = {std::move(primitive)}});
    model.nodes.push_back({.name = name, .mesh = 0});
    model.roots = {0};
    return model;
}

}  // namespace lw
