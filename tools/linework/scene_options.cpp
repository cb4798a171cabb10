#include "scene_options.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "commands.h"
#include "cli_numbers.h"
#include "core/color.h"
#include "gpu/render_target.h"
#include "io/slam_io.h"
#include "render/line_sets.h"

namespace lw::cli {

void add_scene_options(CLI::App* cmd, SceneOptions& o, bool offline) {
    cmd->add_option("input", o.input, "Scene file (.json) or model (.gltf, .glb, .obj, .ply)")->required();
    cmd->add_option("--device", o.device,
                    "auto (discrete GPU if present, else lavapipe), cpu, gpu, or an index from `linework devices`")
        ->capture_default_str();
    cmd->add_option("--compute", o.compute, kComputeSiteHelp)->capture_default_str();
    cmd->add_option("--size", o.size, offline ? "Image size WxH (default: the scene's, else 960x720)"
                                              : "Window size WxH (default: the scene's, else 960x720)");
    cmd->add_option("--background", o.background,
                    "Background: a colour (#rrggbb, #rgb, rgb(r, g, b), a colour name) or \"transparent\": alpha 0 "
                    "where nothing is drawn, PNGs with straight alpha and EXRs premultiplied, to composite the "
                    "lines over a plate (default: the scene's \"background\", else white)");
    cmd->add_option("--samples", o.samples,
                    "Samples per pixel of the shaded surface: 1, 4 or 8 (MSAA; lines and strokes are antialiased "
                    "by their own coverage whatever this is; default: the scene's \"samples\", else 4, but 1 in the viewer on a "
                    "CPU device)")
        ->check(CLI::IsMember({1, 4, 8}));
    cmd->add_option("--lines", o.lines,
                    "Line types to draw, comma-separated, instead of the scene's: silhouette, suggestive, crease, border "
                    "(the default four), rtsc's ridge, valley, apparent_ridge, suggestive_highlight, "
                    "principal_highlight, material_boundary and intersection (scene keys lines.TYPE; README \"Line types\"). "
                    "A scene with \"line_sets\" selects its types in them, and refuses --lines");
    cmd->add_option("--contours", o.contours,
                    "Silhouettes as the smooth zero set of n·v (rtsc's; the default), the mesh's own edges between front- "
                    "and back-facing faces (a closed outline of a low-poly model), or auto: mesh on models whose faces are "
                    "coarse (median angle between neighbouring faces over 12°), smooth elsewhere (scene key lines.contours)")
        ->check(CLI::IsMember({"smooth", "mesh", "auto"}));
    cmd->add_option("--curvature", o.curvature,
                    "How vertex curvature is fitted: exact (the least-squares fit of Rusinkiewicz 2004; the default) or "
                    "trimesh2 (the 3x3 solve of newer trimesh2, which an rtsc built from GitHub today links: every line "
                    "type then lies on that rtsc's lines; scene key lines.curvature)")
        ->check(CLI::IsMember({"exact", "trimesh2"}));
    CLI::Option* slam =
        cmd->add_option("--slam", o.slam, "Draw silhouettes and suggestive contours as strokes textured by this SLAM (.exr)");
    cmd->add_option("--stroke-width", o.stroke_width,
                    "Width of SLAM strokes in pixels, 0.1 to 64 as the scene key lines.TYPE.width (default 6)")
        ->check(within(0.1, 64.0, "pixels"))
        ->needs(slam);
    cmd->add_option("--param", o.param,
                    "Stroke parameterization: coherent (default; Bénard et al. 2010 §4), arclength (tiling) or "
                    "stretch (one texture per path) (scene key coherence.policy)")
        ->check(CLI::IsMember(kParamPolicyNames));
    cmd->add_option("--splat-radius", o.splat_radius,
                    "δ of the parameterization sprites, pixels (default: twice the sample spacing); larger keeps "
                    "fast lines coherent, smaller keeps nearby lines apart (§4.1; scene key coherence.splat_radius)")
        ->check(within(kSplatRadiusRange.min, kSplatRadiusRange.max, "pixels"));
    cmd->add_flag("--validation", o.validation,
                  "Enable the Khronos validation layer; any warning or error fails the run (also LINEWORK_VALIDATION=1)");
    if (!offline) return;
    cmd->add_option("--length-scale", o.length_scale,
                    "κ: SLAM periods per native texture length (default: square texels, the SLAM's height over "
                    "the stroke width; scene key coherence.length_scale)")
        ->check(within(kLengthScaleRange.min, kLengthScaleRange.max));
    cmd->add_option("--inlier-px", o.inlier_px,
                    "RANSAC inlier distance along the path, pixels (§4.2; default " +
                        number_text(RansacParams{}.inlier_px) + "; scene key coherence.inlier_distance)")
        ->check(within(kInlierDistanceRange.min, kInlierDistanceRange.max, "pixels"));
    cmd->add_option("--min-stroke-length", o.min_stroke_length,
                    "Visible paths shorter than this many pixels are not drawn as strokes, splatted or dumped "
                    "(0 keeps every fragment; default " + number_text(CoherenceParams{}.min_stroke_length_px) +
                        "; scene key coherence.min_stroke_length)")
        ->check(within(kMinStrokeLengthRange.min, kMinStrokeLengthRange.max, "pixels"));
}

namespace {

// --lines: exactly these types, as the shorthand's switches (a scene with explicit line sets
// selects its types in them).
void choose_line_types(const std::string& list, LinesDesc& lines) {
    if (!lines.sets.empty())
        throw usage_error("--lines chooses the types of a scene without \"line_sets\"; this scene selects them in its line "
                          "sets (\"select\": {\"types\": [...]})");
    if (list.empty()) throw usage_error("--lines: no line types given (" + line_type_names() + "; --no-lines draws none)");
    std::string error;
    const std::optional<uint32_t> types = line_types_from_list(list, error);
    if (!types) throw usage_error("--lines: " + error);
    set_line_types(lines.params, *types);
    lines.enabled = true;
}

}  // namespace

SceneDesc scene_from_options(const SceneOptions& o) {
    const std::filesystem::path input(o.input);
    if (!std::filesystem::exists(input)) throw Error(o.input + ": no such file");
    check_scene_or_model_path(input);
    SceneDesc desc = is_model_path(input) ? scene_for_model(input) : load_scene_file(input);
    if (!o.size.empty()) {
        const glm::ivec2 size = parse_size(o.size, "--size");
        desc.width = size.x;
        desc.height = size.y;
    }
    if (o.background == "transparent") {
        desc.style.transparent = true;
    } else if (!o.background.empty()) {
        try {
            desc.style.background = parse_color(o.background, "--background");
        } catch (const Error& e) {
            throw usage_error(e.what());
        }
        desc.style.transparent = false;
    }
    if (o.samples > 0) desc.style.samples = static_cast<uint32_t>(o.samples);
    if (o.lines) choose_line_types(*o.lines, desc.lines);
    // A scene that draws no lines ("lines": false, and no --lines to turn them on): a flag
    // that shapes them would be dropped in silence.
    if (!desc.lines.enabled)
        for (const auto& [given, flag] : {std::pair{!o.contours.empty(), "--contours"},
                                          std::pair{!o.curvature.empty(), "--curvature"}, std::pair{!o.slam.empty(), "--slam"}})
            if (given)
                throw usage_error(std::string(flag) + ": " + o.input + " draws no lines (\"lines\": false)");
    if (!o.contours.empty()) desc.lines.params.contours = contour_mode(o.contours);
    if (!o.curvature.empty()) desc.lines.params.curvature = curvature_fit(o.curvature);
    // Read here as well as when the first frame is drawn (about 25 ms more): a farm plans its
    // tasks from these options, and the session, which speaks in scene keys, would name a file
    // it cannot read by the key the flag sets. (read_slam also says when there is no file.)
    if (!o.slam.empty()) {
        try {
            (void)read_slam(o.slam);
        } catch (const Error& e) {
            throw Error(std::string("--slam: ") + e.what());
        }
    }
    if (!o.slam.empty()) use_slam_strokes(desc.lines, o.slam, o.stroke_width);
    return desc;
}

void check_flags_shape_drawn_lines(const SceneOptions& o, const LinesDesc& lines) {
    if (!lines.enabled) return;
    uint32_t drawn = 0;  // bit (1 << LineType) of every type an enabled set draws
    for (const LineSetDesc& set : effective_line_sets(lines))
        if (set.enabled) drawn |= set.select.types;
    const auto draws = [&](std::initializer_list<LineType> types) {
        return std::any_of(types.begin(), types.end(), [&](LineType t) { return (drawn >> uint32_t(t)) & 1u; });
    };
    const std::string which = o.lines ? "--lines " + *o.lines : o.input;
    if (!o.contours.empty() && !draws({LineType::Silhouette}))
        throw usage_error("--contours: shapes silhouettes, which " + which + " does not draw");
    if (!o.slam.empty() && !draws({LineType::Silhouette, LineType::Suggestive}))
        throw usage_error("--slam: textures silhouettes and suggestive contours, which " + which + " does not draw");
    // Creases, borders, material boundaries and intersections read no curvature.
    if (!o.curvature.empty() &&
        !draws({LineType::Silhouette, LineType::Suggestive, LineType::Ridge, LineType::Valley, LineType::ApparentRidge,
                LineType::SuggestiveHighlight, LineType::PrincipalHighlight}))
        throw usage_error("--curvature: fits the curvature of silhouettes, suggestive contours and rtsc's other lines, "
                          "none of which " + which + " draws");
}

SessionOptions session_options(const SceneOptions& o, const SceneDesc& desc) {
    SessionOptions session = default_session_options(desc);
    CoherenceParams& c = session.coherence;
    if (!o.param.empty()) c.policy = param_policy_named(o.param);
    if (o.splat_radius > 0.0f) c.splat_radius_px = o.splat_radius;
    if (o.inlier_px) c.ransac.inlier_px = *o.inlier_px;
    if (o.min_stroke_length) c.min_stroke_length_px = *o.min_stroke_length;
    if (o.length_scale > 0.0f) session.length_scale = o.length_scale;
    // A policy given on the command line: every set is fitted (and dumped), as
    // SessionOptions::coherent says. The scene's key only sets the policy, as in Python.
    session.coherent = !o.param.empty();
    return session;
}

bool validation_on(const SceneOptions& o) { return o.validation || validation_from_environment(); }

void check_samples_on_device(const Context& ctx, const SceneOptions& o, const SceneDesc& desc) {
    try {
        (void)sample_count_bit(ctx, surface_samples(desc.style));
    } catch (const ParameterError& e) {
        if (o.samples > 0) throw Error("--samples" + e.rest());  // a count the flag takes, but not this device
        if (desc.style.samples > 0 && !desc.source.empty()) throw Error(desc.source.string() + ": samples:" + e.rest());
        throw Error("samples per pixel (the default)" + e.rest());
    }
}

}  // namespace lw::cli
