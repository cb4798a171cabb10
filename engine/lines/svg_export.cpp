#include "lines/svg_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/color.h"
#include "core/error.h"

namespace lw {

namespace {


// Widths with two decimals; coordinates with three, so that a path read back from the file
// lies within 5e-4 px of the one drawn (the Python module's lines are compared to it).
std::string number(float v, int decimals = 2) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, double(v));
    return text;
}

std::string point(glm::vec2 p) { return number(p.x, 3) + "," + number(p.y, 3); }

}  // namespace

std::string lines_svg(int width, int height, const std::vector<SvgGroup>& groups) {
    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
           std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) + "\">\n";
    static const std::vector<ScreenPath> none;
    for (const SvgGroup& group : groups) {
        svg += "  <g id=\"" + group.id + "\" fill=\"none\" stroke=\"" + hex_color(group.color) + "\" stroke-width=\"" +
               number(group.width) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
        for (const ScreenPath& path : group.paths ? *group.paths : none) {
            if (!path.visible || path.samples.size() < 2) continue;
            svg += "    <polyline points=\"";
            for (const ScreenSample& s : path.samples) svg += point(s.pixel) + " ";
            if (path.closed) svg += point(path.samples.front().pixel);
            if (svg.back() == ' ') svg.pop_back();
            svg += "\"/>\n";
        }
        svg += "  </g>\n";
    }
    svg += "</svg>\n";
    return svg;
}

void write_lines_svg(const std::filesystem::path& path, int width, int height, const std::vector<SvgGroup>& groups) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw Error(path.string() + ": cannot open for writing");
    out << lines_svg(width, height, groups);
    if (!out.flush()) throw Error(path.string() + ": write failed");
}

}  // namespace lw
