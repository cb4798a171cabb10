// tools/bench/main.cpp — `linework-bench`: GPU and CPU timings that can travel.
//
// Links the engine and Vulkan only (no OpenImageIO, no GLFW), so that
// ../shared/tools/gpu-bundle.sh can carry it to a GPU machine. Figures go to
// docs/BENCHMARKS.md with the device and the command line.
//
//   linework-bench surface MODEL.glb [--subdivide K] [--size WxH] [--frames N] [--device D]
//   linework-bench lines   MODEL.glb [--subdivide K] [--size WxH] [--frames N] [--device D]
//   linework-bench ribbon  [--pattern NAME] [--exemplar-size WxH] [--rows N] [--device D]
//   linework-bench pattern [--elements N] [--path-elements N] [--repeats R]   (CPU)
//   linework-bench hatch   [--count N] [--training-size N] [--window N] [--repeats R]   (CPU)
//   linework-bench slam    [--levels N] [--iterations K] [--length L] [--threads T] [--repeat R]
//
// surface: the shaded surface pass (colour + depth), GPU time from timestamps.
// lines:   the whole line frame (surface + extraction + depth readback + chaining +
//          visibility + line drawing, wall time; the finished image stays on the GPU as a
//          viewer's would) and its stages: extraction on the GPU
//          (timestamps), the CPU reference extraction, chaining and visibility (CPU).
// Both print the median (and min, max) over N frames after two warm-up frames.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_errors.h"
#include "cli_numbers.h"
#include "core/error.h"
#include "core/memory.h"
#include "core/timer.h"
#include "geometry/subdivide.h"
#include "gpu/context.h"
#include "gpu/timestamps.h"
#include "lines/extract_reference.h"
#include "render/frame_renderer.h"
#include "render/surface_pass.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "stroke/slam.h"
#include "pattern_bench.h"
#include "extract_bench.h"
#include "ribbon_bench.h"
#include "slam_bench.h"

namespace {

struct BenchOptions {
    std::string model;
    int subdivide = 0;
    std::string size = "1920x1080";
    int frames = 20;
    std::string device = "auto";
    std::string compute = "auto";  // lines: where extraction, splat and RANSAC run
    bool shaded = false;     // lines: toon shading under the lines (default: depth only)
    bool coherence = false;  // lines: parameterize every visible path (splat, votes, RANSAC)
    bool strokes = false;    // lines: draw silhouettes and suggestive contours as SLAM strokes (implies coherence)
    float orbit_deg = 0.0f;  // lines: the camera's turn about the vertical per frame (0: a still view)
    lw::bench::CameraFlags camera;  // over the framing camera
    bool extract_only = false;      // lines: the host extraction alone (extract_bench.h)
    bool crossed_copy = false;      // lines --extract-only: the model and a copy crossing it
    int hidden_levels = 0;          // lines: hidden lines dashed, up to this occlusion level (0: none drawn)
    std::string types;
    std::string contours = "smooth";
    std::vector<int> threads{1};
    int repeat = 50;
    int samples = 1;  // samples per pixel of the surface pass (MSAA)
    bool all_faces = false;  // surface: draw every back face (no culling of hidden ones)
};

struct Series {
    std::vector<double> values;
    double median() const {
        std::vector<double> v = values;
        std::sort(v.begin(), v.end());
        const size_t n = v.size();
        return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
    }
    void print(const char* name) const {
        if (values.empty()) return;  // a stage this device and compute site do not run
        std::printf("  %-22s median %9.3f ms  (min %.3f, max %.3f)\n", name, median(),
                    *std::min_element(values.begin(), values.end()), *std::max_element(values.begin(), values.end()));
    }
};

// Loads, subdivides and frames the model; prints the device and the mesh.
struct BenchScene {
    lw::LoadedScene scene;
    int width = 0, height = 0;
    lw::CameraMatrices camera;
};

BenchScene prepare(const BenchOptions& b, const lw::Context& ctx) {
    BenchScene s;
    if (std::sscanf(b.size.c_str(), "%dx%d", &s.width, &s.height) != 2 || s.width < 1 || s.height < 1)
        throw lw::usage_error("--size: expected WxH, got \"" + b.size + "\"");
    lw::SceneDesc desc = lw::scene_for_model(b.model);
    desc.width = s.width;
    desc.height = s.height;
    s.scene = lw::load_scene(desc);
    lw::Timer subdivide_timer;
    s.scene.mesh = lw::subdivide_midpoint(s.scene.mesh, b.subdivide);
    lw::bench::apply_camera_flags(s.scene.camera, b.camera);
    s.camera = lw::camera_matrices(s.scene.camera, float(s.width) / float(s.height), s.scene.bounds);
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("mesh: %s subdivided %dx: %zu triangles (%.0f ms to build)\n", b.model.c_str(), b.subdivide,
                s.scene.mesh.triangle_count(), subdivide_timer.elapsed_ms());
    if (!ctx.has_timestamps()) throw lw::Error(ctx.info().name + " has no timestamp queries");
    return s;
}

int run_surface(const BenchOptions& b) {
    lw::Context ctx({.device = lw::parse_device_choice(b.device)});
    BenchScene s = prepare(b, ctx);
    lw::Timer closed_timer;
    const lw::ClosedSurfaces closed = lw::find_closed_surfaces(s.scene.mesh);
    const double closed_ms = closed_timer.elapsed_ms();
    lw::GpuMesh mesh = lw::upload_mesh(ctx, s.scene.mesh, nullptr, &closed.face_both_ways);
    const lw::BackFaceCulling culling{
        .surfaces = &closed,
        .hidden = lw::back_faces_hidden(closed, s.camera)};
    const size_t hidden = size_t(std::count(culling.hidden.begin(), culling.hidden.end(), uint8_t{1}));
    std::printf("closed surfaces: %zu components (found in %.0f ms), back faces hidden from this view in %zu%s\n",
                closed.components.size(), closed_ms, hidden, b.all_faces ? " (not culled: --all-faces)" : "");
    const uint32_t samples = uint32_t(b.samples);
    lw::SurfacePass pass(ctx, VK_FORMAT_R8G8B8A8_UNORM, samples);
    lw::RenderTarget target(ctx, uint32_t(s.width), uint32_t(s.height), VK_FORMAT_R8G8B8A8_UNORM, samples);
    lw::GpuTimer timer(ctx);
    const lw::SurfaceStyle style{.samples = samples};
    Series gpu, wall;
    for (int frame = -2; frame < b.frames; ++frame) {  // two warm-up frames
        lw::Timer w;
        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            timer.reset(cmd);
            timer.begin(cmd, "surface");
            pass.record(cmd, target, mesh, s.camera, s.scene.camera.eye, style, nullptr,
                        b.all_faces ? nullptr : &culling);
            timer.end(cmd);
        });
        const double ms = w.elapsed_ms();
        if (frame < 0) continue;
        wall.values.push_back(ms);
        gpu.values.push_back(timer.results().front().ms);
    }
    std::printf("surface pass %dx%d, %u sample(s) per pixel, %d frames:\n", s.width, s.height, samples, b.frames);
    gpu.print("GPU surface");
    wall.print("wall (submit+wait)");
    return 0;
}

int run_lines(const BenchOptions& b) {
    lw::Context ctx({.device = lw::parse_device_choice(b.device),
                     .compute_site = lw::parse_compute_site(b.compute)});
    BenchScene s = prepare(b, ctx);
    lw::FrameRenderer renderer(ctx, uint32_t(s.width), uint32_t(s.height));
    lw::LinesDesc lines;
    if (b.hidden_levels > 0) {  // occlusion levels counted for every hidden sample (lines/occlusion.h)
        lines.hidden = lw::HiddenLines::Dashed;
        lines.hidden_levels = uint32_t(b.hidden_levels);
    }
    lw::CoherenceParams coherence;
    const bool coherent = b.coherence || b.strokes;
    if (b.strokes) {
        // The whole stylized frame: a procedural dots SLAM (1024 × 32) on 6 px strokes, as
        // `linework render --slam scenes/slams/dots.exr` draws it.
        const lw::Slam slam = lw::make_procedural_slam(lw::SlamPattern::Dots);
        for (lw::LineType t : {lw::LineType::Silhouette, lw::LineType::Suggestive}) {
            renderer.set_slam(size_t(t), slam);
            lines.styles[size_t(t)].width = 6.0f;
            lines.styles[size_t(t)].taper_px = 12.0f;
        }
        coherence.slam_length_px = float(slam.length);
        coherence.length_scale = float(slam.height) / 6.0f;
    }
    lw::Timer prepare_timer;
    renderer.set_mesh(s.scene.mesh, true, lines.params.crease_angle_deg, lines.params.curvature);
    std::printf("line mesh (weld, curvature, feature edges, upload): %.0f ms\n", prepare_timer.elapsed_ms());

    // The extraction alone in its own submission, wall-clock: checks the timestamps.
    lw::LineExtractor extractor(ctx);
    extractor.set_mesh(*renderer.line_mesh());

    lw::SurfaceStyle surface;
    surface.draw_surface = b.shaded;
    surface.samples = uint32_t(b.samples);  // the flag's default is 1, not the scenes' 4

    Series coherence_ms;
    size_t coherent_samples = 0;
    Series frame_ms, frame_released, extract_gpu, extract_host, extract_wall, surface_gpu, draw_gpu, chain, visibility,
        extract_cpu;
    size_t segments = 0, paths = 0, hidden_samples = 0;
    const lw::CameraPath orbit{.kind = lw::CameraPath::Kind::Orbit, .orbit = {.degrees = b.orbit_deg}};
    const lw::ViewCamera base = s.scene.camera;
    for (int frame = -2; frame < b.frames; ++frame) {
        if (b.orbit_deg != 0.0f) {  // turned frame by frame: the paths move, nothing is kept from a still view
            s.scene.camera = lw::camera_at(orbit, base, {.progress = float(frame + 2)});
            s.camera = lw::camera_matrices(s.scene.camera, float(s.width) / float(s.height), s.scene.bounds);
        }
        // The frame as a caller's loop pays for it: drawn, its figures taken, and released
        // (its vertex buffers and path vectors freed), as a Python session's lines() is timed.
        lw::Timer released;
        // --strokes fits the sets that read T, as `linework render --slam` does; --coherence
        // fits every set (issue 19's votes + RANSAC + splat figure).
        std::optional<lw::Frame> held(renderer.render(s.camera, s.scene.camera.eye, surface, lines, {.color = false},
                                                      coherent ? &coherence : nullptr, nullptr, !b.strokes));
        const lw::FrameTimings timings = held->timings;
        if (coherent) {
            coherence_ms.values.push_back(timings.coherence_ms);
            size_t n = 0;
            for (const auto& p : held->screen_paths) n += p.visible ? p.samples.size() : 0;
            coherent_samples = n;
        }
        segments = held->segments.size();
        paths = held->paths.size();
        hidden_samples = 0;
        for (const auto& p : held->screen_paths) hidden_samples += p.visible ? 0 : p.samples.size();
        held.reset();
        const double released_ms = released.elapsed_ms();
        lw::Timer cpu;
        const auto reference = lw::extract_lines_reference(*renderer.line_mesh(), s.scene.camera.eye, lines.params);
        const double cpu_ms = cpu.elapsed_ms();
        lw::Timer gpu_wall;
        const auto gpu_segments = extractor.extract(s.scene.camera.eye, lines.params);
        const double gpu_wall_ms = gpu_wall.elapsed_ms();
        if (frame < 0) continue;
        extract_wall.values.push_back(gpu_wall_ms);
        frame_ms.values.push_back(timings.total_ms);
        frame_released.values.push_back(released_ms);
        if (ctx.preferred_compute_site() == lw::ComputeSite::Host) extract_host.values.push_back(timings.extract_ms);
        chain.values.push_back(timings.chain_ms);
        visibility.values.push_back(timings.visibility_ms);
        extract_cpu.values.push_back(cpu_ms);
        for (const lw::PassTime& t : timings.gpu) {
            if (t.name == "lines extract") extract_gpu.values.push_back(t.ms);
            if (t.name == "surface") surface_gpu.values.push_back(t.ms);
            if (t.name == "lines draw") draw_gpu.values.push_back(t.ms);
        }
        if (reference.size() != gpu_segments.size())
            throw lw::Error("GPU and CPU extraction disagree on the segment count");
    }
    std::printf("line frame %dx%d (%s%s), %d frames, %zu segments, %zu paths:\n", s.width, s.height,
                b.shaded ? "over toon shading" : "over the background: depth-only pass",
                b.strokes ? ", SLAM strokes" : "", b.frames, segments, paths);
    frame_ms.print("line frame (wall)");
    frame_released.print("line frame, drawn and released (wall)");
    surface_gpu.print(b.shaded ? "GPU surface + depth" : "GPU depth pass");
    extract_gpu.print("GPU extraction");
    extract_host.print("host extraction");
    extract_wall.print("GPU extraction alone, wall (submit+wait+readback)");
    chain.print("CPU chaining");
    visibility.print(b.hidden_levels > 0 ? "CPU visibility with occlusion levels" : "CPU visibility");
    if (b.hidden_levels > 0) std::printf("  %zu hidden samples, each given its level by a ray cast\n", hidden_samples);
    draw_gpu.print("GPU line drawing");
    extract_cpu.print("CPU reference extract");
    if (coherent) {
        std::printf("  coherent parameterization of %zu visible samples:\n", coherent_samples);
        coherence_ms.print(ctx.preferred_compute_site() == lw::ComputeSite::Host ? "votes+RANSAC+splat (host)"
                                                                                : "votes+RANSAC+splat (device)");
    }
    return 0;
}

void add_options(CLI::App* cmd, BenchOptions& o) {
    cmd->add_option("model", o.model, "Model (.gltf/.glb)")->required();
    cmd->add_option("--subdivide", o.subdivide, "Midpoint subdivisions (each ×4 triangles)")
        ->check(CLI::Range(0, 6))
        ->capture_default_str();
    cmd->add_option("--size", o.size, "Image size WxH")->capture_default_str();
    cmd->add_option("--frames", o.frames, "Timed frames")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--device", o.device, "auto, cpu, gpu or an index")->capture_default_str();
    cmd->add_option("--compute", o.compute, lw::kComputeSiteHelp)->capture_default_str();
    cmd->add_option("--eye", o.camera.eye, "Camera position x,y,z (default: the camera framing the model)");
    cmd->add_option("--target", o.camera.target, "Point looked at x,y,z");
    cmd->add_option("--up", o.camera.up, "Up vector x,y,z");
    cmd->add_option("--fov", o.camera.fov, "Vertical field of view in degrees");
    cmd->add_option("--samples", o.samples, "Samples per pixel of the surface pass: 1, 4 or 8 (MSAA)")
        ->check(CLI::IsMember({1, 4, 8}))
        ->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
    lw::keep_freed_memory();  // as `linework` does, so the figures are the same program's
    CLI::App app{"linework-bench — timings of Linework passes (median of N frames; GPU time from timestamp queries)."};
    app.require_subcommand(1);
    BenchOptions surface, lines;
    CLI::App* surface_cmd = app.add_subcommand("surface", "Shaded surface pass of a (subdivided) model.");
    add_options(surface_cmd, surface);
    surface_cmd->add_flag("--all-faces", surface.all_faces,
                          "Draw every back face, also where no pixel can see one (what the pass did before it "
                          "culled hidden ones: for comparing)");
    CLI::App* lines_cmd = app.add_subcommand("lines", "The whole line frame and its stages.");
    add_options(lines_cmd, lines);
    CLI::Option* shaded =
        lines_cmd->add_flag("--shaded", lines.shaded, "Draw the lines over toon shading instead of the background");
    CLI::Option* extract_only = lines_cmd->add_flag("--extract-only", lines.extract_only,
                        "Time the host extraction alone (no device): one line `extract: median X ms`, to set beside "
                        "rtsc's per-view extraction");
    shaded->excludes(extract_only);
    for (const char* frame_only : {"--size", "--frames", "--device", "--compute", "--samples"})
        lines_cmd->get_option(frame_only)->excludes(extract_only);
    lines_cmd
        ->add_option("--threads", lines.threads,
                     "--extract-only: threads over vertex and face blocks; a list (1,2) times each count in turn, "
                     "run by run, and prints their speed-ups over the first")
        ->delimiter(',')
        ->capture_default_str()
        ->needs(extract_only);
    lines_cmd->add_option("--types", lines.types,
                          "--extract-only: line types, e.g. silhouette,suggestive (default: the four default types)")
        ->needs(extract_only)
        ->check(CLI::Validator([](std::string& t) { return t.empty() ? "give at least one line type" : ""; }, "TYPES"));
    lines_cmd->add_option("--contours", lines.contours, "--extract-only: silhouettes smooth, mesh or auto")
        ->check(CLI::IsMember({"smooth", "mesh", "auto"}))
        ->capture_default_str()
        ->needs(extract_only);
    lines_cmd->add_option("--repeat", lines.repeat, "--extract-only: timed runs (after one warm-up)")
        ->capture_default_str()
        ->needs(extract_only);
    lines_cmd->add_option("--hidden-levels", lines.hidden_levels,
                          "Draw hidden lines dashed up to this occlusion level, counted exactly by a ray cast per hidden "
                          "sample (the CPU visibility time includes it)")
        ->check(CLI::Range(0, 1000))
        ->excludes(extract_only);
    lines_cmd->add_flag("--crossed-copy", lines.crossed_copy,
                        "--extract-only: add a copy of the model turned 30° about the vertical and moved by a third of "
                        "its size, so that the two cut through each other (intersection lines)")
        ->needs(extract_only);
    lw::bench::RibbonBenchOptions ribbon;
    CLI::App* ribbon_cmd = lw::bench::add_ribbon_bench(app, ribbon);
    lw::bench::PatternBenchOptions pattern;
    CLI::App* pattern_cmd = lw::bench::add_pattern_bench(app, pattern);
    lw::bench::HatchBenchOptions hatch;
    CLI::App* hatch_cmd = lw::bench::add_hatch_bench(app, hatch);
    lw::bench::SlamBenchOptions slam;
    CLI::App* slam_cmd = lw::bench::add_slam_bench(app, slam);
    lines_cmd->add_flag("--coherence", lines.coherence,
                        "Also parameterize every visible path coherently (splat, votes, RANSAC) and time it")
        ->excludes(extract_only);
    lines_cmd->add_option("--orbit", lines.orbit_deg,
                          "Turn the camera this many degrees about the vertical each frame (default 0: a still view, "
                          "where the coherent parameterization keeps the paths that did not move and fits none)")
        ->check(lw::cli::within(-360.0, 360.0, "degrees"))
        ->excludes(extract_only);
    lines_cmd->add_flag("--strokes", lines.strokes,
                        "The whole stylized frame: silhouettes and suggestive contours as coherent SLAM strokes "
                        "(procedural dots, 6 px)")
        ->excludes(extract_only);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "linework-bench: error: %s\nRun with --help for more information.\n",
                     lw::cli::parse_error_text(e, app, argc, argv).c_str());
        return 2;
    }
    try {
        if (surface_cmd->parsed()) return run_surface(surface);
        if (lines_cmd->parsed() && lines.extract_only)
            return lw::bench::run_extract_bench({.model = lines.model, .subdivide = lines.subdivide,
                                                 .camera = lines.camera, .types = lines.types, .contours = lines.contours,
                                                 .threads = lines.threads, .repeat = lines.repeat,
                                                 .crossed_copy = lines.crossed_copy});
        if (lines_cmd->parsed()) return run_lines(lines);
        if (ribbon_cmd->parsed()) return lw::bench::run_ribbon_bench(ribbon);
        if (pattern_cmd->parsed()) return lw::bench::run_pattern_bench(pattern);
        if (hatch_cmd->parsed()) return lw::bench::run_hatch_bench(hatch);
        if (slam_cmd->parsed()) return lw::bench::run_slam_bench(slam);
    } catch (const lw::ParameterError& e) {
        // The engine names what it knows ("samples 8: …"); here that is a flag.
        const std::string name = e.name() == "samples" ? "--samples" : e.name();
        std::fprintf(stderr, "linework-bench: error: %s%s\n", name.c_str(), e.rest().c_str());
        return 1;
    } catch (const lw::Error& e) {
        std::fprintf(stderr, "linework-bench: error: %s\n", e.what());
        return e.exit_code();
    }
    return 0;
}
