// engine/ribbon/exemplar.h — the exemplar E of a ribbon pattern and the pixel matching cost ξ.
//
// Input:  an RGBA8 image whose alpha outlines the pattern (Zhou et al. 2013, "Input
//         exemplars"): α(p) = 1 (opaque) when alpha ≥ 128, else 0.
// Output: `Exemplar`, W × H texels packed as the GPU kernels read them (R in the low byte,
//         alpha in the high byte: bit 31 is α(p)); texels outside E read as 0, transparent.
//
// ξ(p, q) = ‖p − q‖ (RGB in [0, 255]³) when α(p)·α(q) = 1 or (1 − α(p))·(1 − α(q)) = 1,
// and γ = 1024 otherwise. As in the paper, transparent pixels are compared by their RGB too:
// exemplars should store one colour under zero alpha (the generated ones store black).
// The same expressions are in shaders/ribbon_shared.glsl.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "../../shaders/ribbon_shared.glsl"

namespace lw {

inline constexpr float kRibbonGamma = RIBBON_GAMMA;
inline constexpr float kStitchP = RIBBON_STITCH_P;

struct Exemplar {
    int width = 0;
    int height = 0;
    std::vector<uint32_t> texels;  // width × height, rows top to bottom

    uint32_t at(int x, int y) const {
        return (x < 0 || y < 0 || x >= width || y >= height) ? 0u : texels[size_t(y) * size_t(width) + size_t(x)];
    }
};

// Checks the size (1..4096 per side) and that some texel is opaque; `where` names the file.
[[nodiscard]] Exemplar make_exemplar(const ImageRGBA8& image, const std::string& where);
[[nodiscard]] ImageRGBA8 exemplar_image(const Exemplar& exemplar);

inline constexpr uint32_t pack_rgba(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    return uint32_t(r) | (uint32_t(g) << 8) | (uint32_t(b) << 16) | (uint32_t(a) << 24);
}
inline bool texel_opaque(uint32_t t) { return (t >> 31) != 0u; }

inline float rgb_distance(uint32_t p, uint32_t q) {
    const int dr = int(p & 0xffu) - int(q & 0xffu);
    const int dg = int((p >> 8) & 0xffu) - int((q >> 8) & 0xffu);
    const int db = int((p >> 16) & 0xffu) - int((q >> 16) & 0xffu);
    return std::sqrt(float(dr * dr + dg * dg + db * db));
}

// The paper's matching cost ξ(p, q).
inline float xi(uint32_t p, uint32_t q) {
    return texel_opaque(p) == texel_opaque(q) ? rgb_distance(p, q) : kRibbonGamma;
}

}  // namespace lw
