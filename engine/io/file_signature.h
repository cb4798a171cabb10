// engine/io/file_signature.h — what a file is by its first bytes, not its name (inside
// engine/io): a PNG named .exr, or a text file named .png, goes to the right reader or gets
// the right error.
#pragma once

#include <filesystem>

namespace lw {

enum class FileKind {
    Png,    // PNG's 8-byte signature
    Exr,    // OpenEXR's magic number (76 2f 31 01)
    Other,  // anything else, a file too short for either, or one that cannot be opened
};

[[nodiscard]] FileKind file_kind(const std::filesystem::path& path);

}  // namespace lw
