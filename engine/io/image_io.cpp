#include "io/image_io.h"

#include <algorithm>

#include <OpenImageIO/imageio.h>

#include "core/color.h"
#include "core/error.h"
#include "core/text.h"

namespace lw {

namespace {

void write_image(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const void* data) {
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throw Error(path.string() + ": cannot write: " + one_line(OIIO::geterror()));
    if (!out->open(path.string(), spec)) throw Error(path.string() + ": cannot open for writing: " + one_line(out->geterror()));
    if (!out->write_image(spec.format, data)) throw Error(path.string() + ": write failed: " + one_line(out->geterror()));
    if (!out->close()) throw Error(path.string() + ": close failed: " + one_line(out->geterror()));
}

}  // namespace

void write_png(const std::filesystem::path& path, const ImageRGBA8& image) {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // store the bytes as given, never premultiplied
    write_image(path, spec, image.pixels.data());
}

ImageRGBA8 read_image_rgba8(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw Error(path.string() + ": no such file");
    if (std::filesystem::is_directory(path)) throw Error(path.string() + ": a folder, not an image");
    // OpenImageIO's own readers allocate from the header as they open a file: cap what they
    // may believe (16384² RGBA is 1 GiB) so that a corrupt header fails fast (fuzz_image found
    // a 26-byte TGA that made it allocate for 20 s).
    static const bool limited = OIIO::attribute("limits:imagesize_MB", 1024) && OIIO::attribute("limits:channels", 64);
    (void)limited;
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // no premultiplication: bytes as stored
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) throw Error(path.string() + ": cannot read image: " + one_line(OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw Error(path.string() + ": empty image");
    // A SLAM file (io/slam_io.h) opens as an image of its first level: as a ribbon exemplar
    // it gave an opaque 1024-texel pattern whose DP ran for many minutes, in diff it compared
    // one level of many.
    if (const int levels = spec.get_int_attribute("linework:levels", 0); levels > 0)
        throw Error(path.string() + ": a SLAM file (" + std::to_string(levels) + " levels of " + std::to_string(spec.width) +
                    "x" + std::to_string(spec.height) + "), not an image: a SLAM goes in a style's \"slam\" or --slam");
    // Before allocating: a header may claim any size (found by tests/fuzz/fuzz_image).
    if (spec.width > 16384 || spec.height > 16384 || spec.nchannels > 64)
        throw Error(path.string() + ": image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                    " with " + std::to_string(spec.nchannels) + " channels is too large (at most 16384x16384, 64 channels)");
    std::vector<uint8_t> raw(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, raw.data()))
        throw Error(path.string() + ": read failed: " + one_line(in->geterror()));
    in->close();

    ImageRGBA8 image{spec.width, spec.height, std::vector<uint8_t>(size_t(spec.width) * spec.height * 4)};
    const int n = spec.nchannels;
    for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p) {
        const uint8_t* src = &raw[p * n];
        uint8_t* dst = &image.pixels[p * 4];
        if (n == 1 || n == 2) {
            dst[0] = dst[1] = dst[2] = src[0];
            dst[3] = n == 2 ? src[1] : 255;
        } else {
            dst[0] = src[0];
            dst[1] = src[1];
            dst[2] = src[2];
            dst[3] = n >= 4 ? src[3] : 255;
        }
    }
    return image;
}

void write_exr(const std::filesystem::path& path, const ImageRGBA8& color, const std::vector<float>& z) {
    const size_t pixels = size_t(color.width) * color.height;
    if (z.size() != pixels) throw Error(path.string() + ": depth size does not match the image");
    std::vector<float> data(pixels * 5);
    for (size_t p = 0; p < pixels; ++p) {
        const float alpha = color.pixels[p * 4 + 3] / 255.0f;
        for (size_t c = 0; c < 3; ++c) {
            // Straight, decoded, premultiplied again: linear light as compositing adds it.
            const float straight = alpha > 0.0f ? std::min(1.0f, color.pixels[p * 4 + c] / 255.0f / alpha) : 0.0f;
            data[p * 5 + c] = srgb_to_linear(straight) * alpha;
        }
        data[p * 5 + 3] = alpha;
        data[p * 5 + 4] = z[p];
    }
    OIIO::ImageSpec spec(color.width, color.height, 5, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A", "Z"};
    spec.alpha_channel = 3;
    spec.z_channel = 4;
    write_image(path, spec, data.data());
}

}  // namespace lw
