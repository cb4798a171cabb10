#include "vector/layer.h"

#include <algorithm>
#include <cmath>

namespace lw {

namespace {
constexpr float kViewMargin = 16.0f;  // pixels around the image where strokes are still kept
}  // namespace

LayerTransform layer_transform_at(const std::vector<LayerKey>& keys, float seconds) {
    if (keys.empty()) return {};
    if (seconds <= keys.front().time) return keys.front().transform;
    if (seconds >= keys.back().time) return keys.back().transform;
    size_t k = 1;
    while (keys[k].time < seconds) ++k;
    const LayerKey& a = keys[k - 1];
    const LayerKey& b = keys[k];
    const float u = b.time > a.time ? (seconds - a.time) / (b.time - a.time) : 1.0f;
    LayerTransform t;
    if (a.transform.center || b.transform.center) {
        const glm::vec2 ca = a.transform.center.value_or(b.transform.center.value_or(glm::vec2(0.0f)));
        const glm::vec2 cb = b.transform.center.value_or(ca);
        t.center = glm::mix(ca, cb, u);
    }
    // Geometric: equal zoom factors in equal times.
    t.scale = a.transform.scale * std::pow(b.transform.scale / a.transform.scale, u);
    t.rotate_deg = glm::mix(a.transform.rotate_deg, b.transform.rotate_deg, u);
    return t;
}

glm::vec2 layer_to_pixel(const LayerTransform& t, glm::vec2 point, glm::vec2 image_size) {
    const glm::vec2 middle = 0.5f * image_size;
    const glm::vec2 d = (point - t.center.value_or(middle)) * t.scale;
    const float a = glm::radians(t.rotate_deg), c = std::cos(a), s = std::sin(a);
    return middle + glm::vec2(c * d.x - s * d.y, s * d.x + c * d.y);
}

CameraMatrices layer_camera(const LayerTransform& t, glm::vec2 image_size) {
    // pixel = middle + s·R·(p − center); clip = 2·pixel / size − 1 (project_to_pixel inverted).
    const glm::vec2 middle = 0.5f * image_size;
    const glm::vec2 center = t.center.value_or(middle);
    const float a = glm::radians(t.rotate_deg), c = std::cos(a) * t.scale, s = std::sin(a) * t.scale;
    glm::mat4 to_pixel(1.0f);  // column-major: columns are the images of x, y, z and the origin
    to_pixel[0] = glm::vec4(c, s, 0.0f, 0.0f);
    to_pixel[1] = glm::vec4(-s, c, 0.0f, 0.0f);
    to_pixel[3] = glm::vec4(middle - glm::vec2(c * center.x - s * center.y, s * center.x + c * center.y), 0.0f, 1.0f);
    glm::mat4 to_clip(1.0f);
    to_clip[0][0] = 2.0f / image_size.x;
    to_clip[1][1] = 2.0f / image_size.y;
    to_clip[3] = glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f);
    CameraMatrices m;
    m.view_proj = to_clip * to_pixel;
    m.znear = 0.0f;
    m.zfar = 1.0f;
    return m;
}

namespace {

// One stroke as a screen path sampled every `spacing` pixels of its on-screen arclength
// and at its corners; each sample keeps its drawing point (for reprojection) and width.
ScreenPath stroke_path(const Stroke& stroke, const LayerTransform& transform, glm::vec2 size, float spacing) {
    ScreenPath path{.type = LineType::Border, .closed = stroke.closed && stroke.points.size() > 2, .visible = true};
    std::vector<glm::vec2> points = stroke.points;
    std::vector<float> widths = stroke.widths;
    if (points.size() == 1) {  // a stipple: one sample, which the stroke builder draws as a dot
        points.push_back(points.front());
        widths.push_back(widths.front());
    }
    if (path.closed) {  // walk the closing segment too; the renderer closes the loop itself
        points.push_back(points.front());
        widths.push_back(widths.front());
    }
    std::vector<glm::vec2> pixels;
    std::vector<float> arclength{0.0f};
    for (const glm::vec2& p : points) pixels.push_back(layer_to_pixel(transform, p, size));
    for (size_t i = 1; i < pixels.size(); ++i) arclength.push_back(arclength.back() + glm::length(pixels[i] - pixels[i - 1]));
    const float length = arclength.back();
    std::vector<float> at = arclength;
    for (float x = spacing; x < length; x += spacing) at.push_back(x);
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end(), [](float a, float b) { return b - a < 1e-4f; }), at.end());
    if (path.closed && at.size() > 1) at.pop_back();  // the closing point repeats the first
    size_t i = 0;
    for (const float x : at) {
        while (i + 2 < pixels.size() && arclength[i + 1] < x) ++i;
        const float span = arclength[i + 1] - arclength[i];
        const float u = span > 0.0f ? std::clamp((x - arclength[i]) / span, 0.0f, 1.0f) : 0.0f;
        path.samples.push_back(ScreenSample{.pixel = glm::mix(pixels[i], pixels[i + 1], u), .depth = 1.0f, .s = x,
                                            .position = glm::vec3(glm::mix(points[i], points[i + 1], u), 0.0f),
                                            .face = 0, .bary = glm::vec3(1.0f, 0.0f, 0.0f), .alpha = 1.0f,
                                            .width = glm::mix(widths[i], widths[i + 1], u)});
    }
    return path;
}

// The runs of a path inside the image grown by `margin` pixels: a zoomed drawing reaches far
// off-screen, and only what can be seen is worth splatting and voting with. A loop cut by
// the border becomes open runs (started after an outside sample, so that no run wraps).
std::vector<ScreenPath> clip_to_view(ScreenPath path, glm::vec2 size, float margin) {
    auto inside = [&](const ScreenSample& s) {
        return s.pixel.x >= -margin && s.pixel.y >= -margin && s.pixel.x <= size.x + margin &&
               s.pixel.y <= size.y + margin;
    };
    auto& samples = path.samples;
    const auto outside = std::find_if_not(samples.begin(), samples.end(), inside);
    if (outside == samples.end()) return {std::move(path)};
    if (path.closed) {
        std::rotate(samples.begin(), outside, samples.end());
        path.closed = false;
    }
    std::vector<ScreenPath> runs;
    ScreenPath run{.type = path.type, .closed = false, .visible = true, .source = path.source};
    for (const ScreenSample& sample : samples) {
        if (inside(sample)) {
            run.samples.push_back(sample);
        } else if (!run.samples.empty()) {
            if (run.samples.size() > 1) runs.push_back(run);
            run.samples.clear();
        }
    }
    if (run.samples.size() > 1) runs.push_back(std::move(run));
    return runs;
}

}  // namespace

LayerFrame layer_frame(const StrokeSet& drawing, const std::vector<glm::vec2>& fill_triangles,
                       const VectorLayerDesc& desc, const LayerTransform& transform, glm::vec2 image_size,
                       float spacing) {
    LayerFrame frame;
    frame.camera = layer_camera(transform, image_size);
    for (const glm::vec2& p : fill_triangles) frame.fill.push_back(layer_to_pixel(transform, p, image_size));
    if (!desc.outline) return frame;
    const float width_scale = desc.width_scale * (desc.scale_widths ? transform.scale : 1.0f);
    for (const Stroke& stroke : drawing.strokes) {
        if (stroke.points.empty()) continue;
        ScreenPath path = stroke_path(stroke, transform, image_size, spacing);
        path.source = frame.colors.size();  // its colour, through clipping and the tracker's splits
        for (ScreenSample& sample : path.samples) sample.width *= width_scale;
        for (ScreenPath& run : clip_to_view(std::move(path), image_size, kViewMargin)) frame.paths.push_back(std::move(run));
        frame.colors.push_back(desc.color.value_or(stroke.color));
    }
    return frame;
}

}  // namespace lw
