// engine/coherence/path_dump.h — per-frame path dumps, and the coherence measures read from them.
//
// Dump contract (`linework render --dump-paths DIR`, one DIR/frame_NNNN.json per frame):
//   {"frame": f, "width": W, "height": H, "paths": [{"type": "silhouette|suggestive|crease|border|layer",
//    "line_set": the name of the line set that drew it (absent for layers), "layer": the index
//    of the scene's layer that drew it (absent for line sets), "closed": bool, "rho": ρ, "phi": φ, "level": l, "votes": n, "samples": [{"x": px, "y": px,
//    "s": arclength px, "t": T(s) = ρs + φ, "u": the coordinate along the SLAM level actually
//    sampled, in periods of that level's texture, "p": [x, y, z] surface position}]}]}
// Only visible paths are dumped.
//
// Measures (the coherence issue's acceptance, computed from dumps so outside tools agree):
//   sliding — for consecutive frames, |Δt| (wrapped to half a period) between samples of the
//             two frames lying within 1.5 px of each other on screen (the nearest; of samples
//             as near to 0.05 px, such as the end one path shares with the next, the nearest
//             in phase), each matched in its own line set (each set has its own texture and
//             tracker, so T of a crease and T of a silhouette crossing it are not
//             comparable): its median, its 90th percentile (the tail a viewer sees), and the
//             share of "pops" (|Δt| > 0.25);
//   sliding on the surface — for lines attached to the surface (line_type.h's
//             attached_to_surface: creases, borders, ridges, …), the same |Δt| with each sample
//             matched to the previous frame's path of its set nearest to its surface point "p"
//             (within 1.5 px, converted to the model's units by the sample's own path, and at
//             most twice the frame's median such radius), T
//             interpolated there. The screen measure counts a crease's motion across the screen
//             with its surface as sliding under any policy that keeps its texture on the
//             surface; this one counts what moves along the surface. Static models only: "p" is
//             the posed point, so a skinned model's own motion would count as sliding;
//   stretch — per sample, the on-screen length of one period of the sampled texture,
//             ds/du, and the share of samples inside the best factor-of-2 band [x, 2x).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "coherence/coherence.h"
#include "lines/visibility.h"

namespace lw {

// Paths of vector layers follow the 3D paths with "type": "layer" (their "p" is the drawing
// point, z = 0).
// One line set's paths of a frame (a path in several sets is dumped once per set).
struct DumpGroup {
    std::string line_set;
    const std::vector<ScreenPath>* paths = nullptr;
    const std::vector<PathParam>* params = nullptr;  // per path; null or short: default parameters
};
[[nodiscard]] std::string path_dump_json(int frame, int width, int height, const std::vector<DumpGroup>& sets,
                                         const std::vector<ParameterizedPaths>& layers = {});

struct DumpSample {
    glm::vec2 pixel;
    float s, t, u;
    glm::vec3 position{0.0f};  // "p", the surface point
};
struct DumpPath {
    std::string type;
    std::string line_set;  // "layers[N]" for a layer's paths ("" in dumps written before the index)
    float rho = 0.0f;
    std::vector<DumpSample> samples;
};
// Whether the path's type is attached to the surface (line_type.h; layers are not).
[[nodiscard]] bool attached_to_surface(const DumpPath& path);
struct PathDump {
    int frame = 0;
    int width = 0, height = 0;  // the image's (0: not given)
    std::vector<DumpPath> paths;
};

// Throw lw::Error naming the file (or `name`) on malformed input.
[[nodiscard]] PathDump read_path_dump(const std::filesystem::path& file);
[[nodiscard]] PathDump parse_path_dump(const std::string& text, const std::string& name);

struct SlidingStats {
    double median_dt = 0.0;  // median |Δt| over matched sample pairs, periods
    double p90_dt = 0.0;     // its 90th percentile
    double pops = 0.0;       // share of pairs with |Δt| > 0.25 period
    // The same two in pixels along the path (|Δt| / |ρ|): periods depend on the scale a
    // policy draws at, pixels are what a viewer sees slide.
    double median_px = 0.0, p90_px = 0.0;
    size_t pairs = 0;
};
struct SlidingMeasure : SlidingStats {
    // The pairs where one path alone lies within the match radius in both frames (no other
    // path of the set within `match_px` of either sample). Where two paths of a set run closer
    // than that (parallel silhouettes of nested parts, thin shells), the nearest sample a
    // frame earlier is as often the other path's, and |Δt| there compares two textures, not
    // one texture's motion: Bénard et al. 2010 §7 name "complex models with many overlapping
    // lines" as the splat's limit. Reported beside the whole measure, not in its place.
    SlidingStats alone;
};
// Per sample of each frame after the first: |Δt| (wrapped to half a period) against T on the
// previous frame's nearest path of the same line set within `match_px`, interpolated where
// the sample lies between that path's samples, as measure_phase_error does. (Against the
// nearest sample's own T, as until 2026-12-05, the measure could not see less than a sample
// spacing, 2 px: a texture that did not slide read one spacing wherever the samples had
// moved along the path, and one that slid by less read 0 or a spacing.)
[[nodiscard]] SlidingMeasure measure_sliding(const std::vector<PathDump>& frames, float match_px = 1.5f);

// Sliding on the surface (above), over the paths attached to it; `alone` is not measured.
[[nodiscard]] SlidingStats measure_sliding_on_surface(const std::vector<PathDump>& frames, float match_px = 1.5f);

// How far one frame's parameterization is from a reference render of the same frame (a
// farm chunk's first frames against one render of the shot): per sample, |Δt| (wrapped to
// half a period) against T interpolated on the nearest reference path of the same line set
// within `match_px`.
struct PhaseError {
    double median = 0.0, p90 = 0.0, max = 0.0;  // periods
    double over_quarter = 0.0;                   // share of samples off by more than 0.25 period
    size_t pairs = 0;
};
[[nodiscard]] PhaseError measure_phase_error(const PathDump& frame, const PathDump& reference, float match_px = 1.5f);

struct StretchMeasure {
    double band_low = 0.0;           // the best band is [band_low, 2·band_low) pixels per period
    double share_in_band = 0.0;      // of all samples
    double median_ds_du = 0.0;
    size_t samples = 0;
};
[[nodiscard]] StretchMeasure measure_stretch(const std::vector<PathDump>& frames);

// The frames with only the paths of one line set ("layers[N]": a layer's), so that each set is
// measured on its own; and the line-set names found, in order of first appearance.
[[nodiscard]] std::vector<PathDump> paths_of_line_set(const std::vector<PathDump>& frames, const std::string& line_set);
[[nodiscard]] std::vector<std::string> line_sets_in(const std::vector<PathDump>& frames);
// The same by line type ("silhouette", …, "layer").
[[nodiscard]] std::vector<PathDump> paths_of_type(const std::vector<PathDump>& frames, const std::string& type);
[[nodiscard]] std::vector<std::string> types_in(const std::vector<PathDump>& frames);

}  // namespace lw
