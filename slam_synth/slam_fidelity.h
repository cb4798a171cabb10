// slam_synth/slam_fidelity.h — how closely a synthesized SLAM level resembles its exemplar,
// texel for texel and element for element (the third, "desirable" condition of Bénard et
// al. 2010 §3.2: any texture extracted from the SLAM closely resembles the exemplar).
//
// Input: an ink plane (rows across the stroke, columns along it, ink in [0, 1]) and, for
// the stray-ink figure, the exemplar whose empty rows are looked at. Output: plain figures.
//
// - grain: mean |I(x−1) − 2 I(x) + I(x+1)| along the length over every texel (x taken
//   modulo the length for synthesized levels, which are periodic; the exemplar is not, so
//   its first and last columns are left out). Salt-and-pepper speckle and ragged band
//   edges raise it; the exemplar's own value is the reference.
// - elements: connected components of ink > 0.5 (8-connected, wrapping along the length
//   for periodic levels): count per 100 texels of length, mean area, the coefficient of
//   variation of the areas, and holes — components of ink ≤ 0.5 (4-connected) that touch
//   neither the first nor the last row, i.e. paper enclosed by ink (a hollow dot; one
//   element with two holes counts two). Components cut by a non-periodic plane's end
//   columns, and components that go all the way round a periodic one (a line, a band of
//   paper between lines), are neither elements nor holes: the exemplar and its levels are
//   then measured alike.
// - stray ink: in the rows that are empty in the exemplar (every texel below
//   kEmptyRowInk), the share of the level's texels above kStrayInk.
#pragma once

#include "element_sizes.h"
#include "fft.h"

namespace lw::synth {

inline constexpr float kEmptyRowInk = 0.02f;  // an exemplar row with no texel above this is empty
inline constexpr float kStrayInk = 0.1f;      // a texel above this in an empty row is a visible speck

[[nodiscard]] double grain(const Plane& ink, bool periodic);

struct ElementStatistics {
    int count = 0;
    double per_100_texels = 0;
    double mean_area = 0;   // texels
    double area_cv = 0;     // standard deviation / mean of the areas
    int holes = 0;          // enclosed paper components
};
[[nodiscard]] ElementStatistics element_statistics(const Plane& ink, bool periodic);

struct StrayInk {
    int empty_rows = 0;
    double share = 0;  // of the empty rows' texels in the level
};
// `exemplar` and `level` have the same row count.
[[nodiscard]] StrayInk stray_ink(const Plane& exemplar, const Plane& level);

struct LevelFidelity {
    double grain = 0;
    ElementStatistics elements;
    StrayInk stray;
};
[[nodiscard]] LevelFidelity level_fidelity(const Plane& exemplar, const Plane& level);

}  // namespace lw::synth
