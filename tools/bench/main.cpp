// tools/bench/main.cpp — `linework-bench`: GPU timings that can travel.
//
// Links the engine and Vulkan only (no OpenImageIO, no GLFW), so that
// ../shared/tools/gpu-bundle.sh can carry it to a GPU machine. Figures go to
// docs/BENCHMARKS.md with the device and the command line.
//
//   linework-bench surface MODEL.glb [--subdivide K] [--size WxH] [--frames N] [--device D]
//
// surface: the shaded surface pass (colour + depth) of MODEL after K midpoint subdivisions,
// timed with GPU timestamps; prints the median, min and max over N frames, plus the median
// wall time of record + submit + wait.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/error.h"
#include "core/timer.h"
#include "geometry/subdivide.h"
#include "gpu/context.h"
#include "gpu/timestamps.h"
#include "render/surface_pass.h"
#include "scene/scene.h"

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

struct SurfaceBench {
    std::string model;
    int subdivide = 0;
    std::string size = "1920x1080";
    int frames = 20;
    std::string device = "auto";
};

int run_surface(const SurfaceBench& b) {
    int width = 0, height = 0;
    if (std::sscanf(b.size.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1)
        throw lw::usage_error("--size: expected WxH, got \"" + b.size + "\"");

    lw::SceneDesc desc = lw::scene_for_model(b.model);
    desc.width = width;
    desc.height = height;
    lw::LoadedScene scene = lw::load_scene(desc);
    lw::Timer subdivide_timer;
    scene.mesh = lw::subdivide_midpoint(scene.mesh, b.subdivide);

    lw::Context ctx({.device = lw::parse_device_choice(b.device)});
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("mesh: %s subdivided %dx: %zu triangles (%.0f ms to build)\n", b.model.c_str(), b.subdivide,
                scene.mesh.triangle_count(), subdivide_timer.elapsed_ms());
    if (!ctx.has_timestamps()) throw lw::Error(ctx.info().name + " has no timestamp queries");

    const lw::CameraMatrices camera = lw::camera_matrices(scene.camera, float(width) / float(height), scene.bounds);
    lw::GpuMesh mesh = lw::upload_mesh(ctx, scene.mesh);
    lw::SurfacePass pass(ctx);
    lw::RenderTarget target(ctx, uint32_t(width), uint32_t(height));
    lw::GpuTimer timer(ctx);
    lw::SurfaceStyle style;

    std::vector<double> gpu_ms, wall_ms;
    for (int frame = -2; frame < b.frames; ++frame) {  // two warm-up frames
        lw::Timer wall;
        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            timer.reset(cmd);
            timer.begin(cmd, "surface");
            pass.record(cmd, target, mesh, camera, scene.camera.eye, style);
            timer.end(cmd);
        });
        const double w = wall.elapsed_ms();
        if (frame < 0) continue;
        wall_ms.push_back(w);
        gpu_ms.push_back(timer.results().front().ms);
    }
    std::printf("surface pass %dx%d, %d frames: GPU median %.3f ms (min %.3f, max %.3f); wall median %.3f ms\n", width,
                height, b.frames, median(gpu_ms), *std::min_element(gpu_ms.begin(), gpu_ms.end()),
                *std::max_element(gpu_ms.begin(), gpu_ms.end()), median(wall_ms));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"linework-bench — GPU timings of Linework passes (median of N frames, timestamp queries)."};
    app.require_subcommand(1);
    SurfaceBench surface;
    CLI::App* cmd = app.add_subcommand("surface", "Shaded surface pass of a (subdivided) model.");
    cmd->add_option("model", surface.model, "Model (.gltf/.glb)")->required();
    cmd->add_option("--subdivide", surface.subdivide, "Midpoint subdivisions (each ×4 triangles)")
        ->check(CLI::Range(0, 6))
        ->capture_default_str();
    cmd->add_option("--size", surface.size, "Image size WxH")->capture_default_str();
    cmd->add_option("--frames", surface.frames, "Timed frames")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--device", surface.device, "auto, cpu, gpu or an index")->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    }
    try {
        if (cmd->parsed()) return run_surface(surface);
    } catch (const lw::Error& e) {
        std::fprintf(stderr, "linework-bench: error: %s\n", e.what());
        return e.exit_code();
    }
    return 0;
}
