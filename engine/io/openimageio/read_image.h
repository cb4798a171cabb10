// engine/io/openimageio/read_image.h — the contract between image_io.cpp and the module it
// loads for images that are not PNG (linework-openimageio.so, the only code that links
// OpenImageIO). Loaded with dlopen on first use: OpenImageIO's 260 shared libraries cost
// 0.3 s of CPU at every process start when linked in.
//
// Input: a path. Output: the image as 8-bit RGBA, bytes as stored (grey and RGB expanded,
// alpha 255 where there is none), or false with the reason in *error (starting
// "cannot read image: " or naming what is wrong with it).
#pragma once

#include <string>

#include "core/image.h"

namespace lw {

inline constexpr const char* kOpenImageIOModuleName = "linework-openimageio.so";
inline constexpr const char* kOpenImageIOEntry = "lw_read_image_through_openimageio";

}  // namespace lw

extern "C" bool lw_read_image_through_openimageio(const char* path, lw::ImageRGBA8* image, std::string* error);
