#include "render_options.h"

#include <algorithm>

namespace lw::cli {

void add_frame_options(CLI::App* cmd, RenderOptions& o) {
    add_scene_options(cmd, o.scene, true);
    cmd->add_option("--eye", o.eye, "Camera position x,y,z");
    cmd->add_option("--target", o.target, "Point looked at x,y,z");
    cmd->add_option("--up", o.up, "Up vector x,y,z (default 0,1,0)");
    cmd->add_option("--fov", o.fov, "Vertical field of view in degrees (default 40)");
    cmd->add_option("--shading", o.shading, "Surface shading")->check(CLI::IsMember({"flat", "toon", "unlit", "none"}));
    cmd->add_flag("--exr", o.exr, "Also write OUT/frame_0000.exr (RGBA + depth channel Z)");
    cmd->add_flag("--lines-only", o.lines_only, "Draw the lines over the background, without shading");
    cmd->add_flag("--no-lines", o.no_lines, "Shading only, no feature lines");
    cmd->add_option("--svg", o.svg, "Also write the visible lines as SVG (pixel coordinates, one <g> per line set)");
    cmd->add_option("--hidden", o.hidden, "Hidden lines: none (default), dashed or faint")
        ->check(CLI::IsMember({"none", "dashed", "faint"}));
    cmd->add_option("--orbit", o.orbit, "Turn the camera DEG degrees about the bounding-box centre over the frames");
    cmd->add_option("--dump-paths", o.dump_paths,
                    "Write DIR/frame_NNNN.json per frame: visible paths, their line set, (ρ, φ), level and samples");
}

namespace {

bool left_out(const CLI::Option& option, const std::vector<std::string>& except) {
    return option.count() == 0 || std::find(except.begin(), except.end(), option.get_name()) != except.end();
}

}  // namespace

std::string given_options_signature(const CLI::App& cmd, const std::vector<std::string>& except) {
    std::string signature;
    for (const CLI::Option* option : cmd.get_options()) {
        if (left_out(*option, except)) continue;
        signature += option->get_name() + "=";
        for (const std::string& value : option->results()) signature += value + ";";
        signature += "\n";
    }
    return signature;
}

std::vector<std::string> given_arguments(const CLI::App& cmd, const std::vector<std::string>& except) {
    std::vector<std::string> positionals, named;
    for (const CLI::Option* option : cmd.get_options()) {
        if (left_out(*option, except)) continue;
        if (option->get_positional()) {
            for (const std::string& value : option->results()) positionals.push_back(value);
            continue;
        }
        // A flag takes no value: CLI11 records "true" (or a count) for it.
        if (option->get_items_expected_max() == 0) {
            named.push_back(option->get_name());
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
