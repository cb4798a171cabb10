// engine/geometry/closed_surfaces.h — where skipping back faces changes no pixel.
//
// Input:  a `TriangleMesh` (its topology and the pose it is in) and, per frame, the view.
// Output: `ClosedSurfaces` — the mesh's faces in components joined across consistently
//         oriented edges, each with its bounds, the caps that close its holes (never drawn)
//         and whether it is closed and outward in this pose; per view, the components whose
//         back faces no ray from the eye can reach first (`back_faces_hidden`).
//
// Why it is exact. A component's faces and its caps form a closed oriented surface. Its
// winding number is 0 far away and changes by ±1 across each face; if it is never negative,
// a ray that starts outside the component's bounds (they lie wholly beyond the near plane)
// first crosses a face it enters: a front face. The caps are not drawn, so a ray may cross a
// cap first and then a back face — unless every cap faces away from the eye, which the view
// test requires. So the first face of a pixel is the same with the component's back faces
// and without them, and with it the colour and the depth that the lines' visibility reads
// (render/surface_pass.h). Within each component separately: a back face that is never the
// first of its own component is never the first of all.
// What makes the winding number never negative, checked by `find_closed_surfaces`:
//   - every edge is open (one face) or used once each way (no fold of the orientation, no
//     fin of three faces, no face with its reverse);
//   - the closed volume is positive, beyond rounding (the outside is the front side);
//   - where the surface passes through itself it may enclose a pocket inside out (winding
//     number −1), into which a ray's first face is a back face. The argument then holds face
//     by face: a back face is first along a ray only where its front side has a negative
//     winding number. Faces that meet another face of their component beyond the corners
//     they share (CGAL's exact predicates, caps included) are drawn both ways, and so is any
//     other face whose front side has a negative winding number (a ray cast from its
//     centroid: on a face that meets no other it is the same all over the face).
// The self-intersection search costs about as much as intersection lines (docs/BENCHMARKS.md),
// so it is made for the pose given here; a caller with another pose of the same mesh (an
// animation frame) has no such check for it and should not cull (render/frame_renderer.cpp).
// glTF's `doubleSided` plays no part: a back face that is never seen first is never seen.
// Faces cut by an alpha mask or blended let the eye through a front face; the surface pass
// culls a component only if all of its faces are opaque.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/triangle_mesh.h"

namespace lw {

struct ClosedSurfaces {
    // Per input triangle: its component, or -1 for a face with no area (two corners at one
    // position), which rasterizes nothing.
    std::vector<int32_t> face_component;
    // Per input triangle: 1 where it must be drawn both ways even when its component may be
    // culled (near where the surface passes through itself, see above).
    std::vector<uint8_t> face_both_ways;
    struct Component {
        glm::vec3 min{0.0f}, max{0.0f};  // bounds, caps included
        // The caps closing its holes, 3 corners per triangle: fans from each boundary cycle's
        // centroid, wound the other way from the faces along it.
        std::vector<glm::vec3> caps;
        bool closable = true;  // its edges and self-intersections allow the argument above
        bool outward = false;  // closable, and its closed volume is positive
        // Closed without caps, its volume negative, and not inside an outward component (the
        // wall of a cavity faces in by right): its faces wind inside out (the front side
        // inside), as an OBJ exported with flipped winding does.
        bool inward = false;
    };
    std::vector<Component> components;
};

[[nodiscard]] ClosedSurfaces find_closed_surfaces(const TriangleMesh& mesh);

// Per component, 1 where its back faces are hidden from this view: it is outward, lies
// wholly beyond the near plane, and no cap faces the eye. `camera` is a perspective view
// with a rigid view matrix (the eye at its origin), as camera_matrices makes.
[[nodiscard]] std::vector<uint8_t> back_faces_hidden(const ClosedSurfaces& surfaces, const CameraMatrices& camera);

}  // namespace lw
