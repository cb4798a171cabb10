// engine/lines/occlusion.h — occlusion levels (quantitative invisibility, Appel 1967; the
// "QI" of Freestyle and Line Art): how many surfaces lie between the eye and a point.
//
// Input:  a `LineMesh` pose (its welded triangles), the eye, a point on the surface and the
//         face it lies on.
// Output: the number of distinct surface crossings on the segment from the eye to the point.
//
// Exact by ray casting against the scene's triangles, with Embree's BVH as the spatial index
// (built once per pose, LineMesh::generation; robust mode: watertight triangle tests). Not counted: hits at the point itself
// (the last 1e-3 of the way, where the line's own surface is — a crease or an intersection
// line lies on two faces), and for a point on a contour hits on the faces round the point's
// face (those sharing a vertex with it): a smooth contour lies inside a face where the
// interpolated normal turns away, the ray to it is tangent to the surface there, and it may
// graze the polygons beside it. (Other lines keep those faces: a box's front face is beside
// its side faces and hides their back rim.) A ray through an edge or a vertex hits several
// triangles at one point: hits closer together than 1e-6 of the way count as one crossing.
//
// The visibility stage (visibility.h) asks for a level only where the depth test found a
// sample hidden; this is the only implementation (a CPU ray cast; there is no GPU pass).
// Queries are thread-safe (the visibility stage runs paths on every core).
#pragma once

#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "lines/line_mesh.h"

namespace lw {

class OcclusionCounter {
public:
    OcclusionCounter();
    ~OcclusionCounter();
    OcclusionCounter(OcclusionCounter&&) noexcept;
    OcclusionCounter& operator=(OcclusionCounter&&) noexcept;

    // Builds the index of `mesh`'s pose unless it holds that pose already (its generation).
    void set_mesh(const LineMesh& mesh);
    [[nodiscard]] bool empty() const;

    // Surfaces crossed between `eye` and `point` (on face `face` of the mesh given; on a
    // contour when `contour`).
    [[nodiscard]] uint32_t surfaces_in_front(const glm::vec3& eye, const glm::vec3& point, uint32_t face,
                                             bool contour) const;

private:
    struct Index;
    std::unique_ptr<Index> index_;
    uint64_t generation_ = 0;
};

}  // namespace lw
