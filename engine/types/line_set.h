// engine/types/line_set.h — a line set: a selection of lines with its own style, modifiers
// and coherence settings, drawn in scene order (Blender Freestyle's unit of style).
//
// Scene files give them as "line_sets" (README "Line sets"); the older per-type keys of
// "lines" are shorthand for one set per line type (scene/scene_file.cpp). A path may belong
// to several sets: each set selects, parameterizes and draws its own copy.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "types/line_type.h"

namespace lw {

// How a set's strokes are parameterized along their length (Bénard et al. 2010 §4):
// coherent (votes + RANSAC), arclength (tiling, T = s·κ/Lmax) or stretch (T = s/L).
enum class ParamPolicy { Coherent, Arclength, Stretch };

// The names scene keys and flags give the policies ("coherent", "arclength", "stretch").
inline const char* param_policy_name(ParamPolicy policy) {
    switch (policy) {
        case ParamPolicy::Coherent: return "coherent";
        case ParamPolicy::Arclength: return "arclength";
        case ParamPolicy::Stretch: return "stretch";
    }
    return "?";
}
// The three names in the enum's order (a flag's check lists them so), and as the set a scene
// key's reader checks against.
inline const std::vector<std::string> kParamPolicyNames{"coherent", "arclength", "stretch"};
inline const std::set<std::string> kParamPolicyNameSet{kParamPolicyNames.begin(), kParamPolicyNames.end()};
// The caller has checked that `name` is one of the three.
inline ParamPolicy param_policy_named(const std::string& name) {
    return name == "arclength" ? ParamPolicy::Arclength : name == "stretch" ? ParamPolicy::Stretch : ParamPolicy::Coherent;
}

// The values the parameterization's settings take, as scene keys ("coherence", a set's
// "coherence") and as the flags that override them: one range for both, so that a view
// saved with a flag's value reads back.
struct ValueRange {
    double min, max;
};
inline constexpr ValueRange kSplatRadiusRange{0.1, 1024.0};       // px
inline constexpr ValueRange kInlierDistanceRange{0.01, 1024.0};   // px
inline constexpr ValueRange kMinStrokeLengthRange{0.0, 1e5};      // px
inline constexpr ValueRange kLengthScaleRange{1e-3, 1e4};         // κ

enum class Visibility { Visible, Hidden, Any };

// Occlusion levels a set selects (ScreenPath::qi): 0 is visible, 1 behind one surface, …
struct LevelRange {
    uint32_t min = 0, max = 0;
    bool operator==(const LevelRange&) const = default;
};

struct LineSelection {
    uint32_t types = kDefaultLineTypes;  // bit (1 << LineType): the types selected (default: those drawn by default)
    Visibility visibility = Visibility::Visible;
    // "qi": [min, max] — runs whose occlusion level is in the range, counted exactly (the
    // frame then casts rays for hidden samples, lines/occlusion.h); replaces `visibility`.
    std::optional<LevelRange> qi;
    std::vector<std::string> models;     // model file names (as in the scene's "model"); empty: all
    std::vector<std::string> materials;  // glTF material names; empty: all

    bool has_type(LineType t) const { return (types >> uint32_t(t)) & 1u; }
    // Whether it selects runs behind a surface.
    bool selects_hidden() const { return qi ? qi->max > 0 : visibility != Visibility::Visible; }
};

// Stroke ends (Freestyle's caps): butt stops at the end sample, square extends by half the
// width, round adds a half disc of the width.
enum class Cap { Butt, Round, Square };
// Stroke joins: mitre (clamped to twice the half width) or round.
enum class Join { Mitre, Round };

// What a modifier reads per sample, mapped to [0, 1] before its ramp:
//   along     — arc length / path length (0 at the start, 1 at the end);
//   distance  — eye depth, (depth − near) / (far − near), clamped;
//   curvature — |2D curvature| in 1/px, (κ − min) / (max − min), clamped.
enum class ModifierInput { Along, Distance, Curvature };

// How a modifier's value combines with the value before it.
enum class ModifierBlend { Multiply, Replace, Add };

// A piecewise-linear curve: points (x, y) with x increasing in [0, 1]; flat beyond the ends.
struct Ramp {
    std::vector<glm::vec2> points;
};

struct ColorRamp {
    std::vector<std::pair<float, glm::vec3>> points;  // x increasing in [0, 1], linear colour
};

// Width (multiplies or replaces the width in pixels) or alpha (in [0, 1]).
struct ScalarModifier {
    ModifierInput input = ModifierInput::Along;
    float range_min = 0.0f, range_max = 1.0f;  // distance: scene units; curvature: 1/px; along: unused
    Ramp ramp;
    ModifierBlend blend = ModifierBlend::Multiply;
};

struct ColorModifier {
    ModifierInput input = ModifierInput::Along;
    float range_min = 0.0f, range_max = 1.0f;
    ColorRamp ramp;
    float influence = 1.0f;  // mix(colour before, ramp colour, influence)
};

// Geometry modifiers (Freestyle's), applied in order to the screen polyline before the
// stroke is built. Displacements are functions of the coherent parameter, not of the frame,
// so that they stay on the surface while the view moves.
struct GeometryModifier {
    enum class Kind { Sinus, Noise, BackboneStretch, TipRemove, Simplify } kind = Kind::Sinus;
    float wavelength_px = 32.0f;  // sinus: period along the stroke; noise: feature size
    float amplitude_px = 2.0f;    // sinus, noise: displacement along the normal
    float phase = 0.0f;           // sinus: in periods
    uint64_t seed = 1;            // noise
    float length_px = 8.0f;       // backbone stretch: added at both ends; tip removal: cut at both ends
    float tolerance_px = 1.0f;    // simplification: Douglas–Peucker tolerance
};

// Each kind's scene-file name and keys, in the order they are written: the scene reader
// (scene/line_set_file.cpp) takes exactly these keys for the kind, the writer
// (scene/scene_write.cpp) writes them.
struct GeometryKindKeys {
    GeometryModifier::Kind kind;
    const char* name;
    std::array<const char*, 3> keys;  // the first `count`
    size_t count;
};
inline constexpr std::array<GeometryKindKeys, 5> kGeometryKinds{{
    {GeometryModifier::Kind::Sinus, "sinus", {"wavelength", "amplitude", "phase"}, 3},
    {GeometryModifier::Kind::Noise, "noise", {"wavelength", "amplitude", "seed"}, 3},
    {GeometryModifier::Kind::BackboneStretch, "backbone_stretch", {"length"}, 1},
    {GeometryModifier::Kind::TipRemove, "tip_remove", {"length"}, 1},
    {GeometryModifier::Kind::Simplify, "simplify", {"tolerance"}, 1},
}};
inline const GeometryKindKeys& geometry_kind_keys(GeometryModifier::Kind kind) {
    return kGeometryKinds[static_cast<size_t>(kind)];
}
// The member a key names ("wavelength", "amplitude", "phase", "seed", "length", "tolerance").
inline double geometry_key_value(const GeometryModifier& m, std::string_view key) {
    if (key == "wavelength") return m.wavelength_px;
    if (key == "amplitude") return m.amplitude_px;
    if (key == "phase") return m.phase;
    if (key == "seed") return double(m.seed);
    if (key == "length") return m.length_px;
    return m.tolerance_px;
}

// Chaining options applied to each selected run before it is parameterized.
struct ChainingOptions {
    float split_angle_deg = 180.0f;  // split where the polyline turns by more than this (180: never)
    float min_length_px = 0.0f;      // drop runs shorter than this
    float max_length_px = 0.0f;      // cut runs into pieces no longer than this (0: no limit)
    bool outline = false;            // join the runs into the closed outer outline of each drawing (stroke/outline.h)
};

struct LineSetStyle {
    glm::vec3 color{0.0f};         // linear 0..1
    float alpha = 1.0f;
    float width = 2.5f;            // pixels
    Cap cap = Cap::Square;
    Join join = Join::Mitre;
    float taper_in_px = 0.0f;      // the width grows from the start over this length
    float taper_out_px = 0.0f;     // and shrinks to the end over this one
    bool fade = true;              // suggestive contours fade in as rtsc's test grows (alpha)
    std::string slam;              // SLAM file: textured strokes
    std::string ribbon;            // ribbon exemplar: a structured pattern along each path
    float ribbon_scale = 0.0f;     // exemplar pixels across the ribbon (0: its default)
    std::vector<float> dashes;     // [dash, gap, dash, gap, ...] pixels along the parameterization
    std::vector<ScalarModifier> width_modifiers;
    std::vector<ScalarModifier> alpha_modifiers;
    std::vector<ColorModifier> color_modifiers;
    std::vector<GeometryModifier> geometry;
    ChainingOptions chaining;
};

struct LineSetCoherence {
    std::optional<ParamPolicy> policy;  // absent: the render's (coherent unless --param says)
    float length_scale = 0.0f;       // κ; 0: square texels (the SLAM's height over the width)
    float sample_spacing_px = 0.0f;  // δ; 0: the scene's "sample_spacing"
};

struct LineSetDesc {
    std::string name;
    bool enabled = true;
    LineSelection select;
    LineSetStyle style;
    LineSetCoherence coherence;
};

}  // namespace lw
