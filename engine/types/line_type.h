// engine/types/line_type.h — the kinds of feature line and the thresholds that find them.
//
// Shared by extraction (lines/), visibility, line sets, strokes, SVG and dumps; it lives
// below all of them so that none includes upward.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace lw {

// No face: of a sample or segment that lies on one surface only (not an intersection line).
inline constexpr uint32_t kNoFace = 0xffffffffu;

// The first four are drawn by default; the rest are rtsc's other lines, off by default as in
// rtsc (docs/research/rtsc-lines.md §6). The numbers are shared with the GPU passes
// (shaders/lines_shared.glsl) and written in path dumps: append, never renumber.
enum class LineType : uint32_t {
    Silhouette = 0,
    Suggestive = 1,
    Crease = 2,
    Border = 3,
    Ridge = 4,
    Valley = 5,
    ApparentRidge = 6,
    SuggestiveHighlight = 7,
    PrincipalHighlight = 8,
    MaterialBoundary = 9,  // between faces of different primitives (materials, objects)
    Intersection = 10,     // where surfaces cut through each other (lines/intersections.h)
};
constexpr int kLineTypeCount = 11;
// Those the per-face extraction passes find (extract_reference.h, extract_gpu.h); the GPU
// passes give type t flag bit t, so only these have one. Intersections are found apart.
constexpr int kFaceLineTypeCount = 10;

// The types a line set selects when it does not say: those drawn by default.
constexpr uint32_t kDefaultLineTypes = 0xfu;

// Lines that lie where the surface is, whatever the view (creases, borders, ridges, valleys,
// material boundaries, intersections): a texture on them moves with the surface. The others
// move over the surface as the view turns (contours, suggestive contours and rtsc's other
// view-dependent lines), so a point of the surface is not a point of the line a frame later.
constexpr bool attached_to_surface(LineType type) {
    return type != LineType::Silhouette && type != LineType::Suggestive && type != LineType::ApparentRidge &&
           type != LineType::SuggestiveHighlight && type != LineType::PrincipalHighlight;
}

// SVG group ids, scene-file keys and `--lines` names.
inline const char* line_type_name(LineType type) {
    constexpr const char* names[kLineTypeCount] = {"silhouette",     "suggestive",           "crease",
                                                   "border",         "ridge",                "valley",
                                                   "apparent_ridge", "suggestive_highlight", "principal_highlight",
                                                   "material_boundary", "intersection"};
    return names[static_cast<uint32_t>(type) % kLineTypeCount];
}

inline std::optional<LineType> line_type_from_name(std::string_view name) {
    for (int t = 0; t < kLineTypeCount; ++t)
        if (name == line_type_name(LineType(t))) return LineType(t);
    return std::nullopt;
}

// "silhouette, suggestive, ..., principal_highlight", for error messages.
inline std::string line_type_names() {
    std::string list;
    for (int t = 0; t < kLineTypeCount; ++t) {
        if (t) list += ", ";
        list += line_type_name(LineType(t));
    }
    return list;
}

// Which contours silhouettes are: the smooth zero set of interpolated n·v (rtsc's), the
// mesh's own edges between a front- and a back-facing face (the polygon's outline: closed
// on a closed, consistently wound, manifold mesh; it stops at borders and at edges of more
// than two faces), or per model, mesh where its faces are coarse (LineMesh::face_coarse).
enum class ContourMode : uint32_t { Smooth, Mesh, Auto };

// "smooth", "mesh", "auto" (scene key lines.contours, --contours); the name of a mode.
inline ContourMode contour_mode(std::string_view name) {
    return name == "mesh" ? ContourMode::Mesh : name == "auto" ? ContourMode::Auto : ContourMode::Smooth;
}
inline const char* contour_mode_name(ContourMode mode) {
    return mode == ContourMode::Mesh ? "mesh" : mode == ContourMode::Auto ? "auto" : "smooth";
}

// How the per-vertex curvature is fitted (Rusinkiewicz 2004, as trimesh2 does it): the exact
// least-squares solve of the paper and of older trimesh2 (the default), or the 3×3 solve of
// newer trimesh2 (Forceflow/trimesh2 on GitHub, which a CMake build of rtsc links today),
// whose last pivot skips a term (geometry/curvature.h, CurvatureOptions). With the second,
// every line type lies on the segments of an rtsc built that way; the first is the
// surface's curvature (docs/research/rtsc-lines.md §5.5, §7.4).
enum class CurvatureFit : uint32_t { Exact, Trimesh2 };

// "exact", "trimesh2" (scene key lines.curvature, --curvature); the name of a fit.
inline CurvatureFit curvature_fit(std::string_view name) {
    return name == "trimesh2" ? CurvatureFit::Trimesh2 : CurvatureFit::Exact;
}
inline const char* curvature_fit_name(CurvatureFit fit) { return fit == CurvatureFit::Trimesh2 ? "trimesh2" : "exact"; }

// Thresholds and switches of the feature-line extraction, as rtsc defines them
// (DESIGN.md "Line extraction as rtsc does it"; docs/research/rtsc-lines.md). Every
// threshold is rtsc's, scaled by its feature size fs as rtsc scales it.
struct LineParams {
    bool silhouettes = true;
    bool suggestive = true;
    bool creases = true;
    bool borders = true;
    bool ridges = false;
    bool valleys = false;
    bool apparent_ridges = false;
    bool suggestive_highlights = false;
    bool principal_highlights = false;
    bool material_boundaries = false;
    bool intersections = false;
    float sug_thresh = 0.01f;        // tanθ·DwKr threshold, scaled by 1 / feature_size²
    bool fade = true;                // fade lines in as their test grows (rtsc's draw_faded)
    float fade_thresh = 0.03f;       // alpha = t / (t + fade_thresh / fs²) (suggestive contours and highlights)
    float crease_angle_deg = 45.0f;  // creases where face normals turn by more than this
    float rv_thresh = 0.1f;          // ridges and valleys: |k1| above rv_thresh / fs
    float ar_thresh = 0.1f;          // apparent ridges: view-dependent q1 above ar_thresh / fs²
    float sh_thresh = 0.02f;         // suggestive highlights: −tanθ·DwKr above sh_thresh / fs²
    float ph_thresh = 0.04f;         // principal highlights: (k1² − k2²)·n·v above ph_thresh / fs²
    ContourMode contours = ContourMode::Smooth;
    CurvatureFit curvature = CurvatureFit::Exact;  // the line mesh's; changing it rebuilds that
};

// The switch of one type in `p` (const or not).
template <class Params>
auto line_type_switch(Params& p, LineType type) -> decltype(&p.silhouettes) {
    switch (type) {
        case LineType::Silhouette: return &p.silhouettes;
        case LineType::Suggestive: return &p.suggestive;
        case LineType::Crease: return &p.creases;
        case LineType::Border: return &p.borders;
        case LineType::Ridge: return &p.ridges;
        case LineType::Valley: return &p.valleys;
        case LineType::ApparentRidge: return &p.apparent_ridges;
        case LineType::SuggestiveHighlight: return &p.suggestive_highlights;
        case LineType::PrincipalHighlight: return &p.principal_highlights;
        case LineType::MaterialBoundary: return &p.material_boundaries;
        case LineType::Intersection: return &p.intersections;
    }
    return &p.silhouettes;  // unreachable: every enumerator is listed
}

// The field a type's scene key "threshold" sets; none (nullptr) for silhouettes, creases
// and borders. Ridges and valleys share rtsc's one rv_thresh.
template <class Params>
auto line_type_threshold(Params& p, LineType type) -> decltype(&p.sug_thresh) {
    switch (type) {
        case LineType::Suggestive: return &p.sug_thresh;
        case LineType::Ridge:
        case LineType::Valley: return &p.rv_thresh;
        case LineType::ApparentRidge: return &p.ar_thresh;
        case LineType::SuggestiveHighlight: return &p.sh_thresh;
        case LineType::PrincipalHighlight: return &p.ph_thresh;
        default: return nullptr;
    }
}

inline bool line_type_enabled(const LineParams& p, LineType type) {
    return *line_type_switch(p, type);
}

inline void set_line_type_enabled(LineParams& p, LineType type, bool on) { *line_type_switch(p, type) = on; }

inline void disable_line_type(LineParams& p, LineType type) { set_line_type_enabled(p, type, false); }

constexpr uint32_t kAllLineTypes = (1u << kLineTypeCount) - 1;

// Exactly the types of `mask` (bit 1 << LineType) on, the others off.
inline void set_line_types(LineParams& p, uint32_t mask) {
    for (int t = 0; t < kLineTypeCount; ++t) set_line_type_enabled(p, LineType(t), (mask >> t) & 1u);
}

// The types of a comma-separated list of names ("silhouette,ridge") as such a mask; an
// unknown or empty name: none, and in `problem` what is wrong ("unknown line type "x" (...)").
inline std::optional<uint32_t> line_types_from_list(std::string_view list, std::string& problem) {
    uint32_t mask = 0;
    for (size_t start = 0; start <= list.size();) {
        const size_t comma = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, comma - start);
        const std::optional<LineType> type = line_type_from_name(name);
        if (!type) {
            const std::string names = line_type_names();
            problem = name.size() == 0 ? "an empty name in the list (names are separated by single commas: " + names + ")"
                                   : "unknown line type \"" + std::string(name) + "\" (" + names + ")";
            return std::nullopt;
        }
        mask |= 1u << uint32_t(*type);
        start = comma + 1;
    }
    return mask;
}

}  // namespace lw
