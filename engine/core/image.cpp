#include "core/image.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "core/error.h"

namespace lw {

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
