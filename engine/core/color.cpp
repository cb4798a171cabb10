#include "core/color.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/text.h"

namespace lw {

namespace {

// HTML 4's sixteen colour names (also SVG's and CSS's, with the same values), and a few more
// that drawings use; SVG files name colours so.
const std::map<std::string, glm::vec3>& color_names() {
    constexpr float h = 128 / 255.f;
    static const std::map<std::string, glm::vec3> names = {
        {"black", {0, 0, 0}},      {"silver", {192 / 255.f, 192 / 255.f, 192 / 255.f}},
        {"gray", {h, h, h}},       {"grey", {h, h, h}},
        {"white", {1, 1, 1}},      {"maroon", {h, 0, 0}},
        {"red", {1, 0, 0}},        {"purple", {h, 0, h}},
        {"fuchsia", {1, 0, 1}},    {"magenta", {1, 0, 1}},
        {"green", {0, h, 0}},      {"lime", {0, 1, 0}},
        {"olive", {h, h, 0}},      {"yellow", {1, 1, 0}},
        {"navy", {0, 0, h}},       {"blue", {0, 0, 1}},
        {"teal", {0, h, h}},       {"aqua", {0, 1, 1}},
        {"cyan", {0, 1, 1}},       {"orange", {1, 165 / 255.f, 0}},
        {"brown", {165 / 255.f, 42 / 255.f, 42 / 255.f}}, {"pink", {1, 192 / 255.f, 203 / 255.f}}};
    return names;
}

std::string color_name_list() {
    std::string list;
    for (const auto& [name, value] : color_names()) list += (list.empty() ? "" : ", ") + name;
    return list;
}

}  // namespace

glm::vec3 parse_color(const std::string& text, const std::string& where) {
    const std::string t = lower(trim(text));
    auto fail = [&]() -> glm::vec3 {
        throw Error(where + ": colour \"" + text + "\" is not #rgb, #rrggbb, rgb(r, g, b) or a colour name (" +
                    color_name_list() + ")");
    };
    auto hex = [&](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        fail();
        return 0;
    };
    if (!t.empty() && t[0] == '#') {
        if (t.size() == 4) return glm::vec3(hex(t[1]), hex(t[2]), hex(t[3])) * (17.0f / 255.0f);
        if (t.size() == 7)
            return glm::vec3(hex(t[1]) * 16 + hex(t[2]), hex(t[3]) * 16 + hex(t[4]), hex(t[5]) * 16 + hex(t[6])) / 255.0f;
        return fail();
    }
    if (t.rfind("rgb(", 0) == 0 && t.back() == ')') {
        std::stringstream parts(t.substr(4, t.size() - 5));
        std::string part;
        std::vector<float> v;
        while (std::getline(parts, part, ',')) {
            part = trim(part);
            const bool percent = !part.empty() && part.back() == '%';
            if (percent) part.pop_back();
            char* end = nullptr;
            const double x = std::strtod(part.c_str(), &end);
            if (part.empty() || *end != '\0') return fail();
            v.push_back(float(std::clamp(percent ? x / 100.0 : x / 255.0, 0.0, 1.0)));
        }
        if (v.size() != 3) return fail();
        return {v[0], v[1], v[2]};
    }
    const auto it = color_names().find(t);
    if (it == color_names().end()) return fail();
    return it->second;
}

std::string hex_color(glm::vec3 c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", unit_to_byte(c.r), unit_to_byte(c.g), unit_to_byte(c.b));
    return text;
}

uint8_t unit_to_byte(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float linear_to_srgb(float c) { return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

}  // namespace lw
