#include "view_keys.h"

#include <array>
#include <utility>

#include <GLFW/glfw3.h>

#include "core/text.h"

namespace lw::cli {

namespace {

constexpr std::array<std::pair<const char*, int>, 26> kKeys{{
    {"l", GLFW_KEY_L},         {"s", GLFW_KEY_S},         {"c", GLFW_KEY_C},         {"b", GLFW_KEY_B},
    {"p", GLFW_KEY_P},         {"t", GLFW_KEY_T},         {"h", GLFW_KEY_H},         {"r", GLFW_KEY_R},
    {"q", GLFW_KEY_Q},         {"1", GLFW_KEY_1},         {"2", GLFW_KEY_2},         {"3", GLFW_KEY_3},
    {"4", GLFW_KEY_4},         {"space", GLFW_KEY_SPACE}, {"[", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET},
    {"left", GLFW_KEY_LEFT},   {"right", GLFW_KEY_RIGHT}, {"up", GLFW_KEY_UP},       {"down", GLFW_KEY_DOWN},
    {"equal", GLFW_KEY_EQUAL}, {"minus", GLFW_KEY_MINUS}, {"f1", GLFW_KEY_F1},       {"f5", GLFW_KEY_F5},
    {"f12", GLFW_KEY_F12},     {"escape", GLFW_KEY_ESCAPE},
}};

}  // namespace

int key_from_name(const std::string& name) {
    const std::string lowered = lower(name);
    for (const auto& [n, key] : kKeys)
        if (lowered == n) return key;
    return -1;
}

std::string key_names() {
    std::string text;
    for (const auto& [n, key] : kKeys) text += (text.empty() ? "" : ", ") + std::string(n);
    return text;
}

}  // namespace lw::cli
