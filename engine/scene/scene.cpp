#include "scene/scene.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "core/log.h"

namespace lw {

void append_mesh(TriangleMesh& mesh, const TriangleMesh& part) {
    const auto offset = static_cast<uint32_t>(mesh.positions.size());
    if (!part.texcoords.empty() || !mesh.texcoords.empty()) {
        pad_texcoords(mesh);
        if (part.texcoords.empty()) {
            mesh.texcoords.resize(mesh.texcoords.size() + part.positions.size(), glm::vec2(0.0f));
        } else {
            mesh.texcoords.insert(mesh.texcoords.end(), part.texcoords.begin(), part.texcoords.end());
        }
    }
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    mesh.indices.reserve(mesh.indices.size() + part.indices.size());
    for (uint32_t i : part.indices) mesh.indices.push_back(i + offset);
    mesh.face_material.insert(mesh.face_material.end(), part.face_material.begin(), part.face_material.end());
    for (uint32_t p : part.face_part) mesh.face_part.push_back(mesh.part_count + p);
    mesh.part_count += part.part_count;
}

// The same, the part being the scene's model number `model`.
void append_model_mesh(TriangleMesh& mesh, const TriangleMesh& part, uint32_t model) {
    mesh.face_model.resize(mesh.triangle_count(), 0u);
    append_mesh(mesh, part);
    mesh.face_model.resize(mesh.triangle_count(), model);
}

namespace {

// Every model has the clips "animation" asks of it, checked once here rather than at the
// first posed frame. One clip for a scene of several models asks each of them for it.
void check_clips(const LoadedScene& scene) {
    const AnimationDesc& animation = scene.desc.animation;
    if (!animation.play) return;
    const std::string file = scene.desc.source.empty() ? std::string() : scene.desc.source.string() + ": ";
    if (animation.clips.size() != 1 && animation.clips.size() != scene.models.size())
        throw Error(file + "animation.clip: " + std::to_string(animation.clips.size()) + " clips for " +
                    std::to_string(scene.models.size()) + " models (one per model, in \"model\" order, or one for all)");
    const bool one_for_all = animation.clips.size() == 1;
    for (size_t m = 0; m < scene.models.size(); ++m) {
        try {
            (void)select_clips(scene.models[m], clip_of_model(animation, m));
        } catch (const Error& e) {
            // The model's own message names the model and its clips; the scene key says
            // which value asked for the clip.
            if (!one_for_all) throw Error(file + "animation.clip[" + std::to_string(m) + "]: " + e.what());
            if (scene.models.size() == 1) throw Error(file + "animation.clip: " + e.what());
            throw Error(file + "animation.clip: one clip for every model of the scene, and " + e.what() +
                        "; give one per model, in \"model\" order (\"all\" plays every clip of its model)");
        }
    }
}

}  // namespace

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
        append_model_mesh(scene.mesh, flatten_posed(model, rest_pose(model)), uint32_t(scene.models.size() - 1));
        scene.model_triangles.push_back(scene.mesh.triangle_count() - before);
    }
    if (scene.mesh.indices.empty()) throw Error(scene.models.front().path.string() + ": no triangles to draw");
    check_clips(scene);
    scene.bounds = compute_bounds(scene.mesh.positions);
    const float aspect = float(desc.width) / float(desc.height);
    scene.camera = desc.camera ? *desc.camera : frame_bounds(scene.bounds, aspect, desc.fov_deg);
    return scene;
}

TriangleMesh pose_scene(const LoadedScene& scene, float seconds) {
    TriangleMesh mesh;
    for (size_t m = 0; m < scene.models.size(); ++m) {
        const Model& model = scene.models[m];
        const std::vector<int> clips =
            scene.desc.animation.play ? select_clips(model, clip_of_model(scene.desc.animation, m)) : std::vector<int>{};
        append_model_mesh(mesh, flatten_posed(model, clips.empty() ? rest_pose(model) : evaluate_pose(model, clips, seconds)),
                          uint32_t(m));
    }
    return mesh;
}

float animation_duration(const LoadedScene& scene) {
    if (!scene.desc.animation.play) return 0.0f;
    float duration = 0.0f;
    for (size_t m = 0; m < scene.models.size(); ++m) {
        const Model& model = scene.models[m];
        duration = std::max(duration, clips_duration(model, select_clips(model, clip_of_model(scene.desc.animation, m))));
    }
    return duration;
}

std::vector<size_t> model_of_faces(const LoadedScene& scene, size_t triangles, int subdivide) {
    std::vector<size_t> model_of(triangles, 0);
    size_t first = 0;
    for (size_t m = 0; m < scene.model_triangles.size(); ++m) {
        const size_t count = scene.model_triangles[m] << (2 * subdivide);  // each subdivision ×4
        std::fill(model_of.begin() + std::ptrdiff_t(std::min(first, model_of.size())),
                  model_of.begin() + std::ptrdiff_t(std::min(first + count, model_of.size())), m);
        first += count;
    }
    return model_of;
}

SurfaceMaterials scene_materials(const LoadedScene& scene, const TriangleMesh& mesh, int subdivide, bool decode) {
    SurfaceMaterials out;
    std::vector<int32_t> first_of_model;
    for (const Model& model : scene.models) {
        first_of_model.push_back(int32_t(out.materials.size()));
        // Each image decoded (and later uploaded) once, however many materials share it (an
        // atlas usually is).
        std::map<int, std::pair<int32_t, std::string>> decoded;  // model image → index in out.images, or why not
        for (const Material& material : model.materials) {
            out.materials.push_back(material);
            out.material_image.push_back(-1);
            const int image = material.base_color_texture.image;
            if (!decode || !material.has_color) continue;
            if (image < 0) {
                if (!material.base_color_texture.problem.empty())
                    log_warning(material.base_color_texture.problem + "; material \"" + material.name +
                                "\" is drawn with its base colour factor");
                continue;
            }
            auto [it, first] = decoded.try_emplace(image, -1, std::string());
            if (first) {
                try {
                    out.images.push_back(decode_model_image(model, image));
                    it->second.first = int32_t(out.images.size() - 1);
                } catch (const Error& e) {
                    it->second.second = e.what();
                }
            }
            if (it->second.second.empty())
                out.material_image.back() = it->second.first;
            else
                log_warning(it->second.second + "; material \"" + material.name + "\" is drawn with its base colour factor");
        }
    }
    if (mesh.face_material.size() != mesh.triangle_count()) return out;
    const std::vector<size_t> model_of = model_of_faces(scene, mesh.triangle_count(), subdivide);
    out.face_material.resize(mesh.triangle_count(), -1);
    for (size_t t = 0; t < out.face_material.size(); ++t) {
        const int32_t local = mesh.face_material[t];
        const size_t model = model_of[t];
        if (local >= 0 && size_t(local) < scene.models[model].materials.size())
            out.face_material[t] = first_of_model[model] + local;
    }
    return out;
}

bool scene_needs_textures(const LoadedScene& scene, const SurfaceStyle& style) {
    if (!style.materials) return false;
    if (style.draw_surface) return true;
    for (const Model& model : scene.models)
        for (const Material& material : model.materials)
            if (material.alpha_mode == AlphaMode::Mask) return true;
    return false;
}

}  // namespace lw
