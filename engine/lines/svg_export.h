// engine/lines/svg_export.h — visible brush paths as SVG.
//
// Output contract: pixel coordinates with the image size as the viewBox; one `<g id=NAME>`
// per line set in drawing order (the per-type shorthand: "silhouette", "suggestive",
// "crease", "border", always all four, possibly empty); one `<polyline>` per visible path;
// a closed loop repeats its first point. Stroke width and colour per set are attributes of
// the group.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "types/screen_path.h"

namespace lw {

struct SvgGroup {
    std::string id;
    glm::vec3 color{0.0f};
    float width = 1.0f;
    const std::vector<ScreenPath>* paths = nullptr;  // null: an empty group
};

[[nodiscard]] std::string lines_svg(int width, int height, const std::vector<SvgGroup>& groups);

// Writes `lines_svg` to `path`; throws lw::Error naming the file on failure.
void write_lines_svg(const std::filesystem::path& path, int width, int height, const std::vector<SvgGroup>& groups);

}  // namespace lw
