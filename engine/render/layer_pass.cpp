#include "render/layer_pass.h"

#include <algorithm>

#include "core/error.h"
#include "stroke/modifiers.h"

namespace lw {

namespace {

// A layer's strokes are drawn as the SVG writer writes them (stroke-linecap and -linejoin
// round): round caps, so that a stipple (one point, or a stroke of a pixel) is a dot of its
// width and not a one-pixel tick; round joins; the point widths of the file; the layer's
// taper at both ends (to 15 % at the tips, as line sets taper).
LineSetStyle layer_stroke_style(const LayerStyle& style, const glm::vec3& color) {
    LineSetStyle s;
    s.color = color;
    s.width = 1.0f;  // × each sample's width, the file's
    s.cap = Cap::Round;
    s.join = Join::Round;
    s.taper_in_px = s.taper_out_px = style.taper_px;
    s.fade = false;
    return s;
}

}  // namespace

LayerPass::LayerPass(const Context& ctx, uint32_t width, uint32_t height, std::vector<LayerStyle> styles)
    : solid_(std::make_unique<SlamTexture>(ctx, solid_slam())) {
    for (LayerStyle& style : styles) {
        Layer layer{.style = std::move(style)};
        if (layer.style.slam) {
            layer.texture = std::make_unique<SlamTexture>(ctx, *layer.style.slam);
            layer.tracker = std::make_unique<CoherenceTracker>(ctx, width, height);
        }
        layers_.push_back(std::move(layer));
    }
}

std::vector<LayerResult> LayerPass::prepare(std::vector<LayerFrame>& frames, bool coherent, float spacing) {
    if (frames.size() != layers_.size()) throw Error("LayerPass: one LayerFrame per layer expected");
    std::vector<LayerResult> results(frames.size());
    for (size_t i = 0; i < layers_.size(); ++i) {
        Layer& layer = layers_[i];
        LayerFrame& frame = frames[i];
        LayerResult& result = results[i];
        layer.fill.clear();
        layer.strokes.clear();
        layer.plain.clear();
        for (const glm::vec2& p : frame.fill)
            layer.fill.push_back({p, glm::vec3(0.0f, 0.5f, 1.0f), glm::vec4(layer.style.fill_color, 1.0f), kInteriorEdge});
        if (layer.tracker) {
            CoherenceParams params = layer.style.coherence;
            if (!coherent) params.policy = ParamPolicy::Arclength;
            // The artist's dots and short dashes are not fragments of an extraction: they
            // are drawn solid rather than dropped with them.
            const auto short_end = std::stable_partition(frame.paths.begin(), frame.paths.end(), [&](const ScreenPath& path) {
                return too_short_for_texture(path, params);
            });
            for (auto path = frame.paths.begin(); path != short_end && layer.style.strokes; ++path) {
                const LineSetStyle style = layer_stroke_style(layer.style, frame.colors[path->source]);
                append_stroke(*path, StrokeParams{}, evaluate_attributes(*path, style), style.cap, style.join, layer.plain);
            }
            frame.paths.erase(frame.paths.begin(), short_end);
            result.params = layer.tracker->update(frame.paths, frame.camera, {}, params);
            for (size_t p = 0; p < frame.paths.size(); ++p)
                frame.paths[p] = resample_at_phase(frame.paths[p], result.params[p], spacing);
        } else {
            result.params.assign(frame.paths.size(), PathParam{});
        }
        for (size_t p = 0; p < frame.paths.size() && layer.style.strokes; ++p) {
            const PathParam& param = result.params[p];
            const LineSetStyle style = layer_stroke_style(layer.style, frame.colors[frame.paths[p].source]);
            append_stroke(frame.paths[p], StrokeParams{.rho = param.rho, .phi = param.phi, .fold = param.fold},
                          evaluate_attributes(frame.paths[p], style), style.cap, style.join, layer.strokes);
        }
        result.paths = frame.paths;
    }
    return results;
}

std::vector<std::optional<CoherenceTracker::State>> LayerPass::states() const {
    std::vector<std::optional<CoherenceTracker::State>> out;
    for (const Layer& layer : layers_)
        out.push_back(layer.tracker ? std::optional(layer.tracker->state()) : std::nullopt);
    return out;
}

void LayerPass::restore(const std::vector<std::optional<CoherenceTracker::State>>& states) {
    if (states.size() != layers_.size()) throw Error("the saved state has " + std::to_string(states.size()) +
                                                     " layers, the scene " + std::to_string(layers_.size()));
    for (size_t i = 0; i < layers_.size(); ++i) {
        if (bool(states[i]) != bool(layers_[i].tracker)) throw Error("the saved state's layers differ from the scene's");
        if (states[i]) layers_[i].tracker->restore(*states[i], {});
    }
}

void LayerPass::record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target, const StrokePass& strokes,
                       UploadArena& arena) const {
    for (const Layer& layer : layers_) {
        if (!layer.fill.empty()) strokes.record(ctx, cmd, target, layer.fill, *solid_, arena);
        if (!layer.plain.empty()) strokes.record(ctx, cmd, target, layer.plain, *solid_, arena);
        if (!layer.strokes.empty())
            strokes.record(ctx, cmd, target, layer.strokes, layer.texture ? *layer.texture : *solid_, arena);
    }
}

}  // namespace lw
