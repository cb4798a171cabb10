// engine/lines/extract_reference.h — plain C++ feature-line extraction (the reference).
//
// Input:  a `LineMesh`, the eye (world space, same as the mesh), `LineParams`.
// Output: `LineSegment`s: per face, the contour (zero set of n·v kept where kr ≥ 0), the
//         suggestive contour (zero set of kr where tanθ·DwKr > sug_thresh/fs², faded), the
//         creases and borders the face owns, and those of rtsc's other lines that
//         `LineParams` turns on: suggestive highlights (zero set of kr where
//         −tanθ·DwKr > sh_thresh/fs², here) and the ridge-like lines (ridge_lines.h). Rules and their order follow rtsc's
//         draw_face_isoline (docs/research/rtsc-lines.md §2) so that our lines match rtsc's.
//
// The GPU pass (extract_gpu.h, shaders/lines_extract.comp) must produce the same segments;
// tests compare the two after `sort_segments`.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lines/line_mesh.h"
#include "lines/line_types.h"
#include "lines/ridge_lines.h"

namespace lw {

// The per-view scratch, kept by a caller that extracts every frame so that a frame
// allocates nothing: per vertex n·v, kr, the suggestive test's numerator and a byte of
// their signs; with several threads, each face block's segments.
struct ExtractWorkspace {
    std::vector<float> ndotv, kr, test_num;
    std::vector<uint8_t> signs;
    std::vector<float> highlight_num;        // suggestive highlights' test numerator (when drawn)
    ApparentArrays apparent;                 // apparent ridges' view-dependent curvature (when drawn)
    std::vector<float> principal_along, principal_strength;  // principal highlights' (when drawn)
    std::vector<uint8_t> principal_flags;
    std::vector<uint8_t> front;  // per face, 1 where it faces the eye (mesh contours)
    // Per pose, for mesh contours: each face's n = (x1 − x0) × (x2 − x0) and x0, as six
    // arrays, so that a view's facing n · (eye − x0) > 0 is one streaming pass (the same
    // operations as the GPU's `front_facing`, split between the pose and the view). As the
    // ridge cache: a pose's first view (every frame of an animation) computes the facing
    // from the corners and keeps nothing; its second fills the arrays; later views stream.
    struct FacePlanes {
        uint64_t generation = 0;  // LineMesh::generation of the arrays (0: none)
        uint64_t seen = 0;        // the last pose viewed
        enum class Use : uint8_t { Corners, Fill, Stream } use = Use::Corners;  // this view's
        std::vector<float> nx, ny, nz, x0, y0, z0;
    } face_planes;
    uint64_t principal_generation = 0;  // LineMesh::generation of principal_shapes
    std::vector<uint8_t> principal_shapes;  // per face, view-independent (principal_highlight_shapes)
    // Ridges and valleys do not depend on the view but for back-face culling: a mesh pose
    // seen a second time (a still model) has them found once (all faces, culling aside), and
    // each view keeps those on faces not back-facing; a pose seen once (an animation frame)
    // finds them per face with culling, as rtsc does. Per type (ridges, valleys): the
    // segments in face order and where each face block starts.
    struct RidgeCache {
        struct Key {
            uint64_t generation = 0;  // LineMesh::generation (0: none)
            float thresh = 0.0f;
            bool fade = false;
            bool operator==(const Key&) const = default;
        };
        Key filled, seen;  // what `segments` holds; the last pose asked for
        bool use = false;  // this view reads `segments`
        std::vector<LineSegment> segments;
        std::vector<uint32_t> block_start;
    } ridge_cache[2];
    std::vector<std::vector<LineSegment>> blocks;  // a team's blocks taken from the back
};

// Fills `out` (its capacity reused). Segments come out per block of 1024 faces, in order;
// within a block by type (suggestive contours, contours, creases and borders, then rtsc's
// other lines), each type in face order; chaining does not depend on the order. `threads` > 1 runs vertex
// and face blocks on several threads (core/parallel.h) and concatenates the face blocks'
// segments in block order: the same segments in the same order whatever the count. Frames extract on
// one thread (1, the default): the other core is lavapipe's while it draws the surface
// (frame_renderer.cpp).
void extract_lines_reference(const LineMesh& mesh, const glm::vec3& eye, const LineParams& params,
                             std::vector<LineSegment>& out, ExtractWorkspace& workspace, size_t threads = 1);
[[nodiscard]] std::vector<LineSegment> extract_lines_reference(const LineMesh& mesh, const glm::vec3& eye,
                                                               const LineParams& params, size_t threads = 1);

// Mesh contours (ContourMode::Mesh, or Auto on a coarse model's faces): the edges between a
// face that faces the eye and one that does not, emitted by the front face as silhouettes.
// Facing: (x1 − x0) × (x2 − x0) · (eye − x0) > 0. An endpoint's key names the fan of front
// faces around its vertex that the segment's face belongs to (`mesh_contour_key`): each
// fan is bounded by two contour edges, so the key joins exactly those two, and where two
// contours touch at a vertex (four contour edges) each goes on through its own fan instead
// of ending at a junction. Keys lie past the edge numbers that key smooth contours.
template <class Facing>
[[nodiscard]] uint32_t mesh_contour_key(const LineMesh& lm, uint32_t face, int corner, Facing front) {
    // Walk round the vertex both ways across front faces; the fan's smallest face and the
    // vertex's corner in it name the fan.
    const uint32_t v = lm.mesh.faces[face][corner];
    uint32_t smallest = face;
    for (int way = 1; way <= 2; ++way) {
        uint32_t at = face;
        int c = corner;
        for (int step = 0; step < 64; ++step) {  // (a bound for non-manifold fans)
            const int next = lm.mesh.face_neighbors[at][(c + way) % 3];  // across an edge at v
            if (next < 0 || uint32_t(next) == face || !front(uint32_t(next))) break;
            at = uint32_t(next);
            const glm::uvec3 f = lm.mesh.faces[at];
            c = f.x == v ? 0 : f.y == v ? 1 : 2;
            // On a consistently wound mesh the same corner step keeps turning the same way.
            smallest = std::min(smallest, at);
        }
    }
    const glm::uvec3 f = lm.mesh.faces[smallest];
    const uint32_t c = f.x == v ? 0u : f.y == v ? 1u : 2u;
    return uint32_t(lm.mesh.edges.size()) + 3u * smallest + c;
}
[[nodiscard]] inline bool mesh_contours_at(const LineMesh& mesh, const LineParams& params, uint32_t face) {
    return params.contours == ContourMode::Mesh || (params.contours == ContourMode::Auto && mesh.face_coarse[face]);
}

// The scaled thresholds both implementations use, as rtsc scales them: sug_thresh/fs²,
// (fade on) 0.03/fs², rv_thresh/fs, ar_thresh/fs², sh_thresh/fs², ph_thresh/fs².
struct ScaledThresholds {
    float sug_thresh;
    float fade;
    float rv_thresh, ar_thresh, sh_thresh, ph_thresh;
};
[[nodiscard]] ScaledThresholds scaled_thresholds(const LineParams& params, float feature_size);

}  // namespace lw
