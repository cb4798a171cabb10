// engine/lines/ridge_lines.h — rtsc's lines at extrema of a curvature along its own
// direction: ridges and valleys, principal highlights and apparent ridges (the plain C++
// reference; shaders/lines_ridges.glsl does the same per face on the GPU).
//
// Input:  a `LineMesh` (curvature, derivative tensor, vertex → face adjacency), per vertex
//         the view's n·v, the eye; for apparent ridges the per-vertex `ApparentArrays`
//         computed here first. Thresholds as LineParams gives them (scaled by fs inside).
// Output: `LineSegment`s appended per face, endpoints keyed by the mesh edge they lie on
//         (kNoKey at a face's centre, where three pieces meet).
//
// Every rule is rtsc 1.6's (docs/research/rtsc-lines.md §6), so that our lines lie on its:
//  - ridges (valleys): faces whose three k1 are > 0 (< 0), not all back-facing, where the
//    derivative of k1 along e1 changes sign across at least two edges (Ohtake et al. 2004);
//    endpoints where it crosses zero, kept where |k1| exceeds rv_thresh / fs, faded by
//    |k1| − thresh over itself;
//  - principal highlights (DeCarlo & Rusinkiewicz 2007): faces whose e1 agree within 45°,
//    where v·e1 changes sign; strength (k1² − k2²)·n·v above ph_thresh / fs²; both rtsc's
//    flavours, on convex (all k1 ≥ 0) and on concave (all k1 ≤ 0) faces;
//  - apparent ridges (Judd, Durand & Adelson 2007, as rtsc computes them): the largest
//    eigenvalue q1 of QᵀQ, Q the view-dependent shape operator, and its derivative along
//    its own direction t1 taken from the neighbouring faces; lines where that derivative
//    changes sign and both sides rise towards the line, q1 above ar_thresh / fs².
//
// This file is compiled with -ffp-contract=off (as extract_reference.cpp) so that the GPU,
// with `precise`, computes the same values.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "lines/line_mesh.h"
#include "lines/line_types.h"

namespace lw {

// A vertex's view-dependent curvature for apparent ridges, as the GPU pass keeps it: q1 (the
// largest eigenvalue of QᵀQ, a squared curvature), its direction t1 in the (e1, e2) frame,
// and D_t1 q1.
struct ApparentVertex {
    float q1;
    float t1x, t1y;
    float dt1q1;
};
static_assert(sizeof(ApparentVertex) == 16, "ApparentVertex must match shaders/lines_shared.glsl");

// What the host's face test reads of a vertex, in one 16-byte load: tmax = D_t1 q1 · t1 in
// world space (rtsc's direction of increasing q1, scaled) and q1.
struct ApparentCorner {
    glm::vec3 tmax;
    float q1;
};
static_assert(sizeof(ApparentCorner) == 16, "ApparentCorner is read as one 16-byte record");

// The same values on the host, an array each (the first pass's loop vectorizes), and the
// corners the face test reads.
struct ApparentArrays {
    std::vector<float> q1, t1x, t1y, dt1q1;
    std::vector<ApparentCorner> corners;
    void resize(size_t vertices) {
        for (std::vector<float>* a : {&q1, &t1x, &t1y, &dt1q1}) a->resize(vertices);
        corners.resize(vertices);
    }
};

// Apparent ridges need two vertex passes: q1 and t1 of vertices [begin, end) first, then
// (once every vertex has them) D_t1 q1 from each vertex's first two neighbouring faces
// where the line along t1 crosses the opposite edge, in face order (rtsc's compute_Dt1q1),
// and the vertex's `ApparentCorner`; zero where no face around the vertex has a corner with
// q1 over `ar_thresh`, as no face test reads it there.
void apparent_curvature(const LineMesh& mesh, const glm::vec3& eye, const float* ndotv, size_t begin, size_t end,
                        ApparentArrays& out);
void apparent_derivative(const LineMesh& mesh, const float* ndotv, float ar_thresh, size_t begin, size_t end,
                         ApparentArrays& inout);

// rtsc's back-face culling: all three corners have n·v ≤ 0.
inline bool back_facing(const float* ndotv, const glm::uvec3& corners) {
    return ndotv[corners.x] <= 0.0f && ndotv[corners.y] <= 0.0f && ndotv[corners.z] <= 0.0f;
}

// One face's lines of each type; `fade`: rtsc's draw_faded.
void ridge_face(const LineMesh& mesh, uint32_t face, const float* ndotv, bool ridge, float rv_thresh, bool fade,
                std::vector<LineSegment>& out);
// Principal highlights read two values per vertex, computed once per view: v·e1 and the
// strength (k1² − k2²)·n·v, v the unit direction to the eye; and a byte per vertex that
// lets most faces be passed over unread (`principal_highlight_candidate`).
void highlight_vertices(const LineMesh& mesh, const glm::vec3& eye, const float* ndotv, float ph_thresh, size_t begin,
                        size_t end, float* along, float* strength, uint8_t* flags);
// Whether a face with these corners' bytes can have a principal highlight: one corner not
// back-facing and one whose strength is not below the threshold (an interpolated strength
// is at most the larger of its ends', to 3 ulp, and below the threshold nothing is drawn).
inline bool principal_highlight_candidate(uint8_t a, uint8_t b, uint8_t c) { return (a | b | c) == 3u; }
// What of a face's principal highlight does not depend on the view, a byte per face:
// kPrincipalConvex / kPrincipalConcave where that flavour may draw (its k1 signs, and e1
// turning by at most 45° from v0's), kPrincipalFlip << i where v_i's e1 is turned.
constexpr uint8_t kPrincipalConvex = 1, kPrincipalConcave = 2, kPrincipalFlip = 4;
[[nodiscard]] std::vector<uint8_t> principal_highlight_shapes(const LineMesh& mesh);
// One face's principal highlights, for a face whose shape has a flavour and whose corners'
// bytes make it a candidate (the caller's tests: rtsc's back-face culling among them).
void principal_highlight_face(const LineMesh& mesh, uint32_t face, uint8_t shape, const float* along,
                              const float* strength, float ph_thresh, bool fade, std::vector<LineSegment>& out);
// Whether a face with these corners can have an apparent ridge: q1 above the threshold at a
// corner, and tmax turning (a dot product ≤ 0) across two of its edges at least. Neither
// test depends on the corner order, so most faces (on FlightHelmet 61 % at the default
// camera) are passed over here, before their strip order is read. (The dot product's
// operations are dot3's in ridge_lines.cpp, in the same order: bit-exact only where the
// caller is compiled with -ffp-contract=off, as extract_reference.cpp is.)
inline bool apparent_ridge_candidate(const ApparentCorner* corners, const glm::uvec3& c, float ar_thresh) {
    const ApparentCorner a = corners[c.x], b = corners[c.y], d = corners[c.z];
    const auto turns = [](const glm::vec3& u, const glm::vec3& v) {
        return int(u.x * v.x + u.y * v.y + u.z * v.z <= 0.0f);
    };
    return !(a.q1 <= ar_thresh && b.q1 <= ar_thresh && d.q1 <= ar_thresh) &&
           turns(a.tmax, b.tmax) + turns(b.tmax, d.tmax) + turns(d.tmax, a.tmax) >= 2;
}
// One face's apparent ridges, for a face that `apparent_ridge_candidate` lets through. No
// back-face culling: rtsc keeps faces that are just back-facing, so that apparent ridges
// reach the contours they end at.
void apparent_ridge_face(const LineMesh& mesh, uint32_t face, const ApparentArrays& apparent, float ar_thresh, bool fade,
                         std::vector<LineSegment>& out);

}  // namespace lw
