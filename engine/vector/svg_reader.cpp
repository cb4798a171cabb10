// engine/vector/svg_reader.cpp — parse_strokes_svg: SVG drawings as strokes, through pugixml.
//
// pugixml (Debian's libpugixml-dev) parses the XML: comments, CDATA, processing instructions,
// entities and any attribute quoting are its business. We walk the element tree as a
// renderer would: each element's transform composes with its parents' (SVG 1.1 §7.5, the
// list applied right to left), stroke paint and width are inherited through `stroke`,
// `stroke-width` and the CSS `style` attribute, and `display: none` hides a subtree (an
// Inkscape layer switched off). <use> draws the element it names, translated by x, y.
// Points are transformed; a width is scaled by the transform's mean scale √|det|.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "core/color.h"
#include "core/error.h"
#include "core/text.h"
#include "vector/curve.h"
#include "vector/stroke_io.h"
#include "vector/xml.h"

namespace lw {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxUseDepth = 32;
// <use> of groups of <use>s multiplies: ten levels of ten uses are 10^10 strokes from 2 KB.
constexpr size_t kMaxPoints = 10'000'000;
constexpr int kMaxNesting = 256;  // elements in elements: deeper is no drawing, and the walk recurses

// An element's name in SVG's namespace: where a file binds a prefix to it (xmlns:svg, as XML
// tools write SVG inside other documents) "svg:path" is "path". A name in another namespace
// (sodipodi:namedview, inkscape:…) keeps its prefix: editors' own data, not drawn.
std::string element_name(const pugi::xml_node& node) {
    const std::string name = node.name();
    const size_t colon = name.find(':');
    if (colon == std::string::npos) return name;
    const std::string binding = "xmlns:" + name.substr(0, colon);
    for (pugi::xml_node n = node; n; n = n.parent())
        if (const pugi::xml_attribute a = n.attribute(binding.c_str()))
            return std::string(a.as_string()) == "http://www.w3.org/2000/svg" ? name.substr(colon + 1) : name;
    return name;
}

// Numbers separated by white space and commas (points lists, data-widths, viewBox, transforms).
std::vector<double> number_list(const std::string& text, const std::string& where, const std::string& what) {
    std::vector<double> out;
    const char* p = text.c_str();
    while (*p) {
        while (*p && (std::isspace(static_cast<unsigned char>(*p)) || *p == ',')) ++p;
        if (!*p) break;
        char* end = nullptr;
        const double v = std::strtod(p, &end);
        if (end == p) throw Error(where + ": " + what + ": expected numbers, got \"" + text + "\"");
        out.push_back(v);
        p = end;
    }
    return out;
}

// A length in user units (px): CSS absolute units at 96 per inch (SVG 1.1 §7.10).
double parse_length(const std::string& text, const std::string& where, const std::string& what) {
    const std::string t = trim(text);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || end == t.c_str()) throw Error(where + ": " + what + ": expected a length, got \"" + text + "\"");
    const std::string unit = lower(trim(end));
    static const std::map<std::string, double> units = {{"", 1.0},          {"px", 1.0},         {"in", 96.0},
                                                        {"cm", 96.0 / 2.54}, {"mm", 96.0 / 25.4}, {"pt", 96.0 / 72.0},
                                                        {"pc", 16.0}};
    const auto it = units.find(unit);
    if (it == units.end())
        throw Error(where + ": " + what + ": unit \"" + unit + "\" of \"" + text +
                    "\" is not read (px, in, cm, mm, pt, pc are; relative units need a viewport)");
    return v * it->second;
}

// One transform list: matrix, translate, scale, rotate, skewX, skewY, composed left to right
// (the rightmost applies first to the points).
glm::dmat3 parse_transform(const std::string& text, const std::string& where, const std::string& what) {
    glm::dmat3 m(1.0);
    size_t i = 0;
    while (true) {
        while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ',')) ++i;
        if (i >= text.size()) break;
        size_t name_end = i;
        while (name_end < text.size() && std::isalpha(static_cast<unsigned char>(text[name_end]))) ++name_end;
        const std::string name = text.substr(i, name_end - i);
        const size_t open = text.find('(', name_end), close = text.find(')', name_end);
        if (name.empty() || open == std::string::npos || close == std::string::npos || close < open ||
            !trim(text.substr(name_end, open - name_end)).empty())
            throw Error(where + ": " + what + ": transform: expected name(numbers), got \"" + text + "\"");
        const std::vector<double> a = number_list(text.substr(open + 1, close - open - 1), where, what + " transform");
        const auto need = [&](size_t lo, size_t hi) {
            if (a.size() < lo || a.size() > hi)
                throw Error(where + ": " + what + ": transform: " + name + " takes " + std::to_string(lo) +
                            (hi > lo ? " to " + std::to_string(hi) : std::string()) + " numbers");
        };
        glm::dmat3 t(1.0);  // column-major: t[column][row]
        if (name == "matrix") {
            need(6, 6);
            t = glm::dmat3(a[0], a[1], 0.0, a[2], a[3], 0.0, a[4], a[5], 1.0);
        } else if (name == "translate") {
            need(1, 2);
            t[2] = glm::dvec3(a[0], a.size() > 1 ? a[1] : 0.0, 1.0);
        } else if (name == "scale") {
            need(1, 2);
            t[0][0] = a[0];
            t[1][1] = a.size() > 1 ? a[1] : a[0];
        } else if (name == "rotate") {
            if (a.size() != 1 && a.size() != 3)
                throw Error(where + ": " + what + ": transform: rotate takes 1 or 3 numbers (angle [cx cy])");
            const double r = a[0] * kPi / 180.0, c = std::cos(r), s = std::sin(r);
            const glm::dmat3 rot(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
            if (a.size() == 3) {
                glm::dmat3 to(1.0), back(1.0);
                to[2] = glm::dvec3(a[1], a[2], 1.0);
                back[2] = glm::dvec3(-a[1], -a[2], 1.0);
                t = to * rot * back;
            } else {
                t = rot;
            }
        } else if (name == "skewX" || name == "skewY") {
            need(1, 1);
            const double k = std::tan(a[0] * kPi / 180.0);
            if (name == "skewX") t[1][0] = k;
            else t[0][1] = k;
        } else {
            throw Error(where + ": " + what + ": transform: unknown \"" + name +
                        "\" (matrix, translate, scale, rotate, skewX, skewY are)");
        }
        m = m * t;
        i = close + 1;
    }
    return m;
}

// What an element inherits from its ancestors.
struct Context {
    glm::dmat3 transform{1.0};
    std::string stroke, stroke_width;
    bool visible = true;  // "visibility": inherited, and a child may say "visible" again
    int use_depth = 0;
    int nesting = 0;
};

// The element's own paint over the inherited one (attributes, then `style`, which wins).
// Returns false when the element is not displayed.
bool apply_paint(const pugi::xml_node& node, Context& c) {
    bool shown = std::string(node.attribute("display").as_string()) != "none";
    const auto visibility = [&](const std::string& value) {
        const std::string v = lower(trim(value));
        if (v == "hidden" || v == "collapse") c.visible = false;
        if (v == "visible") c.visible = true;
    };
    if (auto a = node.attribute("stroke")) c.stroke = a.as_string();
    if (auto a = node.attribute("stroke-width")) c.stroke_width = a.as_string();
    if (auto a = node.attribute("visibility")) visibility(a.as_string());
    std::stringstream style(node.attribute("style").as_string());
    std::string declaration;
    while (std::getline(style, declaration, ';')) {
        const size_t colon = declaration.find(':');
        if (colon == std::string::npos) continue;
        const std::string key = lower(trim(declaration.substr(0, colon)));
        const std::string value = trim(declaration.substr(colon + 1));
        if (key == "stroke") c.stroke = value;
        if (key == "stroke-width") c.stroke_width = value;
        if (key == "display") shown = value != "none";
        if (key == "visibility") visibility(value);
    }
    return shown;
}

// The largest factor by which the transform stretches a length (its largest singular value):
// curves are flattened in user units, to chords of about a pixel after the transform.
double max_stretch(const glm::dmat3& t) {
    const glm::dmat2 m(t);
    const double a = m[0][0] * m[0][0] + m[0][1] * m[0][1], b = m[0][0] * m[1][0] + m[0][1] * m[1][1];
    const double c = m[1][0] * m[1][0] + m[1][1] * m[1][1];  // MᵀM = [a b; b c]
    return std::sqrt(0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b));
}

// An ellipse (rect corners: a quarter of one) as points, chords of about a pixel once
// stretched by `stretch`.
void append_arc(std::vector<glm::vec2>& out, glm::dvec2 centre, glm::dvec2 radii, double from, double to,
                double stretch) {
    const double span = std::abs(to - from), r = std::max(radii.x, radii.y) * std::min(stretch, 1e4);
    const int n = int(std::clamp(std::ceil(span * r), 4.0, 4096.0));
    for (int k = 0; k <= n; ++k) {
        const double a = from + (to - from) * k / n;
        out.push_back(glm::vec2(centre + radii * glm::dvec2(std::cos(a), std::sin(a))));
    }
}

class Reader {
public:
    // `geometry_only`: a curve file's reading, where paint means nothing (an unstroked path
    // is a curve as well as a stroked one).
    Reader(const pugi::xml_document& doc, std::string where, bool geometry_only = false)
        : where_(std::move(where)), geometry_only_(geometry_only) {
        for (const pugi::xpath_node& n : doc.select_nodes("//*[@id]")) ids_.emplace(n.node().attribute("id").as_string(), n.node());
        for (const pugi::xpath_node& n : doc.select_nodes("//*[local-name()='style']"))
            style_sheet_ |= !trim(n.node().child_value()).empty() || !trim(n.node().text().as_string()).empty();
    }

    void walk(const pugi::xml_node& node, Context c, StrokeSet& set) {
        const std::string name = element_name(node);
        static const std::set<std::string> hidden = {"defs",  "metadata", "title",   "desc",           "style",
                                                     "symbol", "clipPath", "mask",   "linearGradient", "radialGradient",
                                                     "pattern", "marker",  "filter", "script", "foreignObject"};
        if (hidden.count(name) || name.find(':') != std::string::npos) return;  // not drawn; editors' own data
        // Illustrator's default export styles by class from a <style> sheet; drawn without
        // it, every stroke would come out black and 1 px wide.
        if (style_sheet_ && node.attribute("class"))
            throw Error(where_ + ": <" + name + " class=\"" + node.attribute("class").as_string() +
                        "\">: CSS rules of <style> sheets are not read (export with style attributes instead)");
        if (!apply_paint(node, c)) return;
        if (++c.nesting > kMaxNesting) throw Error(where_ + ": <" + name + ">: elements nest deeper than 256");
        if (auto t = node.attribute("transform"))
            c.transform = c.transform * parse_transform(t.as_string(), where_, "<" + name + ">");
        if (name == "svg" && node.parent() != node.root() &&
            (node.attribute("viewBox") || node.attribute("x") || node.attribute("y")))
            throw Error(where_ + ": <svg>: nested viewports (viewBox, x, y) are not read");
        if (name == "switch") {
            // SVG 1.1 §5.8: only the first child whose conditions hold is drawn; we hold no
            // extension or feature, so that is the first child asking for none.
            for (const pugi::xml_node& child : node.children())
                if (child.type() == pugi::node_element && !child.attribute("requiredExtensions") &&
                    !child.attribute("requiredFeatures")) {
                    walk(child, c, set);
                    break;
                }
        } else if (name == "svg" || name == "g" || name == "a") {
            for (const pugi::xml_node& child : node.children())
                if (child.type() == pugi::node_element) walk(child, c, set);
        } else if (name == "use") {
            use(node, c, set);
        } else if (name == "path" || name == "polyline" || name == "polygon" || name == "line" || name == "rect" ||
                   name == "circle" || name == "ellipse") {
            if (c.visible) draw(node, c, set);
        } else if (geometry_only_ && (name == "text" || name == "image")) {
            return;  // a curve file's label or backdrop: no curve in it
        } else {
            throw Error(where_ + ": <" + name +
                        ">: unsupported element (path, polyline, polygon, line, rect, circle, ellipse, g, use are read)");
        }
    }

private:
    void use(const pugi::xml_node& node, Context c, StrokeSet& set) {
        std::string href = node.attribute("href").as_string();
        if (href.empty()) href = node.attribute("xlink:href").as_string();
        if (href.size() < 2 || href[0] != '#') throw Error(where_ + ": <use>: expected href=\"#id\", got \"" + href + "\"");
        const auto it = ids_.find(href.substr(1));
        if (it == ids_.end()) throw Error(where_ + ": <use>: no element with id \"" + href.substr(1) + "\"");
        if (++c.use_depth > kMaxUseDepth) throw Error(where_ + ": <use>: references nest deeper than 32 (a cycle?)");
        glm::dmat3 offset(1.0);
        offset[2] = glm::dvec3(length_of(node, "x", 0.0), length_of(node, "y", 0.0), 1.0);
        c.transform = c.transform * offset;
        const pugi::xml_node target = it->second;
        if (element_name(target) == "symbol") {  // a symbol is drawn through <use> only, as a group
            if (target.attribute("viewBox")) throw Error(where_ + ": <symbol> with a viewBox: its viewport is not read");
            if (!apply_paint(target, c)) return;
            for (const pugi::xml_node& child : target.children())
                if (child.type() == pugi::node_element) walk(child, c, set);
        } else {
            walk(target, c, set);
        }
    }

    double length_of(const pugi::xml_node& node, const char* attribute, std::optional<double> fallback) const {
        const pugi::xml_attribute a = node.attribute(attribute);
        if (!a) {
            if (fallback) return *fallback;
            throw Error(where_ + ": " + what(node) + ": missing the " + attribute + " attribute");
        }
        return parse_length(a.as_string(), where_, what(node) + " " + attribute);
    }

    std::string what(const pugi::xml_node& node) const {
        std::string s = "<";  // appended, not concatenated: GCC 12 warns (-Wrestrict) on the latter here
        s += element_name(node);
        s += "> #";
        s += std::to_string(index_ + 1);
        return s;
    }

    std::vector<Curve2D> curves_of(const pugi::xml_node& node, double stretch) const {
        const std::string name = element_name(node), w = what(node);
        std::vector<Curve2D> curves(1);
        Curve2D& c = curves[0];
        if (name == "path") {
            if (!node.attribute("d")) throw Error(where_ + ": " + w + ": missing the d attribute");
            return parse_svg_subpaths(node.attribute("d").as_string(), where_ + ": " + w, stretch);
        } else if (name == "polyline" || name == "polygon") {
            if (!node.attribute("points")) throw Error(where_ + ": " + w + ": missing the points attribute");
            const std::vector<double> v = number_list(node.attribute("points").as_string(), where_, w + " points");
            if (v.size() % 2 != 0) throw Error(where_ + ": " + w + ": points: an odd number of coordinates");
            for (size_t i = 0; i + 1 < v.size(); i += 2) c.points.push_back({float(v[i]), float(v[i + 1])});
            c.closed = name == "polygon";
        } else if (name == "line") {
            c.points = {glm::vec2(float(length_of(node, "x1", 0.0)), float(length_of(node, "y1", 0.0))),
                        glm::vec2(float(length_of(node, "x2", 0.0)), float(length_of(node, "y2", 0.0)))};
        } else if (name == "rect") {
            const double x = length_of(node, "x", 0.0), y = length_of(node, "y", 0.0);
            const double wd = length_of(node, "width", std::nullopt), ht = length_of(node, "height", std::nullopt);
            if (!(wd > 0.0 && ht > 0.0)) throw Error(where_ + ": " + w + ": width and height must be positive");
            // SVG 1.1 §9.2: a missing rx or ry takes the other's value; both at most half the side.
            double rx = node.attribute("rx") ? length_of(node, "rx", 0.0) : -1.0;
            double ry = node.attribute("ry") ? length_of(node, "ry", 0.0) : -1.0;
            if (rx < 0.0) rx = std::max(ry, 0.0);
            if (ry < 0.0) ry = rx;
            rx = std::min(rx, wd / 2), ry = std::min(ry, ht / 2);
            if (rx > 0.0 && ry > 0.0) {
                const glm::dvec2 r(rx, ry);
                append_arc(c.points, {x + wd - rx, y + ry}, r, -kPi / 2, 0.0, stretch);
                append_arc(c.points, {x + wd - rx, y + ht - ry}, r, 0.0, kPi / 2, stretch);
                append_arc(c.points, {x + rx, y + ht - ry}, r, kPi / 2, kPi, stretch);
                append_arc(c.points, {x + rx, y + ry}, r, kPi, 1.5 * kPi, stretch);
            } else {
                c.points = {glm::vec2(x, y), glm::vec2(x + wd, y), glm::vec2(x + wd, y + ht), glm::vec2(x, y + ht)};
            }
            c.closed = true;
        } else {  // circle, ellipse
            const glm::dvec2 centre(length_of(node, "cx", 0.0), length_of(node, "cy", 0.0));
            const glm::dvec2 r = name == "circle" ? glm::dvec2(length_of(node, "r", std::nullopt))
                                                  : glm::dvec2(length_of(node, "rx", std::nullopt),
                                                               length_of(node, "ry", std::nullopt));
            if (!(r.x > 0.0 && r.y > 0.0)) throw Error(where_ + ": " + w + ": the radius must be positive");
            append_arc(c.points, centre, r, 0.0, 2.0 * kPi, stretch);
            c.points.pop_back();  // the first point again
            c.closed = true;
        }
        return curves;
    }

    void draw(const pugi::xml_node& node, const Context& c, StrokeSet& set) {
        const std::string w = what(node);
        std::vector<Curve2D> curves = curves_of(node, max_stretch(c.transform));
        if (!geometry_only_ && lower(trim(c.stroke)) == "none")
            throw Error(where_ + ": " + w + ": stroke=\"none\": only stroked elements are strokes");
        const glm::vec3 color =
            c.stroke.empty() || geometry_only_ ? glm::vec3(0.0f) : parse_color(c.stroke, where_ + ": " + w);
        const double scale = std::sqrt(std::abs(glm::determinant(glm::dmat2(c.transform))));
        if (!(scale > 0.0) || !std::isfinite(scale))
            throw Error(where_ + ": " + w + ": its transform is degenerate (it flattens the element to a line or a point)");
        const double width = c.stroke_width.empty() || geometry_only_
                                 ? 1.0
                                 : parse_length(c.stroke_width, where_, w + " stroke-width");
        std::vector<Stroke> out;
        for (Curve2D& curve : curves) {
            for (glm::vec2& p : curve.points) p = glm::vec2(c.transform * glm::dvec3(p, 1.0));
            Stroke s = make_stroke(std::move(curve.points), float(width * scale), color, curve.closed);
            if (s.closed && s.points.size() > 1 && s.points.back() == s.points.front()) s.points.pop_back(), s.widths.pop_back();
            out.push_back(std::move(s));
        }
        if (auto a = node.attribute("data-widths")) {
            const std::vector<double> v = number_list(a.as_string(), where_, w + " data-widths");
            if (out.size() != 1 || v.size() != out[0].points.size())
                throw Error(where_ + ": " + w + ": data-widths needs one width per point of a single stroke (" +
                            std::to_string(v.size()) + " for " + std::to_string(out.empty() ? 0 : out[0].points.size()) +
                            " points)");
            for (size_t i = 0; i < v.size(); ++i) out[0].widths[i] = float(v[i] * scale);
        }
        for (Stroke& s : out) {
            check_stroke(s, where_, w);
            points_ += s.points.size();
            if (points_ > kMaxPoints)
                throw Error(where_ + ": " + w + ": more than 10 million points drawn (<use> of <use>s multiplies)");
            set.strokes.push_back(std::move(s));
        }
        ++index_;
    }

    std::string where_;
    bool geometry_only_ = false;
    std::map<std::string, pugi::xml_node> ids_;
    size_t index_ = 0;  // drawn elements so far, for "<path> #3" in errors
    size_t points_ = 0;
    bool style_sheet_ = false;  // a <style> element with rules
};

}  // namespace

namespace {

// The drawing of a parsed file: its strokes, and its viewBox (or its width and height) as the
// set's extent.
StrokeSet read_svg(const pugi::xml_document& doc, const std::string& where, bool geometry_only) {
    const pugi::xml_node root = doc.document_element();
    if (element_name(root) != "svg") throw Error(where + ": no <svg> element");
    StrokeSet set;
    if (auto v = root.attribute("viewBox")) {
        const std::vector<double> box = number_list(v.as_string(), where, "viewBox");
        if (box.size() != 4 || box[2] <= 0 || box[3] <= 0) throw Error(where + ": viewBox: expected x y width height");
        set.origin = {float(box[0]), float(box[1])};
        set.size = {float(box[2]), float(box[3])};
    } else if (root.attribute("width") && root.attribute("height")) {
        set.size = {float(parse_length(root.attribute("width").as_string(), where, "<svg> width")),
                    float(parse_length(root.attribute("height").as_string(), where, "<svg> height"))};
    }
    Reader(doc, where, geometry_only).walk(root, Context{}, set);
    return set;
}

// The root's viewBox onto its page (SVG 1.1 §7.7–7.8): user units to the CSS pixels a renderer
// draws at 1:1 when width and height are given (Inkscape writes width="210mm" with a viewBox
// in millimetres). preserveAspectRatio: the default xMidYMid meet, or none.
// `set`: read_svg's drawing of the file, whose extent is the viewBox when there is one.
// `page`: the page's width and height (0 where the file gives neither a viewBox nor a size).
glm::dmat3 page_transform(const pugi::xml_node& root, const StrokeSet& set, const std::string& where, glm::vec2& page) {
    const auto length_of = [&](const char* name) -> std::optional<double> {
        const pugi::xml_attribute a = root.attribute(name);
        if (!a || trim(a.as_string()) == "100%") return std::nullopt;
        return parse_length(a.as_string(), where, std::string("<svg> ") + name);
    };
    if (!root.attribute("viewBox")) {
        page = set.size;  // width and height when both are given, else none
        return glm::dmat3(1.0);
    }
    const std::array<double, 4> box{set.origin.x, set.origin.y, set.size.x, set.size.y};
    const std::optional<double> w = length_of("width"), h = length_of("height");
    // Neither given: the page is the viewBox's size (as renderers draw such a file). One given:
    // the other follows the viewBox's aspect.
    const double page_w = w ? *w : h ? *h * box[2] / box[3] : box[2];
    const double page_h = h ? *h : w ? *w * box[3] / box[2] : box[3];
    page = glm::vec2(float(page_w), float(page_h));
    glm::dvec2 scale(page_w / box[2], page_h / box[3]), offset(0.0);
    const std::string align = trim(root.attribute("preserveAspectRatio").as_string());
    if (align.empty() || align == "xMidYMid" || align == "xMidYMid meet") {
        scale = glm::dvec2(std::min(scale.x, scale.y));
        offset = 0.5 * (glm::dvec2(page_w, page_h) - scale * glm::dvec2(box[2], box[3]));
    } else if (align != "none") {
        throw Error(where + ": <svg> preserveAspectRatio=\"" + align +
                    "\" is not read (the default, xMidYMid meet, and none are)");
    }
    glm::dmat3 m(1.0);
    m[0][0] = scale.x, m[1][1] = scale.y;
    m[2] = glm::dvec3(offset - scale * glm::dvec2(box[0], box[1]), 1.0);
    return m;
}

}  // namespace

StrokeSet parse_strokes_svg(const std::string& text, const std::string& where) {
    return read_svg(*parse_xml(text, where), where, false);
}

// A curve file is read as a drawing is (transforms, shapes, <use>, the viewBox onto the page),
// and must hold one curve: which of several to follow is not ours to guess.
Curve2D parse_curve_svg(const std::string& text, const std::string& where) {
    const auto doc = parse_xml(text, where);
    StrokeSet set = read_svg(*doc, where, true);
    if (set.strokes.empty()) throw Error(where + ": no drawn element (a <path>, <polyline>, <circle>, … holding the curve)");
    if (set.strokes.size() > 1)
        throw Error(where + ": " + std::to_string(set.strokes.size()) +
                    " curves (drawn elements, or subpaths of a <path>): a curve file holds one curve; keep the one "
                    "to follow");
    Stroke& s = set.strokes.front();
    if (s.points.size() < 2) throw Error(where + ": the curve needs at least two points");
    glm::vec2 page_size(0.0f);
    const glm::dmat3 page = page_transform(doc->document_element(), set, where, page_size);
    for (glm::vec2& p : s.points) p = glm::vec2(page * glm::dvec3(p, 1.0));
    return Curve2D{.points = std::move(s.points), .closed = s.closed, .page = page_size};
}

}  // namespace lw
