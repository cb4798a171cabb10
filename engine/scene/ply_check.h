// engine/scene/ply_check.h — a PLY file's structure checked before Assimp reads it
// (scene/ply_check.cpp says why). Input: a .ply path; output: nothing, or lw::Error naming
// the file and the problem (no end_header, counts the file cannot hold, ASCII list lengths
// past its end). Reads the whole file once.
#pragma once

#include <filesystem>
#include <string>

namespace lw {

void check_ply_structure(const std::filesystem::path& path, const std::string& file);

}  // namespace lw
