// `linework render SCENE.json|MODEL.glb -o DIR` — headless render to PNG (and EXR).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.h"
#include "core/error.h"
#include "core/timer.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "lines/svg_export.h"
#include "render/frame_renderer.h"
#include "scene/scene.h"

namespace lw::cli {

namespace {

struct RenderOptions {
    std::string input;
    std::string output;
    std::string device = "auto";
    std::string size, eye, target, up;
    std::optional<float> fov;
    std::string shading;
    bool exr = false;
    bool validation = false;
    bool lines_only = false;
    bool no_lines = false;
    std::string svg;
    std::string hidden;
};

// Applies command-line overrides to the scene description. A partial camera (only --eye)
// keeps the framed target so that a user can move the eye alone.
void apply_overrides(const RenderOptions& o, SceneDesc& desc) {
    if (!o.size.empty()) {
        const glm::ivec2 size = parse_size(o.size, "--size");
        desc.width = size.x;
        desc.height = size.y;
    }
    if (o.fov) {
        if (!(*o.fov > 0.0f && *o.fov < 180.0f)) throw usage_error("--fov: must be between 0 and 180 degrees");
        desc.fov_deg = *o.fov;
        if (desc.camera) desc.camera->fov_deg = *o.fov;
    }
    if (!o.shading.empty()) {
        desc.style.draw_surface = o.shading != "none";
        if (o.shading == "flat") desc.style.shading = Shading::Flat;
        if (o.shading == "toon") desc.style.shading = Shading::Toon;
        if (o.shading == "unlit") desc.style.shading = Shading::Unlit;
    }
    if (o.lines_only) desc.style.draw_surface = false;
    if (o.no_lines) desc.lines.enabled = false;
    if (!o.hidden.empty())
        desc.lines.hidden = o.hidden == "dashed" ? HiddenLines::Dashed
                            : o.hidden == "faint" ? HiddenLines::Faint
                                                  : HiddenLines::None;
    if (o.lines_only && o.no_lines) throw usage_error("--lines-only and --no-lines leave nothing to draw");
    if (!o.svg.empty() && !desc.lines.enabled) throw usage_error("--svg needs lines (drop --no-lines)");
}

void apply_camera_overrides(const RenderOptions& o, LoadedScene& scene) {
    if (!o.eye.empty()) scene.camera.eye = parse_vec3(o.eye, "--eye");
    if (!o.target.empty()) scene.camera.target = parse_vec3(o.target, "--target");
    if (!o.up.empty()) scene.camera.up = parse_vec3(o.up, "--up");
    if (scene.camera.eye == scene.camera.target) throw usage_error("--eye and --target coincide");
}

int run_render(const RenderOptions& o) {
    const std::filesystem::path input(o.input);
    if (!std::filesystem::exists(input)) throw Error(o.input + ": no such file");
    SceneDesc desc = is_model_path(input) ? scene_for_model(input) : load_scene_file(input);
    apply_overrides(o, desc);

    const std::filesystem::path out_dir(o.output);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec || !std::filesystem::is_directory(out_dir))
        throw Error(o.output + ": cannot create output folder" + (ec ? " (" + ec.message() + ")" : ""));

    Timer load_timer;
    LoadedScene scene = load_scene(desc);
    apply_camera_overrides(o, scene);
    std::printf("scene: %s (%zu triangles, loaded in %.0f ms)\n", o.input.c_str(), scene.mesh.triangle_count(),
                load_timer.elapsed_ms());

    const bool validation = o.validation || validation_from_environment();
    Context ctx({.device = parse_device_choice(o.device), .validation = validation});
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("size: %dx%d\n", desc.width, desc.height);

    const auto width = static_cast<uint32_t>(desc.width), height = static_cast<uint32_t>(desc.height);
    const CameraMatrices camera = camera_matrices(scene.camera, float(width) / float(height), scene.bounds);
    FrameRenderer renderer(ctx, width, height);
    Timer prepare_timer;
    renderer.set_mesh(scene.mesh, desc.lines.enabled, desc.lines.params.crease_angle_deg);
    if (const LineMesh* lm = renderer.line_mesh())
        std::printf("lines: %zu welded vertices, feature size %.4g, curvature in %.0f ms\n", lm->mesh.positions.size(),
                    double(lm->feature_size), prepare_timer.elapsed_ms());

    const Frame frame = renderer.render(camera, scene.camera.eye, desc.style, desc.lines, {.color = true, .depth = o.exr});

    const std::filesystem::path png = out_dir / "frame_0000.png";
    write_png(png, frame.image.color);
    std::optional<std::filesystem::path> exr;
    if (o.exr) {
        exr = out_dir / "frame_0000.exr";
        write_exr(*exr, frame.image.color, frame.image.depth);
    }
    if (!o.svg.empty()) write_lines_svg(o.svg, desc.width, desc.height, frame.screen_paths, desc.lines.styles);

    std::printf("frame 0: %.2f ms", frame.timings.total_ms);
    for (const PassTime& t : frame.timings.gpu)
        if (t.ms >= 0.0) std::printf(" (GPU %s %.3f ms)", t.name.c_str(), t.ms);
    std::printf("\n");
    if (desc.lines.enabled) {
        size_t visible = 0;
        for (const auto& p : frame.screen_paths) visible += p.visible;
        std::printf("lines: %zu segments, %zu paths, %zu visible runs (chain %.2f ms, visibility %.2f ms)\n",
                    frame.segments.size(), frame.paths.size(), visible, frame.timings.chain_ms,
                    frame.timings.visibility_ms);
    }
    std::printf("wrote %s\n", png.string().c_str());
    if (exr) std::printf("wrote %s\n", exr->string().c_str());
    if (!o.svg.empty()) std::printf("wrote %s\n", o.svg.c_str());

    if (validation) {
        const auto messages = ctx.validation_messages();
        if (!messages.empty()) {
            std::fprintf(stderr, "linework: error: %zu validation message(s); see above\n", messages.size());
            return 1;
        }
    }
    return 0;
}

}  // namespace

Runner add_render_command(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Render a scene file or a glTF model headlessly to OUT/frame_0000.png.\n"
        "Without a camera in the scene (or --eye/--target), the camera frames the bounding box.");
    cmd->add_option("input", o->input, "Scene file (.json) or model (.gltf/.glb)")->required();
    cmd->add_option("-o,--output", o->output, "Output folder (created if missing)")->required();
    cmd->add_option("--device", o->device,
                    "auto (discrete GPU if present, else lavapipe), cpu, gpu, or an index from `linework devices`")
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Image size WxH (default: the scene's, else 960x720)");
    cmd->add_option("--eye", o->eye, "Camera position x,y,z");
    cmd->add_option("--target", o->target, "Point looked at x,y,z");
    cmd->add_option("--up", o->up, "Up vector x,y,z (default 0,1,0)");
    cmd->add_option("--fov", o->fov, "Vertical field of view in degrees (default 40)");
    cmd->add_option("--shading", o->shading, "Surface shading")->check(CLI::IsMember({"flat", "toon", "unlit", "none"}));
    cmd->add_flag("--exr", o->exr, "Also write OUT/frame_0000.exr (RGBA + depth channel Z)");
    cmd->add_flag("--lines-only", o->lines_only, "Draw the lines over the background, without shading");
    cmd->add_flag("--no-lines", o->no_lines, "Shading only, no feature lines");
    cmd->add_option("--svg", o->svg,
                    "Also write the visible lines as SVG (pixel coordinates, one <g> per line type)");
    cmd->add_option("--hidden", o->hidden, "Hidden lines: none (default), dashed or faint")
        ->check(CLI::IsMember({"none", "dashed", "faint"}));
    cmd->add_flag("--validation", o->validation,
                  "Enable the Khronos validation layer; any warning or error fails the run "
                  "(also LINEWORK_VALIDATION=1)");
    return [o] { return run_render(*o); };
}

}  // namespace lw::cli
