// tools/linework/scene_options.h — the command-line options `render` and `view` share, and
// what they make: the scene description with the overrides applied, the session's options
// and the Vulkan context's. Flags live here, in tools/; the engine speaks in scene keys.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "gpu/context.h"
#include "scene/scene_file.h"
#include "session/scene_session.h"

namespace lw::cli {

struct SceneOptions {
    std::string input;
    std::string device = "auto";
    std::string compute = "auto";
    std::string size;
    std::string background;  // a colour, "transparent", or empty: the scene's
    int samples = 0;         // 1, 4 or 8; 0: the scene's
    std::optional<std::string> lines;  // --lines TYPE,TYPE,...: the types drawn (none: the scene's)
    std::string contours;  // --contours smooth|mesh|auto (empty: the scene's)
    std::string curvature;  // --curvature exact|trimesh2 (empty: the scene's)
    std::string slam;
    float stroke_width = 6.0f;
    // The parameterization's flags; each unset (empty, 0, absent) leaves the scene's
    // "coherence" key, else the default.
    std::string param;
    float splat_radius = 0.0f;
    std::optional<float> inlier_px;
    std::optional<float> min_stroke_length;
    float length_scale = 0.0f;
    bool validation = false;
};

// Registers the shared options on `cmd` (render: `offline` adds the ones only it has).
void add_scene_options(CLI::App* cmd, SceneOptions& o, bool offline);

// The scene file or bare model with --size and --slam applied; errors name the file.
[[nodiscard]] SceneDesc scene_from_options(const SceneOptions& o);
// Offline renders: a flag that shapes only line types `lines` does not draw (--contours
// without silhouettes, --slam without silhouettes or suggestive contours, --curvature with
// only creases, borders, material boundaries or intersections) changes nothing, and is
// refused as the flags that style lines on a render without lines are. (The viewer takes
// them: its panel can turn the types on.)
void check_flags_shape_drawn_lines(const SceneOptions& o, const LinesDesc& lines);

// The surface's samples per pixel against the device, before the first frame, named where
// the count came from: --samples, the scene's "samples" key, or the default.
void check_samples_on_device(const Context& ctx, const SceneOptions& o, const SceneDesc& desc);
// Policy, splat radius, RANSAC inlier distance, fragment length and κ.
[[nodiscard]] SessionOptions session_options(const SceneOptions& o, const SceneDesc& desc);
[[nodiscard]] bool validation_on(const SceneOptions& o);

}  // namespace lw::cli
