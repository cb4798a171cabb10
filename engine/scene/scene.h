// engine/scene/scene.h — a scene description made concrete: models loaded, geometry merged.
//
// Input:  `SceneDesc` (scene file or bare model).
// Output: `LoadedScene` — the validated models, every mesh instance in world space merged
//         into one `TriangleMesh` (rest pose), its bounds, and the camera to render with
//         (the scene's own, or one framing the bounds).
#pragma once

#include <vector>

#include "scene/camera.h"
#include "scene/model.h"
#include "scene/scene_file.h"
#include "scene/triangle_mesh.h"

namespace lw {

struct LoadedScene {
    SceneDesc desc;
    std::vector<Model> models;
    TriangleMesh mesh;
    Bounds bounds;
    ViewCamera camera;
};

[[nodiscard]] LoadedScene load_scene(const SceneDesc& desc);

// Appends `part` to `mesh` (indices offset).
void append_mesh(TriangleMesh& mesh, const TriangleMesh& part);

}  // namespace lw
