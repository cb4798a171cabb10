// engine/lines/line_types.h — the data the line stages pass along.
//
//   extraction (per face)  ->  LineSegment[]  ->  chaining  ->  LinePath[]
//   LinePath[] + depth     ->  visibility     ->  ScreenPath[] (visible and hidden runs)
//
// `LineSegment` is shared with the GPU (shaders/lines_shared.glsl mirrors it, std430).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "types/line_type.h"

namespace lw {

// Chaining key of an endpoint: for contours and suggestive contours the mesh edge the
// endpoint lies on; for creases and borders the mesh vertex; kNoKey where a segment was cut
// inside a face (the test changed sign there) — a path ends there.
constexpr uint32_t kNoKey = 0xffffffffu;

struct LineSegment {
    glm::vec4 p0;     // xyz: world position; w: fade alpha in [0, 1]
    glm::vec4 p1;
    glm::vec3 bary0;  // barycentric coordinates of p0 in `face`
    // Intersection lines: the face of the other surface the line lies on (the line belongs
    // to both); kNoFace for every other type.
    uint32_t other_face = kNoFace;
    glm::vec3 bary1;
    uint32_t pad = 0;
    uint32_t face;
    uint32_t type;    // LineType
    uint32_t key0;    // chaining key of p0
    uint32_t key1;
};
static_assert(sizeof(LineSegment) == 80 && offsetof(LineSegment, other_face) == 44 && offsetof(LineSegment, face) == 64,
              "LineSegment must match shaders/lines_shared.glsl (std430: a uint packs after a vec3)");

// One vertex of a brush path: where it is on the surface, and how opaque.
struct PathVertex {
    glm::vec3 position;  // world
    uint32_t face;
    glm::vec3 bary;      // in `face`
    float alpha;
    uint32_t other_face = kNoFace;  // intersection lines: the other surface's face
};

struct LinePath {
    LineType type = LineType::Silhouette;
    bool closed = false;        // a loop: the last vertex connects back to the first
    std::vector<PathVertex> vertices;
};

}  // namespace lw
