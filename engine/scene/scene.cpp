#include "scene/scene.h"

#include <algorithm>

#include "core/error.h"

namespace lw {

void append_mesh(TriangleMesh& mesh, const TriangleMesh& part) {
    const auto offset = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    mesh.indices.reserve(mesh.indices.size() + part.indices.size());
    for (uint32_t i : part.indices) mesh.indices.push_back(i + offset);
    mesh.face_material.insert(mesh.face_material.end(), part.face_material.begin(), part.face_material.end());
}

LoadedScene load_scene(const SceneDesc& desc) {
    std::vector<Model> models;
    for (const auto& path : desc.models) models.push_back(load_model(path));
    return load_scene(desc, std::move(models));
}

LoadedScene load_scene(const SceneDesc& desc, std::vector<Model> models) {
    if (models.empty()) throw Error("scene has no model");
    LoadedScene scene{.desc = desc};
    for (Model& loaded : models) {
        scene.models.push_back(std::move(loaded));
        const Model& model = scene.models.back();
        // The rest pose, skinned: a skinned mesh's node transform does not place it (glTF 2.0
        // §3.7.3), its joints do — RobotExpressive's hands sit at its wrists only so.
        const size_t before = scene.mesh.triangle_count();
        append_mesh(scene.mesh, flatten_posed(model, rest_pose(model)));
        scene.model_triangles.push_back(scene.mesh.triangle_count() - before);
    }
    if (scene.mesh.indices.empty()) throw Error(scene.models.front().path.string() + ": no triangles to draw");
    scene.bounds = compute_bounds(scene.mesh.positions);
    const float aspect = float(desc.width) / float(desc.height);
    scene.camera = desc.camera ? *desc.camera : frame_bounds(scene.bounds, aspect, desc.fov_deg);
    return scene;
}

TriangleMesh pose_scene(const LoadedScene& scene, float seconds) {
    TriangleMesh mesh;
    for (const Model& model : scene.models) {
        const std::vector<int> clips =
            scene.desc.animation.play ? select_clips(model, scene.desc.animation.clip) : std::vector<int>{};
        append_mesh(mesh, flatten_posed(model, clips.empty() ? rest_pose(model) : evaluate_pose(model, clips, seconds)));
    }
    return mesh;
}

float animation_duration(const LoadedScene& scene) {
    if (!scene.desc.animation.play) return 0.0f;
    float duration = 0.0f;
    for (const Model& model : scene.models)
        duration = std::max(duration, clips_duration(model, select_clips(model, scene.desc.animation.clip)));
    return duration;
}

}  // namespace lw
