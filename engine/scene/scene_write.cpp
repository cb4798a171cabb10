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

}  // namespace

std::string scene_json(const SceneDesc& desc, const ViewCamera& camera, const std::filesystem::path& dest_dir) {
    json root;
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
    root["background"] = vec3(style.background);

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
            if (type == LineType::Suggestive) {
                entry["threshold"] = round6(lines.params.sug_thresh);
                entry["fade"] = lines.params.fade;
            }
            if (type == LineType::Crease) entry["angle"] = round6(lines.params.crease_angle_deg);
            l[line_type_name(type)] = entry;
        }
        l["hidden"] = lines.hidden == HiddenLines::Dashed ? "dashed" : lines.hidden == HiddenLines::Faint ? "faint" : "none";
        l["sample_spacing"] = round6(lines.sample_spacing_px);
        root["lines"] = l;
    }
    if (desc.animation.play) {
        json a{{"fps", round6(desc.animation.fps)}};
        if (desc.animation.clip.kind == ClipChoice::Kind::Name) a["clip"] = desc.animation.clip.name;
        if (desc.animation.clip.kind == ClipChoice::Kind::Index) a["clip"] = desc.animation.clip.index;
        if (desc.animation.frames) a["frames"] = json::array({desc.animation.frames->first, desc.animation.frames->last});
        root["animation"] = a;
    }
    return root.dump(2) + "\n";
}

}  // namespace lw
