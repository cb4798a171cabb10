// The module linework-openimageio.so: any image OpenImageIO reads, as 8-bit RGBA (see
// read_image.h). It uses only header-only parts of the engine, so that it links OpenImageIO
// and nothing of ours.
#include "io/openimageio/read_image.h"

#include <OpenImageIO/imageio.h>

extern "C" __attribute__((visibility("default"))) bool lw_read_image_through_openimageio(const char* path,
                                                                                       lw::ImageRGBA8* image,
                                                                                       std::string* error) try {
    // OpenImageIO's own readers allocate from the header as they open a file: cap what they
    // may believe (16384² RGBA is 1 GiB) so that a corrupt header fails fast (fuzz_image found
    // a 26-byte TGA that made it allocate for 20 s).
    static const bool limited = OIIO::attribute("limits:imagesize_MB", 1024) && OIIO::attribute("limits:channels", 64);
    (void)limited;
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // no premultiplication: bytes as stored
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        *error = "cannot read image: " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        *error = "empty image";
        return false;
    }
    // Before allocating: a header may claim any size (found by tests/fuzz/fuzz_image).
    if (spec.width > lw::kLargestImageSide || spec.height > lw::kLargestImageSide || spec.nchannels > 64) {
        const std::string side = std::to_string(lw::kLargestImageSide);
        *error = "image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " with " +
                 std::to_string(spec.nchannels) + " channels is too large (at most " + side + "x" + side + ", 64 channels)";
        return false;
    }
    const int n = spec.nchannels;
    const size_t count = size_t(spec.width) * spec.height;
    std::vector<uint8_t> raw(count * n);
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::UINT8, raw.data())) {
        *error = "read failed: " + in->geterror();
        return false;
    }
    in->close();
    *image = lw::ImageRGBA8{spec.width, spec.height, std::vector<uint8_t>(count * 4)};
    for (size_t p = 0; p < count; ++p) {
        const uint8_t* src = &raw[p * n];
        uint8_t* dst = &image->pixels[p * 4];
        const bool grey = n <= 2;
        dst[0] = src[0];
        dst[1] = grey ? src[0] : src[1];
        dst[2] = grey ? src[0] : src[2];
        dst[3] = n == 2 ? src[1] : n >= 4 ? src[3] : 255;
    }
    return true;
} catch (const std::exception& e) {  // no exception crosses the module's C entry
    *error = std::string("cannot read image: ") + e.what();
    return false;
}
