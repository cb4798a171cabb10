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
        layer.runs.clear();
        // Appends a stroke to the run of its kind, starting a new run where the kind changes.
        const auto append = [&](const ScreenPath& path, const PathParam& param, bool solid) {
            if (layer.runs.empty() || layer.runs.back().solid != solid) layer.runs.push_back({.solid = solid});
            const LineSetStyle style = layer_stroke_style(layer.style, frame.colors[path.source]);
            append_stroke(path, StrokeParams{.rho = param.rho, .phi = param.phi, .fold = param.fold},
                          evaluate_attributes(path, style), style.cap, style.join, layer.runs.back().vertices);
        };
        std::vector<ScreenPath> short_paths;  // in file order (by source)
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
            short_paths.assign(std::make_move_iterator(frame.paths.begin()), std::make_move_iterator(short_end));
            frame.paths.erase(frame.paths.begin(), short_end);
            result.params = layer.tracker->update(frame.paths, frame.camera, {}, params);
            for (size_t p = 0; p < frame.paths.size(); ++p)
                frame.paths[p] = resample_at_phase(frame.paths[p], result.params[p], spacing);
        } else {
            result.params.assign(frame.paths.size(), PathParam{});
        }
        // The textured strokes in the tracker's order, each solid one drawn before the first
        // textured stroke that comes after it in the file.
        size_t next_short = 0;
        for (size_t p = 0; p < frame.paths.size() && layer.style.strokes; ++p) {
            for (; next_short < short_paths.size() && short_paths[next_short].source < frame.paths[p].source; ++next_short)
                append(short_paths[next_short], PathParam{}, true);
            append(frame.paths[p], result.params[p], false);
        }
        for (; next_short < short_paths.size() && layer.style.strokes; ++next_short)
            append(short_paths[next_short], PathParam{}, true);
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
        for (const Layer::Run& run : layer.runs)
            strokes.record(ctx, cmd, target, run.vertices, run.solid || !layer.texture ? *solid_ : *layer.texture, arena);
    }
}

}  // namespace lw
