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

// The triangles as filled `<path>`s, one per run of consecutive triangles of one colour and
// opacity (to 1/255: what the PNG can tell apart), each triangle wound the same way so that
// the nonzero rule fills their union.
std::string shape_paths(const std::vector<StrokeVertex>& triangles, const std::string& indent) {
    std::string out, key, d;
    float opacity = 1.0f;
    auto flush = [&] {
        if (d.empty()) return;
        out += indent + "<path fill=\"" + key.substr(0, 7) + "\"";
        if (opacity < 1.0f) out += " fill-opacity=\"" + number(opacity, 3) + "\"";
        out += " d=\"" + d + "\"/>\n";
        d.clear();
    };
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const StrokeVertex *a = &triangles[t], *b = &triangles[t + 1], *c = &triangles[t + 2];
        const glm::vec2 ab = b->pixel - a->pixel, ac = c->pixel - a->pixel;
        const float area = ab.x * ac.y - ab.y * ac.x;
        if (area == 0.0f) continue;
        if (area < 0.0f) std::swap(b, c);
        const glm::vec4 mean = (a->color + b->color + c->color) / 3.0f;
        const float alpha = std::round(std::clamp(mean.a, 0.0f, 1.0f) * 255.0f) / 255.0f;
        if (alpha <= 0.0f) continue;
        const std::string k = hex_color(glm::vec3(mean)) + number(alpha, 3);
        if (k != key) {
            flush();
            key = k;
            opacity = alpha;
        }
        d += (d.empty() ? "M" : " M") + number(a->pixel.x) + "," + number(a->pixel.y) + " " + number(b->pixel.x) + "," +
             number(b->pixel.y) + " " + number(c->pixel.x) + "," + number(c->pixel.y) + "Z";
    }
    flush();
    return out;
}

}  // namespace

std::string lines_svg(int width, int height, const std::vector<SvgGroup>& groups) {
    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
           std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) + "\">\n";
    static const std::vector<ScreenPath> none;
    for (const SvgGroup& group : groups) {
        svg += "  <g id=\"" + group.id + "\" fill-rule=\"nonzero\" stroke=\"none\">\n";
        svg += shape_paths(group.shapes, "    ");
        if (!group.hidden_shapes.empty()) {
            svg += "    <g id=\"" + group.id + "-hidden\">\n";
            svg += shape_paths(group.hidden_shapes, "      ");
            svg += "    </g>\n";
        }
        svg += "  </g>\n";
        svg += "  <g id=\"" + group.id + "-centerlines\" display=\"none\" fill=\"none\" stroke=\"" +
               hex_color(group.color) + "\" stroke-width=\"" + number(group.width) +
               "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
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
