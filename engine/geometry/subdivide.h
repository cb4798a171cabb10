// engine/geometry/subdivide.h — midpoint (1-to-4) subdivision of a triangle mesh.
//
// Input:  an indexed `TriangleMesh`.
// Output: a mesh with 4× the triangles: each edge split at its midpoint (shared between
//         the two faces, so the result stays watertight where the input was), normals
//         interpolated and renormalized. The surface is unchanged — only denser — which
//         makes it the way to build the ~1M-triangle benchmark meshes from real models.
#pragma once

#include "scene/triangle_mesh.h"

namespace lw {

[[nodiscard]] TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int levels = 1);

}  // namespace lw
