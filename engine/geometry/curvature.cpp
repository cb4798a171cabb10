// engine/geometry/curvature.cpp — curvature and its derivative, Rusinkiewicz 2004.
//
// The steps, each as trimesh2 does it (rtsc's lines come from trimesh2's numbers, so we
// keep its choices even where another would do as well):
//   1. vertex normals with Max's weights                      (trimesh2 TriMesh_normals.cc)
//   2. Voronoi corner and point areas                         (TriMesh_pointareas.cc)
//   3. per face, the second fundamental form from the normal differences along its edges,
//      least squares (paper §3); reprojected into each vertex's frame and averaged with
//      corner-area weights (§3); diagonalized                    (TriMesh_curvature.cc)
//   4. the same for the derivative tensor C from curvature-tensor differences (§4)
//   5. rtsc's feature size                                     (rtsc.cc compute_feature_size)
// All arithmetic is in float, like trimesh2's: against a line-by-line transcription of
// those routines, normals, areas, k1, k2 and directions came out bit-identical and C within
// 1e-7 relative (our trilinear form groups its products differently).
#include "geometry/curvature.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lw {

namespace {

using glm::vec3;

int next3(int i) { return i == 2 ? 0 : i + 1; }
int prev3(int i) { return i == 0 ? 2 : i - 1; }

// trimesh2's normalize(): a zero (or NaN) vector becomes +z instead of NaN.
vec3 unit_or_z(const vec3& v) {
    const float len = std::sqrt(glm::dot(v, v));
    if (len > 0.0f) return v * (1.0f / len);
    return vec3(0.0f, 0.0f, 1.0f);
}

// The corners of face f and its edges; edge i is opposite corner i and runs from corner
// i+1 to corner i+2, so edge i and the normal difference n[i+2] − n[i+1] belong together.
struct FaceGeometry {
    uint32_t v[3];
    vec3 e[3];
};

FaceGeometry face_geometry(const WeldedMesh& mesh, size_t f) {
    FaceGeometry g;
    for (int i = 0; i < 3; ++i) g.v[i] = mesh.faces[f][i];
    for (int i = 0; i < 3; ++i) g.e[i] = mesh.positions[g.v[prev3(i)]] - mesh.positions[g.v[next3(i)]];
    return g;
}

// The face's own orthonormal tangent frame: t along edge 0, b = n × t (paper §3).
struct TangentFrame {
    vec3 t, b;
};

TangentFrame face_frame(const FaceGeometry& g) {
    const vec3 t = unit_or_z(g.e[0]);
    const vec3 n = glm::cross(g.e[0], g.e[1]);
    return {t, unit_or_z(glm::cross(n, t))};
}

// Turns the orthonormal tangent frame (u, v) by the smallest rotation that takes its normal
// u × v onto `normal` (Rodrigues' formula, specialised to vectors perpendicular to the old
// normal). Frames of neighbouring vertices and faces are not coplanar; the paper (§3)
// rotates one into the other's plane before comparing tensors. Opposite normals: flip both.
void rotate_frame(const vec3& u, const vec3& v, const vec3& normal, vec3& ru, vec3& rv) {
    const vec3 old_normal = glm::cross(u, v);
    const float cos_angle = glm::dot(old_normal, normal);
    if (cos_angle <= -1.0f) {
        ru = -u;
        rv = -v;
        return;
    }
    const vec3 toward_new = normal - cos_angle * old_normal;  // ⟂ old normal, in the rotation plane
    const vec3 shift = (1.0f / (1.0f + cos_angle)) * (old_normal + normal);
    ru = u - shift * glm::dot(u, toward_new);
    rv = v - shift * glm::dot(v, toward_new);
}

// The axes (a, b) of a target frame, rotated into the source frame's tangent plane and
// written in source coordinates: a = (a_u, a_v), b = (b_u, b_v).
struct FrameChange {
    float au, av, bu, bv;
};

FrameChange frame_change(const vec3& src_u, const vec3& src_v, const vec3& dst_u, const vec3& dst_v) {
    vec3 a, b;
    rotate_frame(dst_u, dst_v, glm::cross(src_u, src_v), a, b);
    return {glm::dot(a, src_u), glm::dot(a, src_v), glm::dot(b, src_u), glm::dot(b, src_v)};
}

// A symmetric 2-tensor (the second fundamental form [ku kuv; kuv kv]) re-expressed in the
// target frame: its entries are II(a, a), II(a, b), II(b, b).
glm::vec3 change_tensor(const FrameChange& m, float ku, float kuv, float kv) {
    auto form = [&](float xu, float xv, float yu, float yv) {
        return ku * xu * yu + kuv * (xu * yv + xv * yu) + kv * xv * yv;
    };
    return {form(m.au, m.av, m.au, m.av), form(m.au, m.av, m.bu, m.bv), form(m.bu, m.bv, m.bu, m.bv)};
}

// The symmetric 3-tensor C = (C111, C112, C122, C222) re-expressed in the target frame:
// C(a,a,a), C(a,a,b), C(a,b,b), C(b,b,b), with C(x,y,z) the trilinear form (paper §4).
glm::vec4 change_tensor(const FrameChange& m, const glm::vec4& c) {
    auto form = [&](float xu, float xv, float yu, float yv, float zu, float zv) {
        return c[0] * xu * yu * zu + c[1] * (xu * yu * zv + xu * yv * zu + xv * yu * zu) +
               c[2] * (xu * yv * zv + xv * yu * zv + xv * yv * zu) + c[3] * xv * yv * zv;
    };
    const float au = m.au, av = m.av, bu = m.bu, bv = m.bv;
    return {form(au, av, au, av, au, av), form(au, av, au, av, bu, bv), form(au, av, bu, bv, bu, bv),
            form(bu, bv, bu, bv, bu, bv)};
}

// LDLᵀ factorisation without square roots of a symmetric positive-definite matrix (Golub &
// Van Loan §4.1.2), the solver trimesh2 applies to the normal equations: reads the upper
// triangle, leaves L·D in the strict lower one and the reciprocal pivots in inv_d. A
// non-positive pivot means a degenerate face; the caller skips it, as trimesh2 does.
template <int N>
bool ldlt_factor(float (&a)[N][N], float (&inv_d)[N]) {
    for (int i = 0; i < N; ++i) {
        float l_row[N];  // row i of L, from L·D and the pivots found so far
        for (int k = 0; k < i; ++k) l_row[k] = a[i][k] * inv_d[k];
        for (int j = i; j < N; ++j) {
            float sum = a[i][j];
            for (int k = 0; k < i; ++k) sum -= l_row[k] * a[j][k];
            if (j > i) {
                a[j][i] = sum;
            } else if (sum > 0.0f) {  // also false for NaN
                inv_d[i] = 1.0f / sum;
            } else {
                return false;
            }
        }
    }
    return true;
}

// Solves A x = rhs in place after ldlt_factor: forward (L D y = rhs), then back (Lᵀ x = y).
template <int N>
void ldlt_solve(const float (&a)[N][N], const float (&inv_d)[N], float (&x)[N]) {
    for (int i = 0; i < N; ++i) {
        float sum = x[i];
        for (int k = 0; k < i; ++k) sum -= a[i][k] * x[k];
        x[i] = sum * inv_d[i];
    }
    for (int i = N - 1; i >= 0; --i) {
        float sum = 0.0f;
        for (int k = i + 1; k < N; ++k) sum += a[k][i] * x[k];
        x[i] -= sum * inv_d[i];
    }
}

// Voronoi area of each corner, clipped to the triangle (Meyer et al. 2003, the weights of
// Rusinkiewicz 2004 §3). Circumcentre inside: the triangle splits into three isosceles
// triangles (circumcentre + an edge), each shared evenly by its edge's two corners; the
// circumcentre's barycentric weights give their areas. Circumcentre outside or on an edge
// (corner i obtuse or right): each other corner keeps the right triangle bounded by its
// edge toward i, that edge's midpoint and perpendicular bisector — |edge|²·tan(angle)/8 —
// and corner i keeps the rest. (This is trimesh2's rule; Meyer's "mixed area" would give
// the obtuse corner half the triangle and the others a quarter each.)
vec3 corner_areas_of(const FaceGeometry& g, float area) {
    const float l2[3] = {glm::dot(g.e[0], g.e[0]), glm::dot(g.e[1], g.e[1]), glm::dot(g.e[2], g.e[2])};
    float circ[3];  // barycentric weights of the circumcentre, ∝ sin 2A_i, up to a factor
    for (int i = 0; i < 3; ++i) circ[i] = l2[i] * (l2[next3(i)] + l2[prev3(i)] - l2[i]);
    vec3 out(0.0f);
    for (int i = 0; i < 3; ++i) {
        if (circ[i] > 0.0f) continue;
        // Corner i is not acute. e[i]·e[j] = −|e_i||e_j|·cos(angle between them).
        const int a = next3(i), b = prev3(i);
        out[a] = -0.25f * l2[b] * area / glm::dot(g.e[i], g.e[b]);
        out[b] = -0.25f * l2[a] * area / glm::dot(g.e[i], g.e[a]);
        out[i] = area - out[a] - out[b];
        return out;
    }
    const float scale = 0.5f * area / (circ[0] + circ[1] + circ[2]);
    for (int i = 0; i < 3; ++i) out[i] = scale * (circ[next3(i)] + circ[prev3(i)]);
    return out;
}

// Corner and point areas; a face of zero area (collinear corners) has zero corner areas.
void compute_areas(const WeldedMesh& mesh, SurfaceCurvature& out) {
    out.point_areas.assign(mesh.positions.size(), 0.0f);
    out.corner_areas.assign(mesh.faces.size(), vec3(0.0f));
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceGeometry g = face_geometry(mesh, f);
        const float area = 0.5f * glm::length(glm::cross(g.e[0], g.e[1]));
        if (!(area > 0.0f)) continue;
        out.corner_areas[f] = corner_areas_of(g, area);
        for (int i = 0; i < 3; ++i) out.point_areas[g.v[i]] += out.corner_areas[f][i];
    }
}

// trimesh2's starting tangent frame per vertex: the edge toward the next corner in the last
// face (in face order) that uses the vertex, turned 90° about the normal. Only the final
// sign of pdir1 depends on it. A vertex in no face (trimesh2 would leave a zero pdir2 there)
// gets some frame perpendicular to its normal instead.
void initial_frames(const WeldedMesh& mesh, SurfaceCurvature& out) {
    const size_t nv = mesh.positions.size();
    out.pdir1.assign(nv, vec3(0.0f));
    out.pdir2.assign(nv, vec3(0.0f));
    for (const glm::uvec3& face : mesh.faces)
        for (int i = 0; i < 3; ++i) out.pdir1[face[i]] = mesh.positions[face[next3(i)]] - mesh.positions[face[i]];
    for (size_t v = 0; v < nv; ++v) {
        const vec3& n = out.normals[v];
        vec3 side = glm::cross(out.pdir1[v], n);
        if (glm::dot(side, side) == 0.0f) side = glm::cross(std::fabs(n.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0), n);
        out.pdir1[v] = unit_or_z(side);
        out.pdir2[v] = glm::cross(n, out.pdir1[v]);
    }
}

// The share of face f's estimate that corner i's vertex receives (§3: corner area over the
// vertex's total Voronoi area).
float corner_weight(const SurfaceCurvature& c, size_t f, int i, uint32_t v) {
    return c.point_areas[v] > 0.0f ? c.corner_areas[f][i] / c.point_areas[v] : 0.0f;
}

// Paper §3: in the face frame (t, b), the second fundamental form [e f; f g] maps each
// edge to the difference of the normals at its ends: II·(e·t, e·b) ≈ (Δn·t, Δn·b). Three
// edges give six equations in (e, f, g); their normal equations are solved by LDLᵀ. The
// result is pushed into each corner's vertex frame with its Voronoi weight.
void accumulate_face_curvatures(const WeldedMesh& mesh, const CurvatureOptions& options, SurfaceCurvature& out,
                                std::vector<glm::vec3>& vertex_tensors) {
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceGeometry g = face_geometry(mesh, f);
        if (out.corner_areas[f] == vec3(0.0f)) continue;  // zero area: no weight anywhere
        const TangentFrame fr = face_frame(g);
        float w[3][3] = {};
        float x[3] = {};
        for (int j = 0; j < 3; ++j) {
            const float u = glm::dot(g.e[j], fr.t), v = glm::dot(g.e[j], fr.b);
            w[0][0] += u * u;
            w[0][1] += u * v;
            w[2][2] += v * v;
            const vec3 dn = out.normals[g.v[prev3(j)]] - out.normals[g.v[next3(j)]];
            const float dnu = glm::dot(dn, fr.t), dnv = glm::dot(dn, fr.b);
            x[0] += dnu * u;
            x[1] += dnu * v + dnv * u;
            x[2] += dnv * v;
        }
        w[1][1] = w[0][0] + w[2][2];  // f appears in both rows of the tensor
        w[1][2] = w[0][1];
        float inv_d[3];
        if (!ldlt_factor(w, inv_d)) continue;
        if (options.trimesh2_ldlt_shortcut) {
            // The newer trimesh2's 3×3 shortcut ends with the pivot w22 itself (see header).
            if (w[2][2] == 0.0f) continue;
            inv_d[2] = 1.0f / w[2][2];
        }
        ldlt_solve(w, inv_d, x);
        for (int i = 0; i < 3; ++i) {
            const uint32_t v = g.v[i];
            const vec3 k = change_tensor(frame_change(fr.t, fr.b, out.pdir1[v], out.pdir2[v]), x[0], x[1], x[2]);
            vertex_tensors[v] += corner_weight(out, f, i, v) * k;
        }
    }
}

// Principal curvatures and directions from the vertex's tensor [ku kuv; kuv kv] in its frame
// (first re-aligned with the normal): one Jacobi rotation by angle θ with t = tan θ the
// smaller root of t² + 2ht − 1 = 0, h = (kv − ku)/(2 kuv) (the stable form, Numerical
// Recipes §11.1). Ordered by magnitude, pdir2 = n × pdir1 — trimesh2's conventions.
void diagonalize(const vec3& u, const vec3& v, const vec3& kt, const vec3& normal, vec3& pdir1, vec3& pdir2,
                 float& k1, float& k2) {
    vec3 ru, rv;
    rotate_frame(u, v, normal, ru, rv);
    const float ku = kt[0], kuv = kt[1], kv = kt[2];
    float c = 1.0f, s = 0.0f, tan_theta = 0.0f;
    if (kuv != 0.0f) {
        const float h = 0.5f * (kv - ku) / kuv;
        const float root = std::sqrt(1.0f + h * h);
        tan_theta = 1.0f / (h < 0.0f ? h - root : h + root);
        c = 1.0f / std::sqrt(1.0f + tan_theta * tan_theta);
        s = tan_theta * c;
    }
    k1 = ku - tan_theta * kuv;  // eigenvalue along c·ru − s·rv
    k2 = kv + tan_theta * kuv;  // eigenvalue along s·ru + c·rv
    if (std::fabs(k1) >= std::fabs(k2)) {
        pdir1 = c * ru - s * rv;
    } else {
        std::swap(k1, k2);
        pdir1 = s * ru + c * rv;
    }
    pdir2 = glm::cross(normal, pdir1);
}

// Paper §4: the same fit one order up. Each corner's diagonal tensor (k1, 0, k2) is
// re-expressed in the face frame; along each edge (u, v) the change of the tensor
// [e f; f g] is modelled as [a u + b v, b u + c v; b u + c v, c u + d v] with
// (a, b, c, d) = C. Least squares over the three edges (the off-diagonal equation counted
// twice, as the tensor has it twice) gives the 4×4 normal equations below.
void accumulate_face_dcurv(const WeldedMesh& mesh, SurfaceCurvature& out) {
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        if (out.corner_areas[f] == vec3(0.0f)) continue;
        const FaceGeometry g = face_geometry(mesh, f);
        const TangentFrame fr = face_frame(g);
        vec3 face_tensor[3];
        for (int j = 0; j < 3; ++j) {
            const uint32_t v = g.v[j];
            face_tensor[j] = change_tensor(frame_change(out.pdir1[v], out.pdir2[v], fr.t, fr.b), out.k1[v], 0.0f,
                                           out.k2[v]);
        }
        float w[4][4] = {};
        float x[4] = {};
        for (int j = 0; j < 3; ++j) {
            const vec3 dk = face_tensor[prev3(j)] - face_tensor[next3(j)];
            const float u = glm::dot(g.e[j], fr.t), v = glm::dot(g.e[j], fr.b);
            w[0][0] += u * u;
            w[0][1] += u * v;
            w[3][3] += v * v;
            x[0] += u * dk[0];
            x[1] += v * dk[0] + 2.0f * u * dk[1];
            x[2] += 2.0f * v * dk[1] + u * dk[2];
            x[3] += v * dk[2];
        }
        w[1][1] = 2.0f * w[0][0] + w[3][3];
        w[1][2] = 2.0f * w[0][1];
        w[2][2] = w[0][0] + 2.0f * w[3][3];
        w[2][3] = w[0][1];
        float inv_d[4];
        if (!ldlt_factor(w, inv_d)) continue;
        ldlt_solve(w, inv_d, x);
        const glm::vec4 c(x[0], x[1], x[2], x[3]);
        for (int i = 0; i < 3; ++i) {
            const uint32_t v = g.v[i];
            out.dcurv[v] += corner_weight(out, f, i, v) * change_tensor(frame_change(fr.t, fr.b, out.pdir1[v], out.pdir2[v]), c);
        }
    }
}

}  // namespace

std::vector<glm::vec3> compute_vertex_normals(const WeldedMesh& mesh) {
    // Max 1999: at each corner the face normal weighs sin(angle)/(|e1||e2|), which makes the
    // average exact for vertices on a sphere. With the unnormalised normal |e1||e2|·sin(angle)·n̂
    // that is one division by |e1|²|e2|². Faces with a zero-length edge are skipped.
    std::vector<vec3> normals(mesh.positions.size(), vec3(0.0f));
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceGeometry g = face_geometry(mesh, f);
        const float l2[3] = {glm::dot(g.e[0], g.e[0]), glm::dot(g.e[1], g.e[1]), glm::dot(g.e[2], g.e[2])};
        if (l2[0] == 0.0f || l2[1] == 0.0f || l2[2] == 0.0f) continue;
        const vec3 face_normal = glm::cross(g.e[2], g.e[0]);  // (p1 − p0) × (p2 − p1)
        for (int i = 0; i < 3; ++i)  // corner i lies between edges i+1 and i+2
            normals[g.v[i]] += face_normal * (1.0f / (l2[next3(i)] * l2[prev3(i)]));
    }
    for (vec3& n : normals) n = unit_or_z(n);
    return normals;
}

SurfaceCurvature compute_curvature(const WeldedMesh& mesh, const CurvatureOptions& options) {
    const size_t nv = mesh.positions.size();
    SurfaceCurvature out;
    out.normals = compute_vertex_normals(mesh);
    compute_areas(mesh, out);
    initial_frames(mesh, out);

    std::vector<vec3> tensors(nv, vec3(0.0f));  // (ku, kuv, kv) in each vertex's initial frame
    accumulate_face_curvatures(mesh, options, out, tensors);
    out.k1.assign(nv, 0.0f);
    out.k2.assign(nv, 0.0f);
    for (size_t v = 0; v < nv; ++v)
        diagonalize(out.pdir1[v], out.pdir2[v], tensors[v], out.normals[v], out.pdir1[v], out.pdir2[v], out.k1[v],
                    out.k2[v]);

    out.dcurv.assign(nv, glm::vec4(0.0f));
    accumulate_face_dcurv(mesh, out);
    return out;
}

float feature_size(const WeldedMesh& mesh, const SurfaceCurvature& curvature) {
    const size_t nv = std::min(mesh.positions.size(), curvature.k1.size());
    if (nv == 0) return 0.0f;
    // rtsc: 500 draws of a 32-bit LCG (Numerical Recipes' constants) from 0, both |k| kept.
    const size_t draws = std::min<size_t>(nv, 500);
    std::vector<float> samples;
    samples.reserve(2 * draws);
    uint32_t state = 0;
    for (size_t i = 0; i < draws; ++i) {
        state = 1664525u * state + 1013904223u;
        const size_t v = state % static_cast<uint32_t>(nv);
        samples.push_back(std::fabs(curvature.k1[v]));
        samples.push_back(std::fabs(curvature.k2[v]));
    }
    const auto which = static_cast<size_t>(0.1f * static_cast<float>(samples.size()));
    std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(which), samples.end());
    const float max_size = 0.05f * minimal_bounding_sphere(mesh.positions).radius;
    // A flat mesh has q = 0 and 0.01/q = inf: the cap applies, as in rtsc.
    return std::min(0.01f / samples[which], max_size);
}

}  // namespace lw
