#include "vector/stroke_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/color.h"
#include "core/error.h"
#include "core/text.h"
#include "vector/curve.h"
#include "vector/json_object.h"

namespace lw {

namespace {

constexpr double kMaxCoordinate = 1e6;  // as vector/curve.cpp: larger is surely a unit mistake

std::string read_text(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw Error(path.string() + ": no such file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open the stroke file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// Numbers separated by white space and commas (SVG points lists, data-widths, viewBox).
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

double parse_length(const std::string& text, const std::string& where, const std::string& what) {
    std::string t = trim(text);
    if (t.size() > 2 && t.compare(t.size() - 2, 2, "px") == 0) t.resize(t.size() - 2);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0') throw Error(where + ": " + what + ": expected a number, got \"" + text + "\"");
    return v;
}

void check_stroke(const Stroke& s, const std::string& where, const std::string& what) {
    if (s.points.empty()) throw Error(where + ": " + what + ": a stroke needs at least one point");
    for (const glm::vec2& p : s.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > kMaxCoordinate ||
            std::abs(p.y) > kMaxCoordinate)
            throw Error(where + ": " + what + ": coordinates must be finite and within ±1e6");
    for (float w : s.widths)
        if (!std::isfinite(w) || w <= 0.0f || w > 1e4f)
            throw Error(where + ": " + what + ": widths must be positive and finite");
    for (int c = 0; c < 3; ++c)
        if (!(s.color[c] >= 0.0f && s.color[c] <= 1.0f))
            throw Error(where + ": " + what + ": colour components must lie in [0, 1]");
}

// ---- JSON ----------------------------------------------------------------------------

glm::vec3 json_color(const nlohmann::json& c, const std::string& where, const std::string& what) {
    if (c.is_string()) return parse_color(c.get<std::string>(), where + ": " + what);
    if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() || !c[2].is_number())
        throw Error(where + ": " + what + ": expected [r, g, b] in [0, 1] or \"#rrggbb\"");
    return {c[0].get<float>(), c[1].get<float>(), c[2].get<float>()};
}

// ---- SVG -----------------------------------------------------------------------------

struct Tag {
    std::string name;  // lower case; "/g" for a closing tag
    std::map<std::string, std::string> attributes;
    bool self_closing = false;
};

// Splits `<name a="…" b='…'/>` (the text between < and >) into its name and attributes.
Tag parse_tag(const std::string& body, const std::string& where) {
    Tag tag;
    size_t i = 0;
    while (i < body.size() && !std::isspace(static_cast<unsigned char>(body[i])) && body[i] != '/') ++i;
    tag.name = lower(body.substr(0, i));
    if (tag.name.empty() && !body.empty() && body[0] == '/') {
        size_t j = 1;
        while (j < body.size() && !std::isspace(static_cast<unsigned char>(body[j]))) ++j;
        tag.name = "/" + lower(body.substr(1, j - 1));
        return tag;
    }
    while (i < body.size()) {
        while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        if (i >= body.size()) break;
        if (body[i] == '/') {
            tag.self_closing = true;
            ++i;
            continue;
        }
        const size_t name_start = i;
        while (i < body.size() && body[i] != '=' && !std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        const std::string name = lower(body.substr(name_start, i - name_start));
        while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        if (i >= body.size() || body[i] != '=') {
            tag.attributes[name] = "";  // an attribute without a value
            continue;
        }
        ++i;
        while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        if (i >= body.size() || (body[i] != '"' && body[i] != '\''))
            throw Error(where + ": <" + tag.name + "> " + name + ": attribute values must be quoted");
        const size_t close = body.find(body[i], i + 1);
        if (close == std::string::npos) throw Error(where + ": <" + tag.name + "> " + name + ": unterminated value");
        tag.attributes[name] = body.substr(i + 1, close - i - 1);
        i = close + 1;
    }
    return tag;
}

// The stroke attributes an element has, or inherits from enclosing <g> elements.
struct Paint {
    std::string stroke, stroke_width;
};

Paint paint_of(const Tag& tag, Paint inherited, const std::string& where) {
    if (tag.attributes.count("transform"))
        throw Error(where + ": <" + tag.name + ">: transform attributes are not supported (apply them first)");
    if (auto it = tag.attributes.find("stroke"); it != tag.attributes.end()) inherited.stroke = it->second;
    if (auto it = tag.attributes.find("stroke-width"); it != tag.attributes.end()) inherited.stroke_width = it->second;
    if (auto it = tag.attributes.find("style"); it != tag.attributes.end()) {
        std::stringstream style(it->second);
        std::string declaration;
        while (std::getline(style, declaration, ';')) {
            const size_t colon = declaration.find(':');
            if (colon == std::string::npos) continue;
            const std::string key = lower(trim(declaration.substr(0, colon)));
            const std::string value = trim(declaration.substr(colon + 1));
            if (key == "stroke") inherited.stroke = value;
            if (key == "stroke-width") inherited.stroke_width = value;
        }
    }
    return inherited;
}

std::vector<Stroke> strokes_of(const Tag& tag, const Paint& paint, const std::string& where, size_t index) {
    const std::string what = "<" + tag.name + "> #" + std::to_string(index + 1);
    auto attribute = [&](const char* name) -> const std::string& {
        const auto it = tag.attributes.find(name);
        if (it == tag.attributes.end()) throw Error(where + ": " + what + ": missing the " + name + " attribute");
        return it->second;
    };
    std::vector<Curve2D> curves;
    if (tag.name == "path") {
        curves = parse_svg_subpaths(attribute("d"), where + ": " + what);
    } else if (tag.name == "polyline" || tag.name == "polygon") {
        const std::vector<double> v = number_list(attribute("points"), where, what + " points");
        if (v.size() % 2 != 0) throw Error(where + ": " + what + ": points: an odd number of coordinates");
        Curve2D c;
        for (size_t i = 0; i + 1 < v.size(); i += 2) c.points.push_back({float(v[i]), float(v[i + 1])});
        c.closed = tag.name == "polygon";
        curves.push_back(std::move(c));
    } else {  // line
        Curve2D c;
        c.points.push_back({float(parse_length(attribute("x1"), where, what + " x1")),
                            float(parse_length(attribute("y1"), where, what + " y1"))});
        c.points.push_back({float(parse_length(attribute("x2"), where, what + " x2")),
                            float(parse_length(attribute("y2"), where, what + " y2"))});
        curves.push_back(std::move(c));
    }
    if (lower(trim(paint.stroke)) == "none")
        throw Error(where + ": " + what + ": stroke=\"none\": only stroked elements are strokes");
    const glm::vec3 color = paint.stroke.empty() ? glm::vec3(0.0f) : parse_color(paint.stroke, where + ": " + what);
    const float width = paint.stroke_width.empty() ? 1.0f
                                                   : float(parse_length(paint.stroke_width, where, what + " stroke-width"));
    std::vector<Stroke> out;
    for (Curve2D& c : curves) {
        Stroke s = make_stroke(std::move(c.points), width, color, c.closed);
        if (s.closed && s.points.size() > 1 && s.points.back() == s.points.front()) s.points.pop_back(), s.widths.pop_back();
        out.push_back(std::move(s));
    }
    if (auto it = tag.attributes.find("data-widths"); it != tag.attributes.end()) {
        const std::vector<double> w = number_list(it->second, where, what + " data-widths");
        if (out.size() != 1 || w.size() != out[0].points.size())
            throw Error(where + ": " + what + ": data-widths needs one width per point of a single stroke (" +
                        std::to_string(w.size()) + " for " + std::to_string(out.empty() ? 0 : out[0].points.size()) +
                        " points)");
        for (size_t i = 0; i < w.size(); ++i) out[0].widths[i] = float(w[i]);
    }
    for (const Stroke& s : out) check_stroke(s, where, what);
    return out;
}

std::string format_number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", std::abs(v) < 5e-7 ? 0.0 : v);
    return buffer;
}

}  // namespace

StrokeSet parse_strokes_json(const std::string& text, const std::string& where) {
    using json = nlohmann::json;
    json root = parse_json_object(text, where, {"strokes", "size"},
                                  "a stroke file must be a JSON object with \"strokes\"");
    if (!root.contains("strokes") || !root["strokes"].is_array())
        throw Error(where + ": strokes: missing or not an array");
    StrokeSet set;
    if (root.contains("size")) {
        const json& s = root["size"];
        if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number() || s[0].get<double>() <= 0 ||
            s[1].get<double>() <= 0)
            throw Error(where + ": size: expected [width, height], both positive");
        set.size = {s[0].get<float>(), s[1].get<float>()};
    }
    const json& strokes = root["strokes"];
    for (size_t i = 0; i < strokes.size(); ++i) {
        const std::string what = "strokes[" + std::to_string(i) + "]";
        const json& js = strokes[i];
        if (!js.is_object()) throw Error(where + ": " + what + ": expected an object with \"points\"");
        for (const auto& [key, value] : js.items())
            if (key != "points" && key != "width" && key != "widths" && key != "color" && key != "closed")
                throw Error(where + ": " + what + "." + key + ": unknown key");
        if (!js.contains("points") || !js["points"].is_array())
            throw Error(where + ": " + what + ".points: missing or not an array of [x, y]");
        Stroke s;
        for (size_t k = 0; k < js["points"].size(); ++k) {
            const json& p = js["points"][k];
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                throw Error(where + ": " + what + ".points[" + std::to_string(k) + "]: expected [x, y]");
            s.points.push_back({p[0].get<float>(), p[1].get<float>()});
        }
        if (js.contains("width") && js.contains("widths"))
            throw Error(where + ": " + what + ": give either width or widths, not both");
        float width = 1.0f;
        if (js.contains("width")) {
            if (!js["width"].is_number()) throw Error(where + ": " + what + ".width: expected a number");
            width = js["width"].get<float>();
        }
        s.widths.assign(s.points.size(), width);
        if (js.contains("widths")) {
            const json& w = js["widths"];
            if (!w.is_array() || w.size() != s.points.size())
                throw Error(where + ": " + what + ".widths: expected one number per point");
            for (size_t k = 0; k < w.size(); ++k) {
                if (!w[k].is_number()) throw Error(where + ": " + what + ".widths: expected numbers");
                s.widths[k] = w[k].get<float>();
            }
        }
        if (js.contains("color")) s.color = json_color(js["color"], where, what + ".color");
        if (js.contains("closed")) {
            if (!js["closed"].is_boolean()) throw Error(where + ": " + what + ".closed: expected true or false");
            s.closed = js["closed"].get<bool>();
        }
        check_stroke(s, where, what);
        set.strokes.push_back(std::move(s));
    }
    return set;
}

StrokeSet parse_strokes_svg(const std::string& text, const std::string& where) {
    StrokeSet set;
    std::vector<Paint> stack{Paint{}};
    bool seen_svg = false;
    size_t index = 0, i = 0;
    int skip_depth = 0;  // inside <defs>, <metadata>, <title>, <desc>: nothing is drawn
    while ((i = text.find('<', i)) != std::string::npos) {
        if (text.compare(i, 4, "<!--") == 0) {
            const size_t end = text.find("-->", i);
            if (end == std::string::npos) throw Error(where + ": unterminated comment");
            i = end + 3;
            continue;
        }
        if (text.compare(i, 2, "<?") == 0 || text.compare(i, 2, "<!") == 0) {
            const size_t end = text.find('>', i);
            if (end == std::string::npos) throw Error(where + ": unterminated declaration");
            i = end + 1;
            continue;
        }
        const size_t end = text.find('>', i);
        if (end == std::string::npos) throw Error(where + ": unterminated element");
        const Tag tag = parse_tag(text.substr(i + 1, end - i - 1), where);
        i = end + 1;
        static const char* const hidden[] = {"defs", "metadata", "title", "desc", "style"};
        const bool is_hidden = std::any_of(std::begin(hidden), std::end(hidden), [&](const char* h) {
            return tag.name == h || tag.name == std::string("/") + h;
        });
        if (is_hidden) {
            if (tag.name[0] == '/') --skip_depth;
            else if (!tag.self_closing) ++skip_depth;
            continue;
        }
        if (skip_depth > 0) continue;
        if (tag.name == "svg") {
            seen_svg = true;
            if (auto it = tag.attributes.find("viewbox"); it != tag.attributes.end()) {
                const std::vector<double> v = number_list(it->second, where, "viewBox");
                if (v.size() != 4 || v[2] <= 0 || v[3] <= 0) throw Error(where + ": viewBox: expected x y width height");
                set.origin = {float(v[0]), float(v[1])};
                set.size = {float(v[2]), float(v[3])};
            } else if (tag.attributes.count("width") && tag.attributes.count("height")) {
                set.size = {float(parse_length(tag.attributes.at("width"), where, "<svg> width")),
                            float(parse_length(tag.attributes.at("height"), where, "<svg> height"))};
            }
            stack.push_back(paint_of(tag, stack.back(), where));
            if (tag.self_closing) stack.pop_back();
        } else if (tag.name == "g" || tag.name == "a") {
            stack.push_back(paint_of(tag, stack.back(), where));
            if (tag.self_closing) stack.pop_back();
        } else if (tag.name == "/g" || tag.name == "/a" || tag.name == "/svg") {
            if (stack.size() > 1) stack.pop_back();
        } else if (tag.name == "path" || tag.name == "polyline" || tag.name == "polygon" || tag.name == "line") {
            const Paint paint = paint_of(tag, stack.back(), where);
            for (Stroke& s : strokes_of(tag, paint, where, index)) set.strokes.push_back(std::move(s));
            ++index;
        } else if (!tag.name.empty() && tag.name[0] != '/') {
            throw Error(where + ": <" + tag.name + ">: unsupported element (path, polyline, polygon and line are read)");
        }
    }
    if (!seen_svg) throw Error(where + ": no <svg> element");
    return set;
}

StrokeSet load_strokes(const std::filesystem::path& path) {
    const std::string text = read_text(path);
    const std::string ext = lower(path.extension().string());
    StrokeSet set = ext == ".svg" ? parse_strokes_svg(text, path.string()) : parse_strokes_json(text, path.string());
    if (set.strokes.empty()) throw Error(path.string() + ": no strokes");
    return set;
}

std::string strokes_to_svg(const StrokeSet& set) {
    glm::vec2 origin = set.origin, size = set.size;
    if (size.x <= 0.0f || size.y <= 0.0f) {
        const Box2 b = stroke_bounds(set.strokes);
        float margin = 1.0f;
        for (const Stroke& s : set.strokes)
            for (float w : s.widths) margin = std::max(margin, w);
        origin = glm::floor(b.lo - margin);
        size = glm::max(glm::ceil(b.hi + margin) - origin, glm::vec2(1.0f));
    }
    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + format_number(origin.x) + " " +
                      format_number(origin.y) + " " + format_number(size.x) + " " + format_number(size.y) +
                      "\" width=\"" + format_number(size.x) + "\" height=\"" + format_number(size.y) + "\">\n";
    out += "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    for (const Stroke& s : set.strokes) {
        std::string coords;
        const bool varying = std::any_of(s.widths.begin(), s.widths.end(),
                                         [&](float w) { return std::abs(w - s.widths.front()) > 1e-6f; });
        if (s.closed) {
            out += "<path d=\"";
            for (size_t k = 0; k < s.points.size(); ++k)
            {
                out += k == 0 ? "M" : " L";  // (+= only: GCC 12 warns falsely about "…" + std::string&&)
                out += format_number(s.points[k].x);
                out += ' ';
                out += format_number(s.points[k].y);
            }
            out += " Z\"";
        } else {
            out += "<polyline points=\"";
            // One point draws nothing: repeat it (round caps make it a dot).
            const size_t n = std::max<size_t>(s.points.size(), 2);
            for (size_t k = 0; k < n; ++k) {
                const glm::vec2 p = s.points[std::min(k, s.points.size() - 1)];
                if (k > 0) out += ' ';
                out += format_number(p.x);
                out += ',';
                out += format_number(p.y);
            }
            out += "\"";
        }
        out += " stroke=\"" + hex_color(s.color) + "\" stroke-width=\"" + format_number(mean_width(s)) + "\"";
        if (varying || (s.points.size() == 1 && !s.closed)) {
            out += " data-widths=\"";
            for (size_t k = 0; k < s.widths.size(); ++k) {
                if (k > 0) out += ' ';
                out += format_number(s.widths[k]);
            }
            if (s.points.size() == 1 && !s.closed) {
                out += ' ';
                out += format_number(s.widths[0]);
            }
            out += "\"";
        }
        out += "/>\n";
    }
    out += "</g>\n</svg>\n";
    return out;
}

std::string strokes_to_json(const StrokeSet& set) {
    using json = nlohmann::json;
    json strokes = json::array();
    for (const Stroke& s : set.strokes) {
        json points = json::array();
        for (const glm::vec2& p : s.points) points.push_back({p.x, p.y});
        json js = {{"points", points}, {"widths", s.widths}, {"color", {s.color.r, s.color.g, s.color.b}}};
        if (s.closed) js["closed"] = true;
        strokes.push_back(std::move(js));
    }
    json root = {{"strokes", strokes}};
    if (set.size.x > 0.0f && set.size.y > 0.0f) root["size"] = {set.size.x, set.size.y};
    return root.dump() + "\n";
}

bool is_stroke_file_path(const std::filesystem::path& path) {
    const std::string ext = lower(path.extension().string());
    return ext == ".svg" || ext == ".json";
}

void save_strokes(const std::filesystem::path& path, const StrokeSet& set) {
    const std::string ext = lower(path.extension().string());
    if (!is_stroke_file_path(path))
        throw Error(path.string() + ": unsupported stroke file format" + extension_phrase(ext) +
                    ": strokes are written as .svg or .json");
    std::ofstream out(path, std::ios::binary);
    if (!out) throw Error(path.string() + ": cannot write the stroke file");
    out << (ext == ".json" ? strokes_to_json(set) : strokes_to_svg(set));
    if (!out) throw Error(path.string() + ": cannot write the stroke file");
}

}  // namespace lw
