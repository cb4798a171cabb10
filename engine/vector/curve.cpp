#include "vector/curve.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/text.h"
#include "vector/json_object.h"
#include "vector/vector_file.h"

namespace lw {

namespace {

constexpr double kMaxCoordinate = 1e6;  // output pixels; larger is surely a unit mistake

glm::vec2 checked_point(double x, double y, const std::string& where, const std::string& what) {
    if (!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > kMaxCoordinate || std::abs(y) > kMaxCoordinate)
        throw Error(where + ": " + what + ": coordinates must be finite and within ±1e6");
    return {static_cast<float>(x), static_cast<float>(y)};
}

// A tokenizer for SVG path data: command letters and numbers (sign, decimals, exponent),
// separated by white space and commas.
class PathLexer {
public:
    PathLexer(const std::string& d, const std::string& where) : d_(d), where_(where) {}

    void skip_separators() {
        while (i_ < d_.size() && (std::isspace(static_cast<unsigned char>(d_[i_])) || d_[i_] == ',')) ++i_;
    }
    bool at_end() {
        skip_separators();
        return i_ >= d_.size();
    }
    bool at_command() {
        skip_separators();
        return i_ < d_.size() && std::isalpha(static_cast<unsigned char>(d_[i_])) && d_[i_] != 'e' && d_[i_] != 'E';
    }
    char command() { return d_[i_++]; }
    double number() {
        skip_separators();
        const char* begin = d_.c_str() + i_;
        char* end = nullptr;
        const double value = std::strtod(begin, &end);
        if (end == begin) fail("expected a number at character " + std::to_string(i_ + 1));
        i_ += static_cast<size_t>(end - begin);
        return value;
    }
    // x then y: two statements, since the order of evaluation of arguments is unspecified.
    glm::dvec2 point() {
        const double x = number();
        const double y = number();
        return {x, y};
    }
    [[noreturn]] void fail(const std::string& problem) const { throw Error(where_ + ": path data: " + problem); }

private:
    const std::string& d_;
    const std::string& where_;
    size_t i_ = 0;
};

}  // namespace

Curve2D parse_curve_json(const std::string& text, const std::string& where) {
    using json = nlohmann::json;
    json root = parse_json_object(text, where, {"points", "closed"}, "the curve must be a JSON object with \"points\"");
    if (!root.contains("points")) throw Error(where + ": points: missing (an array of [x, y] pairs)");
    const json& points = root["points"];
    if (!points.is_array()) throw Error(where + ": points: expected an array of [x, y] pairs");
    Curve2D curve;
    for (size_t i = 0; i < points.size(); ++i) {
        const json& p = points[i];
        const std::string what = "points[" + std::to_string(i) + "]";
        if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
            throw Error(where + ": " + what + ": expected [x, y]");
        curve.points.push_back(checked_point(p[0].get<double>(), p[1].get<double>(), where, what));
    }
    if (curve.points.size() < 2) throw Error(where + ": points: at least two points are needed");
    if (root.contains("closed")) {
        if (!root["closed"].is_boolean()) throw Error(where + ": closed: expected true or false");
        curve.closed = root["closed"].get<bool>();
    }
    return curve;
}

std::vector<Curve2D> parse_svg_subpaths(const std::string& d, const std::string& where, double stretch) {
    PathLexer lex(d, where);
    std::vector<Curve2D> subpaths;
    glm::dvec2 current{0.0}, start{0.0};
    glm::dvec2 last_control{0.0};  // of the previous C/S (cubic) or Q/T (quadratic), for S and T
    char command = 0, previous = 0;
    auto add = [&](glm::dvec2 p) { subpaths.back().points.push_back(checked_point(p.x, p.y, where, "path data")); };
    // A cubic Bézier from the current point, flattened to chords under ~1 px once stretched
    // by `stretch` (a transform applied later): the control polygon bounds the curve's length. Clamped as a double: a huge hull does not fit an int
    // (found by fuzz_strokes).
    auto cubic = [&](glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 p3) {
        const glm::dvec2 p0 = current;
        const double hull = glm::length(p1 - p0) + glm::length(p2 - p1) + glm::length(p3 - p2);
        if (!std::isfinite(hull)) lex.fail("curve control points out of range");
        const int n = static_cast<int>(std::clamp(std::ceil(hull * std::min(stretch, 1e4)), 4.0, 4096.0));
        for (int k = 1; k <= n; ++k) {
            const double t = double(k) / n, s = 1.0 - t;
            add(s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3);
        }
        current = p3;
    };
    // A quadratic is the cubic with controls 2/3 of the way to its one control point.
    auto quadratic = [&](glm::dvec2 q, glm::dvec2 p) {
        cubic(current + 2.0 / 3.0 * (q - current), p + 2.0 / 3.0 * (q - p), p);
        last_control = q;
    };
    while (!lex.at_end()) {
        if (lex.at_command()) {
            command = lex.command();
        } else if (command == 0) {
            lex.fail("must start with M");
        }
        const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
        const glm::dvec2 base = relative ? current : glm::dvec2(0.0);
        const int upper = std::toupper(static_cast<unsigned char>(command));
        if (upper != 'M' && subpaths.empty()) lex.fail("must start with M");
        if (upper != 'M' && upper != 'Z' && subpaths.back().closed) {
            // SVG: drawing after Z starts a new subpath at the closed one's start.
            subpaths.push_back({});
            add(start);
        }
        // S and T reflect the previous segment's control point when it was of their kind
        // (SVG 1.1 §8.3.6, §8.3.7); otherwise the control point is the current point.
        const bool after_cubic = previous == 'C' || previous == 'S', after_quadratic = previous == 'Q' || previous == 'T';
        switch (upper) {
            case 'M': {
                const glm::dvec2 p = base + lex.point();
                subpaths.push_back({});
                add(p);
                current = start = p;
                command = relative ? 'l' : 'L';  // further pairs are line-tos (SVG rule)
                break;
            }
            case 'L': {
                current = base + lex.point();
                add(current);
                break;
            }
            case 'H':
            case 'V': {  // one coordinate moves: x for H, y for V
                const int axis = upper == 'H' ? 0 : 1;
                current[axis] = (relative ? current[axis] : 0.0) + lex.number();
                add(current);
                break;
            }
            case 'C':
            case 'S': {  // S's first control point is C's or S's second, reflected
                const glm::dvec2 p1 = upper == 'C' ? base + lex.point() : after_cubic ? 2.0 * current - last_control : current;
                const glm::dvec2 p2 = base + lex.point();
                const glm::dvec2 p3 = base + lex.point();
                cubic(p1, p2, p3);
                last_control = p2;
                break;
            }
            case 'Q':
            case 'T': {  // T's control point is Q's or T's, reflected
                const glm::dvec2 q = upper == 'Q' ? base + lex.point() : after_quadratic ? 2.0 * current - last_control : current;
                quadratic(q, base + lex.point());
                break;
            }
            case 'Z': {
                subpaths.back().closed = true;
                current = start;
                // Z takes no numbers: without this check they would be read as Z again, for ever
                // (found by tests/fuzz/fuzz_strokes; regression input in its corpus).
                if (!lex.at_end() && !lex.at_command()) lex.fail("expected a command after Z");
                break;
            }
            default:
                lex.fail(std::string("unsupported command '") + command +
                         "' (M, L, H, V, C, S, Q, T, Z and their relative forms are)");
        }
        previous = char(upper);
    }
    return subpaths;
}

Curve2D parse_svg_path_data(const std::string& d, const std::string& where) {
    std::vector<Curve2D> subpaths = parse_svg_subpaths(d, where);
    if (subpaths.size() > 1) throw Error(where + ": path data: more than one subpath (one curve per file)");
    if (subpaths.empty() || subpaths[0].points.size() < 2)
        throw Error(where + ": path data: at least two points are needed");
    return std::move(subpaths[0]);
}

Curve2D load_curve(const std::filesystem::path& path) {
    const std::string text = read_vector_file(path, "curve");
    return lower(path.extension().string()) == ".svg" ? parse_curve_svg(text, path.string()) : parse_curve_json(text, path.string());
}

ArclengthCurve::ArclengthCurve(const Curve2D& curve) : closed_(curve.closed) {
    for (const glm::vec2& p : curve.points)
        if (points_.empty() || glm::length(p - points_.back()) > 1e-6f) points_.push_back(p);
    if (closed_ && points_.size() > 1 && glm::length(points_.back() - points_.front()) <= 1e-6f) points_.pop_back();
    if (points_.size() < 2) throw Error("the curve needs at least two distinct points");
    cumulative_.push_back(0.0);
    const size_t segments = closed_ ? points_.size() : points_.size() - 1;
    for (size_t i = 0; i < segments; ++i)
        cumulative_.push_back(cumulative_.back() +
                              glm::length(glm::dvec2(points_[(i + 1) % points_.size()]) - glm::dvec2(points_[i])));
    length_ = static_cast<float>(cumulative_.back());
}

glm::vec2 ArclengthCurve::point_at(float x) const {
    double t = x;
    const double length = cumulative_.back();
    if (closed_) {
        t = std::fmod(t, length);
        if (t < 0.0) t += length;
    } else {
        t = std::clamp(t, 0.0, length);
    }
    // The segment [cumulative_[i], cumulative_[i + 1]] holding t.
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), t);
    const size_t i = std::min<size_t>(static_cast<size_t>(std::max<std::ptrdiff_t>(it - cumulative_.begin() - 1, 0)),
                                      cumulative_.size() - 2);
    const double span = cumulative_[i + 1] - cumulative_[i];
    const double f = span > 0.0 ? (t - cumulative_[i]) / span : 0.0;
    const glm::dvec2 a = points_[i], b = points_[(i + 1) % points_.size()];
    return glm::vec2(a + (b - a) * f);
}

glm::vec2 ArclengthCurve::tangent_at(float x, float h) const {
    glm::vec2 chord = point_at(x + h) - point_at(x - h);
    if (glm::length(chord) < 1e-6f) chord = point_at(x + 2.0f * h) - point_at(x - 2.0f * h);
    if (glm::length(chord) < 1e-6f) chord = points_[1] - points_[0];  // a fold back on itself
    return glm::normalize(chord);
}

std::vector<glm::vec2> resample_arclength(const ArclengthCurve& curve, float spacing) {
    if (!(spacing > 0.0f)) throw Error("resample_arclength: the spacing must be positive");
    const float length = curve.length();
    std::vector<glm::vec2> out;
    if (curve.closed()) {
        const int n = std::max(3, static_cast<int>(std::lround(length / spacing)));
        for (int i = 0; i < n; ++i) out.push_back(curve.point_at(length * float(i) / float(n)));
    } else {
        const int n = std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-4f)));
        for (int i = 0; i < n; ++i) out.push_back(curve.point_at(std::min(length, spacing * float(i))));
        out.push_back(curve.point_at(length));
    }
    return out;
}

}  // namespace lw
