#include "lines/svg_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/color.h"
#include "core/error.h"

namespace lw {

namespace {


// Two decimals for the shapes' coordinates (a hundredth of a pixel); three for the centre
// lines, so that a path read back from the file lies within 5e-4 px of the one drawn (the
// Python module's lines are compared to it).
std::string number(float v, int decimals = 2) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, double(v));
    return text;
}

std::string point(glm::vec2 p) { return number(p.x, 3) + "," + number(p.y, 3); }

// SVG's stroke-linecap and -linejoin for a set's ends and joins. SVG's miter limit is the
// mitre's length over the stroke's width, 1/sin(θ/2), which is the builder's limit in half
// widths: both stop mitring at the same angle.
std::string cap_and_join(Cap cap, Join join) {
    std::string out = " stroke-linecap=\"";
    out += cap == Cap::Butt ? "butt" : cap == Cap::Round ? "round" : "square";
    out += join == Join::Round ? "\" stroke-linejoin=\"round\""
                               : "\" stroke-linejoin=\"miter\" stroke-miterlimit=\"" +
                                     number(StrokeParams{}.mitre_limit) + "\"";
    return out;
}

// The triangles as filled `<path>`s, one per run of consecutive triangles of one colour (to
// 1/255, what the PNG tells apart) whose opacity stays within 0.02 of the run's first, drawn at
// the run's mean: a fading line is a few paths, not one per triangle (every path is
// antialiased on its own, so each break is a faint seam). Each triangle is wound the same way
// so that the nonzero rule fills their union.
// `group_opacity`: the enclosing group's, by which each triangle's alpha is divided.
std::string shape_paths(const std::vector<StrokeVertex>& triangles, float group_opacity, const std::string& indent) {
    std::string out, color, d;
    if (!(group_opacity > 0.0f)) return out;  // an invisible set
    float first_alpha = 1.0f, alpha_sum = 0.0f;
    int count = 0;
    auto flush = [&] {
        if (d.empty()) return;
        const float opacity = std::round(alpha_sum / float(count) * 255.0f) / 255.0f;
        out += indent + "<path fill=\"" + color + "\"";
        if (opacity < 1.0f) out += " fill-opacity=\"" + number(opacity, 3) + "\"";
        out += " d=\"" + d + "\"/>\n";
        d.clear();
        alpha_sum = 0.0f;
        count = 0;
    };
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const StrokeVertex *a = &triangles[t], *b = &triangles[t + 1], *c = &triangles[t + 2];
        const glm::vec2 ab = b->pixel - a->pixel, ac = c->pixel - a->pixel;
        const float area = ab.x * ac.y - ab.y * ac.x;
        if (area == 0.0f) continue;
        if (area < 0.0f) std::swap(b, c);
        const glm::vec4 mean = (a->color + b->color + c->color) / 3.0f;
        const float alpha = std::round(std::clamp(mean.a / group_opacity, 0.0f, 1.0f) * 255.0f) / 255.0f;
        if (alpha <= 0.0f) continue;
        const std::string fill = hex_color(glm::vec3(mean));
        if (fill != color || std::abs(alpha - first_alpha) > 0.02f) {
            flush();
            color = fill;
            first_alpha = alpha;
        }
        alpha_sum += alpha;
        ++count;
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
        svg += "  <g id=\"" + group.id + "\" fill-rule=\"nonzero\" stroke=\"none\"";
        if (group.opacity < 1.0f) svg += " opacity=\"" + number(group.opacity, 3) + "\"";
        svg += ">\n";
        svg += shape_paths(group.shapes, group.opacity, "    ");
        if (group.hidden || !group.hidden_shapes.empty()) {
            svg += "    <g id=\"" + group.id + "-hidden\">\n";
            svg += shape_paths(group.hidden_shapes, group.opacity, "      ");
            svg += "    </g>\n";
        }
        svg += "  </g>\n";
        svg += "  <g id=\"" + group.id + "-centerlines\" display=\"none\" fill=\"none\" stroke=\"" +
               hex_color(group.color) + "\" stroke-width=\"" + number(group.width) + "\"" +
               cap_and_join(group.cap, group.join) + ">\n";
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
