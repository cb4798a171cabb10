// engine/lines/strip_order.h — the order in which rtsc visits each face's corners.
//
// Input:  a `WeldedMesh` and the faces around each vertex in face order (LineMesh's).
// Output: per face, the face-local numbers (0–2) of the corners rtsc's face loops see as
//         their v0, v1, v2, packed 2 bits each (`StripCorners`).
//
// rtsc walks the faces through trimesh2's triangle strips (need_tstrips), and a strip's
// face (t−2, t−1, t) starts at whichever corner the strip reached it from, every other one
// wound backwards. Two of rtsc's rules read that order (docs/research/rtsc-lines.md §6):
// principal highlights measure e1's turn from v0's, and an apparent ridge piece to a face's
// centre is kept by a test on the winding of (v0, v1, v2). To draw what rtsc draws, we
// rebuild trimesh2's strips: its across-edge map (the first consistently oriented face
// across each edge, in face order around the edge's first vertex) and its greedy strip
// builder (faces with one free neighbour first, each strip started where it can run
// longest), step for step.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/welded_mesh.h"

namespace lw {

// Corner number i of v0, v1, v2 at bits 2i..2i+1.
using StripCorners = uint8_t;

[[nodiscard]] std::vector<StripCorners> strip_corner_order(const WeldedMesh& mesh,
                                                           const std::vector<uint32_t>& vertex_face_offsets,
                                                           const std::vector<uint32_t>& vertex_faces);

inline int strip_corner(StripCorners packed, int i) { return (packed >> (2 * i)) & 3; }

}  // namespace lw
