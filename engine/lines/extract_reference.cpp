// Compiled with -ffp-contract=off -fno-math-errno (CMakeLists.txt): see view_quantities.h.
//
// Two passes, laid out for memory speed (issue 22):
//   1. per vertex, over `LineVertexArrays` (structure of arrays, one vectorized loop): n·v,
//      kr and the suggestive test's numerator into arrays, and a byte of signs per vertex;
//   2. per block of faces: the three corners' sign bytes decide whether a line can cross
//      each face (most faces: none; face_scan.h), and only those faces read the values and
//      positions.
#include "lines/extract_reference.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <optional>

#include "core/parallel.h"
#include "lines/face_scan.h"
#include "lines/view_quantities.h"

namespace lw {

ScaledThresholds scaled_thresholds(const LineParams& params, float feature_size) {
    const float fs2 = feature_size * feature_size;
    return {params.sug_thresh / fs2,      params.fade ? params.fade_thresh / fs2 : 0.0f, params.rv_thresh / feature_size,
            params.ar_thresh / fs2,       params.sh_thresh / fs2,                         params.ph_thresh / fs2};
}

namespace {

// Pass 1 over vertices [begin, end). Cloned for AVX2, chosen at load time where the CPU has
// it: 8 vertices an instruction instead of 4, the same IEEE operations (no FMA) and so the
// same bits. `kHighlights`: also suggestive highlights' test numerator −num1 − sh_thresh·n·v
// (rtsc-lines.md §1), from the same num1 — a loop of its own, as a test inside the loop
// would keep it from vectorizing.
template <bool kHighlights>
[[gnu::always_inline]] inline void vertex_loop(const LineVertexArrays& va, const glm::vec3& eye, float sug_thresh,
                                               float sh_thresh, size_t begin, size_t end, ExtractWorkspace& ws) {
    using F = LineVertexArrays::Field;
    const float *px = va.field(F::Px), *py = va.field(F::Py), *pz = va.field(F::Pz);
    const float *nx = va.field(F::Nx), *ny = va.field(F::Ny), *nz = va.field(F::Nz);
    const float *ax = va.field(F::E1x), *ay = va.field(F::E1y), *az = va.field(F::E1z);
    const float *bx = va.field(F::E2x), *by = va.field(F::E2y), *bz = va.field(F::E2z);
    const float *k1 = va.field(F::K1), *k2 = va.field(F::K2);
    const float *c0 = va.field(F::C0), *c1 = va.field(F::C1), *c2 = va.field(F::C2), *c3 = va.field(F::C3);
    float* ndotv = ws.ndotv.data();
    float* kr = ws.kr.data();
    float* test_num = ws.test_num.data();
    float* highlight = ws.highlight_num.data();
    uint8_t* signs = ws.signs.data();
    const glm::vec3 e = eye;
    // The outputs overlap no input (the workspace's own arrays): no alias checks needed.
#pragma GCC ivdep
    for (size_t i = begin; i < end; ++i) {
        const VertexView v = vertex_view({px[i], py[i], pz[i]}, {nx[i], ny[i], nz[i]}, {ax[i], ay[i], az[i]},
                                         {bx[i], by[i], bz[i]}, k1[i], k2[i], {c0[i], c1[i], c2[i], c3[i]}, e, sug_thresh);
        ndotv[i] = v.ndotv;
        kr[i] = v.kr;
        test_num[i] = v.test_num;
        signs[i] = sign_byte(v.ndotv, v.kr, v.test_num);
        if constexpr (kHighlights) highlight[i] = -v.num1 - sh_thresh * v.ndotv;
    }
}

__attribute__((target_clones("avx2", "default"))) void vertex_pass(const LineVertexArrays& va, const glm::vec3& eye,
                                                                   float sug_thresh, size_t begin, size_t end,
                                                                   ExtractWorkspace& ws) {
    vertex_loop<false>(va, eye, sug_thresh, 0.0f, begin, end, ws);
}

__attribute__((target_clones("avx2", "default"))) void vertex_pass_with_highlights(const LineVertexArrays& va,
                                                                                   const glm::vec3& eye, float sug_thresh,
                                                                                   float sh_thresh, size_t begin,
                                                                                   size_t end, ExtractWorkspace& ws) {
    vertex_loop<true>(va, eye, sug_thresh, sh_thresh, begin, end, ws);
}

// Pass 1, with or without suggestive highlights' numerator.
void vertex_passes(const LineVertexArrays& va, const glm::vec3& eye, const LineParams& params,
                   const ScaledThresholds& t, size_t begin, size_t end, ExtractWorkspace& ws) {
    if (params.suggestive_highlights)
        vertex_pass_with_highlights(va, eye, t.sug_thresh, t.sh_thresh, begin, end, ws);
    else
        vertex_pass(va, eye, t.sug_thresh, begin, end, ws);
}

// The facing of faces [begin, end) from their corners, and (kKeep, a pose's second view)
// each face's n = (x1 − x0) × (x2 − x0) and x0 kept for its later views
// (ExtractWorkspace::FacePlanes): the values facing_pass reads, in the same operations.
template <bool kKeep>
void facing_from_corners(const LineMesh& lm, const glm::vec3& eye, size_t begin, size_t end,
                         ExtractWorkspace::FacePlanes& planes, uint8_t* front) {
    const auto& x = lm.mesh.positions;
    for (size_t f = begin; f < end; ++f) {
        const glm::uvec3 c = lm.mesh.faces[f];
        const glm::vec3 x0 = x[c.x], a = x[c.y] - x0, b = x[c.z] - x0, v = eye - x0;
        const float nx = a.y * b.z - a.z * b.y, ny = a.z * b.x - a.x * b.z, nz = a.x * b.y - a.y * b.x;
        if constexpr (kKeep) {
            planes.nx[f] = nx;
            planes.ny[f] = ny;
            planes.nz[f] = nz;
            planes.x0[f] = x0.x;
            planes.y0[f] = x0.y;
            planes.z0[f] = x0.z;
        }
        front[f] = uint8_t(nx * v.x + ny * v.y + nz * v.z > 0.0f);
    }
}

// Whether faces [begin, end) face the eye, for mesh contours: n · (eye − x0) > 0 from the
// pose's arrays, a loop GCC vectorizes (no FMA: -ffp-contract=off, so each lane gives the
// GPU's bits). Per view it reads 24 bytes a face in order, where computing n read three
// corners through the face's indices.
__attribute__((target_clones("avx2", "default"))) void facing_pass(const ExtractWorkspace::FacePlanes& p,
                                                                   const glm::vec3& eye, size_t begin, size_t end,
                                                                   uint8_t* front) {
    // (restrict: `front` is bytes, which may alias anything; without it GCC checks at run time.)
    const float *__restrict nx = p.nx.data(), *__restrict ny = p.ny.data(), *__restrict nz = p.nz.data();
    const float *__restrict x0 = p.x0.data(), *__restrict y0 = p.y0.data(), *__restrict z0 = p.z0.data();
    uint8_t* __restrict out = front;
    const float ex = eye.x, ey = eye.y, ez = eye.z;
    for (size_t f = begin; f < end; ++f) {
        const float vx = ex - x0[f], vy = ey - y0[f], vz = ez - z0[f];
        out[f] = uint8_t(nx[f] * vx + ny[f] * vy + nz[f] * vz > 0.0f);
    }
}

// Once every share is filled, the arrays hold the pose.
void planes_filled(const LineMesh& lm, ExtractWorkspace::FacePlanes& planes) {
    if (planes.use != ExtractWorkspace::FacePlanes::Use::Fill) return;
    planes.use = ExtractWorkspace::FacePlanes::Use::Stream;
    planes.generation = lm.generation;
}

// The per-vertex values only rtsc's optional lines read, over vertices [begin, end) (and
// the facing of the faces in the same share of the face list, for mesh contours):
// apparent ridges' q1 and t1 (their derivative needs every vertex's: a second pass) and
// principal highlights' v·e1 and strength. (Suggestive highlights': in vertex_pass.)
void optional_vertex_pass(const LineMesh& lm, const glm::vec3& eye, const LineParams& params,
                          const ScaledThresholds& thresholds, size_t begin, size_t end, ExtractWorkspace& ws) {
    if (params.apparent_ridges) apparent_curvature(lm, eye, ws.ndotv.data(), begin, end, ws.apparent);
    if (params.silhouettes && params.contours != ContourMode::Smooth) {
        const size_t nv = std::max<size_t>(1, lm.vertex_arrays.count), faces = lm.mesh.faces.size();
        const size_t first = faces * begin / nv, last = faces * end / nv;
        using Use = ExtractWorkspace::FacePlanes::Use;
        switch (ws.face_planes.use) {
            case Use::Corners: facing_from_corners<false>(lm, eye, first, last, ws.face_planes, ws.front.data()); break;
            case Use::Fill: facing_from_corners<true>(lm, eye, first, last, ws.face_planes, ws.front.data()); break;
            case Use::Stream: facing_pass(ws.face_planes, eye, first, last, ws.front.data()); break;
        }
    }
    if (params.principal_highlights)
        highlight_vertices(lm, eye, ws.ndotv.data(), thresholds.ph_thresh, begin, end, ws.principal_along.data(),
                           ws.principal_strength.data(), ws.principal_flags.data());
}

// Whether this view reads the ridges (kind 0) or valleys (1) from the cache, filling it on
// the second view of a pose (and threshold): the first finds them face by face.
void prepare_ridge_cache(const LineMesh& lm, const LineParams& params, int kind, float thresh, size_t block_faces,
                         ExtractWorkspace::RidgeCache& cache) {
    const ExtractWorkspace::RidgeCache::Key key{lm.generation, thresh, params.fade};
    cache.use = holds_pose(cache.filled.generation, lm) && key == cache.filled;
    if (cache.use) return;
    if (!holds_pose(cache.seen.generation, lm) || !(key == cache.seen)) {
        cache.seen = key;
        return;
    }
    const std::vector<float> front(lm.mesh.positions.size(), 1.0f);  // every n·v > 0: nothing culled
    cache.segments.clear();
    cache.block_start.clear();
    for (size_t f = 0; f < lm.mesh.faces.size(); ++f) {
        if (f % block_faces == 0) cache.block_start.push_back(uint32_t(cache.segments.size()));
        ridge_face(lm, uint32_t(f), front.data(), kind == 0, thresh, params.fade, cache.segments);
    }
    cache.block_start.push_back(uint32_t(cache.segments.size()));
    cache.filled = key;
    cache.use = true;
}

// The edge opposite corner i of face f as a segment, its ends keyed `key0`, `key1`.
void edge_segment(const LineMesh& lm, uint32_t f, int i, LineType type, uint32_t key0, uint32_t key1,
                  std::vector<LineSegment>& out) {
    const glm::uvec3 corners = lm.mesh.faces[f];
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    LineSegment& s = out.emplace_back();  // value-initialized: zeros, other_face kNoFace
    s.p0 = glm::vec4(lm.mesh.positions[corners[j]], 1.0f);
    s.p1 = glm::vec4(lm.mesh.positions[corners[k]], 1.0f);
    s.bary0[j] = 1.0f;
    s.bary1[k] = 1.0f;
    s.face = f;
    s.type = uint32_t(type);
    s.key0 = key0;
    s.key1 = key1;
}

// A face's mesh contours: its edges to neighbours that do not face the eye.
void mesh_contour_face(const LineMesh& lm, uint32_t f, const uint8_t* front, std::vector<LineSegment>& out) {
    const auto facing = [&](uint32_t g) { return front[g] != 0; };
    for (int i = 0; i < 3; ++i) {
        const int g = lm.mesh.face_neighbors[f][i];
        if (g < 0 || front[g]) continue;
        edge_segment(lm, f, i, LineType::Silhouette, mesh_contour_key(lm, f, (i + 1) % 3, facing),
                     mesh_contour_key(lm, f, (i + 2) % 3, facing), out);
    }
}

// rtsc's face tests for the suggestive highlight, as for the suggestive contour
// (rtsc-lines.md §2.1–2.2) with its own test: kr changes sign, not all back-facing, and
// the test is not failed at all three corners.
bool highlight_candidate(const glm::uvec3& c, const ExtractWorkspace& ws) {
    const unsigned any = ws.signs[c.x] | ws.signs[c.y] | ws.signs[c.z];
    constexpr unsigned kNeeded = SIGN_KR_POSITIVE | SIGN_KR_NEGATIVE | SIGN_NOT_BACK_FACING;
    if ((any & kNeeded) != kNeeded) return false;
    const auto below = [&](uint32_t v) { return ws.highlight_num[v] <= 0.0f && ws.ndotv[v] >= 0.0f; };
    const auto above = [&](uint32_t v) { return ws.highlight_num[v] >= 0.0f && ws.ndotv[v] <= 0.0f; };
    return !(below(c.x) && below(c.y) && below(c.z)) && !(above(c.x) && above(c.y) && above(c.z));
}

// One face's isoline, rtsc's draw_face_isoline + draw_face_isoline2 (rtsc-lines.md §2.2–2.3):
// the zero set of `val` through the face, trimmed where num/den (num alone without a
// denominator) changes sign, faded by `fade`. The values are read from the per-vertex
// arrays by corner; the corners are turned once so that the lone one comes first.
template <bool kHasDen>
void face_isoline(const LineMesh& lm, uint32_t f, const float* val, const float* num, const float* den, float fade,
                  LineType type, std::vector<LineSegment>& out) {
    const glm::uvec3 corner = lm.mesh.faces[f];
    const float v0 = val[corner.x], v1 = val[corner.y], v2 = val[corner.z];
    // Lone vertex a: the one whose sign differs; zeros count with the other side. Bitwise
    // operators, not && and ||: which corner is alone is anyone's guess, and a mispredicted
    // branch costs more than evaluating every comparison.
    const auto alone = [](float i, float j, float k) {
        return ((i < 0.0f) & (j >= 0.0f) & (k >= 0.0f)) | ((i > 0.0f) & (j <= 0.0f) & (k <= 0.0f));
    };
    const int a = alone(v0, v1, v2) ? 0 : alone(v1, v2, v0) ? 1 : 2;
    // Corners a, b = a + 1, c = a + 2 (mod 3), and the face's edge opposite each.
    const glm::ivec3 opposite = lm.mesh.face_edges[f];
    const uint32_t ia = a == 0 ? corner.x : a == 1 ? corner.y : corner.z;
    const uint32_t ib = a == 0 ? corner.y : a == 1 ? corner.z : corner.x;
    const uint32_t ic = a == 0 ? corner.z : a == 1 ? corner.x : corner.y;
    const uint32_t edge_ab = uint32_t(a == 0 ? opposite.z : a == 1 ? opposite.x : opposite.y);  // opposite c
    const uint32_t edge_ac = uint32_t(a == 0 ? opposite.y : a == 1 ? opposite.z : opposite.x);  // opposite b

    const glm::vec3 xa = lm.mesh.positions[ia], xb = lm.mesh.positions[ib], xc = lm.mesh.positions[ic];
    // Crossings on edges a–b and a–c, measured from a.
    const float va = val[ia];
    const float s_ab = va / (va - val[ib]);
    const float s_ac = va / (va - val[ic]);
    const glm::vec3 p1 = (1.0f - s_ab) * xa + s_ab * xb;
    const glm::vec3 p2 = (1.0f - s_ac) * xa + s_ac * xc;
    // Their barycentric coordinates in the face's own corner order.
    const float ra = 1.0f - s_ab, rc = 1.0f - s_ac;
    const glm::vec3 bary1 = a == 0 ? glm::vec3(ra, s_ab, 0.0f) : a == 1 ? glm::vec3(0.0f, ra, s_ab) : glm::vec3(s_ab, 0.0f, ra);
    const glm::vec3 bary2 = a == 0 ? glm::vec3(rc, 0.0f, s_ac) : a == 1 ? glm::vec3(s_ac, rc, 0.0f) : glm::vec3(0.0f, s_ac, rc);

    // The test at both ends, numerator and denominator interpolated separately.
    const float n1 = (1.0f - s_ab) * num[ia] + s_ab * num[ib];
    const float n2 = (1.0f - s_ac) * num[ia] + s_ac * num[ic];
    const float d1 = kHasDen ? (1.0f - s_ab) * den[ia] + s_ab * den[ib] : 1.0f;
    const float d2 = kHasDen ? (1.0f - s_ac) * den[ia] + s_ac * den[ic] : 1.0f;
    const bool valid1 = (n1 >= 0.0f) == (d1 >= 0.0f);
    float z1 = (n1 >= 0.0f) != (n2 >= 0.0f) ? n1 / (n1 - n2) : 0.0f;
    float z2 = (d1 >= 0.0f) != (d2 >= 0.0f) ? d1 / (d1 - d2) : 0.0f;
    if (z1 == 0.0f) {
        z1 = z2;
        z2 = 0.0f;
    } else if (z2 != 0.0f && z2 < z1) {
        std::swap(z1, z2);
    }

    // Points along P1 → P2 where the test holds, paired into segments (GL_LINES semantics):
    // P1 itself where the test holds there, the test's zero crossings between, P2 unless the
    // pieces already pair up. As rtsc, P1 and P2 are emitted as computed, not re-interpolated.
    const auto alpha = [&](float n, float d) {
        // rtsc: alpha = N / (D·fade + N), clamped by GL; no fading means full opacity.
        return fade > 0.0f ? std::clamp(n / (d * fade + n), 0.0f, 1.0f) : 1.0f;
    };
    if (valid1 && z1 == 0.0f) {  // the test holds all along (most faces): P1 to P2
        out.push_back({.p0 = glm::vec4(p1, alpha(n1, d1)),
                       .p1 = glm::vec4(p2, alpha(n2, d2)),
                       .bary0 = bary1,
                       .bary1 = bary2,
                       .face = f,
                       .type = uint32_t(type),
                       .key0 = edge_ab,
                       .key1 = edge_ac});
        return;
    }
    struct Point {
        glm::vec4 position;
        glm::vec3 bary;
        uint32_t key;
    };
    std::array<Point, 4> points;
    int count = 0;
    const auto inside = [&](float z) {  // 0 < z < 1
        const float n = (1.0f - z) * n1 + z * n2;
        const float d = (1.0f - z) * d1 + z * d2;
        points[size_t(count++)] = {glm::vec4((1.0f - z) * p1 + z * p2, alpha(n, d)), (1.0f - z) * bary1 + z * bary2, kNoKey};
    };
    if (valid1) points[size_t(count++)] = {glm::vec4(p1, alpha(n1, d1)), bary1, edge_ab};
    if (z1 != 0.0f) inside(z1);
    if (z2 != 0.0f) inside(z2);
    if (count != 2) points[size_t(count++)] = {glm::vec4(p2, alpha(n2, d2)), bary2, edge_ac};
    for (int i = 0; i + 1 < count; i += 2) {
        const Point& from = points[size_t(i)];
        const Point& to = points[size_t(i + 1)];
        out.push_back({.p0 = from.position,
                       .p1 = to.position,
                       .bary0 = from.bary,
                       .bary1 = to.bary,
                       .face = f,
                       .type = uint32_t(type),
                       .key0 = from.key,
                       .key1 = to.key});
    }
}

void feature_edges(const LineMesh& lm, uint32_t f, uint32_t mask, const LineParams& params, std::vector<LineSegment>& out) {
    const glm::uvec3 corners = lm.mesh.faces[f];
    const auto edge = [&](int i, LineType type) {  // keyed by its vertices
        edge_segment(lm, f, i, type, corners[(i + 1) % 3], corners[(i + 2) % 3], out);
    };
    for (int i = 0; i < 3; ++i) {
        const bool crease = params.creases && (mask & (kCreaseBit << i));
        const bool border = params.borders && (mask & (kBorderBit << i));
        if (crease || border) edge(i, border ? LineType::Border : LineType::Crease);
        // An edge between parts is also a boundary (a set may select either nature).
        if (params.material_boundaries && (mask & (kPartBoundaryBit << i))) edge(i, LineType::MaterialBoundary);
    }
}

// The face blocks not yet taken, [front, back), taken from either end by a team's members.
class BlockEnds {
public:
    explicit BlockEnds(size_t blocks) : ends_(pack(0, uint32_t(blocks))) {}
    std::optional<size_t> take_front() { return take(true); }
    std::optional<size_t> take_back() { return take(false); }
    // Once all are taken: the first block taken from the back (the blocks' count if none was).
    size_t front() const { return ends_.load() & 0xffffffffu; }

private:
    static uint64_t pack(uint32_t front, uint32_t back) { return uint64_t(back) << 32 | front; }
    std::optional<size_t> take(bool from_front) {
        uint64_t ends = ends_.load();
        for (;;) {
            const auto front = uint32_t(ends), back = uint32_t(ends >> 32);
            if (front == back) return std::nullopt;
            const uint64_t next = from_front ? pack(front + 1, back) : pack(front, back - 1);
            if (ends_.compare_exchange_weak(ends, next)) return from_front ? front : back - 1;
        }
    }
    std::atomic<uint64_t> ends_;
};

// Faces are taken in blocks of this many, whatever the thread count, so that the output
// order is the same for any count.
constexpr size_t kBlockFaces = 1024;
// A team has at most faces / this many members (one below twice this). A team costs a few
// microseconds (fork, join, two or three barriers; 8.5 us more until worker_count() stopped
// reading /sys at every call). With two threads from 8192 faces, a 13k-face mesh (0.07 ms a
// view) runs 1.7-1.8x faster; 3-6k-face meshes would gain only 1.15-1.44x, and a frame's
// second core is often busy with lavapipe's threads. The blocks, and so the output, do not
// change with the count.
constexpr size_t kMinFacesPerThread = 4096;

// Pass 2 over one block of faces [begin, end), appending to `out`. First the faces a line
// may cross, from the sign bytes alone (face_scan.h); then each list's faces, one line type
// at a time, so that the branches inside an isoline see one kind of face. Segments come out
// by type, each type in face order (chaining orders them canonically: chaining.h).
void face_pass(const LineMesh& lm, const ExtractWorkspace& ws, const LineParams& params,
               const ScaledThresholds& t, uint32_t begin, uint32_t end, std::vector<LineSegment>& out) {
    const float fade = t.fade;
    const glm::uvec3* faces = lm.mesh.faces.data();
    const uint32_t* feature_masks = lm.feature_edges.data();
    const bool features = params.creases || params.borders || params.material_boundaries;
    std::array<uint32_t, kBlockFaces + 8> suggestive, contour;  // + 8: the scan writes past its counts
    const FaceCandidates n = scan_faces(faces, begin, end, ws.signs.data(), suggestive.data(), contour.data());

    const float *ndotv = ws.ndotv.data(), *kr = ws.kr.data(), *test_num = ws.test_num.data();
    if (params.suggestive)
        for (size_t i = 0; i < n.suggestive; ++i)
            face_isoline<true>(lm, suggestive[i], kr, test_num, ndotv, fade, LineType::Suggestive, out);
    if (params.silhouettes) {
        const bool smooth_only = params.contours == ContourMode::Smooth;
        for (size_t i = 0; i < n.contour; ++i)
            if (smooth_only || !mesh_contours_at(lm, params, contour[i]))
                face_isoline<false>(lm, contour[i], ndotv, kr, nullptr, 0.0f, LineType::Silhouette, out);
        if (!smooth_only)
            for (uint32_t f = begin; f < end; ++f)
                if (ws.front[f] && mesh_contours_at(lm, params, f)) mesh_contour_face(lm, f, ws.front.data(), out);
    }
    if (features)
        for (uint32_t f = begin; f < end; ++f)
            if (feature_masks[f]) feature_edges(lm, f, feature_masks[f], params, out);
    // rtsc's other lines (off by default): no byte scan, each face tests itself.
    if (params.suggestive_highlights)
        for (uint32_t f = begin; f < end; ++f)
            if (highlight_candidate(faces[f], ws))
                face_isoline<true>(lm, f, kr, ws.highlight_num.data(), ndotv, fade, LineType::SuggestiveHighlight, out);
    for (int kind = 0; kind < 2; ++kind) {  // ridges, valleys: the view's share of the cache, or face by face
        if (!(kind == 0 ? params.ridges : params.valleys)) continue;
        const ExtractWorkspace::RidgeCache& cache = ws.ridge_cache[kind];
        if (!cache.use) {
            for (uint32_t f = begin; f < end; ++f) ridge_face(lm, f, ndotv, kind == 0, t.rv_thresh, params.fade, out);
            continue;
        }
        const size_t block = begin / kBlockFaces;
        for (uint32_t i = cache.block_start[block]; i < cache.block_start[block + 1]; ++i) {
            const LineSegment& s = cache.segments[i];
            if (!back_facing(ndotv, faces[s.face])) out.push_back(s);
        }
    }
    if (params.apparent_ridges)
        for (uint32_t f = begin; f < end; ++f)
            if (apparent_ridge_candidate(ws.apparent.corners.data(), faces[f], t.ar_thresh))
                apparent_ridge_face(lm, f, ws.apparent, t.ar_thresh, params.fade, out);
    if (params.principal_highlights)
        for (uint32_t f = begin; f < end; ++f) {
            const uint8_t shape = ws.principal_shapes[f];
            if (!(shape & (kPrincipalConvex | kPrincipalConcave))) continue;
            const glm::uvec3 c = faces[f];
            const uint8_t* flags = ws.principal_flags.data();
            if (principal_highlight_candidate(flags[c.x], flags[c.y], flags[c.z]))
                principal_highlight_face(lm, f, shape, ws.principal_along.data(), ws.principal_strength.data(),
                                         t.ph_thresh, params.fade, out);
        }
}

}  // namespace

void extract_lines_reference(const LineMesh& lm, const glm::vec3& eye, const LineParams& params,
                             std::vector<LineSegment>& out, ExtractWorkspace& ws, size_t threads) {
    const ScaledThresholds thresholds = scaled_thresholds(params, lm.feature_size);
    const size_t nv = lm.vertex_arrays.count;
    threads = std::max<size_t>(threads, 1);
    ws.ndotv.resize(nv);
    ws.kr.resize(nv);
    ws.test_num.resize(nv);
    ws.signs.resize(nv + kSignPadding);
    if (params.suggestive_highlights) ws.highlight_num.resize(nv);
    if (params.apparent_ridges) ws.apparent.resize(nv);
    ws.face_planes.use = ExtractWorkspace::FacePlanes::Use::Corners;
    if (params.silhouettes && params.contours != ContourMode::Smooth) {
        const size_t faces = lm.mesh.faces.size();
        ws.front.resize(faces);
        ExtractWorkspace::FacePlanes& planes = ws.face_planes;
        using Use = ExtractWorkspace::FacePlanes::Use;
        if (holds_pose(planes.generation, lm) && planes.nx.size() == faces) {
            planes.use = Use::Stream;
        } else if (holds_pose(planes.seen, lm)) {  // the vertex passes fill them, each its share of the faces
            for (auto* a : {&planes.nx, &planes.ny, &planes.nz, &planes.x0, &planes.y0, &planes.z0}) a->resize(faces);
            planes.generation = 0;
            planes.use = Use::Fill;
        }
        planes.seen = lm.generation;
    }
    if (params.principal_highlights) {
        ws.principal_along.resize(nv);
        ws.principal_strength.resize(nv);
        ws.principal_flags.resize(nv);
        if (!holds_pose(ws.principal_generation, lm) || ws.principal_shapes.size() != lm.mesh.faces.size()) {
            ws.principal_shapes = principal_highlight_shapes(lm);
            ws.principal_generation = lm.generation;
        }
    }
    for (int kind = 0; kind < 2; ++kind)
        if (kind == 0 ? params.ridges : params.valleys)
            prepare_ridge_cache(lm, params, kind, thresholds.rv_thresh, kBlockFaces, ws.ridge_cache[kind]);
    const size_t faces = lm.mesh.faces.size();
    const size_t blocks = (faces + kBlockFaces - 1) / kBlockFaces;
    threads = std::min(threads, std::max<size_t>(1, faces / kMinFacesPerThread));
    const auto face_block = [&](size_t b, std::vector<LineSegment>& into) {
        face_pass(lm, ws, params, thresholds, uint32_t(b * kBlockFaces), uint32_t(std::min(faces, (b + 1) * kBlockFaces)),
                  into);
    };
    if (threads == 1) {  // straight into the output
        vertex_passes(lm.vertex_arrays, eye, params, thresholds, 0, nv, ws);
        optional_vertex_pass(lm, eye, params, thresholds, 0, nv, ws);
        planes_filled(lm, ws.face_planes);
        if (params.apparent_ridges) apparent_derivative(lm, ws.ndotv.data(), thresholds.ar_thresh, 0, nv, ws.apparent);
        out.clear();
        for (size_t b = 0; b < blocks; ++b) face_block(b, out);
        return;
    }
    // A team (one fork and join): its members share out the vertices; then take face blocks
    // one at a time as they finish (lines cluster, as a silhouette crosses few faces all in
    // one part of the mesh, so fixed shares would leave a member idle). Member 0 takes them
    // from the front and appends straight to `out`; the others take them from the back, each
    // into its own vector, which member 0 appends once all are done. Copying every block into
    // place (3.2 MB a FlightHelmet view) cost a tenth of the work, and growing `out` for
    // members to copy side by side first zeroes it, which costs as much as the copy.
    if (ws.blocks.size() < blocks) ws.blocks.resize(blocks);
    out.clear();
    BlockEnds ends(blocks);
    parallel_team(threads, [&](size_t member, size_t members, TeamSync& sync) {
        const size_t first = nv * member / members, last = nv * (member + 1) / members;
        vertex_passes(lm.vertex_arrays, eye, params, thresholds, first, last, ws);
        optional_vertex_pass(lm, eye, params, thresholds, first, last, ws);
        sync.arrive_and_wait();
        if (member == 0) planes_filled(lm, ws.face_planes);  // (the others only read from here on)
        if (params.apparent_ridges) {  // reads the neighbours' q1
            apparent_derivative(lm, ws.ndotv.data(), thresholds.ar_thresh, first, last, ws.apparent);
            sync.arrive_and_wait();
        }
        if (member == 0) {
            for (std::optional<size_t> b = ends.take_front(); b; b = ends.take_front()) face_block(*b, out);
        } else {
            for (std::optional<size_t> b = ends.take_back(); b; b = ends.take_back()) {
                // Filled as a local: neighbouring blocks' vectors share cache lines, and every
                // append writes the vector's end.
                std::vector<LineSegment> segments = std::move(ws.blocks[*b]);
                segments.clear();
                face_block(*b, segments);
                ws.blocks[*b] = std::move(segments);
            }
        }
        sync.arrive_and_wait();
        const size_t back = ends.front();  // the first block taken from the back
        if (member == 0)
            for (size_t b = back; b < blocks; ++b) out.insert(out.end(), ws.blocks[b].begin(), ws.blocks[b].end());
    });
}

std::vector<LineSegment> extract_lines_reference(const LineMesh& lm, const glm::vec3& eye, const LineParams& params,
                                                 size_t threads) {
    ExtractWorkspace ws;
    std::vector<LineSegment> out;
    extract_lines_reference(lm, eye, params, out, ws, threads);
    return out;
}

}  // namespace lw
