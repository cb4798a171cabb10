// Compiled with -ffp-contract=off (CMakeLists.txt): see view_quantities.h.
#include "lines/extract_reference.h"

#include <algorithm>
#include <array>

#include "core/parallel.h"
#include "lines/view_quantities.h"

namespace lw {

ScaledThresholds scaled_thresholds(const LineParams& params, float feature_size) {
    const float fs2 = feature_size * feature_size;
    return {params.sug_thresh / fs2, params.fade ? params.fade_thresh / fs2 : 0.0f};
}

namespace {

// The field whose zero set is drawn through a face, and the test that trims it.
struct IsolineInput {
    std::array<float, 3> val;
    std::array<float, 3> num;
    std::array<float, 3> den;  // all 1 when the test has no denominator
    bool has_den;
};

// One face's isoline, rtsc's draw_face_isoline + draw_face_isoline2 (rtsc-lines.md §2.2–2.3).
void face_isoline(const LineMesh& lm, uint32_t f, const IsolineInput& in, float fade, LineType type,
                  std::vector<LineSegment>& out) {
    const auto& val = in.val;
    // Lone vertex a: the one whose sign differs; zeros count with the other side.
    int a;
    if ((val[0] < 0.0f && val[1] >= 0.0f && val[2] >= 0.0f) || (val[0] > 0.0f && val[1] <= 0.0f && val[2] <= 0.0f))
        a = 0;
    else if ((val[1] < 0.0f && val[2] >= 0.0f && val[0] >= 0.0f) || (val[1] > 0.0f && val[2] <= 0.0f && val[0] <= 0.0f))
        a = 1;
    else
        a = 2;
    const int b = (a + 1) % 3, c = (a + 2) % 3;

    const glm::uvec3 corners = lm.mesh.faces[f];
    const glm::vec3 xa = lm.mesh.positions[corners[a]], xb = lm.mesh.positions[corners[b]],
                    xc = lm.mesh.positions[corners[c]];
    // Crossings on edges a–b and a–c, measured from a.
    const float s_ab = val[a] / (val[a] - val[b]);
    const float s_ac = val[a] / (val[a] - val[c]);
    const glm::vec3 p1 = (1.0f - s_ab) * xa + s_ab * xb;
    const glm::vec3 p2 = (1.0f - s_ac) * xa + s_ac * xc;
    glm::vec3 b1(0.0f), b2(0.0f);
    b1[a] = 1.0f - s_ab;
    b1[b] = s_ab;
    b2[a] = 1.0f - s_ac;
    b2[c] = s_ac;
    const uint32_t key1 = uint32_t(lm.mesh.face_edges[f][c]);  // edge a–b is opposite c
    const uint32_t key2 = uint32_t(lm.mesh.face_edges[f][b]);  // edge a–c is opposite b

    // The test at both ends, numerator and denominator interpolated separately.
    const float n1 = (1.0f - s_ab) * in.num[a] + s_ab * in.num[b];
    const float n2 = (1.0f - s_ac) * in.num[a] + s_ac * in.num[c];
    const float d1 = in.has_den ? (1.0f - s_ab) * in.den[a] + s_ab * in.den[b] : 1.0f;
    const float d2 = in.has_den ? (1.0f - s_ac) * in.den[a] + s_ac * in.den[c] : 1.0f;
    const bool valid1 = (n1 >= 0.0f) == (d1 >= 0.0f);
    float z1 = (n1 >= 0.0f) != (n2 >= 0.0f) ? n1 / (n1 - n2) : 0.0f;
    float z2 = (d1 >= 0.0f) != (d2 >= 0.0f) ? d1 / (d1 - d2) : 0.0f;
    if (z1 == 0.0f) {
        z1 = z2;
        z2 = 0.0f;
    } else if (z2 != 0.0f && z2 < z1) {
        std::swap(z1, z2);
    }

    // Points along P1 → P2 where the test holds, paired into segments (GL_LINES semantics).
    struct Point {
        float z;
        uint32_t key;
    };
    std::array<Point, 4> points;
    int count = 0;
    if (valid1) points[count++] = {0.0f, key1};
    if (z1 != 0.0f) points[count++] = {z1, kNoKey};
    if (z2 != 0.0f) points[count++] = {z2, kNoKey};
    if (count != 2) points[count++] = {1.0f, key2};
    auto make_point = [&](const Point& p, glm::vec4& position, glm::vec4& bary) {
        const float z = p.z;
        const glm::vec3 x = (1.0f - z) * p1 + z * p2;  // exactly p1 at z = 0 and p2 at z = 1
        const float n = (1.0f - z) * n1 + z * n2;
        const float d = (1.0f - z) * d1 + z * d2;
        // rtsc: alpha = N / (D·fade + N), clamped by GL; no fading means full opacity.
        const float alpha = fade > 0.0f ? std::clamp(n / (d * fade + n), 0.0f, 1.0f) : 1.0f;
        position = glm::vec4(x, alpha);
        bary = glm::vec4((1.0f - z) * b1 + z * b2, 0.0f);
    };
    for (int i = 0; i + 1 < count; i += 2) {
        LineSegment s{};
        make_point(points[i], s.p0, s.bary0);
        make_point(points[i + 1], s.p1, s.bary1);
        s.face = f;
        s.type = uint32_t(type);
        s.key0 = points[i].key;
        s.key1 = points[i + 1].key;
        out.push_back(s);
    }
}

bool has_both_signs(const std::array<float, 3>& v) {
    return (v[0] > 0.0f || v[1] > 0.0f || v[2] > 0.0f) && (v[0] < 0.0f || v[1] < 0.0f || v[2] < 0.0f);
}

void feature_edges(const LineMesh& lm, uint32_t f, const LineParams& params, std::vector<LineSegment>& out) {
    const uint32_t mask = lm.feature_edges[f];
    const glm::uvec3 corners = lm.mesh.faces[f];
    for (int i = 0; i < 3; ++i) {
        const bool crease = params.creases && (mask & (kCreaseBit << i));
        const bool border = params.borders && (mask & (kBorderBit << i));
        if (!crease && !border) continue;
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        LineSegment s{};
        s.p0 = glm::vec4(lm.mesh.positions[corners[j]], 1.0f);
        s.p1 = glm::vec4(lm.mesh.positions[corners[k]], 1.0f);
        s.bary0[j] = 1.0f;
        s.bary1[k] = 1.0f;
        s.face = f;
        s.type = uint32_t(border ? LineType::Border : LineType::Crease);
        s.key0 = corners[j];
        s.key1 = corners[k];
        out.push_back(s);
    }
}

}  // namespace

namespace {

// Faces [begin, end) in order: what one block appends.
void extract_faces(const LineMesh& lm, const std::vector<VertexView>& view, const LineParams& params,
                   const ScaledThresholds& thresholds, uint32_t begin, uint32_t end, std::vector<LineSegment>& segments) {
    for (uint32_t f = begin; f < end; ++f) {
        const glm::uvec3 c = lm.mesh.faces[f];
        const VertexView& v0 = view[c[0]];
        const VertexView& v1 = view[c[1]];
        const VertexView& v2 = view[c[2]];
        if (params.suggestive) {
            // Zero set of kr, faces not entirely back-facing, trimmed by the DwKr test, faded.
            const IsolineInput in{{v0.kr, v1.kr, v2.kr},
                                  {v0.test_num, v1.test_num, v2.test_num},
                                  {v0.test_den, v1.test_den, v2.test_den},
                                  true};
            const bool back_facing = v0.ndotv <= 0.0f && v1.ndotv <= 0.0f && v2.ndotv <= 0.0f;
            const bool rejected = (in.num[0] <= 0.0f && in.den[0] >= 0.0f && in.num[1] <= 0.0f && in.den[1] >= 0.0f &&
                                   in.num[2] <= 0.0f && in.den[2] >= 0.0f) ||
                                  (in.num[0] >= 0.0f && in.den[0] <= 0.0f && in.num[1] >= 0.0f && in.den[1] <= 0.0f &&
                                   in.num[2] >= 0.0f && in.den[2] <= 0.0f);
            if (has_both_signs(in.val) && !back_facing && !rejected)
                face_isoline(lm, f, in, thresholds.fade, LineType::Suggestive, segments);
        }
        if (params.silhouettes) {
            // Zero set of n·v on every face, kept where kr ≥ 0, never faded.
            const IsolineInput in{{v0.ndotv, v1.ndotv, v2.ndotv}, {v0.kr, v1.kr, v2.kr}, {1.0f, 1.0f, 1.0f}, false};
            const bool rejected = in.num[0] <= 0.0f && in.num[1] <= 0.0f && in.num[2] <= 0.0f;
            if (has_both_signs(in.val) && !rejected) face_isoline(lm, f, in, 0.0f, LineType::Silhouette, segments);
        }
        if (params.creases || params.borders) feature_edges(lm, f, params, segments);
    }
}

}  // namespace

std::vector<LineSegment> extract_lines_reference(const LineMesh& lm, const glm::vec3& eye, const LineParams& params,
                                                 size_t threads) {
    const ScaledThresholds thresholds = scaled_thresholds(params, lm.feature_size);
    const auto& curv = lm.curvature;
    const size_t nv = lm.mesh.positions.size();
    threads = std::max<size_t>(threads, 1);
    std::vector<VertexView> view(nv);
    parallel_for(
        nv, 4096,
        [&](size_t begin, size_t end, size_t) {
            for (size_t i = begin; i < end; ++i)
                view[i] = vertex_view(lm.mesh.positions[i], curv.normals[i], curv.pdir1[i], curv.pdir2[i], curv.k1[i],
                                      curv.k2[i], curv.dcurv[i], eye, thresholds.sug_thresh);
        },
        threads);

    const size_t faces = lm.mesh.faces.size();
    std::vector<std::vector<LineSegment>> blocks(threads);
    const size_t used = parallel_for(
        faces, 4096,
        [&](size_t begin, size_t end, size_t block) {
            extract_faces(lm, view, params, thresholds, uint32_t(begin), uint32_t(end), blocks[block]);
        },
        threads);
    if (used == 1) return std::move(blocks[0]);
    size_t total = 0;
    for (const auto& b : blocks) total += b.size();
    std::vector<LineSegment> segments;
    segments.reserve(total);
    for (const auto& b : blocks) segments.insert(segments.end(), b.begin(), b.end());
    return segments;
}

}  // namespace lw
