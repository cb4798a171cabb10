#include "scene/scene.h"

#include "core/error.h"

namespace lw {

void append_mesh(TriangleMesh& mesh, const TriangleMesh& part) {
    const auto offset = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    mesh.indices.reserve(mesh.indices.size() + part.indices.size());
    for (uint32_t i : part.indices) mesh.indices.push_back(i + offset);
}

LoadedScene load_scene(const SceneDesc& desc) {
    if (desc.models.empty()) throw Error("scene has no model");
    LoadedScene scene{.desc = desc};
    for (const auto& path : desc.models) {
        scene.models.push_back(load_gltf(path));
        const Model& model = scene.models.back();
        append_mesh(scene.mesh, flatten(model, world_transforms(model)));
    }
    if (scene.mesh.indices.empty()) throw Error(desc.models.front().string() + ": no triangles to draw");
    scene.bounds = compute_bounds(scene.mesh.positions);
    const float aspect = float(desc.width) / float(desc.height);
    scene.camera = desc.camera ? *desc.camera : frame_bounds(scene.bounds, aspect, desc.fov_deg);
    return scene;
}

}  // namespace lw
