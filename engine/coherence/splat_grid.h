// engine/coherence/splat_grid.h — the parameterization splat (Bénard et al. 2010, §4.1) on
// the host, read where it is needed instead of drawn whole.
//
// Input:  sprites (centre x, y in pixels; T), their radius δ, the frame's size; later, the
//         pixels the next frame's votes read.
// Output: at each of those pixels, (Σ w·t, Σ w, Σ w·(c − pixel centre)) over the sprites, in
//         sprite order, w = clamp(1 − d/δ, 0, 1): bit for bit what splat_reference draws
//         there (the same expressions, the same order of the sums).
//
// The votes read the splat at their samples alone (a few tens of thousands of pixels), while
// drawing it evaluates every pixel of every sprite (~80 for δ = 4: 1.6 million for the 20,000
// samples of a dense frame). So the read marks its pixels in a bitmap, and each sprite row
// that holds a marked pixel (one or two 64-bit words) evaluates those pixels alone.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

// The pixels a sprite reaches: its box, clamped to the frame (add_sprites' loop).
struct SpriteBox {
    int x0, x1, y0, y1;  // inclusive
};
inline SpriteBox sprite_box(glm::vec2 c, float radius, int width, int height) {
    return {std::max(0, int(std::floor(c.x - radius))), std::min(width - 1, int(std::ceil(c.x + radius))),
            std::max(0, int(std::floor(c.y - radius))), std::min(height - 1, int(std::ceil(c.y + radius)))};
}

// A sprite's weight at a pixel centre, as the GPU splat's fragment stage computes it.
inline float sprite_weight(glm::vec2 pixel, glm::vec2 c, float radius) {
    const float d = glm::length(pixel - c);
    return std::clamp(1.0f - d / radius, 0.0f, 1.0f);
}

// Adds sprites (centre x, y in pixels; T) of radius δ into `buffer` (width × height, the
// whole frame), in order, with the weights the GPU splat's fragment stage computes at pixel
// centres: the CPU reference the GPU splat and SplatSums are compared with.
void add_sprites(std::span<const glm::vec3> sprites, float radius, int width, int height, std::vector<glm::vec4>& buffer);

class SplatSums {
public:
    // Keeps the sprites (non-finite ones must have been removed).
    void splat(std::span<const glm::vec3> sprites, float radius, int width, int height);
    // The sums at each pixel (x, y inside the frame; repeats allowed), into `sums`.
    void read(std::span<const glm::ivec2> pixels, std::vector<glm::vec4>& sums) const;

private:
    std::vector<glm::vec3> sprites_;
    float radius_ = 0.0f;
    int width_ = 0, height_ = 0;
    size_t words_per_row_ = 0;
    // Scratch of read(), kept for the next: not the splat's state.
    mutable std::vector<uint64_t> marked_;  // a bit per pixel: read now (zero between reads)
    mutable std::vector<uint32_t> slot_;    // per marked pixel: its index in the distinct pixels read
};

}  // namespace lw
