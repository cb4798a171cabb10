// engine/lines/visibility.h — which parts of each brush path the viewer sees.
//
// Input:  `LinePath`s (world space), the camera, and the depth image of the surface pass.
// Output: `ScreenPath`s — each path resampled every `sample_spacing_px` pixels of screen
//         arc length (DESIGN.md step 5), every sample depth-tested, and the path split
//         into runs of equal visibility. Visible runs are what gets drawn and written to
//         SVG; hidden runs can be drawn dashed or faint on request. A sample off the image is
//         hidden; a path is sampled only up to 64 px past the image, and cut into pieces
//         where it goes farther out (or behind the eye), its arc length s running on.
//
// The depth test: a sample is visible when its eye depth is not behind the farthest
// surface depth in its 3×3 pixel neighbourhood by more than a bias. The neighbourhood
// keeps silhouettes (which lie exactly on the depth discontinuity) visible; the bias grows
// with the local depth slope (slope-scaled, as polygon offset does) plus a small share of
// the depth itself, so lines on steeply inclined surfaces are not lost to rasterization.
//
// Occlusion levels: given an `OcclusionCounter`, each hidden sample is also given the number
// of surfaces in front of it (at least 1: the depth test decides hidden), and hidden runs
// are split where that number changes (ScreenPath::qi). Without one, hidden runs have qi 1.
#pragma once

#include <span>
#include <vector>

#include "lines/line_types.h"
#include "lines/occlusion.h"
#include "scene/camera.h"
#include "types/screen_path.h"

namespace lw {

struct VisibilityParams {
    float sample_spacing_px = 2.0f;  // δ
    float depth_bias = 0.002f;       // relative to the sample's eye depth
    float slope_scale = 1.5f;        // × the largest eye-depth step between neighbouring pixels
};

// The surface pass's depth buffer with the planes needed to linearize it.
struct DepthImage {
    int width = 0;
    int height = 0;
    std::span<const float> depth;  // window depth in [0, 1], row-major; 1 = background (not owned)
    float znear = 0.0f;
    float zfar = 0.0f;
};

[[nodiscard]] std::vector<ScreenPath> compute_visibility(const std::vector<LinePath>& paths,
                                                         const CameraMatrices& camera, const DepthImage& depth,
                                                         const VisibilityParams& params = {},
                                                         const OcclusionCounter* levels = nullptr);

// Eye depth of a window depth value (infinity for the background).
[[nodiscard]] float linear_depth(float window_depth, float znear, float zfar);

}  // namespace lw
