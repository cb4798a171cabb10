// tests/test_ribbon_support.h — small exemplars for the ribbon tests.
#pragma once

#include <cstdint>

#include "core/random.h"
#include "ribbon/dp.h"
#include "ribbon/exemplar.h"
#include "test_support.h"

namespace lw::test {

// Random pixels (three colours, opaque with probability 0.6) in rows first .. last, the rest
// transparent black.
inline Exemplar banded_exemplar(int width, int height, int first, int last, uint64_t seed) {
    ImageRGBA8 img{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 0)};
    uint64_t state = seed;
    const uint8_t palette[3][3] = {{200, 30, 30}, {30, 160, 60}, {40, 40, 220}};
    for (int y = first; y <= last; ++y)
        for (int x = 0; x < width; ++x) {
            state = mix64(state);
            if (state % 10 >= 6) continue;
            const uint8_t* c = palette[(state >> 8) % 3];
            uint8_t* p = img.at(x, y);
            p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
        }
    img.at(width / 2, (first + last) / 2)[3] = 255;
    return make_exemplar(img, "banded");
}

// A pattern periodic in x with `period`: bars in rows 3 .. H−4 in the first 5 columns of each
// period, a line through the middle row, colours that differ per column of the period;
// transparent margins of 3 rows.
inline Exemplar periodic_exemplar(int width, int height, int period) {
    ImageRGBA8 img{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 0)};
    for (int y = 3; y < height - 3; ++y)
        for (int x = 0; x < width; ++x) {
            if (x % period >= 5 && y != height / 2) continue;
            uint8_t* p = img.at(x, y);
            p[0] = uint8_t(30 * (x % period));
            p[1] = uint8_t(20 * y);
            p[2] = 100;
            p[3] = 255;
        }
    return make_exemplar(img, "periodic");
}

}  // namespace lw::test
