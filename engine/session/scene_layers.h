// engine/session/scene_layers.h — the vector-art layers of a scene, loaded for a session.
//
// Reads every layer's files once (the drawing, its SLAM or ribbon exemplar; errors name the
// file), triangulates its fill, and per frame places the drawing with the layer's keyframed
// transform (vector/layer.h). Ribbon layers are synthesized over the read-back frame.
#pragma once

#include <optional>
#include <vector>

#include "core/image.h"
#include "gpu/context.h"
#include "render/layer_pass.h"
#include "ribbon/exemplar.h"
#include "scene/scene_file.h"
#include "vector/stroke.h"

namespace lw {

struct SceneLayers {
    std::vector<VectorLayerDesc> descs;
    std::vector<StrokeSet> drawings;
    std::vector<std::vector<glm::vec2>> fills;      // triangles, drawing space
    std::vector<std::optional<Exemplar>> ribbons;
    std::vector<LayerStyle> styles;                 // for FrameRenderer::set_layers
};

[[nodiscard]] SceneLayers load_scene_layers(const SceneDesc& desc);

// This frame of every layer at `seconds` on the animation clock.
[[nodiscard]] std::vector<LayerFrame> scene_layer_frames(const SceneLayers& layers, float seconds, glm::vec2 size,
                                                         float spacing);

// Ribbon layers over the read-back colour; returns the time spent, ms.
double draw_layer_ribbons(const Context& ctx, const SceneLayers& layers, const std::vector<LayerResult>& results,
                          uint64_t seed, ImageRGBA8& image);

}  // namespace lw
