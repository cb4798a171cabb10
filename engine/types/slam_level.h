// engine/types/slam_level.h — which SLAM level a path uses, from its parameterization.
//
// A path's parameterization T(s) = ρ·s + φ counts texture periods along its screen
// arclength s (pixels), so one period spans 1/|ρ| pixels. Drawing the whole texture over a
// path of length s is A(0, 1, κ·s / Lmax) in the paper's notation (§3.1), so a period of
// 1/|ρ| pixels asks for level
//     λ = κ / (|ρ| · Lmax)
// (κ: the user's length scale, Lmax: the SLAM's texture length in pixels). Eq. 1 folds any
// level into [0.5, 1] by self-similarity: g(u1, u2, λ) = (2^t u1, 2^t u2, 2^−t λ) with
// t = ⌈log2 λ⌉. So the texture is sampled at level l = λ / 2^t ∈ (0.5, 1] with the
// coordinate u = 2^t · T(s), and the 3D texture's third coordinate is w = 2l − 1.
// (Eq. 3 of the text as printed is garbled; with d = 1/λ it reads l = 1/d for d ∈ [1, 2],
// and its ω, Ω factors are the 2^t above for d < 1 and d > 2.) Because ρ, not the path's
// length, sets the level, clipping a path does not change its level (§4.3).
//
// Check of the band: one period of u spans (1/|ρ|)/2^t = l·Lmax/κ pixels ∈ (0.5, 1]·Lmax/κ.
#pragma once

#include <cmath>

namespace lw {

struct SlamFold {
    float level = 1.0f;   // l ∈ (0.5, 1]
    float scale = 1.0f;   // 2^t: u = scale · T(s)
    float w = 1.0f;       // 2l − 1, the 3D texture's level coordinate
};

inline SlamFold fold_slam_level(float rho, float length_scale, float slam_length_px) {
    const float lambda = length_scale / (std::abs(rho) * slam_length_px);
    if (!(lambda > 0.0f) || !std::isfinite(lambda)) return {};
    const float t = std::ceil(std::log2(lambda));
    const float scale = std::exp2(t);
    float level = lambda / scale;
    // Rounding at exact powers of two: keep l in (0.5, 1].
    if (level <= 0.5f) level = 0.5f + 1e-7f;
    if (level > 1.0f) level = 1.0f;
    return {level, scale, 2.0f * level - 1.0f};
}

}  // namespace lw
