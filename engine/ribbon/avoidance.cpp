#include "ribbon/avoidance.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "ribbon/triangle_raster.h"

namespace lw {

size_t ForbiddenMask::count() const {
    return size_t(std::count_if(pixels.begin(), pixels.end(), [](uint8_t p) { return p != 0; }));
}

std::vector<uint8_t> coverage_counts_reference(const Ribbon& ribbon, int width, int height) {
    std::vector<uint8_t> counts(size_t(width) * size_t(height), 0);
    auto count = [&](int x, int y) {
        uint8_t& c = counts[size_t(y) * size_t(width) + size_t(x)];
        if (c < 255) ++c;
    };
    for (const RibbonPiece& p : ribbon.pieces) {
        for_each_covered_pixel({glm::dvec2(p.top_left), glm::dvec2(p.bottom_left), glm::dvec2(p.bottom_right)}, width,
                               height, count);
        for_each_covered_pixel({glm::dvec2(p.top_left), glm::dvec2(p.bottom_right), glm::dvec2(p.top_right)}, width,
                               height, count);
    }
    return counts;
}

ForbiddenMask avoidance_map_reference(const Ribbon& ribbon, int width, int height) {
    const std::vector<uint8_t> counts = coverage_counts_reference(ribbon, width, height);
    ForbiddenMask mask{width, height, std::vector<uint8_t>(counts.size())};
    for (size_t i = 0; i < counts.size(); ++i) mask.pixels[i] = counts[i] > 1 ? 1 : 0;
    return mask;
}

ForbiddenMask forbidden_from_image(const ImageRGBA8& image) {
    ForbiddenMask mask{image.width, image.height, std::vector<uint8_t>(size_t(image.width) * size_t(image.height))};
    for (size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = image.pixels[i * 4 + 3] >= 128 ? 1 : 0;
    return mask;
}

void merge_forbidden(ForbiddenMask& into, const ForbiddenMask& other) {
    if (into.width != other.width || into.height != other.height)
        throw Error("the avoidance map is " + std::to_string(other.width) + "x" + std::to_string(other.height) +
                    " but the canvas is " + std::to_string(into.width) + "x" + std::to_string(into.height));
    for (size_t i = 0; i < into.pixels.size(); ++i) into.pixels[i] = into.pixels[i] | other.pixels[i];
}

}  // namespace lw
