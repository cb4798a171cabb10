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
#include "vector/vector_file.h"

namespace lw {

namespace {

constexpr double kMaxCoordinate = 1e6;  // as vector/curve.cpp: larger is surely a unit mistake

// ---- JSON ----------------------------------------------------------------------------

glm::vec3 json_color(const nlohmann::json& c, const std::string& where, const std::string& what) {
    if (c.is_string()) return parse_color(c.get<std::string>(), where + ": " + what);
    if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() || !c[2].is_number())
        throw Error(where + ": " + what + ": expected [r, g, b] in [0, 1] or \"#rrggbb\"");
    return {c[0].get<float>(), c[1].get<float>(), c[2].get<float>()};
}

std::string format_number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", std::abs(v) < 5e-7 ? 0.0 : v);
    return buffer;
}

}  // namespace

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

StrokeSet load_strokes(const std::filesystem::path& path) {
    const std::string text = read_vector_file(path, "stroke");
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
