// engine/vector/layer.h — vector-art layers: 2D drawings placed over (or without) the 3D
// frame, moved by keyframed 2D transforms, drawn by the same stroke renderer as 3D lines.
//
// Input:  a `VectorLayerDesc` from a scene file (the stroke file, its style, keyframes) and
//         the drawing it names (`StrokeSet`, engine/vector/stroke_io.h).
// Output: per frame, `LayerFrame`: the strokes as screen paths in output pixels (cut to the
//         image and a small margin around it), sampled every `spacing` pixels (what the coherent parameterization splats and votes with),
//         each sample's drawing-space point in `position` so that the tracker can carry it to
//         the previous frame with the previous transform (Bénard et al. 2010 §4 in 2D), and
//         the filled regions as pixel triangles.
//
// A transform puts drawing point `center` at the middle of the image, scaled by `scale` and
// turned by `rotate` degrees (clockwise on screen, y down). Keyframes interpolate the centre
// and the angle linearly and the scale geometrically, so that a zoom runs at a constant rate
// (the SLAM paper's Fig. 5: a 16× zoom into a drawing).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lines/visibility.h"
#include "scene/camera.h"
#include "scene/layer_desc.h"
#include "vector/stroke.h"

namespace lw {

// The transform at `seconds` (clamped to the first and last keys).
[[nodiscard]] LayerTransform layer_transform_at(const std::vector<LayerKey>& keys, float seconds);

// Drawing point → output pixel.
[[nodiscard]] glm::vec2 layer_to_pixel(const LayerTransform& t, glm::vec2 point, glm::vec2 image_size);

// The same as camera matrices for the coherence tracker: drawing (x, y, 0) → clip space, so
// that project_to_pixel(layer_camera(t), (p, 0)) == layer_to_pixel(t, p).
[[nodiscard]] CameraMatrices layer_camera(const LayerTransform& t, glm::vec2 image_size);

struct LayerFrame {
    std::vector<ScreenPath> paths;     // visible, type Border (no contour rules); sample.width is
                                       // the point's width in pixels (strokes drawn with width 1)
    std::vector<glm::vec3> colors;     // per stroke; a path's is colors[path.source]
    std::vector<glm::vec2> fill;       // triangles, pixels
    CameraMatrices camera;             // layer_camera of this frame
};

// `fill_triangles`: the layer's fill in drawing space (triangulate_even_odd of its closed
// strokes, computed once). Strokes are sampled every `spacing` output pixels.
[[nodiscard]] LayerFrame layer_frame(const StrokeSet& drawing, const std::vector<glm::vec2>& fill_triangles,
                                     const VectorLayerDesc& desc, const LayerTransform& transform,
                                     glm::vec2 image_size, float spacing);

}  // namespace lw
