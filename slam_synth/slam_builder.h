// slam_synth/slam_builder.h — a self-similar line artmap synthesized from one exemplar
// (Bénard et al. 2010 §3.2): Portilla–Simoncelli synthesis of each level A_l from the seed W_l.
//
// Input: the exemplar's ink (rows = the stroke's width, 4–64 texels; columns along the
// stroke, cropped to a multiple of the pyramid's unit), and the SLAM's level count N, length
// Lmax and iterations per level. As in the authors' code the exemplar is padded across the
// stroke to twice its height with zeros (so the vertical wrap of the periodic pyramid does
// not glue the stroke's two edges), with Nsc = ⌊log2 padded⌋ − 2 scales, 4 orientations and
// Na = 9; the padded height is rounded up to a multiple of 2^(Nsc+1).
// Level i (l = 0.5 + 0.5·i/(N − 1)) is synthesized at its own length l·Lmax (rounded to a
// multiple of 2^(Nsc+1)), so texture elements keep the exemplar's size in every level;
// level 1.0 is A_0.5 twice, which is what its synthesis computes in exact arithmetic;
// it is cropped back to the exemplar's rows and stored in the Slam at Lmax texels by
// periodic linear resampling (engine/stroke/slam.h: texel x samples u = x/Lmax).
// Output: the Slam (levels ordered 0.5 … 1.0; exemplar name and seed recorded), the levels
// at their synthesized lengths, and timings.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/image.h"
#include "stroke/slam.h"
#include "texture_synthesis.h"

namespace lw::synth {

struct SlamModel {
    int exemplar_rows = 0, padded_rows = 0, pad_top = 0, scales = 0;
    int unit = 0;  // 2^(scales + 1): every synthesized length is a multiple of it
};
// Throws lw::Error (naming `name`) for heights outside 4–64.
[[nodiscard]] SlamModel slam_model(int exemplar_rows, const std::string& name);

// Ink in [0, 1] from an image: its alpha when any pixel is translucent (a-painter's brushes),
// else 1 − luminance (dark ink on a light ground).
[[nodiscard]] Plane exemplar_ink(const ImageRGBA8& image);

struct SlamLevelReport {
    int index = 0;
    double level = 0;
    int length = 0;  // texels synthesized
    double ms = 0;
    bool tiled = false;  // level 1.0: [A_0.5 A_0.5], not synthesized (see synthesize_slam)
};

struct SlamSynthesisDesc {
    int levels = 17;
    int length = 1024;     // Lmax; a multiple of 2·unit
    int iterations = 15;   // the authors' SLAM code runs 15 per level from the seed
    uint32_t seed = 1;
    StatisticsScope scope = StatisticsScope::Rows;  // 1.5D (§3.2.2)
    int threads = 0;       // levels synthesized in parallel; 0: one per core
    std::string exemplar_name;
    // Called as each level finishes (from the worker threads, one at a time).
    std::function<void(const SlamLevelReport&)> on_level;
};

struct SlamSynthesis {
    Slam slam;
    SlamModel model;
    int exemplar_cols = 0;          // after cropping to a multiple of the unit
    TextureStatistics target;       // of the padded exemplar
    std::vector<Plane> levels;      // [i], exemplar rows × synthesized length, clamped to [0, 1]
    std::vector<SlamLevelReport> reports;
    double analysis_ms = 0, synthesis_ms = 0;
};

// The checks synthesize_slam makes before any work, for callers that print a header first:
// throws lw::Error naming desc.exemplar_name for an exemplar too short for the pyramid, and
// ParameterError ("SLAM length", "SLAM levels") for a length that is not a multiple of
// 2·unit or fewer than 2 levels. Returns the model and the cropped column count.
struct SlamPlan {
    SlamModel model;
    int exemplar_cols = 0;
};
[[nodiscard]] SlamPlan check_slam_synthesis(const Plane& exemplar, const SlamSynthesisDesc& desc);

// Throws as check_slam_synthesis does, and lw::Error for an exemplar with no ink.
[[nodiscard]] SlamSynthesis synthesize_slam(const Plane& exemplar, const SlamSynthesisDesc& desc);

// The padded exemplar (zeros above and below) cropped to `cols` columns.
[[nodiscard]] Plane pad_exemplar(const Plane& exemplar, const SlamModel& model, int cols);

// All levels at their synthesized lengths, one above the other from 0.5 to 1.0 (the
// pyramid of the paper's figure 3), under the exemplar, black ink on white.
[[nodiscard]] ImageRGBA8 contact_sheet(const SlamSynthesis& s, const Plane& exemplar);

}  // namespace lw::synth
