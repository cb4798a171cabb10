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

// How far past the image a path is still sampled. A sample off the image is hidden (nothing
// there can see it), so a visible run ends at the image's edge either way; beyond this margin a
// path is cut instead of sampled: a model far off screen projects to paths millions of pixels
// long (a viewer panned 1e7 took 0.8 s and 840 MB a frame, 1e9 ran out of memory).
constexpr float kSampledMarginPx = 64.0f;

// The fractions [t0, t1] of the screen segment a → b inside the image grown by the margin
// (Liang–Barsky); t0 > t1 where none of it is.
glm::vec2 inside_fractions(glm::vec2 a, glm::vec2 b, float width, float height) {
    const glm::vec2 lo(-kSampledMarginPx), hi(width + kSampledMarginPx, height + kSampledMarginPx);
    float t0 = 0.0f, t1 = 1.0f;
    const glm::vec2 d = b - a;
    for (int k = 0; k < 2; ++k) {
        if (d[k] == 0.0f) {
            if (a[k] < lo[k] || a[k] > hi[k]) return {1.0f, 0.0f};
            continue;
        }
        float enter = (lo[k] - a[k]) / d[k], leave = (hi[k] - a[k]) / d[k];
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
    }
    return {t0, t1};
}

// Samples of one path every `spacing` pixels of screen arc length, ends included, in pieces:
// the path is cut where it leaves the image by more than the margin or passes behind the eye,
// and `s` counts the whole path's screen length either way. A closed path that is not cut
// stays closed (one piece); one that is cut, with a piece through its start, has that piece
// carried on after its last one.
struct SampledPieces {
    std::vector<std::vector<ScreenSample>> pieces;
    bool cut = false;
};

SampledPieces resample(const LinePath& path, const CameraMatrices& camera, const DepthImage& image, float spacing) {
    const size_t n = path.vertices.size();
    const size_t edges = path.closed ? n : n - 1;
    std::vector<glm::vec3> projected(n);
    for (size_t i = 0; i < n; ++i)
        projected[i] = project_to_pixel(camera, path.vertices[i].position, float(image.width), float(image.height));

    SampledPieces out;
    out.pieces.emplace_back();
    const auto cut = [&] {
        out.cut = true;
        if (!out.pieces.back().empty()) out.pieces.emplace_back();
    };
    float s = 0.0f, next_sample = 0.0f;
    for (size_t e = 0; e < edges; ++e) {
        const PathVertex& a = path.vertices[e];
        const PathVertex& b = path.vertices[(e + 1) % n];
        const glm::vec3 pa = projected[e], pb = projected[(e + 1) % n];
        if (pa.z <= 0.0f || pb.z <= 0.0f) {  // behind the eye
            cut();
            continue;
        }
        const float length = glm::length(glm::vec2(pb) - glm::vec2(pa));
        const glm::vec2 inside = inside_fractions(glm::vec2(pa), glm::vec2(pb), float(image.width), float(image.height));
        // Skips the samples before screen arc length `to` of the path, cutting it if there are any.
        const auto skip_to = [&](float to) {
            if (next_sample >= to) return;
            cut();
            next_sample += std::ceil((to - next_sample) / spacing) * spacing;
        };
        if (inside.x > inside.y) {
            skip_to(std::nextafter(s + length, INFINITY));
            s += length;
            continue;
        }
        skip_to(s + inside.x * length);
        const float last = inside.y < 1.0f ? s + inside.y * length : s + length;
        while (next_sample <= last) {
            const float t = length > 0.0f ? (next_sample - s) / length : 0.0f;
            // The point of the 3D segment that projects to screen fraction t lies at fraction
            // u of it, perspective-correct (1/w is linear on screen, w the eye depth): a long
            // segment running away from the eye (a box's edge) has its screen middle well
            // before its 3D middle. With t in place of u, the sample's surface point, depth
            // and carried position were off the line by pixels.
            const float u = perspective_fraction(t, pa.z, pb.z);
            const PathVertex& nearer = u < 0.5f ? a : b;
            out.pieces.back().push_back(ScreenSample{.pixel = glm::mix(glm::vec2(pa), glm::vec2(pb), t),
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
        if (inside.y < 1.0f) skip_to(std::nextafter(s + length, INFINITY));
        s += length;
    }
    // The last vertex of an open path, so that paths end where they end.
    const glm::vec3 end = projected[n - 1];
    const std::vector<ScreenSample>& piece = out.pieces.back();
    if (!path.closed && end.z > 0.0f && (piece.empty() || piece.back().s < s) &&
        inside_fractions(glm::vec2(end), glm::vec2(end), float(image.width), float(image.height)).x == 0.0f) {
        const PathVertex& v = path.vertices[n - 1];
        out.pieces.back().push_back(ScreenSample{.pixel = glm::vec2(end),
                                                 .depth = end.z,
                                                 .s = s,
                                                 .position = v.position,
                                                 .face = v.face,
                                                 .bary = v.bary,
                                                 .alpha = v.alpha,
                                                 .other_face = v.other_face});
    }
    if (out.pieces.back().empty()) out.pieces.pop_back();
    // A cut loop whose first piece starts at its start and whose last runs to its end: one
    // piece through the start, its s going on past the loop's length.
    if (path.closed && out.cut && out.pieces.size() > 1 && out.pieces.front().front().s == 0.0f &&
        out.pieces.back().back().s + spacing > s) {
        for (ScreenSample sample : out.pieces.front()) {
            sample.s += s;
            out.pieces.back().push_back(sample);
        }
        out.pieces.erase(out.pieces.begin());
    }
    return out;
}

// One piece of a path (resample): its runs of equal visibility and level.
void split_piece_into_runs(LineType type, bool closed, size_t index, std::vector<ScreenSample> samples,
                           const DepthTester& tester, const OcclusionCounter* levels, const glm::vec3& eye,
                           std::vector<ScreenPath>& out) {
    if (samples.empty()) return;
    std::vector<uint32_t> level(samples.size());
    const bool contour = type == LineType::Silhouette;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (tester.visible(samples[i].pixel, samples[i].depth)) continue;
        level[i] = levels ? std::max(1u, levels->surfaces_in_front(eye, samples[i].position, samples[i].face, contour)) : 1u;
    }

    if (std::all_of(level.begin(), level.end(), [&](uint32_t l) { return l == level[0]; })) {
        out.push_back(ScreenPath{.type = type, .closed = closed, .visible = level[0] == 0, .qi = level[0],
                                 .source = index, .samples = std::move(samples)});
        return;
    }
    size_t begin = 0;
    while (begin < samples.size()) {
        size_t end = begin + 1;
        while (end < samples.size() && level[end] == level[begin]) ++end;
        ScreenPath run{.type = type, .visible = level[begin] == 0, .qi = level[begin], .source = index};
        run.samples.assign(samples.begin() + std::ptrdiff_t(begin),
                           samples.begin() + std::ptrdiff_t(std::min(end + 1, samples.size())));
        if (run.samples.size() >= 2) out.push_back(std::move(run));
        begin = end;
    }
}

// Resamples one path, tests every sample, and appends its runs of equal visibility (and
// occlusion level) to `out`. Neighbouring runs share their boundary sample so that drawn
// runs meet without a gap; a path of one run keeps its samples as they are.
void split_into_runs(const LinePath& path, size_t index, const CameraMatrices& camera, const DepthImage& depth,
                     const DepthTester& tester, float spacing, const OcclusionCounter* levels, const glm::vec3& eye,
                     std::vector<ScreenPath>& out) {
    if (path.vertices.size() < 2) return;
    SampledPieces sampled = resample(path, camera, depth, spacing);
    for (std::vector<ScreenSample>& piece : sampled.pieces)
        split_piece_into_runs(path.type, path.closed && !sampled.cut, index, std::move(piece), tester, levels, eye, out);
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
