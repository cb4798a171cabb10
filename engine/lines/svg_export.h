// engine/lines/svg_export.h — a frame's lines as SVG, drawn as the PNG draws them.
//
// Output contract: pixel coordinates with the image size as the viewBox; per line set, in
// drawing order (the per-type shorthand: "silhouette", "suggestive", "crease", "border",
// always all four, possibly empty):
//   - `<g id=NAME>`: the strokes as filled shapes — the outlines the renderer draws (widths,
//     tapers, caps and joins as geometry), one `<path>` per run of like colour and opacity
//     (fades as `fill-opacity`), nonzero fill; what standard renderers (browsers, Inkscape,
//     rsvg) draw as the PNG shows it, up to antialiasing and the SLAM texture, which SVG has
//     no way to carry (textured strokes are drawn in their solid ink). A translucent set
//     (alpha < 1 or alpha modifiers) has its most opaque shape's alpha as the group's
//     `opacity` and its shapes' opacities relative to it: a group is composited once, as
//     the PNG draws such a set (gpu/coverage_layer.h), so that where its shapes overlap they
//     do not blend twice;
//   - `<g id=NAME-hidden>` inside it when the set selects hidden lines (in every frame, empty
//     in one that has none): their shapes in their look (faint: a quarter of the opacity;
//     dashed: the dashes as shapes);
//   - `<g id=NAME-centerlines display="none">` after it: one `<polyline>` per visible path
//     (a closed loop repeats its first point), the paths themselves for tools to read back,
//     with the set's colour, width, caps and joins (a mitre as SVG's miter at the stroke
//     builder's limit, where the shapes clip a longer mitre and SVG bevels it).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "stroke/stroke_geometry.h"
#include "types/line_set.h"
#include "types/screen_path.h"

namespace lw {

struct SvgGroup {
    std::string id;
    glm::vec3 color{0.0f};
    float width = 1.0f;
    float opacity = 1.0f;  // the group's, for a set drawn once: the shapes' alpha is divided by it
    Cap cap = Cap::Square;  // the set's ends and joins, for the centre lines
    Join join = Join::Mitre;
    bool hidden = false;  // the set selects hidden lines: its -hidden group is written
    const std::vector<ScreenPath>* paths = nullptr;  // the set's paths (null: none)
    // The set's strokes as the renderer builds them without the coverage margin (triangles
    // with per-vertex colour and alpha), visible and hidden runs apart.
    std::vector<StrokeVertex> shapes, hidden_shapes;
};

[[nodiscard]] std::string lines_svg(int width, int height, const std::vector<SvgGroup>& groups);

// Writes `lines_svg` to `path`; throws lw::Error naming the file on failure.
void write_lines_svg(const std::filesystem::path& path, int width, int height, const std::vector<SvgGroup>& groups);

}  // namespace lw
