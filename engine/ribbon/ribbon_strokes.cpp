#include "ribbon/ribbon_strokes.h"

#include <algorithm>
#include <cmath>

#include "core/timer.h"
#include "ribbon/problem.h"
#include "ribbon/synthesize.h"

namespace lw {

namespace {

// Straight-alpha `over` of the ribbon layer onto the frame.
void composite_over(const ImageRGBA8& layer, ImageRGBA8& image) {
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        const int a = layer.pixels[i + 3];
        if (a == 0) continue;
        for (size_t c = 0; c < 3; ++c)
            image.pixels[i + c] = uint8_t((layer.pixels[i + c] * a + image.pixels[i + c] * (255 - a) + 127) / 255);
        image.pixels[i + 3] = uint8_t(a + (image.pixels[i + 3] * (255 - a) + 127) / 255);
    }
}

}  // namespace

RibbonStrokeStats draw_ribbon_strokes(const Context& ctx, const std::vector<ScreenPath>& paths,
                                      std::optional<LineType> type,
                                      const Exemplar& exemplar, const RibbonStrokeDesc& desc, ImageRGBA8& image) {
    Timer timer;
    RibbonStrokeStats stats;
    RibbonSynthesisDesc synthesis;
    synthesis.params.scale = desc.scale > 0.0f ? desc.scale : default_ribbon_scale(exemplar);
    synthesis.params.width = desc.width;
    synthesis.params.piece = std::max(1.0f, std::round(desc.width / 2.0f));
    synthesis.width = image.width;
    synthesis.height = image.height;
    for (size_t p = 0; p < paths.size(); ++p) {
        const ScreenPath& path = paths[p];
        if (!path.visible || (type && path.type != *type) || path.samples.size() < 2) continue;
        if (path.samples.back().s - path.samples.front().s < 2.0f * synthesis.params.piece) {
            ++stats.skipped;
            continue;
        }
        Curve2D curve{.closed = path.closed};
        for (const ScreenSample& sample : path.samples) curve.points.push_back(sample.pixel);
        synthesis.seed = desc.seed * 0x9E3779B97F4A7C15ull + p;
        const RibbonSynthesis s = synthesize_ribbon(ctx, exemplar, ArclengthCurve(curve), synthesis);
        composite_over(s.image, image);
        ++stats.paths;
    }
    stats.ms = timer.elapsed_ms();
    return stats;
}

}  // namespace lw
