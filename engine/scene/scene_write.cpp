// engine/scene/scene_write.cpp — a SceneDesc and a camera back to scene JSON (the viewer's
// "save view"); load_scene_file reads what this writes.
#include <cmath>

#include <nlohmann/json.hpp>

#include "scene/scene_file.h"

namespace lw {

namespace {

using json = nlohmann::ordered_json;

// Six decimals: what a person would write, and floats print without binary noise.
double round6(float v) { return std::round(double(v) * 1e6) / 1e6; }
json vec3(const glm::vec3& v) { return json::array({round6(v.x), round6(v.y), round6(v.z)}); }

std::string relative_to(const std::filesystem::path& path, const std::filesystem::path& dir) {
    std::error_code ec;
    const auto absolute = std::filesystem::absolute(path, ec);
    if (ec) return path.string();
    const auto base = std::filesystem::absolute(dir.empty() ? std::filesystem::path(".") : dir, ec);
    if (ec) return absolute.string();
    const auto rel = absolute.lexically_normal().lexically_relative(base.lexically_normal());
    // A path that climbs to the root shares nothing with the folder: write it absolute.
    size_t ups = 0, depth = 0;
    for (const auto& part : rel) ups += part == "..";
    for (const auto& part : base.lexically_normal().relative_path()) depth += !part.empty();
    return rel.empty() || ups >= depth ? absolute.lexically_normal().string() : rel.generic_string();
}

const char* input_name(ModifierInput input) {
    return input == ModifierInput::Along ? "along" : input == ModifierInput::Distance ? "distance" : "curvature";
}

json scalar_modifiers(const std::vector<ScalarModifier>& modifiers) {
    json out = json::array();
    for (const ScalarModifier& m : modifiers) {
        json ramp = json::array();
        for (const glm::vec2& p : m.ramp.points) ramp.push_back({round6(p.x), round6(p.y)});
        json entry{{"input", input_name(m.input)},
                   {"ramp", ramp},
                   {"blend", m.blend == ModifierBlend::Multiply ? "multiply"
                             : m.blend == ModifierBlend::Replace ? "replace"
                                                                 : "add"}};
        if (m.input != ModifierInput::Along) entry["range"] = {round6(m.range_min), round6(m.range_max)};
        out.push_back(std::move(entry));
    }
    return out;
}

json color_modifiers(const std::vector<ColorModifier>& modifiers) {
    json out = json::array();
    for (const ColorModifier& m : modifiers) {
        json ramp = json::array();
        for (const auto& [x, c] : m.ramp.points) ramp.push_back({round6(x), vec3(c)});
        json entry{{"input", input_name(m.input)}, {"ramp", ramp}, {"influence", round6(m.influence)}};
        if (m.input != ModifierInput::Along) entry["range"] = {round6(m.range_min), round6(m.range_max)};
        out.push_back(std::move(entry));
    }
    return out;
}

json geometry_modifiers(const std::vector<GeometryModifier>& modifiers) {
    json out = json::array();
    for (const GeometryModifier& m : modifiers) {
        // Each kind's own keys (the reader refuses another kind's).
        const GeometryKindKeys& kind = geometry_kind_keys(m.kind);
        json entry{{"kind", kind.name}};
        for (size_t i = 0; i < kind.count; ++i) {
            const std::string key = kind.keys[i];
            if (key == "seed")
                entry[key] = m.seed;
            else
                entry[key] = round6(float(geometry_key_value(m, key)));
        }
        out.push_back(std::move(entry));
    }
    return out;
}

json line_set_style(const LineSetStyle& s, const std::filesystem::path& dest_dir) {
    json style{{"color", vec3(s.color)}, {"alpha", round6(s.alpha)}, {"width", round6(s.width)},
               {"cap", s.cap == Cap::Butt ? "butt" : s.cap == Cap::Round ? "round" : "square"},
               {"join", s.join == Join::Round ? "round" : "mitre"},
               {"taper_in", round6(s.taper_in_px)}, {"taper_out", round6(s.taper_out_px)}};
    if (!s.fade) style["fade"] = false;  // (the default is true; a set of types that do not fade is told it
                                         // changes nothing when the key is there)
    if (!s.slam.empty()) style["slam"] = relative_to(s.slam, dest_dir);
    if (!s.ribbon.empty()) style["ribbon"] = relative_to(s.ribbon, dest_dir);
    if (s.ribbon_scale > 0.0f) style["ribbon_scale"] = round6(s.ribbon_scale);
    if (!s.dashes.empty()) {
        json dashes = json::array();
        for (float d : s.dashes) dashes.push_back(round6(d));
        style["dashes"] = dashes;
    }
    if (!s.width_modifiers.empty()) style["width_modifiers"] = scalar_modifiers(s.width_modifiers);
    if (!s.alpha_modifiers.empty()) style["alpha_modifiers"] = scalar_modifiers(s.alpha_modifiers);
    if (!s.color_modifiers.empty()) style["color_modifiers"] = color_modifiers(s.color_modifiers);
    if (!s.geometry.empty()) style["geometry"] = geometry_modifiers(s.geometry);
    json chaining{{"split_angle", round6(s.chaining.split_angle_deg)}, {"min_length", round6(s.chaining.min_length_px)}};
    if (s.chaining.max_length_px > 0.0f) chaining["max_length"] = round6(s.chaining.max_length_px);
    if (s.chaining.outline) chaining["outline"] = true;
    style["chaining"] = chaining;
    return style;
}

// "line_sets" as scene_file.cpp reads them (line_set_file.cpp).
json line_sets(const std::vector<LineSetDesc>& sets, const std::filesystem::path& dest_dir) {
    json out = json::array();
    for (const LineSetDesc& set : sets) {
        json types = json::array();
        for (int t = 0; t < kLineTypeCount; ++t)
            if (set.select.has_type(LineType(t))) types.push_back(line_type_name(LineType(t)));
        const Visibility v = set.select.visibility;
        json select{{"types", types},
                    {"visibility", v == Visibility::Visible ? "visible" : v == Visibility::Hidden ? "hidden" : "any"}};
        if (const auto& q = set.select.qi) {
            select.erase("visibility");
            select["qi"] = {q->min, q->max};
        }
        if (!set.select.models.empty()) select["models"] = set.select.models;
        if (!set.select.materials.empty()) select["materials"] = set.select.materials;
        json coherence = json::object();
        if (const auto& p = set.coherence.policy) coherence["policy"] = param_policy_name(*p);
        if (set.coherence.length_scale > 0.0f) coherence["length_scale"] = round6(set.coherence.length_scale);
        if (set.coherence.sample_spacing_px > 0.0f) coherence["sample_spacing"] = round6(set.coherence.sample_spacing_px);
        out.push_back({{"name", set.name}, {"enabled", set.enabled}, {"select", select},
                       {"style", line_set_style(set.style, dest_dir)}, {"coherence", coherence}});
    }
    return out;
}

}  // namespace

std::string scene_json(const SceneDesc& desc, const ViewCamera& camera, const std::filesystem::path& dest_dir) {
    json root;
    if (!desc.description.empty()) root["description"] = desc.description;
    if (desc.models.size() == 1) {
        root["model"] = relative_to(desc.models.front(), dest_dir);
    } else if (!desc.models.empty()) {
        json models = json::array();
        for (const auto& m : desc.models) models.push_back(relative_to(m, dest_dir));
        root["model"] = models;
    }
    root["size"] = json::array({desc.width, desc.height});
    root["fov"] = round6(desc.fov_deg);
    json cam{{"eye", vec3(camera.eye)}, {"target", vec3(camera.target)}, {"up", vec3(camera.up)}, {"fov", round6(camera.fov_deg)}};
    if (camera.znear > 0.0f) cam["near"] = double(camera.znear);
    if (camera.zfar > 0.0f) cam["far"] = double(camera.zfar);
    root["camera"] = cam;
    const SurfaceStyle& style = desc.style;
    root["shading"] = !style.draw_surface                ? "none"
                      : style.shading == Shading::Flat  ? "flat"
                      : style.shading == Shading::Unlit ? "unlit"
                                                        : "toon";
    root["color"] = vec3(style.color);
    if (!style.materials) root["materials"] = false;
    root["background"] = style.transparent ? json("transparent") : vec3(style.background);
    if (style.samples != 0) root["samples"] = style.samples;

    const LinesDesc& lines = desc.lines;
    if (!lines.enabled) {
        root["lines"] = false;
    } else {
        json l;
        for (int t = 0; t < kLineTypeCount; ++t) {
            const LineType type = LineType(t);
            const LineStyle& s = lines.styles[size_t(t)];
            json entry{{"enabled", line_type_enabled(lines.params, type)}, {"width", round6(s.width)}, {"color", vec3(s.color)}};
            if (!s.slam.empty()) entry["slam"] = relative_to(s.slam, dest_dir);
            if (s.taper_px > 0.0f) entry["taper"] = round6(s.taper_px);
            if (!s.ribbon.empty()) entry["ribbon"] = relative_to(s.ribbon, dest_dir);
            if (s.ribbon_scale > 0.0f) entry["ribbon_scale"] = round6(s.ribbon_scale);
            if (const float* threshold = line_type_threshold(lines.params, type)) entry["threshold"] = round6(*threshold);
            if (type == LineType::Suggestive) entry["fade"] = lines.params.fade;
            if (type == LineType::Crease) entry["angle"] = round6(lines.params.crease_angle_deg);
            l[line_type_name(type)] = entry;
        }
        // Hidden-line settings style the shorthand's lines only (the reader refuses them beside
        // line sets), and levels only where hidden lines are drawn.
        if (lines.sets.empty()) {
            l["hidden"] = lines.hidden == HiddenLines::Dashed ? "dashed" : lines.hidden == HiddenLines::Faint ? "faint" : "none";
            if (lines.hidden_levels > 0 && lines.hidden != HiddenLines::None) l["hidden_levels"] = lines.hidden_levels;
        }
        l["sample_spacing"] = round6(lines.sample_spacing_px);
        if (lines.params.contours != ContourMode::Smooth) l["contours"] = contour_mode_name(lines.params.contours);
        if (lines.params.curvature != CurvatureFit::Exact) l["curvature"] = curvature_fit_name(lines.params.curvature);
        root["lines"] = l;
        if (!lines.sets.empty()) root["line_sets"] = line_sets(lines.sets, dest_dir);
    }
    json coherence = json::object();
    const SceneCoherence& c = desc.coherence;
    if (c.policy) coherence["policy"] = param_policy_name(*c.policy);
    if (c.splat_radius_px) coherence["splat_radius"] = round6(*c.splat_radius_px);
    if (c.inlier_px) coherence["inlier_distance"] = round6(*c.inlier_px);
    if (c.min_stroke_length_px) coherence["min_stroke_length"] = round6(*c.min_stroke_length_px);
    if (c.length_scale) coherence["length_scale"] = round6(*c.length_scale);
    if (!coherence.empty()) root["coherence"] = coherence;
    if (desc.animation.play) {
        json a{{"fps", round6(desc.animation.fps)}};
        const auto clip_json = [](const ClipChoice& clip) -> json {
            switch (clip.kind) {
                case ClipChoice::Kind::Name: return clip.name;
                case ClipChoice::Kind::Index: return clip.index;
                case ClipChoice::Kind::All: break;
            }
            return "all";
        };
        if (desc.animation.clips.size() == 1) {
            if (desc.animation.clips.front().kind != ClipChoice::Kind::All) a["clip"] = clip_json(desc.animation.clips.front());
        } else {
            for (const ClipChoice& clip : desc.animation.clips) a["clip"].push_back(clip_json(clip));
        }
        if (desc.animation.frames) a["frames"] = json::array({desc.animation.frames->first, desc.animation.frames->last});
        root["animation"] = a;
    }
    return root.dump(2) + "\n";
}

}  // namespace lw
