// engine/scene/ply_check.h — a PLY file's structure checked before Assimp reads it
// (scene/ply_check.cpp says why), and the triangle strips it cannot read.
// Input: a .ply path. Output: nothing, or lw::Error naming the file and the problem (no
// end_header, counts the file cannot hold, ASCII list lengths past its end); for a file of
// triangle strips, its vertices and their triangles. Each reads the whole file once.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lw {

// True when the file's faces are triangle strips (read_ply_strips reads them, not Assimp).
[[nodiscard]] bool check_ply_structure(const std::filesystem::path& path, const std::string& file);

// A PLY whose faces are triangle strips (element "tristrips", a list of vertex indices, -1
// restarting a strip; many scans of the 1990s come so, and rtsc's trimesh2 reads them): its
// vertices (x, y, z; nx, ny, nz where given) and the strips' triangles. Assimp 5.2 keeps only
// the last triangle of each strip element, a whole scan read as one triangle. lw::Error naming
// the file for one that cannot be read.
struct PlyStripMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;  // three per triangle
};
[[nodiscard]] PlyStripMesh read_ply_strips(const std::filesystem::path& path, const std::string& file);

}  // namespace lw
