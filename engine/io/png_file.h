// engine/io/png_file.h — PNG files through libpng (inside engine/io; the public calls are in
// image_io.h).
//
// Bytes as stored: no gamma or colour-space conversion and no premultiplication, so that a
// frame written and read back is the same bytes, as OpenImageIO gave them before.
#pragma once

#include <filesystem>

#include "core/image.h"

namespace lw {

// Any PNG (palette, grey, 16-bit, interlaced, with or without alpha) as 8-bit RGBA: grey and
// RGB are expanded, a missing alpha is 255, 16-bit samples are scaled to 8. Throws lw::Error
// naming the file; refuses a header over 16384 × 16384 before allocating.
[[nodiscard]] ImageRGBA8 read_png(const std::filesystem::path& path);

}  // namespace lw
