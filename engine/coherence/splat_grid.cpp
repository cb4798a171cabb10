#include "coherence/splat_grid.h"

#include <bit>

namespace lw {

void add_sprites(std::span<const glm::vec3> sprites, float radius, int width, int height, std::vector<glm::vec4>& buffer) {
    for (const glm::vec3& sprite : sprites) {
        const glm::vec2 c(sprite);
        const SpriteBox box = sprite_box(c, radius, width, height);
        for (int y = box.y0; y <= box.y1; ++y)
            for (int x = box.x0; x <= box.x1; ++x) {
                const glm::vec2 pixel(float(x) + 0.5f, float(y) + 0.5f);
                const float w = sprite_weight(pixel, c, radius);
                if (w <= 0.0f) continue;
                buffer[size_t(y) * size_t(width) + size_t(x)] += glm::vec4(w * sprite.z, w, w * (c - pixel));
            }
    }
}

void SplatSums::splat(std::span<const glm::vec3> sprites, float radius, int width, int height) {
    sprites_.assign(sprites.begin(), sprites.end());
    radius_ = radius;
    if (width != width_ || height != height_) {
        width_ = width;
        height_ = height;
        words_per_row_ = (size_t(width) + 63) / 64;
        marked_.assign(words_per_row_ * size_t(height), 0);
        slot_.assign(size_t(width) * size_t(height), 0);
    }
}

void SplatSums::read(std::span<const glm::ivec2> pixels, std::vector<glm::vec4>& sums) const {
    sums.assign(pixels.size(), glm::vec4(0.0f));
    if (sprites_.empty() || pixels.empty()) return;
    // The distinct pixels read, each marked and given a slot for its sum.
    std::vector<uint32_t> distinct;
    for (const glm::ivec2& p : pixels) {
        const size_t i = size_t(p.y) * size_t(width_) + size_t(p.x);
        uint64_t& word = marked_[size_t(p.y) * words_per_row_ + size_t(p.x) / 64];
        const uint64_t bit = uint64_t(1) << (p.x % 64);
        if (word & bit) continue;
        word |= bit;
        slot_[i] = uint32_t(distinct.size());
        distinct.push_back(uint32_t(i));
    }
    std::vector<glm::vec4> accumulated(distinct.size(), glm::vec4(0.0f));
    // Sprite by sprite, in order (so each pixel's sum rounds as the drawn splat's); of each
    // box row, the marked pixels alone.
    for (const glm::vec3& sprite : sprites_) {
        const glm::vec2 c(sprite);
        const SpriteBox box = sprite_box(c, radius_, width_, height_);
        if (box.x0 > box.x1) continue;
        for (int y = box.y0; y <= box.y1; ++y) {
            const uint64_t* row = marked_.data() + size_t(y) * words_per_row_;
            for (int word = box.x0 / 64; word <= box.x1 / 64; ++word) {
                const int first = std::max(box.x0 - 64 * word, 0), last = std::min(box.x1 - 64 * word, 63);
                const uint64_t range = (last == 63 ? ~uint64_t(0) : (uint64_t(1) << (last + 1)) - 1) & ~((uint64_t(1) << first) - 1);
                for (uint64_t bits = row[word] & range; bits != 0; bits &= bits - 1) {
                    const int x = 64 * word + std::countr_zero(bits);
                    const glm::vec2 pixel(float(x) + 0.5f, float(y) + 0.5f);
                    const float w = sprite_weight(pixel, c, radius_);
                    if (w <= 0.0f) continue;
                    accumulated[slot_[size_t(y) * size_t(width_) + size_t(x)]] += glm::vec4(w * sprite.z, w, w * (c - pixel));
                }
            }
        }
    }
    for (size_t q = 0; q < pixels.size(); ++q)
        sums[q] = accumulated[slot_[size_t(pixels[q].y) * size_t(width_) + size_t(pixels[q].x)]];
    for (uint32_t i : distinct) marked_[(i / uint32_t(width_)) * words_per_row_ + (i % uint32_t(width_)) / 64] = 0;
}

}  // namespace lw
