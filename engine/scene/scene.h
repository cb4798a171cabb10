// engine/scene/scene.h — a scene description made concrete: models loaded, geometry merged.
//
// Input:  `SceneDesc` (scene file or bare model).
// Output: `LoadedScene` — the validated models, every mesh instance in world space merged
//         into one `TriangleMesh` (rest pose), its bounds, and the camera to render with
//         (the scene's own, or one framing the bounds).
#pragma once

#include <vector>

#include "scene/animation.h"
#include "scene/camera.h"
#include "scene/model.h"
#include "scene/scene_file.h"
#include "scene/style.h"
#include "scene/triangle_mesh.h"

namespace lw {

struct LoadedScene {
    SceneDesc desc;
    std::vector<Model> models;
    TriangleMesh mesh;
    std::vector<size_t> model_triangles;  // triangles of each model, in mesh order
    Bounds bounds;
    ViewCamera camera;
};

[[nodiscard]] LoadedScene load_scene(const SceneDesc& desc);
// The same with the models already in memory (meshes given as arrays), in place of reading
// `desc.models`; each model's path names it.
[[nodiscard]] LoadedScene load_scene(const SceneDesc& desc, std::vector<Model> models);

// The scene's geometry at `seconds` on the animation clock: every model posed by its
// selected clips (the scene's "animation"), skinned; the rest pose when nothing plays.
// Vertex and triangle order are the same at every time (coherence relies on it).
[[nodiscard]] TriangleMesh pose_scene(const LoadedScene& scene, float seconds);

// The longest selected clip over the scene's models, seconds (0 when nothing plays).
[[nodiscard]] float animation_duration(const LoadedScene& scene);

// The model each triangle of `triangles` comes from, for the scene's merged mesh after
// `subdivide` midpoint subdivisions (each ×4 triangles, in place).
[[nodiscard]] std::vector<size_t> model_of_faces(const LoadedScene& scene, size_t triangles, int subdivide);

// The materials `mesh` (the scene's merged mesh, `subdivide`d) is drawn with: every model's
// materials one after another, each triangle pointing into that list; with `decode`, the
// base colour textures too. A texture that cannot be read costs its texels, not the render:
// the material keeps its factor and a warning names the image.
[[nodiscard]] SurfaceMaterials scene_materials(const LoadedScene& scene, const TriangleMesh& mesh, int subdivide,
                                               bool decode);

// Whether drawing with `style` reads the materials' textures: a shaded surface, or holes.
[[nodiscard]] bool scene_needs_textures(const LoadedScene& scene, const SurfaceStyle& style);

// Appends `part` to `mesh` (indices offset).
void append_mesh(TriangleMesh& mesh, const TriangleMesh& part);

}  // namespace lw
