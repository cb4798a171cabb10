#include "core/image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "core/color.h"
#include "core/error.h"

namespace lw {

namespace {

// Linear light of each sRGB byte.
const std::array<float, 256>& srgb_decode() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int v = 0; v < 256; ++v) t[size_t(v)] = srgb_to_linear(float(v) / 255.0f);
        return t;
    }();
    return table;
}

// A level as linear, alpha-weighted colour (r·a, g·a, b·a, a): what averaging needs.
std::vector<float> premultiplied_linear(const ImageRGBA8& image) {
    const std::array<float, 256>& decode = srgb_decode();
    std::vector<float> out(image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        const float a = float(image.pixels[i + 3]) / 255.0f;
        for (size_t c = 0; c < 3; ++c) out[i + c] = decode[image.pixels[i + c]] * a;
        out[i + 3] = a;
    }
    return out;
}

}  // namespace

std::vector<ImageRGBA8> srgb_mip_chain(const ImageRGBA8& image) {
    std::vector<ImageRGBA8> levels{image};
    std::vector<float> above = premultiplied_linear(image);
    const std::array<float, 256>& decode = srgb_decode();
    int w = image.width, h = image.height;
    while (w > 1 || h > 1) {
        const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
        std::vector<float> level(size_t(nw) * size_t(nh) * 4, 0.0f);
        ImageRGBA8 encoded{nw, nh, std::vector<uint8_t>(level.size())};
        for (int y = 0; y < nh; ++y) {
            // The source rows and columns this texel averages: two, three at an odd edge.
            const int y0 = std::min(2 * y, h - 1), y1 = (y == nh - 1) ? h - 1 : 2 * y + 1;
            for (int x = 0; x < nw; ++x) {
                const int x0 = std::min(2 * x, w - 1), x1 = (x == nw - 1) ? w - 1 : 2 * x + 1;
                float sum[4] = {0, 0, 0, 0};
                for (int sy = y0; sy <= y1; ++sy)
                    for (int sx = x0; sx <= x1; ++sx)
                        for (int c = 0; c < 4; ++c) sum[c] += above[(size_t(sy) * size_t(w) + size_t(sx)) * 4 + size_t(c)];
                const float n = float((y1 - y0 + 1) * (x1 - x0 + 1));
                float* texel = &level[(size_t(y) * size_t(nw) + size_t(x)) * 4];
                for (int c = 0; c < 4; ++c) texel[c] = sum[c] / n;
                uint8_t* out = encoded.at(x, y);
                const float a = texel[3];
                if (a > 0.0f) {
                    for (int c = 0; c < 3; ++c) out[c] = unit_to_byte(linear_to_srgb(texel[c] / a));
                } else {
                    // All transparent: the plain mean of the colours above, so that filtering
                    // across a cut-out's edge blends towards its colour, not towards black.
                    const ImageRGBA8& up = levels.back();
                    float plain[3] = {0, 0, 0};
                    for (int sy = y0; sy <= y1; ++sy)
                        for (int sx = x0; sx <= x1; ++sx)
                            for (int c = 0; c < 3; ++c) plain[c] += decode[up.at(sx, sy)[c]];
                    for (int c = 0; c < 3; ++c) out[c] = unit_to_byte(linear_to_srgb(plain[c] / n));
                }
                out[3] = unit_to_byte(a);
            }
        }
        levels.push_back(std::move(encoded));
        above = std::move(level);
        w = nw, h = nh;
    }
    return levels;
}

void composite_over_white(ImageRGBA8& image) {
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        const int a = image.pixels[i + 3];
        for (size_t c = 0; c < 3; ++c)
            image.pixels[i + c] = uint8_t((image.pixels[i + c] * a + 255 * (255 - a) + 127) / 255);
        image.pixels[i + 3] = 255;
    }
}

ImageRGBA8 straight_alpha(const ImageRGBA8& premultiplied) {
    ImageRGBA8 out = premultiplied;
    for (size_t i = 0; i < out.pixels.size(); i += 4) {
        const int a = out.pixels[i + 3];
        if (a == 255) continue;
        for (size_t c = 0; c < 3; ++c)
            out.pixels[i + c] = a == 0 ? 0 : uint8_t(std::min(255, (out.pixels[i + c] * 255 + a / 2) / a));
    }
    return out;
}

ImageDiff compare_images(const ImageRGBA8& a, const ImageRGBA8& b, int tolerance) {
    if (a.width != b.width || a.height != b.height)
        throw Error("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
    ImageDiff d;
    d.diff = ImageRGBA8{a.width, a.height, std::vector<uint8_t>(a.pixels.size(), 0)};
    double squared = 0.0;
    size_t differing = 0;
    const size_t pixel_count = static_cast<size_t>(a.width) * a.height;
    for (size_t p = 0; p < pixel_count; ++p) {
        int pixel_max = 0;
        for (size_t c = 0; c < 4; ++c) {
            const int e = std::abs(int(a.pixels[4 * p + c]) - int(b.pixels[4 * p + c]));
            pixel_max = std::max(pixel_max, e);
            squared += double(e) * e;
            if (c < 3) d.diff.pixels[4 * p + c] = static_cast<uint8_t>(std::min(255, e * 8));
        }
        d.diff.pixels[4 * p + 3] = 255;
        d.max_abs_error = std::max(d.max_abs_error, pixel_max);
        if (pixel_max > tolerance) ++differing;
    }
    const double count = std::max<double>(1.0, double(pixel_count) * 4.0);
    d.rmse = std::sqrt(squared / count);
    d.psnr_db = d.rmse == 0.0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(255.0 / d.rmse);
    d.differing_fraction = pixel_count ? double(differing) / double(pixel_count) : 0.0;
    return d;
}

}  // namespace lw
