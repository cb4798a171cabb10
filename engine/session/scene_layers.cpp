#include "session/scene_layers.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/log.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "ribbon/ribbon_strokes.h"
#include "vector/fill.h"
#include "vector/stroke_io.h"

namespace lw {

SceneLayers load_scene_layers(const SceneDesc& desc) {
    SceneLayers layers;
    layers.descs = desc.layers;
    for (size_t i = 0; i < desc.layers.size(); ++i) {
        const VectorLayerDesc& layer = desc.layers[i];
        const std::string key = "layers[" + std::to_string(i) + "].";
        for (const auto& [name, path] : {std::pair{"strokes", &layer.strokes}, std::pair{"slam", &layer.slam},
                                         std::pair{"ribbon", &layer.ribbon}})
            check_key_file(desc, key + name, *path);
        StrokeSet drawing = read_key_file(desc, key + "strokes", [&] { return load_strokes(layer.strokes); });
        std::vector<std::vector<glm::vec2>> loops;
        for (const Stroke& stroke : drawing.strokes)
            if (stroke.closed) loops.push_back(stroke.points);
        if (layer.fill && loops.empty())  // the file decides, so said rather than refused
            log_warning(key_file_prefix(desc, key + "fill") + layer.strokes +
                        " has no closed stroke (an SVG path ending in Z, a polygon, a closed JSON stroke): nothing is "
                        "filled");
        layers.fills.push_back(layer.fill ? triangulate_even_odd(loops) : std::vector<glm::vec2>{});

        LayerStyle style{.taper_px = layer.taper_px, .strokes = layer.outline && layer.ribbon.empty(),
                         .fill_color = layer.fill.value_or(glm::vec3(0.0f))};
        if (!layer.slam.empty()) {
            style.slam = read_key_file(desc, key + "slam", [&] { return read_slam(layer.slam); });
            // κ: square texels over the drawing's typical stroke width, as for 3D strokes.
            std::vector<float> widths;
            for (const Stroke& stroke : drawing.strokes) widths.push_back(mean_width(stroke) * layer.width_scale);
            std::nth_element(widths.begin(), widths.begin() + std::ptrdiff_t(widths.size() / 2), widths.end());
            const float width = widths.empty() ? 1.0f : std::max(widths[widths.size() / 2], 0.5f);
            style.coherence.slam_length_px = float(style.slam->length);
            style.coherence.length_scale = float(style.slam->height) / width;
        }
        layers.ribbons.push_back(layer.ribbon.empty() ? std::nullopt : std::optional(read_key_file(desc, key + "ribbon", [&] {
            return make_exemplar(read_image_rgba8(layer.ribbon), layer.ribbon);
        })));
        layers.styles.push_back(std::move(style));
        layers.drawings.push_back(std::move(drawing));
    }
    return layers;
}

std::vector<LayerFrame> scene_layer_frames(const SceneLayers& layers, float seconds, glm::vec2 size, float spacing) {
    std::vector<LayerFrame> frames;
    for (size_t i = 0; i < layers.descs.size(); ++i) {
        const VectorLayerDesc& desc = layers.descs[i];
        VectorLayerDesc placed = desc;
        placed.outline = desc.outline || !desc.ribbon.empty();  // ribbons follow the stroke paths
        frames.push_back(layer_frame(layers.drawings[i], layers.fills[i], placed,
                                     layer_transform_at(desc.keys, seconds), size, spacing));
    }
    return frames;
}

double draw_layer_ribbons(const Context& ctx, const SceneLayers& layers, const std::vector<LayerResult>& results,
                          uint64_t seed, ImageRGBA8& image) {
    double ms = 0.0;
    for (size_t i = 0; i < layers.descs.size() && i < results.size(); ++i) {
        if (!layers.ribbons[i]) continue;
        // The ribbon is as wide as the drawing's strokes (their median width).
        std::vector<float> widths;
        for (const ScreenPath& path : results[i].paths)
            for (const ScreenSample& sample : path.samples) widths.push_back(sample.width);
        if (widths.empty()) continue;
        std::nth_element(widths.begin(), widths.begin() + std::ptrdiff_t(widths.size() / 2), widths.end());
        const RibbonStrokeStats stats =
            draw_ribbon_strokes(ctx, results[i].paths, std::nullopt, *layers.ribbons[i],
                                {.width = std::max(widths[widths.size() / 2], 2.0f),
                                 .scale = layers.descs[i].ribbon_scale, .seed = seed},
                                image);
        ms += stats.ms;
    }
    return ms;
}

}  // namespace lw
