// engine/vector/vector_file.h — reading a curve or stroke file's text.
//
// Both are JSON (.json) or SVG (.svg), chosen by the extension. A missing file, a folder or
// another extension (an exemplar PNG given where a curve goes) is one error naming the file,
// not the JSON parser's complaint about a binary first byte.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/text.h"

namespace lw {

// `what`: "curve" or "stroke", for the messages.
inline std::string read_vector_file(const std::filesystem::path& path, const std::string& what) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path.string() + ": no such file");
    if (std::filesystem::is_directory(path, ec)) throw Error(path.string() + ": a folder, not a " + what + " file");
    const std::string ext = lower(path.extension().string());
    if (ext != ".json" && ext != ".svg")
        throw Error(path.string() + ": unsupported " + what + " file" + extension_phrase(ext) + ": " + what +
                    " files are JSON (.json) or SVG (.svg)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open the " + what + " file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

}  // namespace lw
