// engine/render/coverage_reference.h — plain C++ reference for the surface pass's coverage.
//
// Input:  a world-space mesh, camera matrices and an image size.
// Output: one byte per pixel, 1 where some triangle covers the pixel centre — what the
//         GPU rasterizer covers, up to its edge tie-breaking rules. Tests compare the
//         rendered silhouette area against this. Triangles crossing the near plane are
//         skipped (framed cameras keep every vertex in front).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/camera.h"
#include "scene/triangle_mesh.h"

namespace lw {

[[nodiscard]] std::vector<uint8_t> coverage_reference(const TriangleMesh& mesh, const CameraMatrices& camera,
                                                      int width, int height);

}  // namespace lw
