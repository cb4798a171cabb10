// tools/linework/commands.h — the `linework` subcommands.
//
// Each subcommand registers its options on the CLI11 app and returns the function that
// runs it once the command line has been parsed. Runners return the process exit code and
// throw lw::Error for bad input (exit code 1) or bad usage (exit code 2).
#pragma once

#include <functional>
#include <initializer_list>
#include <utility>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "core/error.h"
#include "core/image.h"

namespace lw {
class Context;
struct LinesDesc;
struct Bounds;
}

namespace lw::cli {

using Runner = std::function<int()>;

Runner add_render_command(CLI::App& app);
Runner add_farm_command(CLI::App& app);
Runner add_diff_command(CLI::App& app);
Runner add_devices_command(CLI::App& app);
Runner add_slam_pattern_command(CLI::App& app);
Runner add_slam_command(CLI::App& app);
Runner add_coherence_report_command(CLI::App& app);
Runner add_ribbon_command(CLI::App& app);
Runner add_ribbon_exemplar_command(CLI::App& app);
Runner add_pattern_command(CLI::App& app);
Runner add_hatch_command(CLI::App& app);
Runner add_view_command(CLI::App& app);

// "1,2.5,-3" -> vec3; throws a usage error naming `option`.
glm::vec3 parse_vec3(const std::string& text, const std::string& option);
// "1920x1080" -> (1920, 1080); throws a usage error naming `option`.
glm::ivec2 parse_size(const std::string& text, const std::string& option, glm::ivec2 smallest = {1, 1},
                      glm::ivec2 largest = {kLargestImageSide, kLargestImageSide});
// --slam FILE --stroke-width W: silhouettes and suggestive contours (the shorthand's types,
// or every line set selecting either) as SLAM strokes of width W, tapered over 2W
// (replacing any ribbon style).
void use_slam_strokes(LinesDesc& lines, const std::string& slam, float width);
// For options that name a file to write (-o FILE.exr, --preview ...): a file name, in a
// folder that exists and can be written to, checked when the command line is parsed, so
// that a run does not fail at its last step after minutes of work (the message names the
// folder). render, view and farm make their folders instead (render's -o, --svg and
// --dump-paths).
// With `extension` (".png"), the name must end in it: the file is written in that format
// whatever it is called, and a wrong name would fail only after the work.
[[nodiscard]] CLI::Validator output_file(const std::string& extension = "");
// Only the file part: not an existing folder, not a name ending in "/", and with
// `extension` ending in it (render's --svg, whose folder render makes: an SVG named
// frame_0000.png replaced the frame it was named after).
[[nodiscard]] CLI::Validator output_file_name(const std::string& extension = "");

// frame_0007.png: a frame's file in a sequence (render's frames, EXRs and path dumps).
[[nodiscard]] std::string frame_name(int frame, const char* extension);

// A usage error when `output` names the same file as one of `inputs` (empty ones skipped):
// `hatch tr.svg -o tr.svg` wrote over the hand-drawn training it had just read.
void refuse_writing_over_input(const std::string& output, std::initializer_list<std::string> inputs,
                               const std::string& option = "-o");
// 1 (after one line on stderr) when validation was on and reported anything, else 0.
int exit_code_after_validation(const Context& ctx, bool validation);
// The "bounds:" line render and view print: the model's box in scene units (what a camera
// in the scene file is written against) and its centre, which the automatic camera looks at
// from the glTF front (+Z) and a little above.
void print_bounds(const Bounds& bounds);

// Runs f; an engine ParameterError about one of `flags` (engine name → flag, e.g.
// {"ribbon piece", "--piece"}) is re-thrown naming the flag that set it.
template <typename F>
auto flags_named(std::initializer_list<std::pair<const char*, const char*>> flags, F&& f) {
    try {
        return f();
    } catch (const ParameterError& e) {
        for (const auto& [name, flag] : flags)
            if (e.name() == name) throw Error(flag + e.rest(), e.exit_code());
        throw;
    }
}

// Runs f; an engine error that does not name its file is re-thrown with the file in front.
template <typename F>
auto naming(const std::string& file, F&& f) {
    try {
        return f();
    } catch (const Error& e) {
        const std::string m = e.what();
        if (m.rfind(file, 0) == 0) throw;
        throw Error(file + ": " + m, e.exit_code());
    }
}

}  // namespace lw::cli
