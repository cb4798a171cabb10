// engine/geometry/curvature.h — normals, principal curvatures and their derivatives.
//
// Input:  a `WeldedMesh` (shared vertices, edge adjacency).
// Output: `SurfaceCurvature` — per vertex: unit normal, Voronoi point area, principal
//         curvatures k1, k2 with directions (pdir1, pdir2, n right-handed), and the
//         curvature-derivative tensor C = (C0, C1, C2, C3) in the (pdir1, pdir2) frame:
//         C0 = dk1/de1 (= C111), C1 = C112 (= dk1/de2), C2 = C122 (= dk2/de1),
//         C3 = dk2/de2 (= C222).
//
// The estimators are Rusinkiewicz 2004, "Estimating curvatures and their derivatives on
// triangle meshes", as trimesh2 implements them (which rtsc, our reference for line
// drawings, is built on): per-face least-squares fits of the second fundamental form from
// normal differences, and of C from curvature-tensor differences, reprojected into vertex
// frames and averaged with Voronoi corner-area weights.
//
// Conventions (all trimesh2's):
//  - Sign: the shape operator is dn, so a sphere with outward normals has k1 = k2 = +1/r;
//    a saddle's inner side (torus hole) has negative curvature across the ring.
//  - Order: by MAGNITUDE, |k1| >= |k2| (not k1 >= k2). A concave dent has k1 < 0.
//  - Frame: pdir2 = n × pdir1, so (pdir1, pdir2, n) is right-handed. The sign of pdir1 is
//    arbitrary (it follows from the vertex's initial frame); C is expressed in the frame as
//    returned, and the other sign would negate pdir1, pdir2 and all four Ci together.
//    Everything rtsc builds from them (kr, DwKr) is invariant under that flip.
//  - Normals: trimesh2's vertex normals (Max 1999 weights), not the file's or the
//    area-weighted ones of `vertex_normals` — curvature is estimated from their differences.
//  - Degenerate input: a vertex no face contributes to gets normal (0,0,1); one with zero
//    Voronoi area (in no face, or only in zero-area ones) gets zero curvature and zero C
//    (trimesh2 would divide 0 by 0 there).
//
// Cost: O(V + F), no per-vertex allocation; about 0.47 s per million triangles on one core
// of the development machine (feature_size: 7 ms more).
// Deterministic: faces are visited in order (trimesh2 uses OpenMP atomics, so its float
// sums may differ from ours in the last bits).
// Recompute after any deformation (skinning): all fields depend on positions only.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "geometry/welded_mesh.h"

namespace lw {

struct SurfaceCurvature {
    std::vector<glm::vec3> normals;
    std::vector<float> point_areas;
    std::vector<glm::vec3> corner_areas;  // per face: the Voronoi area of each corner
    std::vector<glm::vec3> pdir1, pdir2;
    std::vector<float> k1, k2;            // |k1| >= |k2|
    std::vector<glm::vec4> dcurv;  // (C0, C1, C2, C3)
};

struct CurvatureOptions {
    // Newer trimesh2 (e.g. the GitHub copy Forceflow/trimesh2, include/lineqn.h; older
    // copies such as bobye/trimesh2 lack it) factors 3×3 systems with a shortcut whose last pivot reads lower-triangle entries
    // before it writes them; for the curvature fit that pivot becomes Σv² instead of
    // Σv² − (Σuv)²/d1, so its (e, f, g) is not the least-squares solution (and depends on
    // which corner comes first). Older trimesh2 and the paper solve the system exactly,
    // which is the default here. Set this to reproduce an rtsc built on the newer library;
    // measured: k1 low by 7–9 % on a 180×60 torus, 4 % on a cylinder, up to 1.3 % on an
    // icosphere (tests/test_curvature.cpp).
    bool trimesh2_ldlt_shortcut = false;
};

// Vertex normals as trimesh2 computes them: each face's normal weighted, at each corner, by
// sin(angle) / (|e1| |e2|) of the two edges there (Max 1999 — exact for a mesh inscribed
// in a sphere). Unit length; (0,0,1) where no face contributes.
[[nodiscard]] std::vector<glm::vec3> compute_vertex_normals(const WeldedMesh& mesh);

[[nodiscard]] SurfaceCurvature compute_curvature(const WeldedMesh& mesh, const CurvatureOptions& options = {});

// rtsc's feature size: min(0.01 / q, 0.05 × R), where q is the 10th percentile of |k1| and
// |k2| at 500 vertices drawn (with repetition) by rtsc's LCG (randq = 1664525·randq +
// 1013904223 from 0, index randq mod V), all vertices when V < 500, and R is the radius of
// the minimal enclosing sphere of the vertices (trimesh2's bsphere: Miniball, not the box).
// Vertex numbering matters (the draw is by index): it matches rtsc when the file had no
// duplicate positions, since `weld` keeps first-appearance order. 0 for an empty mesh.
[[nodiscard]] float feature_size(const WeldedMesh& mesh, const SurfaceCurvature& curvature);

// The smallest sphere enclosing the points (exact up to rounding; defined in
// bounding_sphere.cpp). Radius 0 and centre 0 for no points.
struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
[[nodiscard]] BoundingSphere minimal_bounding_sphere(const std::vector<glm::vec3>& points);

}  // namespace lw
