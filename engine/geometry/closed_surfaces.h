// engine/geometry/closed_surfaces.h — where skipping back faces changes no pixel.
//
// Input:  a `TriangleMesh` (any pose of one topology) and, per frame, the view.
// Output: `ClosedSurfaces` — the mesh's faces in connected components, each with the holes
//         of its boundary closed by caps that are never drawn; per pose, each component's
//         bounds, caps and orientation; per view, the components whose back faces no ray
//         from the eye can reach first (`back_faces_hidden`).
//
// Why it is exact: the faces of a component and its caps form a closed oriented surface
// (every edge used as often in one direction as in the other). If that surface bounds its
// volume from outside (positive volume, no inverted pocket), the winding number of space
// about it is 0 outside and never negative, so along any ray that starts outside it (the
// component lies wholly beyond the near plane) the first face crossed is one the ray
// enters, a front face. The caps are not drawn: a ray may cross a cap first and then a back
// face — unless every cap faces away from the eye, which the view test requires. So the
// first surface a pixel sees is the same with and without the back faces, and with it the
// colour and the depth the lines' visibility reads (render/surface_pass.h). glTF's
// `doubleSided` plays no part: a back face that is never seen first is never seen.
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
    // position), which rasterizes nothing while the pose keeps them together.
    std::vector<int32_t> face_component;
    struct Component {
        // Its faces, each corner the input vertex that stands for its position (below).
        std::vector<glm::uvec3> triangles;
        std::vector<uint32_t> vertices;  // input vertices, one per distinct position
        // The boundary as cycles of input vertices, each running as its faces run along it;
        // a cap is the fan from the cycle's centroid, wound the other way.
        std::vector<std::vector<uint32_t>> holes;
    };
    std::vector<Component> components;
    // Seam copies: every input vertex a face uses, and the one whose position stands for it.
    std::vector<uint32_t> copies, copy_of;
};

[[nodiscard]] ClosedSurfaces find_closed_surfaces(const TriangleMesh& mesh);

// What the view test needs of one pose.
struct ClosedSurfacePose {
    bool welds_hold = true;  // every seam copy still at its vertex's position (no crack opened)
    struct Component {
        glm::vec3 min{0.0f}, max{0.0f};
        bool outward = false;                   // closed volume > 0
        std::vector<glm::vec3> cap_triangles;   // 3 per cap triangle, wound as the surface
    };
    std::vector<Component> components;
};

[[nodiscard]] ClosedSurfacePose pose_closed_surfaces(const ClosedSurfaces& surfaces,
                                                     const std::vector<glm::vec3>& positions);

// Per component, 1 where its back faces are hidden from this view: the pose's welds hold,
// the component is outward, lies wholly beyond the near plane, and no cap faces the eye.
[[nodiscard]] std::vector<uint8_t> back_faces_hidden(const ClosedSurfacePose& pose, const CameraMatrices& camera);

}  // namespace lw
