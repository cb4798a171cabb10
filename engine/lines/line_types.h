// engine/lines/line_types.h — the data the line stages pass along.
//
//   extraction (per face)  ->  LineSegment[]  ->  chaining  ->  LinePath[]
//   LinePath[] + depth     ->  visibility     ->  ScreenPath[] (visible and hidden runs)
//
// `LineSegment` is shared with the GPU (shaders/lines_shared.glsl mirrors it, std430).
#pragma once

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
    glm::vec4 bary0;  // xyz: barycentric coordinates of p0 in `face` (w unused)
    glm::vec4 bary1;
    uint32_t face;
    uint32_t type;    // LineType
    uint32_t key0;    // chaining key of p0
    uint32_t key1;
};
static_assert(sizeof(LineSegment) == 80, "LineSegment must match shaders/lines_shared.glsl");

// One vertex of a brush path: where it is on the surface, and how opaque.
struct PathVertex {
    glm::vec3 position;  // world
    uint32_t face;
    glm::vec3 bary;      // in `face`
    float alpha;
};

struct LinePath {
    LineType type = LineType::Silhouette;
    bool closed = false;        // a loop: the last vertex connects back to the first
    std::vector<PathVertex> vertices;
};

}  // namespace lw
