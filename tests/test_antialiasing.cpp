// Antialiasing on lavapipe: lines and strokes carry analytic coverage (a one-pixel ramp centred
// on the outline, stroke/stroke_geometry.h), the shaded surface is multisampled. Black lines
// are drawn over white, so a pixel's ink is 1 − red/255; the rendered width of a line is the
// ink summed down a column, which for a line at angle θ to the x axis is width / cos θ.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/image.h"
#include "gpu/coverage_layer.h"
#include "render/coverage_reference.h"
#include "render/frame_renderer.h"
#include "render/line_pass.h"
#include "render/surface_pass.h"
#include "scene/scene.h"
#include "stroke/slam.h"
#include "stroke/slam_texture.h"
#include "stroke/stroke_pass.h"
#include "stroke/stroke_reference.h"
#include "test_support.h"

namespace lw {
namespace {

constexpr int kSize = 64;

// A visible path from `a` to `b`, sampled every 2 px.
ScreenPath segment_path(glm::vec2 a, glm::vec2 b) {
    ScreenPath path;
    const float length = glm::length(b - a);
    const int steps = std::max(1, int(std::ceil(length / 2.0f)));
    for (int k = 0; k <= steps; ++k) {
        const float t = float(k) / float(steps);
        path.samples.push_back(ScreenSample{.pixel = glm::mix(a, b, t), .depth = 1.0f, .s = t * length,
                                            .position = {}, .face = 0, .bary = {}, .alpha = 1.0f});
    }
    return path;
}

enum class Drawer { LinePass, SolidStroke };

// Ink (0 paper … 1 black) of a kSize² image drawn over white by `draw` (recording into the
// target, its vertices in the arena).
template <class Draw>
std::vector<float> ink_of(const Context& ctx, Draw&& draw) {
    RenderTarget target(ctx, kSize, kSize, VK_FORMAT_R8G8B8A8_UNORM, 1);
    const SurfacePass surface(ctx);
    Buffer readback(ctx, {.size = VkDeviceSize(kSize) * kSize * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          .purpose = MemoryPurpose::Readback, .name = "test readback"});
    UploadArena arena(VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "test triangles");
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        surface.record_clear(cmd, target, SurfaceStyle{});
        draw(cmd, target, arena);
        record_image_to_buffer(cmd, target.color, readback);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    const ImageRGBA8 image = read_rgba8(ctx, readback, kSize, kSize, VK_FORMAT_R8G8B8A8_UNORM);
    std::vector<float> ink(size_t(kSize) * kSize);
    for (size_t i = 0; i < ink.size(); ++i) ink[i] = 1.0f - float(image.pixels[4 * i]) / 255.0f;
    return ink;
}

// Black strokes textured by the solid SLAM.
std::vector<float> stroke_ink(const Context& ctx, const std::vector<StrokeVertex>& vertices) {
    const StrokePass strokes(ctx);
    const SlamTexture solid(ctx, solid_slam());
    return ink_of(ctx, [&](VkCommandBuffer cmd, RenderTarget& target, UploadArena& arena) {
        strokes.record(ctx, cmd, target, vertices, solid, arena);
    });
}

std::vector<StrokeVertex> build(const ScreenPath& path, float width, Cap cap, Join join, float alpha = 1.0f) {
    std::vector<StrokeVertex> vertices;
    const size_t n = path.samples.size();
    append_stroke(path, StrokeParams{.rho = 0.05f, .phi = 0.0f, .fold = {}},
                  StrokeAttributes{std::vector<float>(n, width), std::vector<float>(n, alpha),
                                   std::vector<glm::vec3>(n, glm::vec3(0.0f))},
                  cap, join, vertices);
    return vertices;
}

// `path` drawn `width` px wide by the line pass, or as a stroke textured by the solid SLAM.
std::vector<float> draw_ink(const Context& ctx, const ScreenPath& path, float width, Drawer drawer) {
    if (drawer == Drawer::SolidStroke) return stroke_ink(ctx, build(path, width, Cap::Butt, Join::Mitre));
    const LinePass lines(ctx);
    return ink_of(ctx, [&](VkCommandBuffer cmd, RenderTarget& target, UploadArena& arena) {
        lines.record(ctx, cmd, target, {path}, LineDrawStyle{.width = width, .fade = false}, arena);
    });
}

float column_ink(const std::vector<float>& ink, int x) {
    float sum = 0.0f;
    for (int y = 0; y < kSize; ++y) sum += ink[size_t(y) * kSize + x];
    return sum;
}

class Antialiasing : public test::GpuTest, public ::testing::WithParamInterface<Drawer> {};
class AntialiasingReference : public test::GpuTest {};

// A shallow line (3° off horizontal, at a fractional height): every column holds intermediate
// values on both edges, none outside the one-pixel ramps, and integrates to the width.
TEST_P(Antialiasing, StraightLineHasItsWidthAndAOnePixelRamp) {
    const glm::vec2 a(4.0f, 30.3f), b(60.0f, 30.3f + 56.0f * std::tan(3.0f * 3.14159265f / 180.0f));
    const float cos_theta = std::cos(std::atan2(b.y - a.y, b.x - a.x));
    for (const float width : {0.5f, 1.0f, 2.5f, 4.0f, 7.0f}) {
        const std::vector<float> ink = draw_ink(ctx(), segment_path(a, b), width, GetParam());
        int columns_with_ramps = 0;
        for (int x = 14; x < 50; ++x) {
            // The issue asks for ± 0.25 px; a box filter's share is exact, so hold it to 0.05
            // (measured: 0.003 at most, the 8-bit rounding).
            EXPECT_NEAR(column_ink(ink, x), width / cos_theta, 0.05f) << "width " << width << " column " << x;
            int partial = 0, first = kSize, last = -1;
            for (int y = 0; y < kSize; ++y) {
                const float v = ink[size_t(y) * kSize + x];
                if (v > 0.02f) first = std::min(first, y), last = std::max(last, y);
                if (v > 0.02f && v < 0.98f) ++partial;
            }
            // Ink spans the width plus a pixel of falloff, and only the falloff is partial: at
            // most two pixels each side (one when an edge lies on a pixel boundary: no ramp).
            EXPECT_LE(last - first + 1, int(std::ceil(width / cos_theta)) + 2) << width << " " << x;
            EXPECT_LE(partial, 4) << width << " " << x;
            columns_with_ramps += partial >= (width >= 1.0f ? 2 : 1);
        }
        EXPECT_GE(columns_with_ramps, 30) << "of 36 columns, width " << width;
    }
}

// A diagonal line's coverage is even along it (no stair steps) and integrates to its width.
TEST_P(Antialiasing, DiagonalLineCoverageIsEven) {
    for (const float width : {1.0f, 2.5f, 4.0f}) {
        for (const float angle_deg : {45.0f, 30.0f, 60.0f}) {
            const float angle = angle_deg * 3.14159265f / 180.0f;
            const glm::vec2 centre(32.2f, 31.7f), d(std::cos(angle), std::sin(angle));
            const std::vector<float> ink = draw_ink(ctx(), segment_path(centre - 40.0f * d, centre + 40.0f * d), width,
                                                    GetParam());
            float lo = 1e9f, hi = 0.0f, sum = 0.0f;
            int count = 0;
            for (int x = 16; x < 48; ++x) {
                // Only columns the line crosses whole (not cut by the image's top or bottom).
                const float y_mid = centre.y + (float(x) + 0.5f - centre.x) * d.y / d.x;
                if (y_mid < 10.0f || y_mid > kSize - 10.0f) continue;
                const float c = column_ink(ink, x);
                lo = std::min(lo, c), hi = std::max(hi, c), sum += c, ++count;
            }
            ASSERT_GT(count, 8);
            const float mean = sum / float(count);
            // The issue asks for < 10 %; measured ≤ 0.4 % (8-bit rounding), so hold it to 2 %.
            EXPECT_LT((hi - lo) / mean, 0.02f) << "width " << width << " angle " << angle_deg;
            EXPECT_NEAR(mean, width / d.x, 0.05f / d.x) << "width " << width << " angle " << angle_deg;
        }
    }
}

// The GPU draws what the CPU reference computes (stroke/stroke_reference.h) for a curve with
// every cap and join, thick, thin and translucent: within 2/255 but at triangle-edge ties.
TEST_F(AntialiasingReference, GpuMatchesCpuReference) {
    ScreenPath curve;
    for (int i = 0; i <= 24; ++i) {
        const float a = 0.25f * float(i);
        const glm::vec2 p(32.0f + 22.0f * std::cos(a) * (1.0f - 0.02f * float(i)), 32.0f + 18.0f * std::sin(1.7f * a));
        const float s = curve.samples.empty() ? 0.0f : curve.samples.back().s + glm::length(p - curve.samples.back().pixel);
        curve.samples.push_back(ScreenSample{.pixel = p, .depth = 1.0f, .s = s, .position = {}, .face = 0, .bary = {}, .alpha = 1.0f});
    }
    struct Case { float width; Cap cap; Join join; float alpha; };
    for (const Case c : {Case{5.0f, Cap::Round, Join::Round, 1.0f}, Case{3.0f, Cap::Square, Join::Mitre, 1.0f},
                         Case{2.0f, Cap::Butt, Join::Round, 0.6f}, Case{0.6f, Cap::Round, Join::Mitre, 1.0f}}) {
        const std::vector<StrokeVertex> vertices = build(curve, c.width, c.cap, c.join, c.alpha);
        const std::vector<float> gpu = stroke_ink(ctx(), vertices), cpu = stroke_ink_reference(vertices, kSize, kSize);
        size_t off = 0;
        double total = 0.0;
        for (size_t i = 0; i < gpu.size(); ++i) {
            off += std::abs(gpu[i] - cpu[i]) > 2.0f / 255.0f;
            total += cpu[i];
        }
        EXPECT_LE(off, 4u) << "width " << c.width;  // measured: 0, every difference ≤ 1/255
        EXPECT_GT(total, 20.0) << "the stroke is drawn";
    }
}

// A translucent set is drawn once (gpu/coverage_layer.h): where its strokes overlap — a
// figure of eight crossing itself, round joins at its sharp turns, a second stroke across
// it — the ink is the larger of the coverages, never more than the set's alpha; drawn over
// the frame one triangle after another it reaches 1 − (1 − α)² there. Both passes, against
// the C++ reference's union.
TEST_F(AntialiasingReference, ATranslucentSetDrawnOnceInksItsUnion) {
    ScreenPath eight, across = segment_path({6.0f, 40.3f}, {58.0f, 24.7f});
    for (int i = 0; i <= 48; ++i) {
        const float t = 6.2831853f * float(i) / 48.0f;
        const glm::vec2 p(32.0f + 24.0f * std::sin(t), 32.0f + 16.0f * std::sin(2.0f * t));
        const float s = eight.samples.empty() ? 0.0f : eight.samples.back().s + glm::length(p - eight.samples.back().pixel);
        eight.samples.push_back(ScreenSample{.pixel = p, .depth = 1.0f, .s = s, .position = {}, .face = 0, .bary = {}, .alpha = 1.0f});
    }
    constexpr float kAlpha = 0.5f, kWidth = 5.0f;
    std::vector<StrokeVertex> vertices = build(eight, kWidth, Cap::Round, Join::Round, kAlpha);
    for (const StrokeVertex& v : build(across, kWidth, Cap::Round, Join::Round, kAlpha)) vertices.push_back(v);
    const std::vector<float> once = stroke_ink_reference(vertices, kSize, kSize, InkBlend::Once);
    const std::vector<float> over = stroke_ink_reference(vertices, kSize, kSize, InkBlend::Over);
    EXPECT_GT(*std::max_element(over.begin(), over.end()), 0.7f) << "the figure overlaps itself";
    EXPECT_NEAR(*std::max_element(once.begin(), once.end()), kAlpha, 1e-6f);

    const LayerComposite composite(ctx(), VK_FORMAT_R8G8B8A8_UNORM);
    CoverageLayer layer(ctx(), kSize, kSize);
    const StrokePass strokes(ctx());
    const SlamTexture solid(ctx(), solid_slam());
    const LinePass lines(ctx());
    const std::vector<float> stroke_gpu = ink_of(ctx(), [&](VkCommandBuffer cmd, RenderTarget& target, UploadArena& arena) {
        ASSERT_TRUE(strokes.record(ctx(), cmd, target, vertices, solid, arena, &layer));
        composite.record(ctx(), cmd, target, layer);
    });
    // The line pass builds its own triangles (mitre joins, square caps): its reference is theirs.
    const LineDrawStyle style{.alpha = kAlpha, .width = kWidth, .fade = false};
    const std::vector<float> line_gpu = ink_of(ctx(), [&](VkCommandBuffer cmd, RenderTarget& target, UploadArena& arena) {
        ASSERT_TRUE(lines.record(ctx(), cmd, target, {eight, across}, style, arena, &layer));
        composite.record(ctx(), cmd, target, layer);
    });
    const std::vector<float> line_once =
        stroke_ink_reference(line_triangles({eight, across}, style, kCoverageMarginPx, false), kSize, kSize, InkBlend::Once);
    for (const auto& [gpu, cpu, name] : {std::tuple{&stroke_gpu, &once, "stroke pass"}, std::tuple{&line_gpu, &line_once, "line pass"}}) {
        size_t off = 0;
        double total = 0.0;
        for (size_t i = 0; i < gpu->size(); ++i) {
            off += std::abs((*gpu)[i] - (*cpu)[i]) > 2.0f / 255.0f;
            total += (*gpu)[i];
        }
        EXPECT_LE(off, 4u) << name;
        EXPECT_GT(total, 50.0) << name << ": drawn";
        EXPECT_LE(*std::max_element(gpu->begin(), gpu->end()), kAlpha + 1.5f / 255.0f) << name;
    }
    // Two sets through the same layer in one command buffer, each cleared and composited over
    // its own box: the second over the first, as two sets blend.
    const std::vector<StrokeVertex> first = build(eight, kWidth, Cap::Round, Join::Round, kAlpha),
                                    second = build(across, kWidth, Cap::Round, Join::Round, 0.8f);
    const std::vector<float> two = ink_of(ctx(), [&](VkCommandBuffer cmd, RenderTarget& target, UploadArena& arena) {
        for (const auto* set : {&first, &second}) {
            ASSERT_TRUE(strokes.record(ctx(), cmd, target, *set, solid, arena, &layer));
            composite.record(ctx(), cmd, target, layer);
        }
    });
    const std::vector<float> a = stroke_ink_reference(first, kSize, kSize, InkBlend::Once),
                             b = stroke_ink_reference(second, kSize, kSize, InkBlend::Once);
    size_t off = 0;
    for (size_t i = 0; i < two.size(); ++i) off += std::abs(two[i] - (1.0f - (1.0f - a[i]) * (1.0f - b[i]))) > 3.0f / 255.0f;
    EXPECT_LE(off, 4u) << "two sets";
}

// A round join leaves no gap on either centre line next to the corner (the inner gap triangles
// ramp like the body they border), and the L holds its area: two arms of 30 × w, less the
// inner square they share (h²), plus the outer quarter disc (πh²/4) and the butt fringes.
TEST_F(AntialiasingReference, RoundJoinKeepsTheInkOfBothArms) {
    const ScreenPath l_path = segment_path({10.5f, 10.5f}, {40.5f, 10.5f});
    ScreenPath path = l_path;
    for (const ScreenSample& q : segment_path({40.5f, 10.5f}, {40.5f, 40.5f}).samples) {
        if (q.s == 0.0f) continue;
        ScreenSample next = q;
        next.s += 30.0f;
        path.samples.push_back(next);
    }
    for (const float width : {1.5f, 2.5f, 5.0f}) {
        const std::vector<float> ink = stroke_ink(ctx(), build(path, width, Cap::Butt, Join::Round));
        for (int k = 0; k <= 3; ++k) {
            EXPECT_GE(ink[size_t(10) * kSize + 40 - k], 0.9f) << "incoming arm, width " << width << " k " << k;
            EXPECT_GE(ink[size_t(10 + k) * kSize + 40], 0.9f) << "outgoing arm, width " << width << " k " << k;
        }
        const float h = 0.5f * width;
        const float area = 60.0f * width - h * h + 3.14159265f * h * h / 4.0f;
        float total = 0.0f;
        for (const float v : ink) total += v;
        // Measured within 0.23 px² (the arc is taken for straight edges pixel by pixel).
        EXPECT_NEAR(total, area, 0.5f) << "width " << width;
        // The C++ reference draws the same pixels (the L's corners lie on pixel centres, so
        // this checks its tie-breaking rule too).
        const std::vector<float> cpu = stroke_ink_reference(build(path, width, Cap::Butt, Join::Round), kSize, kSize);
        size_t off = 0;
        for (size_t i = 0; i < cpu.size(); ++i) off += std::abs(cpu[i] - ink[i]) > 2.0f / 255.0f;
        EXPECT_LE(off, 4u) << "width " << width;
    }
}

INSTANTIATE_TEST_SUITE_P(BothDrawers, Antialiasing, ::testing::Values(Drawer::LinePass, Drawer::SolidStroke),
                         [](const auto& param_info) { return param_info.param == Drawer::LinePass ? "LinePass" : "SolidStroke"; });

class SurfaceMultisampling : public test::GpuTest {};

// Unlit spot over white with 1 and 4 samples: one sample gives two colours only; four give
// edge pixels in between whose coverage (their blend of surface and background) sums to the
// CPU coverage reference's area, and the resolved depth (the farthest sample) never marks a
// pixel covered that the colour shows as background.
TEST_F(SurfaceMultisampling, EdgesBlendAndAreaIsKept) {
    const int width = 240, height = 180;
    SceneDesc desc = scene_for_model(test::data_dir() / "models/spot/spot.glb");
    desc.style.shading = Shading::Unlit;
    desc.lines.enabled = false;
    const LoadedScene scene = load_scene(desc);
    const CameraMatrices camera = camera_matrices(scene.camera, float(width) / float(height), scene.bounds);
    const std::vector<uint8_t> reference = coverage_reference(scene.mesh, camera, width, height);
    const double reference_area = double(std::count(reference.begin(), reference.end(), uint8_t(1)));
    FrameRenderer renderer(ctx(), width, height);
    renderer.set_mesh(scene.mesh, false, 0.0f);
    const float surface_red = desc.style.color.r * 255.0f;
    for (const uint32_t samples : {1u, 4u}) {
        desc.style.samples = samples;
        const FrameReadback frame =
            renderer.render(camera, scene.camera.eye, desc.style, desc.lines, {.color = true, .depth = true}).image;
        double area = 0.0;
        size_t partial = 0, deep_background = 0;
        for (size_t i = 0; i < size_t(width) * height; ++i) {
            const float coverage = (255.0f - float(frame.color.pixels[4 * i])) / (255.0f - surface_red);
            area += std::clamp(coverage, 0.0f, 1.0f);
            partial += coverage > 0.05f && coverage < 0.95f;
            deep_background += frame.depth[i] < 1.0f && coverage < 0.05f;
        }
        EXPECT_NEAR(area, reference_area, 0.01 * reference_area) << samples << " samples";
        EXPECT_EQ(deep_background, 0u) << samples << " samples";
        if (samples == 1) {
            EXPECT_EQ(partial, 0u);
        } else {
            EXPECT_GT(partial, 200u) << "the silhouette's edge pixels blend";
        }
    }
}

}  // namespace
}  // namespace lw
