// engine/io/file_signature.h — what a file is by its first bytes, not its name (inside
// engine/io): a PNG named .exr, or a text file named .png, goes to the right reader or gets
// the right error.
#pragma once

#include <filesystem>

namespace lw {

// PNG's 8-byte signature.
[[nodiscard]] bool has_png_signature(const std::filesystem::path& path);

// OpenEXR's magic number (76 2f 31 01).
[[nodiscard]] bool has_exr_signature(const std::filesystem::path& path);

}  // namespace lw
