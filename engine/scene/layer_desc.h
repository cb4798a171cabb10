// engine/scene/layer_desc.h — a vector-art layer as a scene file describes it: the stroke
// file, its style and its keyframed 2D transform (README "Vector layers"). Drawing it is
// engine/vector/layer.h's and engine/render/layer_pass.h's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

struct LayerTransform {
    std::optional<glm::vec2> center;  // drawing point at the image centre (absent: the image centre, no move)
    float scale = 1.0f;
    float rotate_deg = 0.0f;
};

struct LayerKey {
    float time = 0.0f;  // seconds
    LayerTransform transform;
};

struct VectorLayerDesc {
    std::string strokes;               // stroke file, JSON or SVG (resolved against the scene file)
    std::optional<glm::vec3> color;    // replaces the file's stroke colours
    float width_scale = 1.0f;          // multiplies the file's widths
    bool scale_widths = false;         // widths follow the transform's scale (default: they
                                       // stay in output pixels, as a line drawing's do when zoomed)
    bool outline = true;               // draw the strokes
    std::optional<glm::vec3> fill;     // fill the closed strokes (even-odd) with this colour
    std::string slam;                  // SLAM file: coherent textured strokes (empty: solid)
    std::string ribbon;                // ribbon exemplar: a structured pattern along each stroke
    float ribbon_scale = 0.0f;         // exemplar pixels across the ribbon (0: the exemplar's default)
    float taper_px = 0.0f;
    std::vector<LayerKey> keys;        // sorted by time; empty: the identity transform
};

}  // namespace lw
