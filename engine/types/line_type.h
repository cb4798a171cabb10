// engine/types/line_type.h — the kinds of feature line and the thresholds that find them.
//
// Shared by extraction (lines/), visibility, line sets, strokes, SVG and dumps; it lives
// below all of them so that none includes upward.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace lw {

enum class LineType : uint32_t { Silhouette = 0, Suggestive = 1, Crease = 2, Border = 3 };
constexpr int kLineTypeCount = 4;

// "silhouette", "suggestive", "crease", "border": SVG group ids and scene-file keys.
inline const char* line_type_name(LineType type) {
    constexpr const char* names[kLineTypeCount] = {"silhouette", "suggestive", "crease", "border"};
    return names[static_cast<uint32_t>(type) % kLineTypeCount];
}

inline std::optional<LineType> line_type_from_name(std::string_view name) {
    for (int t = 0; t < kLineTypeCount; ++t)
        if (name == line_type_name(LineType(t))) return LineType(t);
    return std::nullopt;
}

// Thresholds and switches of the feature-line extraction, as rtsc defines them
// (DESIGN.md "Line extraction as rtsc does it"; docs/research/rtsc-lines.md).
struct LineParams {
    bool silhouettes = true;
    bool suggestive = true;
    bool creases = true;
    bool borders = true;
    float sug_thresh = 0.01f;        // tanθ·DwKr threshold, scaled by 1 / feature_size²
    bool fade = true;                // fade suggestive contours in as the test grows
    float fade_thresh = 0.03f;       // alpha = t / (t + fade_thresh / fs²)
    float crease_angle_deg = 45.0f;  // creases where face normals turn by more than this
};

inline bool line_type_enabled(const LineParams& p, LineType type) {
    switch (type) {
        case LineType::Silhouette: return p.silhouettes;
        case LineType::Suggestive: return p.suggestive;
        case LineType::Crease: return p.creases;
        case LineType::Border: return p.borders;
    }
    return false;
}

inline void set_line_type_enabled(LineParams& p, LineType type, bool on) {
    switch (type) {
        case LineType::Silhouette: p.silhouettes = on; break;
        case LineType::Suggestive: p.suggestive = on; break;
        case LineType::Crease: p.creases = on; break;
        case LineType::Border: p.borders = on; break;
    }
}

inline void disable_line_type(LineParams& p, LineType type) { set_line_type_enabled(p, type, false); }

}  // namespace lw
