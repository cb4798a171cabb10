// core/color.h — colours as people write them, shared by every file format that has them
// (scene files, line sets, stroke files in JSON and SVG, the Python module) and written back.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace lw {

// "#rgb", "#rrggbb", "rgb(r, g, b)" (0–255 or percentages) or a colour name (HTML's sixteen,
// as SVG and CSS define them, with orange, brown, pink, cyan, magenta and grey), as the
// components of [r, g, b] in [0, 1] (the same values a scene's arrays give). Throws
// lw::Error "`where`: colour "…" …".
[[nodiscard]] glm::vec3 parse_color(const std::string& text, const std::string& where);

// The sRGB transfer function (IEC 61966-2-1) each way, on [0, 1]: texels and PNGs are
// stored encoded, glTF factors and filtering are linear.
[[nodiscard]] float srgb_to_linear(float encoded);
[[nodiscard]] float linear_to_srgb(float linear);

// A value in [0, 1] (clamped) as a byte 0–255, rounded to nearest: how colours and texels
// are stored.
[[nodiscard]] uint8_t unit_to_byte(float v);

// "#rrggbb", components clamped to [0, 1].
[[nodiscard]] std::string hex_color(glm::vec3 c);

}  // namespace lw
