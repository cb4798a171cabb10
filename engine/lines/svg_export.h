// engine/lines/svg_export.h — visible brush paths as SVG.
//
// Output contract (issue "Feature lines"): pixel coordinates with the image size as the
// viewBox; one `<g id="silhouette|suggestive|crease|border">` per line type (always all
// four, possibly empty, in that order); one `<polyline>` per visible path; a closed loop
// repeats its first point. Stroke width and colour per type are attributes of the group.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "lines/visibility.h"
#include "scene/style.h"

namespace lw {

[[nodiscard]] std::string lines_svg(int width, int height, const std::vector<ScreenPath>& paths,
                                    const std::array<LineStyle, kLineTypeCount>& styles);

// Writes `lines_svg` to `path`; throws lw::Error naming the file on failure.
void write_lines_svg(const std::filesystem::path& path, int width, int height, const std::vector<ScreenPath>& paths,
                     const std::array<LineStyle, kLineTypeCount>& styles);

}  // namespace lw
