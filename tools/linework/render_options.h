// tools/linework/render_options.h — the options of `linework render`, split in two: those
// that shape the frames (the scene, camera, style, lines, dumps) and those that only choose
// which frames are drawn and where they go (output folder, range, part, warm-up, saved
// states). `linework farm` takes the first kind as they are and hands them on to every task.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene_options.h"

namespace lw::cli {

struct RenderOptions {
    SceneOptions scene;
    // Frame-shaping (add_frame_options).
    std::string eye, target, up, shading, svg, hidden, dump_paths;
    std::optional<float> fov, orbit;
    std::optional<int> hidden_levels;
    bool exr = false, lines_only = false, no_lines = false, no_materials = false;
    // Range and output (registered by `render` only).
    std::string output, frames, part, save_states, start_state;
    bool resume = false, state_only = false;
    int warmup = 0, chunk = 0;
    // The options as given, less --resume: what a resumed run must repeat (--resume checks it).
    std::string signature;
    // The options that shape the temporal state, less range and output: what a state saved
    // by --save-states must have been saved with to start another command (--start-state).
    std::string state_signature;
};

// The scene options and every option that shapes the frames, on `cmd` (render and farm).
void add_frame_options(CLI::App* cmd, RenderOptions& o);

// Options of `cmd` that were given, as "--name=v1;v2;\n" lines in registration order (so
// the order on the command line does not matter), leaving out those named in `except` and
// counting those in `presence` by their presence alone (the state a farm part starts from:
// `--dump-paths` changes the frames, every line set is parameterized, but its folder is an
// output a part may choose; a resumed render keeps the folder, so its dumps stay together).
[[nodiscard]] std::string given_options_signature(const CLI::App& cmd, const std::vector<std::string>& except,
                                                  const std::vector<std::string>& presence = {});

// What the options cannot say: the contents of every file the frames are made from (the
// scene file, its models with a .gltf's buffers and images, and the SLAMs, ribbon
// exemplars and stroke files its keys or --slam name), as "file PATH=HASH\n" lines. Appended
// to the signatures, so that --resume and --start-state refuse a state made before one of
// them was edited instead of drawing on from frames of another scene.
[[nodiscard]] std::string input_files_signature(const SceneDesc& desc, const std::string& slam_flag);

// Why a saved signature is not this command's, for its error: the first option or file that
// differs ("--size was 320x240 then", "spot.json has changed since").
[[nodiscard]] std::string signature_difference(const std::string& saved, const std::string& now);

// The given options of `cmd` again as arguments (the positional first), leaving out those
// named in `except`: what `farm` puts on each task's command line.
[[nodiscard]] std::vector<std::string> given_arguments(const CLI::App& cmd, const std::vector<std::string>& except);

// Which frames are drawn and where they go: not part of a saved state's signature. The
// range (--frames) is: the camera path's progress and the state's history span it.
inline const std::vector<std::string> kRangeOptions = {"--output",      "--part",  "--warmup",     "--resume",
                                                       "--state-only",  "--save-states", "--chunk", "--start-state",
                                                       "--exr",         "--svg"};

// The overrides of the scene description the frame options make (a partial camera, only
// --eye, keeps the framed target); usage errors name the flag.
void apply_frame_overrides(const RenderOptions& o, SceneDesc& desc);
[[nodiscard]] CameraOverride camera_override(const RenderOptions& o);

}  // namespace lw::cli
