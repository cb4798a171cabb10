// engine/scene/triangle_mesh.cpp — every mesh instance of a model in one world-space list.
#include "scene/triangle_mesh.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace lw {

namespace {

bool usable(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Normals go through the inverse-transpose so that non-uniform scale keeps them
// perpendicular to the surface; it is computed as the cofactor matrix scaled by the
// determinant's sign, which has the same direction and stays finite when a node's scale
// collapses to zero.
glm::mat3 normal_matrix(const glm::mat3& linear, bool mirrored) {
    const glm::mat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                             glm::cross(linear[0], linear[1]));
    return mirrored ? -cofactor : cofactor;
}

// Linear blend skinning of one vertex (glTF 2.0 §3.7.3 "Skins", skinned mesh attributes):
// Σ wᵢ Jᵢ. The spec says the weights' sum SHOULD be as close to 1 as reasonably possible,
// but CesiumMan (sums down to 0.18) and RobotExpressive (up to 1.76) are far from it and
// an unnormalized blend would shrink or blow up those vertices, so the weights are divided
// by their sum. Returns false for a vertex whose weights are all zero: no joint to follow.
bool blend_joints(const Model& model, const std::vector<glm::mat4>& joints, const glm::u16vec4& index,
                  const glm::vec4& weight, glm::mat4& out) {
    const float sum = weight.x + weight.y + weight.z + weight.w;
    if (!(sum > 0.0f)) return false;
    out = glm::mat4(0.0f);
    for (int c = 0; c < 4; ++c) {
        if (weight[c] == 0.0f) continue;  // unused slots often name joint 0: skip, don't check
        if (index[c] >= joints.size())
            throw Error(model.path.string() + ": JOINTS_0 names joint " + std::to_string(index[c]) +
                        " of a skin with " + std::to_string(joints.size()) + " joints");
        out += (weight[c] / sum) * joints[index[c]];
    }
    return true;
}

// Appends one primitive: rigidly transformed by `transform` (its node's world transform),
// or skinned by `joints` when given and the primitive has joints and weights.
void append_instance(TriangleMesh& out, const Model& model, const Primitive& primitive, const glm::mat4& transform,
                     const std::vector<glm::mat4>* joints) {
    const bool skinned = joints != nullptr && !primitive.joints.empty() &&
                         primitive.joints.size() == primitive.positions.size() &&
                         primitive.weights.size() == primitive.positions.size();
    const glm::mat3 linear(transform);
    // A mirroring transform turns counter-clockwise faces clockwise: swap two corners back.
    // Skinned faces keep the file's order, so that it never depends on the pose.
    const bool flip = !skinned && glm::determinant(linear) < 0.0f;
    const glm::mat3 rigid_normal_matrix = normal_matrix(linear, glm::determinant(linear) < 0.0f);
    const bool has_normals = primitive.normals.size() == primitive.positions.size();

    const size_t base = out.positions.size();
    std::vector<glm::vec3> positions(primitive.positions.size());
    std::vector<glm::vec3> normals(has_normals ? positions.size() : 0);
    bool need_computed = !has_normals;
    glm::mat4 blended(1.0f);
    for (size_t v = 0; v < positions.size(); ++v) {
        const bool blend = skinned && blend_joints(model, *joints, primitive.joints[v], primitive.weights[v], blended);
        const glm::mat4& m = blend ? blended : transform;
        positions[v] = glm::vec3(m * glm::vec4(primitive.positions[v], 1.0f));
        if (!has_normals) continue;
        glm::vec3 n;
        if (blend) {
            const glm::mat3 blended_linear(blended);
            n = normal_matrix(blended_linear, glm::determinant(blended_linear) < 0.0f) * primitive.normals[v];
        } else {
            n = rigid_normal_matrix * primitive.normals[v];
        }
        const float length = glm::length(n);
        if (length > 0.0f && std::isfinite(length)) {
            normals[v] = n / length;
        } else {
            normals[v] = glm::vec3(0.0f);  // replaced below
            need_computed = true;
        }
    }

    std::vector<uint32_t> local(primitive.indices.size());
    for (size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
        local[t] = primitive.indices[t];
        local[t + 1] = primitive.indices[flip ? t + 2 : t + 1];
        local[t + 2] = primitive.indices[flip ? t + 1 : t + 2];
    }

    if (need_computed) {
        // From the transformed, re-wound triangles: already world-space and outward.
        const std::vector<glm::vec3> computed = vertex_normals(positions, local);
        if (normals.empty()) {
            normals = computed;
        } else {
            for (size_t v = 0; v < normals.size(); ++v)
                if (normals[v] == glm::vec3(0.0f)) normals[v] = computed[v];
        }
    }

    if (!primitive.texcoords.empty() || !out.texcoords.empty()) {
        pad_texcoords(out);
        if (primitive.texcoords.size() == positions.size()) {
            const bool known = primitive.material >= 0 && size_t(primitive.material) < model.materials.size();
            const glm::mat3 uv = known ? model.materials[size_t(primitive.material)].base_color_texture.uv_transform
                                       : glm::mat3(1.0f);
            for (const glm::vec2& t : primitive.texcoords) out.texcoords.push_back(glm::vec2(uv * glm::vec3(t, 1.0f)));
        } else {
            out.texcoords.resize(out.texcoords.size() + positions.size(), glm::vec2(0.0f));
        }
    }
    out.positions.insert(out.positions.end(), positions.begin(), positions.end());
    out.normals.insert(out.normals.end(), normals.begin(), normals.end());
    out.indices.reserve(out.indices.size() + local.size());
    for (uint32_t index : local) out.indices.push_back(static_cast<uint32_t>(base + index));
    out.face_material.insert(out.face_material.end(), local.size() / 3, primitive.material);
    out.face_part.insert(out.face_part.end(), local.size() / 3, out.part_count++);
}

}  // namespace

void pad_texcoords(TriangleMesh& mesh) { mesh.texcoords.resize(mesh.positions.size(), glm::vec2(0.0f)); }

TriangleMesh flatten(const Model& model, const std::vector<glm::mat4>& world) { return flatten(model, world, {}); }

TriangleMesh flatten(const Model& model, const std::vector<glm::mat4>& world,
                     const std::vector<std::vector<glm::mat4>>& joint_matrices) {
    if (world.size() != model.nodes.size())
        throw Error(model.path.string() + ": flatten got " + std::to_string(world.size()) + " world transforms for " +
                    std::to_string(model.nodes.size()) + " nodes");
    if (!joint_matrices.empty() && joint_matrices.size() != model.skins.size())
        throw Error(model.path.string() + ": flatten got joint matrices for " + std::to_string(joint_matrices.size()) +
                    " skins, the model has " + std::to_string(model.skins.size()));
    TriangleMesh out;
    // Depth-first from the roots, children in file order: a deterministic vertex order.
    // `visited` keeps a malformed hand-built hierarchy from looping or drawing a node twice.
    std::vector<char> visited(model.nodes.size(), 0);
    std::vector<int> stack(model.roots.rbegin(), model.roots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (n < 0 || static_cast<size_t>(n) >= model.nodes.size() || visited[static_cast<size_t>(n)]) continue;
        visited[static_cast<size_t>(n)] = 1;
        const Node& node = model.nodes[static_cast<size_t>(n)];
        const std::vector<glm::mat4>* joints =
            node.skin >= 0 && static_cast<size_t>(node.skin) < joint_matrices.size()
                ? &joint_matrices[static_cast<size_t>(node.skin)]
                : nullptr;
        if (node.mesh >= 0 && static_cast<size_t>(node.mesh) < model.meshes.size())
            for (const Primitive& primitive : model.meshes[static_cast<size_t>(node.mesh)].primitives)
                append_instance(out, model, primitive, world[static_cast<size_t>(n)], joints);
        stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
    }
    if (out.positions.size() > std::numeric_limits<uint32_t>::max())
        throw Error(model.path.string() + ": more than 2^32 vertices after instancing");
    return out;
}

Bounds compute_bounds(const std::vector<glm::vec3>& positions) {
    Bounds bounds;
    if (positions.empty()) return bounds;
    bounds.min = bounds.max = positions.front();
    for (const glm::vec3& p : positions) {
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds;
}

std::vector<glm::vec3> vertex_normals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
        // The cross product's length is twice the area: summing it weights by area, and a
        // zero-area face adds nothing.
        const glm::vec3 face = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        if (!usable(face)) continue;
        sum[a] += face;
        sum[b] += face;
        sum[c] += face;
    }
    for (glm::vec3& n : sum) {
        const float length = glm::length(n);
        // Isolated vertices, or faces that cancel out: any unit vector beats a NaN.
        n = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return sum;
}

}  // namespace lw
