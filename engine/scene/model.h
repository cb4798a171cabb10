// engine/scene/model.h — a glTF 2.0 asset (or an OBJ or PLY mesh) as plain data.
//
// Input:  a .gltf (external or data-URI buffers) or .glb file; or an .obj or .ply mesh
//         (one root node, one mesh, a primitive per OBJ material group; no cameras,
//         animations or skins).
// Output: `Model` — triangle primitives per mesh, the node hierarchy with local transforms,
//         cameras, animation clips and skins, all validated (indices, accessors, buffer
//         ranges, finite positions, an acyclic hierarchy). Evaluation of animation and
//         skinning happens in later stages; this stage only loads and checks.
//
// Every problem is reported as lw::Error("<file>: <problem>") — never a crash or a silent
// default. Non-triangle primitives (points, lines) are skipped; strips and fans are
// converted to triangle lists.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/material.h"

namespace lw {

struct Primitive {
    std::vector<glm::vec3> positions;   // POSITION, object space
    std::vector<glm::vec3> normals;     // NORMAL, empty when the file has none
    std::vector<glm::vec2> texcoords;   // TEXCOORD_n of its material's base colour texture, else empty
    std::vector<uint32_t> indices;      // triangle list, 3 per triangle, each < positions.size()
    std::vector<glm::u16vec4> joints;   // JOINTS_0, empty when not skinned
    std::vector<glm::vec4> weights;     // WEIGHTS_0, empty when not skinned
    int material = -1;
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

struct Node {
    std::string name;
    int parent = -1;                 // -1 for a root
    std::vector<int> children;
    int mesh = -1;
    int camera = -1;
    int skin = -1;
    // Local transform: either a matrix or translation/rotation/scale (glTF 2.0 §5.25).
    bool has_matrix = false;
    glm::mat4 matrix{1.0f};
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
    glm::vec3 scale{1.0f};

    glm::mat4 local_transform() const;
};

struct Camera {
    enum class Type { Perspective, Orthographic };
    std::string name;
    Type type = Type::Perspective;
    float yfov = 0.8f;         // radians (perspective)
    float aspect = 0.0f;       // 0 = use the image's
    float xmag = 1.0f, ymag = 1.0f;  // orthographic half extents
    float znear = 0.01f;
    float zfar = 0.0f;         // 0 = infinite (perspective)
};

struct AnimationSampler {
    enum class Interpolation { Linear, Step, CubicSpline };
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;   // strictly increasing key times, seconds
    std::vector<float> values;  // times.size() * components (× 3 for CUBICSPLINE)
    int components = 0;         // 3 (T, S), 4 (R) or the morph-target count (weights)
};

struct AnimationChannel {
    enum class Path { Translation, Rotation, Scale, Weights };
    int node = -1;
    Path path = Path::Translation;
    int sampler = -1;
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    float duration = 0.0f;  // last key time over all samplers
};

struct Skin {
    std::string name;
    std::vector<int> joints;                 // node indices
    std::vector<glm::mat4> inverse_bind;     // one per joint (identity when absent)
    int skeleton = -1;
};

struct Model {
    std::filesystem::path path;
    std::vector<Mesh> meshes;
    std::vector<Node> nodes;
    std::vector<int> roots;   // root nodes of the default scene (all parentless nodes if none)
    std::vector<Camera> cameras;
    std::vector<Animation> animations;
    std::vector<Skin> skins;
    std::vector<Material> materials;  // per glTF material (OBJ/PLY: names only)
    std::vector<ModelImage> images;   // per glTF image, encoded
};

// Decodes image `image` of the model to RGBA8 (the texels as stored: sRGB for base colour).
// Throws lw::Error naming the file and the image when it cannot be read or decoded.
[[nodiscard]] ImageRGBA8 decode_model_image(const Model& model, int image);

// Loads and validates a .gltf or .glb file. Throws lw::Error naming the file and the problem.
[[nodiscard]] Model load_gltf(const std::filesystem::path& path);

// True for the mesh formats load_mesh_file reads (.obj, .ply, any case).
[[nodiscard]] bool is_mesh_file_path(const std::filesystem::path& path);

// Loads and validates an OBJ or PLY mesh (Assimp parses; scene/mesh_file_loader.cpp).
// Polygons are triangulated, points and lines dropped, corners equal in every attribute
// merged. Throws lw::Error naming the file and the problem.
[[nodiscard]] Model load_mesh_file(const std::filesystem::path& path);

// load_mesh_file for .obj and .ply, load_gltf for everything else.
[[nodiscard]] Model load_model(const std::filesystem::path& path);

// A model of one triangle mesh given as arrays (the Python module's meshes): one root node
// at the identity, one primitive without a material. `name` stands for the file in errors
// and in line sets' "models". Checked as a file would be: at least one triangle, every index
// below the vertex count, finite positions, normals (when given) one per vertex and finite.
[[nodiscard]] Model model_from_arrays(const std::string& name, std::vector<glm::vec3> positions,
                                      std::vector<uint32_t> indices, std::vector<glm::vec3> normals = {});

// T × R × S, as glTF 2.0 §3.5.2 composes a node's local transform from its properties.
[[nodiscard]] glm::mat4 trs_matrix(const glm::vec3& t, const glm::quat& r, const glm::vec3& s);

// World transform of every node in the rest pose (local transforms composed from the roots).
[[nodiscard]] std::vector<glm::mat4> world_transforms(const Model& model);

// World transforms from any local transform per node (parent × child), guarded against bad
// parent indices and cycles; world_transforms and animated poses both compose through it.
[[nodiscard]] std::vector<glm::mat4> compose_world(const Model& model,
                                                   const std::function<glm::mat4(size_t node)>& local_of);

}  // namespace lw
