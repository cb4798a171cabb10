#include "lines/visibility.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/parallel.h"

namespace lw {

float linear_depth(float window_depth, float znear, float zfar) {
    if (window_depth >= 1.0f) return std::numeric_limits<float>::infinity();
    // Inverse of glm::perspective (depth zero-to-one): d = f (z − n) / (z (f − n)).
    return znear * zfar / (zfar - window_depth * (zfar - znear));
}

namespace {

// Depth is linearized only where samples look (two values per sample, not the image).
struct DepthTester {
    const DepthImage& image;
    const VisibilityParams& params;

    bool visible(glm::vec2 pixel, float depth) const {
        const int cx = int(std::floor(pixel.x)), cy = int(std::floor(pixel.y));
        if (cx < 0 || cy < 0 || cx >= image.width || cy >= image.height) return false;  // off screen
        // Window depth is monotonic in eye depth: find the extremes first, linearize two.
        float far_window = 0.0f, near_window = 1.0f;
        for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, image.height - 1); ++y)
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, image.width - 1); ++x) {
                const float d = image.depth[size_t(y) * image.width + x];
                far_window = std::max(far_window, d);
                if (d < 1.0f) near_window = std::min(near_window, d);
            }
        if (far_window >= 1.0f) return true;  // touches the background: a silhouette
        const float farthest = linear_depth(far_window, image.znear, image.zfar);
        const float slope = farthest - linear_depth(near_window, image.znear, image.zfar);
        return depth <= farthest + params.depth_bias * depth + params.slope_scale * slope;
    }
};

// The fraction along a 3D segment whose projection lies at fraction t of the projected
// segment, for ends at eye depths wa, wb > 0 (clip w; equal for an orthographic camera).
float perspective_fraction(float t, float wa, float wb) {
    const float denominator = (1.0f - t) * wb + t * wa;
    return denominator > 0.0f ? t * wa / denominator : t;
}

// Samples of one path every `spacing` pixels of screen arc length, ends included.
std::vector<ScreenSample> resample(const LinePath& path, const CameraMatrices& camera, const DepthImage& image,
                                   float spacing) {
    const size_t n = path.vertices.size();
    const size_t edges = path.closed ? n : n - 1;
    std::vector<glm::vec3> projected(n);
    for (size_t i = 0; i < n; ++i)
        projected[i] = project_to_pixel(camera, path.vertices[i].position, float(image.width), float(image.height));

    std::vector<ScreenSample> samples;
    float s = 0.0f, next_sample = 0.0f;
    for (size_t e = 0; e < edges; ++e) {
        const PathVertex& a = path.vertices[e];
        const PathVertex& b = path.vertices[(e + 1) % n];
        const glm::vec3 pa = projected[e], pb = projected[(e + 1) % n];
        if (pa.z <= 0.0f || pb.z <= 0.0f) continue;  // behind the eye
        const float length = glm::length(glm::vec2(pb) - glm::vec2(pa));
        while (next_sample <= s + length) {
            const float t = length > 0.0f ? (next_sample - s) / length : 0.0f;
            // The point of the 3D segment that projects to screen fraction t lies at fraction
            // u of it, perspective-correct (1/w is linear on screen, w the eye depth): a long
            // segment running away from the eye (a box's edge) has its screen middle well
            // before its 3D middle. With t in place of u, the sample's surface point, depth
            // and carried position were off the line by pixels.
            const float u = perspective_fraction(t, pa.z, pb.z);
            const PathVertex& nearer = u < 0.5f ? a : b;
            samples.push_back(ScreenSample{.pixel = glm::mix(glm::vec2(pa), glm::vec2(pb), t),
                                           .depth = glm::mix(pa.z, pb.z, u),
                                           .s = next_sample,
                                           .position = glm::mix(a.position, b.position, u),
                                           .face = nearer.face,
                                           .bary = nearer.bary,
                                           .alpha = glm::mix(a.alpha, b.alpha, u),
                                           .other_face = nearer.other_face});
            next_sample += spacing;
            if (length == 0.0f) break;
        }
        s += length;
    }
    // The last vertex of an open path, so that paths end where they end.
    if (!path.closed && n > 0 && projected[n - 1].z > 0.0f && (samples.empty() || samples.back().s < s)) {
        const PathVertex& last = path.vertices[n - 1];
        samples.push_back(ScreenSample{.pixel = glm::vec2(projected[n - 1]),
                                       .depth = projected[n - 1].z,
                                       .s = s,
                                       .position = last.position,
                                       .face = last.face,
                                       .bary = last.bary,
                                       .alpha = last.alpha,
                                       .other_face = last.other_face});
    }
    return samples;
}

}  // namespace

namespace {

// Resamples one path, tests every sample, and appends its runs of equal visibility (and
// occlusion level) to `out`. Neighbouring runs share their boundary sample so that drawn
// runs meet without a gap; a path of one run keeps its samples as they are.
void split_into_runs(const LinePath& path, size_t index, const CameraMatrices& camera, const DepthImage& depth,
                     const DepthTester& tester, float spacing, const OcclusionCounter* levels, const glm::vec3& eye,
                     std::vector<ScreenPath>& out) {
    if (path.vertices.size() < 2) return;
    std::vector<ScreenSample> samples = resample(path, camera, depth, spacing);
    if (samples.empty()) return;
    std::vector<uint32_t> level(samples.size());
    const bool contour = path.type == LineType::Silhouette;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (tester.visible(samples[i].pixel, samples[i].depth)) continue;
        level[i] = levels ? std::max(1u, levels->surfaces_in_front(eye, samples[i].position, samples[i].face, contour)) : 1u;
    }

    if (std::all_of(level.begin(), level.end(), [&](uint32_t l) { return l == level[0]; })) {
        out.push_back(ScreenPath{.type = path.type, .closed = path.closed, .visible = level[0] == 0, .qi = level[0],
                                 .source = index, .samples = std::move(samples)});
        return;
    }
    size_t begin = 0;
    while (begin < samples.size()) {
        size_t end = begin + 1;
        while (end < samples.size() && level[end] == level[begin]) ++end;
        ScreenPath run{.type = path.type, .visible = level[begin] == 0, .qi = level[begin], .source = index};
        run.samples.assign(samples.begin() + std::ptrdiff_t(begin),
                           samples.begin() + std::ptrdiff_t(std::min(end + 1, samples.size())));
        if (run.samples.size() >= 2) out.push_back(std::move(run));
        begin = end;
    }
}

}  // namespace

std::vector<ScreenPath> compute_visibility(const std::vector<LinePath>& paths, const CameraMatrices& camera,
                                           const DepthImage& depth, const VisibilityParams& params,
                                           const OcclusionCounter* levels) {
    const DepthTester tester{depth, params};
    const glm::vec3 eye(glm::inverse(camera.view)[3]);
    // Paths are independent: test them on every core, each chunk into its own list, and
    // concatenate in order (the result does not depend on the thread count).
    std::vector<std::vector<ScreenPath>> chunk_out(worker_count());
    parallel_for(paths.size(), 64, [&](size_t first, size_t last, size_t chunk) {
        for (size_t p = first; p < last; ++p)
            split_into_runs(paths[p], p, camera, depth, tester, params.sample_spacing_px, levels, eye, chunk_out[chunk]);
    });
    std::vector<ScreenPath> out;
    for (auto& list : chunk_out) std::move(list.begin(), list.end(), std::back_inserter(out));
    return out;
}

}  // namespace lw
