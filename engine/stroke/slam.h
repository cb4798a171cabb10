// engine/stroke/slam.h — self-similar line artmaps (SLAMs) as plain data.
//
// A SLAM (Bénard et al. 2010, §3.1) is a stack of stroke textures A_l for levels
// l ∈ [0.5, 1]: level i of N holds l_i = 0.5 + 0.5·i/(N − 1). Every level is stored at the
// same `length` × `height` texels and tiles seamlessly along its length; A_1.0 = [A_0.5 A_0.5]
// (self-similarity), so any stretch folds into [0.5, 1] with the texture coordinate scaled
// by a power of two (DESIGN.md step 7). Texels hold ink in [0, 1] (1 = full ink); texel x of
// a level samples the pattern at u = x / length, which makes the self-similarity exact at
// texels: A_1.0[x] = A_0.5[2x mod length].
//
// Files (engine/io/slam_io.h): one multi-part OpenEXR, one part per level, channel "Y",
// with the level count, length, exemplar and seed in its metadata.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lw {

struct Slam {
    int levels = 0;
    int length = 0;  // texels along the stroke
    int height = 0;  // texels across the stroke
    std::vector<float> ink;  // [level][row][x]
    std::string exemplar;    // what it was made from (a file, or "procedural:NAME")
    uint32_t seed = 0;

    float& at(int level, int row, int x) { return ink[(size_t(level) * height + row) * length + x]; }
    float at(int level, int row, int x) const { return ink[(size_t(level) * height + row) * length + x]; }
    // The level value l ∈ [0.5, 1] of level index i.
    float level_value(int i) const { return levels > 1 ? 0.5f + 0.5f * float(i) / float(levels - 1) : 1.0f; }
};

enum class SlamPattern { Dots, Dashes, Pencil };

// A procedural SLAM: a periodic pattern P(u, v) at level 0.5, P(2u, v) at level 1 (so that
// self-similarity holds exactly), and between them, for dots and dashes, whole elements: each
// element of level 0.5 moves to its place in P(2u) and the others grow from nothing, linearly
// in α = 2l − 1, so that adjacent levels vary little and no level shows two patterns half
// inked (the alpha blending the paper's §2 finds degrades structured patterns; its levels are
// synthesized instead). Pencil's grain, which has no elements, is blended,
// A_l = (1 − α)·P(u) + α·P(2u). Sizes and positions of dots and dashes are jittered from
// `seed` (irregular elements help coherence, §3.1).
[[nodiscard]] Slam make_procedural_slam(SlamPattern pattern, int levels = 17, int length = 1024, int height = 32,
                                        uint32_t seed = 1);

// Largest |A_1.0[x] − A_0.5[2x mod length]| over all rows: 0 for an exactly self-similar SLAM.
[[nodiscard]] float slam_self_similarity_error(const Slam& slam);

// Largest |A_l[x] − A_{l+1}[x]| between adjacent levels (smooth variation).
[[nodiscard]] float slam_max_level_step(const Slam& slam);
// Per pair of adjacent levels, the mean |A_i − A_{i+1}| over texels; and its mean over the
// pairs (elements that move and grow change a few texels fully from one level to the next:
// their largest step is 1, their mean small).
[[nodiscard]] std::vector<float> slam_level_steps(const Slam& slam);
[[nodiscard]] float slam_mean_level_step(const Slam& slam);

// Two levels of full ink: a SLAM that draws every fragment at the stroke's colour (fills,
// solid layer strokes, styled line sets without a texture).
[[nodiscard]] Slam solid_slam();

}  // namespace lw
