#include "extract_bench.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/timer.h"
#include "geometry/subdivide.h"
#include "lines/extract_reference.h"
#include "lines/intersections.h"
#include "lines/line_mesh.h"
#include "lines/line_types.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "stats.h"

namespace lw::bench {

namespace {

glm::vec3 vec3_flag(const std::string& text, const char* flag) {
    glm::vec3 v;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &rest) != 3)
        throw usage_error(std::string(flag) + ": expected x,y,z, got \"" + text + "\"");
    return v;
}

LineParams types_flag(const std::string& types) {
    LineParams params;
    if (types.empty()) return params;
    std::string error;
    const std::optional<uint32_t> mask = line_types_from_list(types, error);
    if (!mask) throw usage_error("--types: " + error);
    set_line_types(params, *mask);
    return params;
}

}  // namespace

void apply_camera_flags(ViewCamera& camera, const CameraFlags& flags) {
    if (!flags.eye.empty()) camera.eye = vec3_flag(flags.eye, "--eye");
    if (!flags.target.empty()) camera.target = vec3_flag(flags.target, "--target");
    if (!flags.up.empty()) camera.up = vec3_flag(flags.up, "--up");
    if (flags.fov) {
        if (!(*flags.fov > 0.0f && *flags.fov < 180.0f)) throw usage_error("--fov: must be between 0 and 180 degrees");
        camera.fov_deg = *flags.fov;
    }
}

int run_extract_bench(const ExtractBenchOptions& o) {
    if (o.threads.empty() || *std::min_element(o.threads.begin(), o.threads.end()) < 1)
        throw usage_error("--threads: each count must be 1 or more");
    if (o.repeat < 1) throw usage_error("--repeat: must be 1 or more");
    LineParams params = types_flag(o.types);
    params.contours = contour_mode(o.contours);
    LoadedScene scene = load_scene(scene_for_model(o.model));
    scene.mesh = subdivide_midpoint(scene.mesh, o.subdivide);
    if (o.crossed_copy) {
        // Turned about the vertical through the model's centre and moved along x by a third
        // of its size: the copy cuts through the model along long curves.
        TriangleMesh copy = scene.mesh;
        const Bounds b = compute_bounds(scene.mesh.positions);
        const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
        const glm::vec3 shift(glm::length(b.max - b.min) / 3.0f, 0.0f, 0.0f);
        for (glm::vec3& x : copy.positions) x = b.center() + turn * (x - b.center()) + shift;
        for (glm::vec3& n : copy.normals) n = turn * n;
        append_mesh(scene.mesh, copy);
    }
    ViewCamera camera = scene.camera;
    apply_camera_flags(camera, o.camera);
    Timer build;
    const LineMesh lm = build_line_mesh(scene.mesh, params.crease_angle_deg);
    std::printf("mesh: %s subdivided %dx: %zu triangles, %zu welded vertices (line mesh %.0f ms)\n", o.model.c_str(),
                o.subdivide, lm.mesh.faces.size(), lm.mesh.positions.size(), build.elapsed_ms());
    std::printf("eye: %g,%g,%g; types: %s\n", double(camera.eye.x), double(camera.eye.y), double(camera.eye.z),
                o.types.empty() ? "the defaults" : o.types.c_str());
    // As a frame extracts: the output and the scratch kept from run to run. Several thread
    // counts take turns run by run, so that the machine's drifts hit them alike.
    const size_t counts = o.threads.size();
    std::vector<std::vector<double>> ms(counts);
    std::vector<LineSegment> segments;
    ExtractWorkspace workspace;
    IntersectionCache intersections;
    for (int r = -1; r < o.repeat; ++r)  // one warm-up round
        for (size_t k = 0; k < counts; ++k) {
            Timer t;
            extract_lines_reference(lm, camera.eye, params, segments, workspace, size_t(o.threads[k]));
            if (params.intersections) {  // as FrameRenderer::begin appends them
                const std::vector<LineSegment>& crossing = intersection_lines(lm, intersections);
                segments.insert(segments.end(), crossing.begin(), crossing.end());
            }
            if (r >= 0) ms[k].push_back(t.elapsed_ms());
        }
    for (size_t k = 0; k < counts; ++k) {
        const Stats s = stats(ms[k]);
        const std::string label = counts == 1 ? "extract" : "extract (" + std::to_string(o.threads[k]) + " threads)";
        std::printf("%s: median %.3f ms (min %.3f, max %.3f) over %d runs, %zu segments\n", label.c_str(), s.median, s.min,
                    s.max, o.repeat, segments.size());
    }
    if (params.intersections) {  // each new pose finds them again
        std::vector<double> pose_ms;
        size_t found = 0, pairs = 0;
        for (int r = -1; r < std::min(o.repeat, 10); ++r) {
            Timer t;
            found = find_intersection_lines(lm, &pairs).size();
            if (r >= 0) pose_ms.push_back(t.elapsed_ms());
        }
        const Stats s = stats(pose_ms);
        std::printf("intersections per new pose: median %.3f ms (min %.3f, max %.3f) over %zu runs, %zu face pairs "
                    "with overlapping boxes, %zu segments\n",
                    s.median, s.min, s.max, pose_ms.size(), pairs, found);
    }
    for (size_t k = 1; k < counts; ++k) {
        std::vector<double> ratios(ms[0].size());
        for (size_t r = 0; r < ratios.size(); ++r) ratios[r] = ms[0][r] / ms[k][r];
        const Stats s = stats(ratios);
        std::printf("speed-up %d threads over %d: median %.2f (min %.2f, max %.2f) of run-by-run ratios\n", o.threads[k],
                    o.threads[0], s.median, s.min, s.max);
    }
    return 0;
}

}  // namespace lw::bench
