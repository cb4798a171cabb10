// Compiled with -ffp-contract=off -fno-math-errno (CMakeLists.txt): see ridge_lines.h.
// Each expression keeps rtsc's order of operations (docs/research/rtsc-lines.md §6), so
// that borderline faces decide as rtsc's do and the GPU (`precise`) gets the same bits.
#include "lines/ridge_lines.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace lw {

namespace {

float dot3(const glm::vec3& a, const glm::vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// trimesh2's in-place normalize: times 1/length; (0, …, 0, 1) for a zero or NaN length.
glm::vec3 unit(glm::vec3 v) {
    const float length = std::sqrt(dot3(v, v));
    if (!(length > 0.0f)) return {0.0f, 0.0f, 1.0f};
    const float inv = 1.0f / length;
    return {v.x * inv, v.y * inv, v.z * inv};
}

// A face as rtsc's loop sees it: its corners in strip order (strip_order.h), v0, v1, v2.
struct StripFace {
    uint32_t face;
    int corner[3];      // face-local number of v0, v1, v2
    uint32_t vertex[3];
};

StripFace strip_face(const LineMesh& lm, uint32_t f) {
    StripFace s{f, {}, {}};
    for (int i = 0; i < 3; ++i) {
        s.corner[i] = strip_corner(lm.strip_corners[f], i);
        s.vertex[i] = lm.mesh.faces[f][s.corner[i]];
    }
    return s;
}

// One ridge-like segment, rtsc's draw_segment_ridge / compute_segment_app_ridge: with
// a = v_r, b = v_(r+1), c = v_(r+2), the line crosses edge a–b where `e` changes sign
// (weights |e|) and goes on to edge b–c, or to the face's centre; the strength `k` is
// interpolated with the same weights, less `thresh`, and a piece below it at both ends is
// dropped. `tmax` (apparent ridges): the test of Judd et al.'s Fig. 6, both sides'
// directions of increase point at the segment. e, k and tmax are per v0, v1, v2.
void ridge_segment(const LineMesh& lm, const StripFace& sf, int r, const float* e, const float* k, float thresh,
                   bool to_center, bool fade, const glm::vec3* tmax, LineType type, std::vector<LineSegment>& out) {
    // The strengths first (most pieces end there), then the points: the same values as
    // rtsc's order gives.
    const int a = r, b = (r + 1) % 3, c = (r + 2) % 3;
    const float w10 = std::fabs(e[a]) / (std::fabs(e[a]) + std::fabs(e[b]));
    const float w01 = 1.0f - w10;
    float k01 = std::fabs(w01 * k[a] + w10 * k[b]);
    float w21 = 0.0f, w12 = 0.0f, k12;
    if (to_center) {
        k12 = std::fabs(k[a] + k[b] + k[c]) / 3.0f;
    } else {
        w21 = std::fabs(e[b]) / (std::fabs(e[b]) + std::fabs(e[c]));
        w12 = 1.0f - w21;
        k12 = std::fabs(w12 * k[b] + w21 * k[c]);
    }
    k01 -= thresh;
    if (k01 < 0.0f) k01 = 0.0f;
    k12 -= thresh;
    if (k12 < 0.0f) k12 = 0.0f;
    if (k01 == 0.0f && k12 == 0.0f) return;
    const glm::vec3 xa = lm.mesh.positions[sf.vertex[a]], xb = lm.mesh.positions[sf.vertex[b]],
                    xc = lm.mesh.positions[sf.vertex[c]];
    const glm::vec3 p01 = w01 * xa + w10 * xb;
    const glm::vec3 p12 = to_center ? (xa + xb + xc) / 3.0f : w12 * xb + w21 * xc;
    // Where e is exactly 0 at both ends of an edge (a symmetric mesh seen symmetrically) the
    // weight is 0/0: rtsc hands GL a NaN vertex, which draws nothing; so do we.
    if (!std::isfinite(p01.x + p01.y + p01.z + p12.x + p12.y + p12.z)) return;
    if (tmax) {
        // perp points from the segment towards b when (v0, v1, v2) winds as the face, away
        // from it when the strip reversed it: rtsc's test, winding and all. (About half the
        // apparent ridge pieces end here: it comes before the rest is filled in.)
        const glm::vec3 normal = 0.5f * glm::cross(xb - xa, xc - xa);
        const glm::vec3 perp = glm::cross(normal, p01 - p12);
        if (dot3(tmax[a], perp) <= 0.0f || dot3(tmax[b], perp) >= 0.0f || dot3(tmax[c], perp) <= 0.0f) return;
    }
    glm::vec3 bary01(0.0f), bary12(1.0f / 3.0f);
    bary01[sf.corner[a]] = w01;
    bary01[sf.corner[b]] = w10;
    uint32_t key12 = kNoKey;  // the centre
    if (!to_center) {
        bary12 = glm::vec3(0.0f);
        bary12[sf.corner[b]] = w12;
        bary12[sf.corner[c]] = w21;
        key12 = uint32_t(lm.mesh.face_edges[sf.face][sf.corner[a]]);  // edge b–c
    }
    float alpha01 = 1.0f, alpha12 = 1.0f;
    if (fade) {  // (an end at 0 with a zero threshold: 0, not rtsc's 0/0)
        alpha01 = k01 > 0.0f ? k01 / (k01 + thresh) : 0.0f;
        alpha12 = k12 > 0.0f ? k12 / (k12 + thresh) : 0.0f;
    }
    out.push_back({.p0 = glm::vec4(p01, alpha01),
                   .p1 = glm::vec4(p12, alpha12),
                   .bary0 = bary01,
                   .bary1 = bary12,
                   .face = sf.face,
                   .type = uint32_t(type),
                   .key0 = uint32_t(lm.mesh.face_edges[sf.face][sf.corner[c]]),  // p01 on edge a–b
                   .key1 = key12});
}

// The crossings of a ridge-like face: an edge "crosses" where the directions of increase
// at its ends point against each other (rtsc: z01, z12, z20); then the segments rtsc draws
// for them — from the two crossed edges, or (all three crossed, `three_to_center`) three
// pieces to the centre; a face crossed on fewer than two edges draws nothing.
void crossed_face(const LineMesh& lm, const StripFace& sf, bool z01, bool z12, bool z20, const float* e, const float* k,
                  float thresh, bool fade, bool three_to_center, const glm::vec3* tmax, LineType type,
                  std::vector<LineSegment>& out) {
    if (int(z01) + int(z12) + int(z20) < 2) return;
    if (!z01) {
        ridge_segment(lm, sf, 1, e, k, thresh, false, fade, tmax, type, out);
    } else if (!z12) {
        ridge_segment(lm, sf, 2, e, k, thresh, false, fade, tmax, type, out);
    } else if (!z20) {
        ridge_segment(lm, sf, 0, e, k, thresh, false, fade, tmax, type, out);
    } else if (three_to_center) {
        ridge_segment(lm, sf, 1, e, k, thresh, true, fade, tmax, type, out);
        ridge_segment(lm, sf, 2, e, k, thresh, true, fade, tmax, type, out);
        ridge_segment(lm, sf, 0, e, k, thresh, true, fade, tmax, type, out);
    }
}


// `condition ? a : b` as bit operations: GCC leaves a float select in a loop as a branch,
// which keeps the loop from vectorizing.
inline float pick(bool condition, float a, float b) {
    const uint32_t mask = 0u - uint32_t(condition);
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) | (std::bit_cast<uint32_t>(b) & ~mask));
}

}  // namespace

// Cloned for AVX2 where the CPU has it, like the base vertex pass (extract_reference.cpp):
// trimesh2's normalize and rtsc's largest_eig_2x2 are written as selects so that the loop
// vectorizes; the operations and their order are rtsc's, so the bits are the same.
__attribute__((target_clones("avx2", "default"))) void apparent_curvature(const LineMesh& lm, const glm::vec3& eye,
                                                                          const float* ndotv, size_t begin, size_t end,
                                                                          ApparentArrays& out) {
    using F = LineVertexArrays::Field;
    const LineVertexArrays& va = lm.vertex_arrays;
    const float *px = va.field(F::Px), *py = va.field(F::Py), *pz = va.field(F::Pz);
    const float *ax = va.field(F::E1x), *ay = va.field(F::E1y), *az = va.field(F::E1z);
    const float *bx = va.field(F::E2x), *by = va.field(F::E2y), *bz = va.field(F::E2z);
    const float *k1 = va.field(F::K1), *k2 = va.field(F::K2);
    float *q1 = out.q1.data(), *t1x = out.t1x.data(), *t1y = out.t1y.data();
    const glm::vec3 e = eye;
#pragma GCC ivdep
    for (size_t i = begin; i < end; ++i) {
        // v: the unit direction to the eye, (0, 0, 1) for a zero or NaN length (`unit`).
        const float dx = e.x - px[i], dy = e.y - py[i], dz = e.z - pz[i];
        const float length = std::sqrt(dx * dx + dy * dy + dz * dz);
        const bool has_length = length > 0.0f;
        const float inv = 1.0f / length;
        const float vx = pick(has_length, dx * inv, 0.0f), vy = pick(has_length, dy * inv, 0.0f),
                    vz = pick(has_length, dz * inv, 1.0f);
        const float u = vx * ax[i] + vy * ay[i] + vz * az[i], w = vx * bx[i] + vy * by[i] + vz * bz[i];
        const float u2 = u * u, w2 = w * w;
        const float csc2 = 1.0f / (u2 + w2);
        // Q = S·P⁻¹ = S + (secθ − 1)·S·ŵŵᵀ, ŵ the unit projected view direction (Judd et al. §3).
        const float sec_minus_1 = 1.0f / std::fabs(ndotv[i]) - 1.0f;
        const float uu = u2 * csc2, uw = u * w * csc2, ww = w2 * csc2;
        const float q11 = k1[i] * (1.0f + sec_minus_1 * uu);
        const float q12 = k1[i] * (sec_minus_1 * uw);
        const float q21 = k2[i] * (sec_minus_1 * uw);
        const float q22 = k2[i] * (1.0f + sec_minus_1 * ww);
        // The eigenvalue of QᵀQ = [m1 m12; m12 m2] of larger magnitude and its unit
        // eigenvector, (0, 1) where that has no length (rtsc's largest_eig_2x2).
        const float m1 = q11 * q11 + q21 * q21, m12 = q11 * q12 + q21 * q22, m2 = q12 * q12 + q22 * q22;
        const float mean = 0.5f * (m1 + m2);
        const float root = std::sqrt(m12 * m12 + 0.25f * ((m2 - m1) * (m2 - m1)));
        const float value = pick(mean > 0.0f, mean + root, mean - root);
        const float vec_x = m2 - value, vec_y = -m12;
        const float vec_length = std::sqrt(vec_x * vec_x + vec_y * vec_y);
        const bool has_direction = vec_length > 0.0f;
        const float vec_inv = 1.0f / vec_length;
        q1[i] = value;
        t1x[i] = pick(has_direction, vec_x * vec_inv, 0.0f);
        t1y[i] = pick(has_direction, vec_y * vec_inv, 1.0f);
    }
}

void apparent_derivative(const LineMesh& lm, const float* ndotv, float ar_thresh, size_t begin, size_t end,
                         ApparentArrays& inout) {
    const SurfaceCurvature& c = lm.curvature;
    const auto& positions = lm.mesh.positions;
    const float* q1_at = inout.q1.data();
    // Whether the line along t1 crosses a face's opposite edge is as good as random from face
    // to face, so a branch per face mispredicts often: the weights of up to kChunk faces are
    // computed first with no branch, then only the crossed ones are read on.
    constexpr uint32_t kChunk = 8;
    for (size_t i = begin; i < end; ++i) {
        const float q1 = q1_at[i];
        // A face is read only if one of its corners has q1 over the threshold
        // (`apparent_ridge_candidate`): where no face around this vertex has, nothing reads
        // the derivative, and most vertices of a model are such (rtsc computes it anyway).
        const uint32_t first = lm.vertex_face_offsets[i], last = lm.vertex_face_offsets[i + 1];
        bool read = !(q1 <= ar_thresh) && first != last;
        for (uint32_t j = first; j < last && !read; ++j)
            read = !(q1_at[lm.vertex_ring[j].x] <= ar_thresh) || !(q1_at[lm.vertex_ring[j].y] <= ar_thresh);
        if (!read) {
            inout.dt1q1[i] = 0.0f;
            inout.corners[i] = {glm::vec3(0.0f), q1};
            continue;
        }
        const glm::vec3 v0 = positions[i];
        const glm::vec3 t1 = inout.t1x[i] * c.pdir1[i] + inout.t1y[i] * c.pdir2[i];
        const glm::vec3 t2 = glm::cross(c.normals[i], t1);
        const float v0_t2 = dot3(v0, t2);
        float derivative = 0.0f;
        int estimates = 0;
        for (uint32_t j0 = first; j0 < last && estimates < 2; j0 += kChunk) {
            const uint32_t n = std::min(kChunk, last - j0);
            float weight[kChunk];
            uint32_t crossed = 0;
            for (uint32_t k = 0; k < n; ++k) {
                // The point p on the opposite edge v1–v2 that lies along t1 from v0: at w1.
                const glm::uvec2 edge = lm.vertex_ring[j0 + k];
                const float v1_t2 = dot3(positions[edge.x], t2), v2_t2 = dot3(positions[edge.y], t2);
                const float w1 = (v2_t2 - v0_t2) / (v2_t2 - v1_t2);
                weight[k] = w1;
                crossed |= (uint32_t(!(w1 < 0.0f)) & uint32_t(!(w1 >= 1.0f))) << k;  // infinities fail; NaN passes, as in rtsc
            }
            for (; crossed != 0 && estimates < 2; crossed &= crossed - 1) {  // a line leaves through two faces at most
                const uint32_t k = uint32_t(std::countr_zero(crossed));
                const glm::uvec2 edge = lm.vertex_ring[j0 + k];
                const float w1 = weight[k], w2 = 1.0f - w1;
                const glm::vec3 p = w1 * positions[edge.x] + w2 * positions[edge.y];
                const float q1_p = w1 * q1_at[edge.x] + w2 * q1_at[edge.y];
                // The derivative along the projected (screen) direction: distances shrink by |n·v|.
                float distance = dot3(p - v0, t1);
                distance *= std::fabs(ndotv[i]);
                derivative += (q1_p - q1) / distance;
                ++estimates;
            }
        }
        if (estimates == 2) derivative *= 0.5f;
        inout.dt1q1[i] = derivative;
        inout.corners[i] = {derivative * t1, q1};
    }
}

void ridge_face(const LineMesh& lm, uint32_t f, const float* ndotv, bool ridge, float thresh, bool fade,
                std::vector<LineSegment>& out) {
    const StripFace sf = strip_face(lm, f);
    if (back_facing(ndotv, lm.mesh.faces[f])) return;
    const float* k1 = lm.curvature.k1.data();
    const float k[3] = {k1[sf.vertex[0]], k1[sf.vertex[1]], k1[sf.vertex[2]]};
    if (ridge ? (k[0] <= 0.0f || k[1] <= 0.0f || k[2] <= 0.0f) : (k[0] >= 0.0f || k[1] >= 0.0f || k[2] >= 0.0f)) return;
    // e1 turned towards increasing k1 (decreasing for valleys): an edge crosses the line
    // where its ends' turned directions oppose (Ohtake et al. 2004).
    const float sign = ridge ? 1.0f : -1.0f;
    float e[3];
    glm::vec3 tmax[3], x[3];
    for (int i = 0; i < 3; ++i) {
        e[i] = lm.curvature.dcurv[sf.vertex[i]].x;
        tmax[i] = (sign * e[i]) * lm.curvature.pdir1[sf.vertex[i]];
        x[i] = lm.mesh.positions[sf.vertex[i]];
    }
    bool z01 = dot3(tmax[0], tmax[1]) <= 0.0f, z12 = dot3(tmax[1], tmax[2]) <= 0.0f, z20 = dot3(tmax[2], tmax[0]) <= 0.0f;
    if (int(z01) + int(z12) + int(z20) < 2) return;
    // The right kind of extremum: along each crossed edge k1 rises into it from one end.
    z01 = z01 && (dot3(tmax[0], x[1] - x[0]) >= 0.0f || dot3(tmax[1], x[1] - x[0]) <= 0.0f);
    z12 = z12 && (dot3(tmax[1], x[2] - x[1]) >= 0.0f || dot3(tmax[2], x[2] - x[1]) <= 0.0f);
    z20 = z20 && (dot3(tmax[2], x[0] - x[2]) >= 0.0f || dot3(tmax[0], x[0] - x[2]) <= 0.0f);
    crossed_face(lm, sf, z01, z12, z20, e, k, thresh, fade, true, nullptr, ridge ? LineType::Ridge : LineType::Valley, out);
}

namespace {

// Not below the threshold (NaN included, which rtsc does not pass over either), with the
// margin of principal_highlight_candidate.
bool strong(float strength, float thresh) { return !(std::fabs(strength) < thresh * 0.999999f); }

}  // namespace

void highlight_vertices(const LineMesh& lm, const glm::vec3& eye, const float* ndotv, float thresh, size_t begin,
                        size_t end, float* along, float* strength, uint8_t* flags) {
    const SurfaceCurvature& c = lm.curvature;
    for (size_t i = begin; i < end; ++i) {
        const glm::vec3 view = unit(eye - lm.mesh.positions[i]);
        along[i] = dot3(view, c.pdir1[i]);  // v·e1: zero where the view looks down e2
        strength[i] = dot3((c.k1[i] * c.k1[i] - c.k2[i] * c.k2[i]) * view, c.normals[i]);
        flags[i] = uint8_t(unsigned(!(ndotv[i] <= 0.0f)) | unsigned(strong(strength[i], thresh)) << 1);
    }
}

std::vector<uint8_t> principal_highlight_shapes(const LineMesh& lm) {
    const SurfaceCurvature& c = lm.curvature;
    std::vector<uint8_t> shapes(lm.mesh.faces.size());
    for (uint32_t f = 0; f < shapes.size(); ++f) {
        const StripFace sf = strip_face(lm, f);
        const uint32_t* v = sf.vertex;
        // Each e1 turned to agree with v0's (strip order: rtsc's "largest |k1|" comment
        // notwithstanding, it takes v0's); none may turn by more than 45°.
        const glm::vec3 reference = c.pdir1[v[0]];
        bool agree = true;
        uint8_t shape = 0;
        for (int i = 0; i < 3; ++i) {
            float agreement = dot3(c.pdir1[v[i]], reference);
            if (agreement < 0.0f) {
                agreement = -agreement;
                shape |= uint8_t(kPrincipalFlip << i);
            }
            // rtsc: give up where the dot product is below √½ (a double): for a float that
            // is ≤ the float just below √½ (shaders/lines_ridges.glsl compares the same).
            agree = agree && !(agreement <= 0.70710677f);
        }
        const float k[3] = {c.k1[v[0]], c.k1[v[1]], c.k1[v[2]]};
        // rtsc's two flavours, its "ridge" and its "valley" pass.
        if (agree && !(std::min({k[0], k[1], k[2]}) < 0.0f)) shape |= kPrincipalConvex;
        if (agree && !(std::max({k[0], k[1], k[2]}) > 0.0f)) shape |= kPrincipalConcave;
        shapes[f] = shape;
    }
    return shapes;
}

void principal_highlight_face(const LineMesh& lm, uint32_t f, uint8_t shape, const float* along_e1,
                              const float* strength_at, float thresh, bool fade, std::vector<LineSegment>& out) {
    const StripFace sf = strip_face(lm, f);
    // v·(−e1) is −(v·e1) to the bit, so turning e1 turns the vertex's value.
    float along[3], strength[3];
    for (int i = 0; i < 3; ++i) {
        along[i] = shape & (kPrincipalFlip << i) ? -along_e1[sf.vertex[i]] : along_e1[sf.vertex[i]];
        strength[i] = strength_at[sf.vertex[i]];
    }
    const bool z01 = along[0] * along[1] <= 0.0f, z12 = along[1] * along[2] <= 0.0f, z20 = along[2] * along[0] <= 0.0f;
    for (const uint8_t flavour : {kPrincipalConvex, kPrincipalConcave})  // both where every k1 is 0, as in rtsc
        if (shape & flavour)
            crossed_face(lm, sf, z01, z12, z20, along, strength, thresh, fade, false, nullptr, LineType::PrincipalHighlight,
                         out);
}

void apparent_ridge_face(const LineMesh& lm, uint32_t f, const ApparentArrays& apparent, float thresh, bool fade,
                         std::vector<LineSegment>& out) {
    const ApparentCorner* corners = apparent.corners.data();
    const StripFace sf = strip_face(lm, f);
    float k[3], e[3];
    glm::vec3 tmax[3];
    for (int i = 0; i < 3; ++i) {
        k[i] = corners[sf.vertex[i]].q1;
        e[i] = apparent.dt1q1[sf.vertex[i]];
        tmax[i] = corners[sf.vertex[i]].tmax;
    }
    const bool z01 = dot3(tmax[0], tmax[1]) <= 0.0f, z12 = dot3(tmax[1], tmax[2]) <= 0.0f,
               z20 = dot3(tmax[2], tmax[0]) <= 0.0f;
    crossed_face(lm, sf, z01, z12, z20, e, k, thresh, fade, true, tmax, LineType::ApparentRidge, out);
}

}  // namespace lw
