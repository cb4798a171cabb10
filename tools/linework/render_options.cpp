#include "render_options.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "cli_numbers.h"
#include "core/log.h"
#include "core/random.h"
#include "render/line_sets.h"

namespace lw::cli {

void add_frame_options(CLI::App* cmd, RenderOptions& o) {
    add_scene_options(cmd, o.scene, true);
    cmd->add_option("--eye", o.eye, "Camera position x,y,z");
    cmd->add_option("--target", o.target, "Point looked at x,y,z");
    cmd->add_option("--up", o.up, "Up vector x,y,z (default 0,1,0)");
    cmd->add_option("--fov", o.fov, "Vertical field of view in degrees (default 40)");
    cmd->add_option("--shading", o.shading, "Surface shading")->check(CLI::IsMember({"flat", "toon", "unlit", "none"}));
    cmd->add_flag("--exr", o.exr, "Also write OUT/frame_0000.exr: RGBA in linear light, premultiplied, and Z, the eye "
                                  "depth in scene units (the largest float where nothing was drawn)");
    cmd->add_flag("--lines-only", o.lines_only, "Draw the lines over the background, without shading");
    cmd->add_flag("--no-lines", o.no_lines, "Shading only, no feature lines");
    cmd->add_flag("--no-materials", o.no_materials,
                  "Ignore the models' glTF materials: every face in the scene colour, opaque (scene key \"materials\": false)");
    cmd->add_option("--svg", o.svg, "Also write the lines as SVG, drawn as the PNG draws them (filled shapes per line set, hidden lines "
                    "in NAME-hidden, centre lines in a hidden NAME-centerlines group; under --frames FILE_NNNN.svg; its "
                    "folder is made if missing). Vector layers are not written to it")
        ->check(output_file_name(".svg"));
    cmd->add_option("--hidden", o.hidden,
                    "Hidden lines: none (default), dashed or faint (a scene with \"line_sets\" draws them in a set "
                    "that selects them, and refuses --hidden and --hidden-levels)")
        ->check(CLI::IsMember({"none", "dashed", "faint"}));
    cmd->add_option("--hidden-levels", o.hidden_levels,
                    "With --hidden: only hidden lines behind at most N surfaces (1: the first hidden level; 0, the "
                    "default: all), counted exactly by casting a ray per hidden sample (scene key lines.hidden_levels)")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                int n = -1;
                const char* end = text.data() + text.size();
                const auto [at, problem] = std::from_chars(text.data(), end, n);
                if (problem != std::errc() || at != end || n < 0 || n > 1000)
                    return "expected a whole number of surfaces, 0 to 1000 (0: all hidden lines), got \"" + text + "\"";
                return {};
            },
            "INT in [0 - 1000]"));
    cmd->add_option("--orbit", o.orbit, "Turn the camera DEG degrees about the bounding-box centre over the frames")
        ->check(within(-36000.0, 36000.0, "degrees"));
    cmd->add_option("--dump-paths", o.dump_paths,
                    "Write DIR/frame_NNNN.json per frame: visible paths, their line set, (ρ, φ), level and samples. "
                    "The dump needs every line set parameterized: a set whose strokes read no parameter (no SLAM, "
                    "dashes or displacement) is fitted for the dump alone (its pieces, without fragments under "
                    "--min-stroke-length, are what the dump holds) and drawn as without --dump-paths");
}

void apply_frame_overrides(const RenderOptions& o, SceneDesc& desc) {
    // Keyframes place every frame's camera: a flag that places it too would be dropped
    // (--eye, --target, --up, --fov) or would drop the keyframes (--orbit).
    if (desc.camera_path.kind == CameraPath::Kind::Keyframes)
        for (const auto& [given, flag] : {std::pair{o.orbit.has_value(), "--orbit"}, std::pair{!o.eye.empty(), "--eye"},
                                          std::pair{!o.target.empty(), "--target"}, std::pair{!o.up.empty(), "--up"},
                                          std::pair{o.fov.has_value(), "--fov"}})
            if (given)
                throw usage_error(std::string(flag) + ": " + o.scene.input +
                                  " moves its camera along \"camera_path\" keyframes; give the flag or the key, not both");
    if (o.fov) {
        if (!(*o.fov > 0.0f && *o.fov < 180.0f)) throw usage_error("--fov: must be between 0 and 180 degrees");
        desc.fov_deg = *o.fov;
        if (desc.camera) desc.camera->fov_deg = *o.fov;
    }
    if (!o.shading.empty()) {
        desc.style.draw_surface = o.shading != "none";
        desc.style.shading = o.shading == "flat" ? Shading::Flat : o.shading == "unlit" ? Shading::Unlit : Shading::Toon;
    }
    if (o.lines_only && o.no_lines) throw usage_error("--lines-only and --no-lines leave nothing to draw");
    if (o.lines_only && !o.shading.empty() && o.shading != "none")
        throw usage_error("--shading " + o.shading + " shades the surface, --lines-only draws none: give one");
    if (o.scene.lines && o.no_lines) throw usage_error("--lines chooses line types, --no-lines draws none: give one");
    // The flag that asks for hidden lines to be drawn, if any.
    const char* hidden_flag = o.hidden_levels.value_or(0) > 0 ? "--hidden-levels"
                              : !o.hidden.empty() && o.hidden != "none" ? "--hidden"
                                                                        : nullptr;
    if (o.no_lines && hidden_flag)
        throw usage_error(std::string(hidden_flag) + " styles hidden lines, --no-lines draws none: give one");
    if (o.lines_only) desc.style.draw_surface = false;
    if (o.no_lines) desc.lines.enabled = false;
    // A scene that draws no lines ("lines": false, no --lines) drops what styles or writes them
    // (the dumps still hold a scene's vector layers).
    if (!desc.lines.enabled && !o.no_lines)
        for (const auto& [given, flag] : {std::pair{hidden_flag != nullptr, hidden_flag ? hidden_flag : ""},
                                          std::pair{!o.svg.empty(), "--svg"},
                                          std::pair{!o.dump_paths.empty() && desc.layers.empty(), "--dump-paths"}})
            if (given)
                throw usage_error(std::string(flag) + ": " + o.scene.input +
                                  " draws no lines (\"lines\": false; --lines TYPE,... draws them)");
    if (o.no_lines)
        for (const auto& [given, flag] : {std::pair{!o.dump_paths.empty() && desc.layers.empty(), "--dump-paths"},
                                          std::pair{!o.scene.contours.empty(), "--contours"},
                                          std::pair{!o.scene.curvature.empty(), "--curvature"}, std::pair{!o.scene.slam.empty(), "--slam"}})
            if (given) throw usage_error(std::string(flag) + " shapes or writes lines, --no-lines draws none: give one");
    if (o.no_materials) desc.style.materials = false;
    if (!desc.lines.sets.empty() && hidden_flag) throw usage_error(std::string(hidden_flag) + " " + kHiddenBesideLineSets);
    if (!o.hidden.empty())
        desc.lines.hidden = o.hidden == "dashed" ? HiddenLines::Dashed : o.hidden == "faint" ? HiddenLines::Faint : HiddenLines::None;
    if (o.hidden_levels) {
        if (*o.hidden_levels > 0 && desc.lines.hidden == HiddenLines::None)
            throw usage_error("--hidden-levels: hidden lines are not drawn (add --hidden dashed or --hidden faint)");
        desc.lines.hidden_levels = uint32_t(*o.hidden_levels);
    }
    if (!o.svg.empty() && o.no_lines) throw usage_error("--svg needs lines (drop --no-lines)");
    // The SVG holds the 3D lines; layers are not in it (README "Scene files").
    if (!o.svg.empty() && desc.models.empty())
        throw usage_error("--svg writes a model's lines, and " + o.scene.input +
                          " has layers only (layers are not written as SVG; their stroke files are SVG already)");
    if (!o.svg.empty()) {
        // A ribbon is an image: its set is in the SVG as hidden centre lines only, and a scene
        // of ribbons alone gave a page that draws nothing, in silence.
        std::string ribbons;
        for (const LineSetDesc& set : effective_line_sets(desc.lines))
            if (set.enabled && !set.style.ribbon.empty()) ribbons += (ribbons.empty() ? "" : ", ") + set.name;
        if (!ribbons.empty())
            log_warning("--svg: the ribbon sets (" + ribbons + ") are written as centre lines only, in hidden groups "
                        "NAME-centerlines: a ribbon is an image, not strokes");
    }
    if (o.orbit) desc.camera_path = CameraPath{.kind = CameraPath::Kind::Orbit, .orbit = {.degrees = *o.orbit}};
}

CameraOverride camera_override(const RenderOptions& o) {
    CameraOverride c;
    if (!o.eye.empty()) c.eye = parse_vec3(o.eye, "--eye");
    if (!o.target.empty()) c.target = parse_vec3(o.target, "--target");
    if (!o.up.empty()) c.up = parse_vec3(o.up, "--up");
    if (c.up && !(glm::length(*c.up) > 0.0f)) throw usage_error("--up: " + o.up + ": a zero vector has no direction");
    return c;
}

namespace {

// The first line of input_files_signature: "file" lines, options in one spelling.
constexpr const char* kSignatureFormat = "signature format=2";

bool left_out(const CLI::Option& option, const std::vector<std::string>& except) {
    return option.count() == 0 || std::find(except.begin(), except.end(), option.get_name()) != except.end();
}

// A file or folder named by an option, as one spelling: `-o out/`, `-o ./out` and `-o
// /abs/out` are one folder, and a resume that spells it another way is the same render.
// (Absolute first: weakly_canonical leaves a relative path as it is while none of it exists,
// as an output folder the first render has yet to make.)
std::string one_spelling(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
    if (ec) return path;
    std::string text = canonical.lexically_normal().string();
    while (text.size() > 1 && text.back() == '/') text.pop_back();
    return text;
}

bool names_a_path(const std::string& option) {
    static const std::set<std::string> kPaths = {"input",         "--output",      "--slam", "--svg", "--dump-paths",
                                                 "--save-states", "--start-state"};
    return kPaths.contains(option);
}

}  // namespace

std::string given_options_signature(const CLI::App& cmd, const std::vector<std::string>& except,
                                    const std::vector<std::string>& presence) {
    std::string signature;
    for (const CLI::Option* option : cmd.get_options()) {
        if (left_out(*option, except)) continue;
        signature += option->get_name() + "=";
        if (std::ranges::find(presence, option->get_name()) != presence.end())
            signature += "given;";
        else
            for (const std::string& value : option->results())
                signature += (names_a_path(option->get_name()) ? one_spelling(value) : value) + ";";
        signature += "\n";
    }
    return signature;
}

namespace {

// A file's bytes as 64 bits (mix64 over 8-byte words and the length): only to tell an edited
// file from the one a state was saved with, not a cryptographic hash.
std::string file_hash(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "unreadable";
    uint64_t h = 0x6c696e65776f726bull;
    std::vector<char> buffer(1 << 16);
    uint64_t length = 0;
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        const size_t n = size_t(in.gcount());
        length += n;
        for (size_t i = 0; i < n; i += 8) {
            uint64_t word = 0;
            std::memcpy(&word, buffer.data() + i, std::min<size_t>(8, n - i));
            h = mix64(h ^ word);
        }
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(mix64(h ^ length)));
    return text;
}

// A glTF URI as a file name: "%20" is a space (glTF 2.0 §3.3, as tinygltf reads it).
std::string percent_decoded(const std::string& uri) {
    std::string name;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            name += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            name += uri[i];
        }
    }
    return name;
}

// A .gltf's external buffers and images (a .glb holds its own; a missing one failed the load).
std::vector<std::filesystem::path> gltf_companions(const std::filesystem::path& model) {
    std::vector<std::filesystem::path> files;
    if (model.extension() != ".gltf") return files;
    std::ifstream in(model);
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
    if (!doc.is_object()) return files;
    for (const char* array : {"buffers", "images"})
        if (const auto it = doc.find(array); it != doc.end() && it->is_array())
            for (const nlohmann::json& entry : *it)
                if (entry.is_object() && entry.contains("uri") && entry["uri"].is_string()) {
                    const std::string uri = entry["uri"].get<std::string>();
                    if (!uri.starts_with("data:")) files.push_back(model.parent_path() / percent_decoded(uri));
                }
    return files;
}

}  // namespace

std::string input_files_signature(const SceneDesc& desc, const std::string& slam_flag) {
    std::vector<std::filesystem::path> files;
    if (!desc.source.empty()) files.push_back(desc.source);
    for (const std::filesystem::path& model : desc.models) {
        files.push_back(model);
        for (std::filesystem::path& companion : gltf_companions(model)) files.push_back(std::move(companion));
    }
    const auto add = [&](const std::string& path) {
        if (!path.empty()) files.emplace_back(path);
    };
    add(slam_flag);
    for (const LineStyle& style : desc.lines.styles) {
        add(style.slam);
        add(style.ribbon);
    }
    for (const LineSetDesc& set : desc.lines.sets) {
        add(set.style.slam);
        add(set.style.ribbon);
    }
    for (const VectorLayerDesc& layer : desc.layers) {
        add(layer.strokes);
        add(layer.slam);
        add(layer.ribbon);
    }
    // Each file once, in one order, however the scene and the options spelled it.
    std::vector<std::pair<std::string, std::filesystem::path>> spelled;
    for (const std::filesystem::path& file : files) spelled.emplace_back(one_spelling(file.string()), file);
    std::ranges::sort(spelled);
    spelled.erase(std::unique(spelled.begin(), spelled.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
                  spelled.end());
    // The first line tells a state of this format from one saved before it recorded files.
    std::string signature = std::string(kSignatureFormat) + "\n";
    for (const auto& [name, file] : spelled) signature += "file " + name + "=" + file_hash(file) + "\n";
    return signature;
}

std::string signature_difference(const std::string& saved, const std::string& now) {
    // "NAME=VALUE" lines by name: an option ("--size") or a file ("file PATH").
    const auto lines = [](const std::string& signature) {
        std::map<std::string, std::string> by_name;
        size_t start = 0;
        for (size_t end; (end = signature.find('\n', start)) != std::string::npos; start = end + 1) {
            const std::string line = signature.substr(start, end - start);
            const size_t equals = line.find('=');
            by_name[line.substr(0, equals)] = equals == std::string::npos ? "" : line.substr(equals + 1);
        }
        return by_name;
    };
    const std::map<std::string, std::string> then = lines(saved), here = lines(now);
    const std::string format = std::string(kSignatureFormat).substr(0, std::string(kSignatureFormat).find('='));
    if (here.contains(format) && !then.contains(format))
        return "it was saved by an older linework, which did not record its input files: render the range again "
               "without --resume";
    const auto value = [](std::string v) {
        while (!v.empty() && v.back() == ';') v.pop_back();
        return v == "given" ? std::string() : v;  // an option counted by its presence
    };
    for (const auto& [name, was] : then) {
        const auto it = here.find(name);
        const bool file = name.starts_with("file ");
        const std::string what = file ? name.substr(5) : name;
        if (it == here.end())
            return file ? what + " was one of its input files, and is not now"
                        : what + (value(was).empty() ? "" : " " + value(was)) + " was given then, not now";
        if (it->second != was) return file ? what + " has changed since" : what + " was " + value(was) + " then, " + value(it->second) + " now";
    }
    for (const auto& [name, is] : here)
        if (!then.contains(name))
            return name.starts_with("file ") ? "it does not record the contents of " + name.substr(5)
                                             : name + (value(is).empty() ? "" : " " + value(is)) + " is given now, not then";
    return "the options are the same but in another form";
}

std::vector<std::string> given_arguments(const CLI::App& cmd, const std::vector<std::string>& except) {
    std::vector<std::string> positionals, named;
    for (const CLI::Option* option : cmd.get_options()) {
        if (left_out(*option, except)) continue;
        if (option->get_positional()) {
            for (const std::string& value : option->results()) positionals.push_back(value);
            continue;
        }
        // A flag takes no value; `--exr=false` is given but off, and stays out.
        if (option->get_items_expected_max() == 0) {
            if (option->as<bool>()) named.push_back(option->get_name());
            continue;
        }
        for (const std::string& value : option->results()) {
            named.push_back(option->get_name());
            named.push_back(value);
        }
    }
    positionals.insert(positionals.end(), named.begin(), named.end());
    return positionals;
}

}  // namespace lw::cli
