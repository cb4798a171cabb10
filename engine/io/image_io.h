// engine/io/image_io.h — image files through OpenImageIO (the only module that links it).
//
// PNG for 8-bit renders and goldens; OpenEXR for float colour with a depth channel "Z".
// Errors name the file and OpenImageIO's reason.
#pragma once

#include <filesystem>
#include <vector>

#include "core/image.h"

namespace lw {

void write_png(const std::filesystem::path& path, const ImageRGBA8& image);

// Reads any 8-bit image OpenImageIO knows as RGBA (grey and RGB are expanded, alpha = 255).
[[nodiscard]] ImageRGBA8 read_image_rgba8(const std::filesystem::path& path);

// Writes a frame as compositing tools read an EXR: RGBA in linear light, premultiplied (from
// the 8-bit frame, whose colours are sRGB-encoded and premultiplied in that encoding), and a
// "Z" channel as given (render writes eye depth).
void write_exr(const std::filesystem::path& path, const ImageRGBA8& color, const std::vector<float>& z);

}  // namespace lw
