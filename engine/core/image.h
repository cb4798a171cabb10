// engine/core/image.h — images in memory, and how two of them differ.
//
// `ImageRGBA8` is what the renderer reads back and what PNG files hold; `compare_images`
// is the golden-image check used by `linework diff` and the tests (STYLE.md habit 15:
// per-channel error, PSNR, the share of differing pixels, an amplified diff image).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lw {

// The largest width and height of an image anything here makes, reads or draws: Vulkan's
// maxImageDimension2D on lavapipe and most GPUs, and 16384² RGBA8 is already 1 GiB, so a
// corrupt header claiming more is refused before anything is allocated.
inline constexpr int kLargestImageSide = 16384;

struct ImageRGBA8 {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels;  // width * height * 4, rows top to bottom

    uint8_t* at(int x, int y) { return &pixels[(static_cast<size_t>(y) * width + x) * 4]; }
    const uint8_t* at(int x, int y) const { return &pixels[(static_cast<size_t>(y) * width + x) * 4]; }
};

struct ImageDiff {
    int max_abs_error = 0;        // largest per-channel difference, 0..255
    double rmse = 0.0;            // over all channels, 0..255
    double psnr_db = 0.0;         // infinity when identical
    double differing_fraction = 0.0;  // pixels with any channel off by more than `tolerance`
    ImageRGBA8 diff;              // |A - B| × 8, clamped; alpha 255
};

// Composites a non-premultiplied RGBA image over white, in place (alpha becomes 255): what
// `linework ribbon` writes unless asked for a transparent background.
void composite_over_white(ImageRGBA8& image);

// Premultiplied RGBA (a frame over a transparent background) to straight alpha, as PNG
// stores it: colour ÷ alpha, rounded; fully transparent pixels black. Opaque pixels are
// unchanged, so an opaque frame comes back as it was.
[[nodiscard]] ImageRGBA8 straight_alpha(const ImageRGBA8& premultiplied);

// Mip levels of an sRGB-encoded RGBA8 image, the image first, down to 1 × 1: each level
// halves the last (sizes rounded down, glTF's and Vulkan's rule), each texel the mean of the
// 2 × 2 (at an odd edge 3-wide) texels above it, in linear light and weighted by alpha so
// that the colour of cut-out texels does not bleed into their neighbours.
[[nodiscard]] std::vector<ImageRGBA8> srgb_mip_chain(const ImageRGBA8& image);

// Compares RGBA images of equal size (throws lw::Error otherwise). `tolerance` is the
// per-channel difference a pixel may have before it counts as differing.
[[nodiscard]] ImageDiff compare_images(const ImageRGBA8& a, const ImageRGBA8& b, int tolerance = 0);

}  // namespace lw
