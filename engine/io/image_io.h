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
// "Z" channel of eye depth (distance along the view axis, scene units) from the depth
// buffer's [0, 1] values under a perspective of planes `znear`, `zfar`; +inf where nothing
// was drawn.
void write_exr(const std::filesystem::path& path, const ImageRGBA8& color, const std::vector<float>& depth, float znear,
               float zfar);

}  // namespace lw
