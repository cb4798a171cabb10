#include "render/line_sets.h"

#include <algorithm>

#include "stroke/modifiers.h"

namespace lw {

std::vector<LineSetDesc> effective_line_sets(const LinesDesc& lines) {
    if (!lines.sets.empty()) return lines.sets;
    std::vector<LineSetDesc> sets;
    for (int t = 0; t < kLineTypeCount; ++t) {
        const LineType type = LineType(t);
        const LineStyle& legacy = lines.styles[size_t(t)];
        LineSetDesc set{.name = line_type_name(type), .enabled = line_type_enabled(lines.params, type)};
        set.select.types = 1u << uint32_t(t);
        set.select.visibility = lines.hidden == HiddenLines::None ? Visibility::Visible : Visibility::Any;
        if (lines.hidden != HiddenLines::None && lines.hidden_levels > 0) set.select.qi = LevelRange{0, lines.hidden_levels};
        set.style.color = legacy.color;
        set.style.width = legacy.width;
        set.style.slam = legacy.slam;
        set.style.ribbon = legacy.ribbon;
        set.style.ribbon_scale = legacy.ribbon_scale;
        // The per-type "taper" tapers both ends (the stroke builder's symmetric taper).
        set.style.taper_in_px = set.style.taper_out_px = legacy.taper_px;
        if (!legacy.slam.empty()) set.style.cap = Cap::Butt;  // SLAM strokes end at their last sample
        set.coherence.length_scale = lines.length_scale;
        set.style.fade = true;  // the extraction already left alpha at 1 when "fade" is off
        sets.push_back(std::move(set));
    }
    return sets;
}

LineParams extraction_params(const LinesDesc& lines, const std::vector<LineSetDesc>& sets) {
    LineParams params = lines.params;
    for (int t = 0; t < kLineTypeCount; ++t) {
        bool wanted = false;
        for (const LineSetDesc& set : sets) wanted = wanted || (set.enabled && set.select.has_type(LineType(t)));
        // Shorthand sets carry the type's switch in `enabled`; explicit sets extract what
        // they select.
        set_line_type_enabled(params, LineType(t), wanted);
    }
    return params;
}

namespace {

bool path_in_groups(const ScreenPath& path, const LineSelection& select, const FaceGroups& groups) {
    // A path lies on the faces of its samples; it belongs where its first sample's face does
    // (runs are cut at visibility changes, not at group boundaries — a path crossing into
    // another material stays whole). An intersection line lies on two surfaces and belongs
    // to both: the line where a wall meets the floor is the wall's and the floor's.
    if (path.samples.empty()) return false;
    const auto listed = [](const std::vector<std::string>& list, const std::string& name) {
        return list.empty() || std::find(list.begin(), list.end(), name) != list.end();
    };
    const auto in_group_of = [&](uint32_t face) {
        if (face >= groups.face_group.size()) return false;
        const uint32_t group = groups.face_group[face];
        return listed(select.models, groups.model_names[group]) && listed(select.materials, groups.material_names[group]);
    };
    const ScreenSample& first = path.samples.front();
    return in_group_of(first.face) || (first.other_face != kNoFace && in_group_of(first.other_face));
}

}  // namespace

std::vector<ScreenPath> select_line_set(const std::vector<ScreenPath>& runs, const LineSetDesc& set,
                                        const FaceGroups* groups) {
    std::vector<ScreenPath> selected;
    if (!set.enabled) return selected;
    const LineSelection& select = set.select;
    const bool by_group = !select.models.empty() || !select.materials.empty();
    for (const ScreenPath& run : runs) {
        if (!select.has_type(run.type)) continue;
        if (select.qi) {
            if (run.qi < select.qi->min || run.qi > select.qi->max) continue;
        } else if ((select.visibility == Visibility::Visible && !run.visible) ||
                   (select.visibility == Visibility::Hidden && run.visible)) {
            continue;
        }
        if (by_group && (!groups || !path_in_groups(run, select, *groups))) continue;
        selected.push_back(run);
    }
    return apply_chaining_options(std::move(selected), set.style.chaining);
}

bool is_plain_line_set(const LineSetStyle& style) {
    return style.slam.empty() && style.dashes.empty() && style.taper_in_px == 0.0f && style.taper_out_px == 0.0f &&
           style.width_modifiers.empty() && style.alpha_modifiers.empty() && style.color_modifiers.empty() &&
           style.geometry.empty() && style.cap == Cap::Square && style.join == Join::Mitre;
}

bool draws_once(const LineSetStyle& style) { return style.alpha < 1.0f || !style.alpha_modifiers.empty(); }

bool needs_parameterization(const LineSetStyle& style) {
    if (!style.slam.empty() || !style.dashes.empty()) return true;
    return std::any_of(style.geometry.begin(), style.geometry.end(), [](const GeometryModifier& m) {
        return m.kind == GeometryModifier::Kind::Sinus || m.kind == GeometryModifier::Kind::Noise;
    });
}

CoherenceParams line_set_coherence(const CoherenceParams& base, const LineSetDesc& set, const Slam* slam,
                                   float scene_spacing_px) {
    CoherenceParams params = base;
    if (set.coherence.policy) params.policy = *set.coherence.policy;
    const float spacing = set.coherence.sample_spacing_px > 0.0f ? set.coherence.sample_spacing_px : scene_spacing_px;
    // The splat radius follows the set's own spacing when the set sets one (§4.1: sprites
    // of radius δ cover the gaps between samples δ apart).
    if (set.coherence.sample_spacing_px > 0.0f) params.splat_radius_px = 2.0f * spacing;
    if (slam) {
        params.slam_length_px = float(slam->length);
        params.length_scale = set.coherence.length_scale > 0.0f ? set.coherence.length_scale
                                                                : float(slam->height) / set.style.width;
    } else {
        params.length_scale = set.coherence.length_scale > 0.0f ? set.coherence.length_scale : 1.0f;
        params.slam_levels = false;
    }
    return params;
}

std::vector<PathParam> tiling_params(const std::vector<ScreenPath>& paths, const CoherenceParams& params) {
    std::vector<PathParam> out(paths.size());
    for (size_t p = 0; p < paths.size(); ++p) {
        out[p].rho = params.length_scale / params.slam_length_px;
        out[p].length_px = paths[p].samples.empty() ? 0.0f : paths[p].samples.back().s - paths[p].samples.front().s;
    }
    return out;
}

}  // namespace lw
