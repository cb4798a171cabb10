// engine/io/image_io.h — image files: PNG through libpng, EXR through OpenEXR, and any other
// format OpenImageIO reads, through a module loaded on first use (io/openimageio/read_image.h).
//
// PNG for 8-bit renders and goldens; OpenEXR for float colour with a depth channel "Z".
// Errors name the file and the library's reason.
#pragma once

#include <filesystem>
#include <vector>

#include "core/image.h"

namespace lw {

void write_png(const std::filesystem::path& path, const ImageRGBA8& image);

// Reads an image as 8-bit RGBA, bytes as stored (grey and RGB are expanded, alpha = 255):
// PNG through libpng, other formats through OpenImageIO. Refuses a SLAM file (an EXR of
// levels) and a header over 16384 × 16384.
[[nodiscard]] ImageRGBA8 read_image_rgba8(const std::filesystem::path& path);

// The same through OpenImageIO whatever the format (what read_image_rgba8 does for formats
// other than PNG): the tests check that both readers give the same bytes.
[[nodiscard]] ImageRGBA8 read_image_rgba8_through_openimageio(const std::filesystem::path& path);

// Writes a frame as compositing tools read an EXR: RGBA in linear light, premultiplied (from
// the 8-bit frame, whose colours are sRGB-encoded and premultiplied in that encoding), and a
// "Z" channel as given (render writes eye depth).
void write_exr(const std::filesystem::path& path, const ImageRGBA8& color, const std::vector<float>& z);

}  // namespace lw
