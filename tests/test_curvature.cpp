// Curvature estimation (Rusinkiewicz 2004 as trimesh2 does it) against analytic surfaces.
//
// Every test prints what it measured ("[ measured ]" lines) so that accuracy can be tracked
// and compared with rtsc; the thresholds are the acceptance bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <random>

#include "geometry/curvature.h"
#include "geometry/test_meshes.h"
#include "geometry/welded_mesh.h"

namespace lw {
namespace {

constexpr double kPi = std::numbers::pi;

struct Stats {
    double sum = 0.0, max = 0.0;
    size_t count = 0;
    void add(double x) {
        sum += x;
        max = std::max(max, x);
        ++count;
    }
    double mean() const { return count ? sum / double(count) : 0.0; }
};

void report(const char* what, const Stats& s) {
    std::printf("[ measured ] %-58s mean %.3e  max %.3e  (n = %zu)\n", what, s.mean(), s.max, s.count);
}

// C(x, y, z) for C = (C111, C112, C122, C222) in the frame (e1, e2), with 3D vectors x, y, z
// projected on that frame — lets a test compare C with an analytic tensor in any frame.
double eval_c(const glm::vec4& c, const glm::vec3& e1, const glm::vec3& e2, const glm::vec3& x, const glm::vec3& y,
              const glm::vec3& z) {
    const double xu = glm::dot(x, e1), xv = glm::dot(x, e2), yu = glm::dot(y, e1), yv = glm::dot(y, e2);
    const double zu = glm::dot(z, e1), zv = glm::dot(z, e2);
    return c[0] * xu * yu * zu + c[1] * (xu * yu * zv + xu * yv * zu + xv * yu * zu) +
           c[2] * (xu * yv * zv + xv * yu * zv + xv * yv * zu) + c[3] * xv * yv * zv;
}

// Angle parameters of a torus vertex (make_torus numbering).
struct TorusAngles {
    double u, v;
};
TorusAngles torus_angles(size_t index, int ring, int tube) {
    const auto i = static_cast<int>(index / size_t(tube)), j = static_cast<int>(index % size_t(tube));
    return {2.0 * kPi * i / ring, 2.0 * kPi * j / tube};
}

// --- normals ------------------------------------------------------------------------------

TEST(Curvature, NormalsAreUnitAndOutwardOnASphere) {
    for (const auto& [name, tri] : {std::pair{"icosphere", make_icosphere(2.0f, 4)},
                                    std::pair{"uv sphere 64x32", make_uv_sphere(2.0f, 64, 32)}}) {
        const WeldedMesh mesh = weld(tri);
        const auto normals = compute_vertex_normals(mesh);
        Stats unit, outward;
        for (size_t v = 0; v < normals.size(); ++v) {
            const glm::dvec3 n(normals[v]), radial = glm::normalize(glm::dvec3(mesh.positions[v]));
            unit.add(std::fabs(glm::length(n) - 1.0));
            outward.add(std::atan2(glm::length(glm::cross(n, radial)), glm::dot(n, radial)));
        }
        std::printf("[ measured ] %s:\n", name);
        report("  | |n| - 1 |", unit);
        report("  angle(n, p - centre) rad", outward);
        EXPECT_LT(unit.max, 1e-6);
        EXPECT_LT(outward.max, 1e-5);  // outward, and radial to float precision (next test)
    }
}

// Max's weights are exact for a mesh inscribed in a sphere, even with irregular faces (the
// UV sphere's thin pole fans, its slanted diagonals); area weights are not. This is how we
// know the weighting is trimesh2's and not the renderer's area-weighted one.
TEST(Curvature, NormalsUseMaxWeightsExactOnSpheres) {
    const WeldedMesh mesh = weld(make_uv_sphere(1.0f, 48, 17));
    const auto max_weighted = compute_vertex_normals(mesh);
    std::vector<uint32_t> indices;
    for (const auto& f : mesh.faces) indices.insert(indices.end(), {f[0], f[1], f[2]});
    const auto area_weighted = vertex_normals(mesh.positions, indices);
    auto angle = [](glm::dvec3 a, glm::dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); };
    Stats max_err, area_err;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 radial(mesh.positions[v]);
        max_err.add(angle(max_weighted[v], radial));
        area_err.add(angle(area_weighted[v], radial));
    }
    report("uv sphere 48x17: angle(n, radial) rad, Max weights", max_err);
    report("uv sphere 48x17: angle(n, radial) rad, area weights", area_err);
    EXPECT_LT(max_err.max, 1e-5);  // float rounding
    EXPECT_GT(area_err.max, 100.0 * max_err.max);
}

// --- areas --------------------------------------------------------------------------------

// Corner areas against a brute-force Voronoi partition of the triangle (nearest corner of
// samples on a fine grid): acute, right and obtuse triangles.
TEST(Curvature, CornerAreasAreVoronoiAreasClippedToTheTriangle) {
    const glm::vec2 triangles[][3] = {{{0.0f, 0.0f}, {1.0f, 0.1f}, {0.3f, 0.9f}},   // acute
                                      {{0.0f, 0.0f}, {2.0f, 0.0f}, {0.0f, 1.0f}},   // right angle at 0
                                      {{0.0f, 0.0f}, {3.0f, 0.0f}, {0.6f, 0.5f}},   // obtuse at 2
                                      {{0.2f, 0.4f}, {-1.0f, 0.0f}, {2.5f, 0.1f}}}; // obtuse at 0
    for (const auto& tri : triangles) {
        TriangleMesh m;
        for (const auto& p : tri) m.positions.push_back(glm::vec3(p, 0.0f));
        m.normals.assign(3, glm::vec3(0, 0, 1));
        m.indices = {0, 1, 2};
        const SurfaceCurvature c = compute_curvature(weld(m));
        // Sample the bounding box; pixel centres inside the triangle vote for their nearest corner.
        const glm::vec2 lo = glm::min(tri[0], glm::min(tri[1], tri[2])), hi = glm::max(tri[0], glm::max(tri[1], tri[2]));
        const int n = 1500;
        const double cell = double(hi.x - lo.x) * double(hi.y - lo.y) / (double(n) * n);
        double area[3] = {0, 0, 0};
        auto edge = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
        const double orient = edge(tri[0], tri[1], tri[2]) > 0 ? 1.0 : -1.0;
        for (int iy = 0; iy < n; ++iy)
            for (int ix = 0; ix < n; ++ix) {
                const glm::dvec2 p(lo.x + (hi.x - lo.x) * (ix + 0.5) / n, lo.y + (hi.y - lo.y) * (iy + 0.5) / n);
                if (orient * edge(tri[0], tri[1], p) < 0 || orient * edge(tri[1], tri[2], p) < 0 ||
                    orient * edge(tri[2], tri[0], p) < 0)
                    continue;
                int best = 0;
                for (int k = 1; k < 3; ++k)
                    if (glm::distance(p, glm::dvec2(tri[k])) < glm::distance(p, glm::dvec2(tri[best]))) best = k;
                area[best] += cell;
            }
        const double total = area[0] + area[1] + area[2];
        for (int k = 0; k < 3; ++k) {
            std::printf("[ measured ] corner %d: ours %.5f  sampled Voronoi %.5f\n", k, c.corner_areas[0][k], area[k]);
            EXPECT_NEAR(c.corner_areas[0][k], area[k], 2e-3 * total);
            EXPECT_FLOAT_EQ(c.point_areas[k], c.corner_areas[0][k]);
        }
    }
}

TEST(Curvature, PointAreasSumToTheSurfaceArea) {
    const WeldedMesh mesh = weld(make_torus(3.0f, 1.0f, 90, 30));
    const SurfaceCurvature c = compute_curvature(mesh);
    double points = 0.0, faces = 0.0;
    for (float a : c.point_areas) points += a;
    for (const auto& f : mesh.faces)
        faces += 0.5 * glm::length(glm::cross(mesh.positions[f[1]] - mesh.positions[f[0]], mesh.positions[f[2]] - mesh.positions[f[0]]));
    std::printf("[ measured ] torus: sum of point areas %.6f, of face areas %.6f, analytic %.6f\n", points, faces,
                4.0 * kPi * kPi * 3.0);
    EXPECT_NEAR(points, faces, 1e-5 * faces);
}

// --- principal curvatures -----------------------------------------------------------------

TEST(Curvature, SphereHasBothCurvaturesOneOverR) {
    for (float r : {0.01f, 1.0f, 37.5f, 1000.0f}) {
        const WeldedMesh mesh = weld(make_icosphere(r, 5, glm::vec3(0.3f * r, -0.2f * r, 0.1f * r)));
        const SurfaceCurvature c = compute_curvature(mesh);
        Stats e1, e2;
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            e1.add(std::fabs(c.k1[v] * r - 1.0));
            e2.add(std::fabs(c.k2[v] * r - 1.0));
        }
        char label[96];
        std::snprintf(label, sizeof label, "icosphere L5 r = %g: |k1 r - 1|", double(r));
        report(label, e1);
        std::snprintf(label, sizeof label, "icosphere L5 r = %g: |k2 r - 1|", double(r));
        report(label, e2);
        EXPECT_LT(e1.max, 0.02);
        EXPECT_LT(e2.max, 0.02);
    }
    // The UV sphere's poles are fans of 64 slivers: less accurate there, but still within 2 %.
    const float r = 2.0f;
    const WeldedMesh mesh = weld(make_uv_sphere(r, 64, 32));
    const SurfaceCurvature c = compute_curvature(mesh);
    Stats e;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        e.add(std::fabs(c.k1[v] * r - 1.0));
        e.add(std::fabs(c.k2[v] * r - 1.0));
    }
    report("uv sphere 64x32 r = 2: |k r - 1| (k1 and k2)", e);
    EXPECT_LT(e.max, 0.02);
}

TEST(Curvature, CylinderAwayFromItsBorders) {
    const float r = 1.5f, h = 6.0f;
    const int around = 96, along = 48;
    const WeldedMesh mesh = weld(make_open_cylinder(r, h, around, along));
    const SurfaceCurvature c = compute_curvature(mesh);
    Stats k1_err, k2_err, dir1_err, dir2_err, border_k1;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const int ring = static_cast<int>(v / around);
        const glm::vec3 p = mesh.positions[v];
        const glm::vec3 around_dir = glm::normalize(glm::vec3(-p.y, p.x, 0.0f));
        if (ring == 0 || ring == along) border_k1.add(std::fabs(c.k1[v] * r - 1.0));
        if (ring < 3 || ring > along - 3) continue;
        k1_err.add(std::fabs(c.k1[v] * r - 1.0));
        k2_err.add(std::fabs(c.k2[v] * r));
        dir1_err.add(1.0 - std::fabs(glm::dot(c.pdir1[v], around_dir)));
        dir2_err.add(1.0 - std::fabs(c.pdir2[v].z));
    }
    report("cylinder r = 1.5 (rings 3..45): |k1 r - 1|", k1_err);
    report("cylinder: |k2| r", k2_err);
    report("cylinder: 1 - |pdir1 . around|", dir1_err);
    report("cylinder: 1 - |pdir2 . axis|", dir2_err);
    report("cylinder border rings (not tested): |k1 r - 1|", border_k1);
    EXPECT_LT(k1_err.max, 0.02);
    EXPECT_LT(k2_err.max, 0.02);
    EXPECT_LT(dir1_err.max, 0.05);
    EXPECT_LT(dir2_err.max, 0.05);
}

// The input vertex (make_torus's numbering, which torus_angles reads) of each welded vertex:
// welding numbers vertices by first use in the faces.
std::vector<size_t> input_vertex_of(const WeldedMesh& mesh) {
    std::vector<size_t> input(mesh.positions.size());
    for (size_t i = mesh.welded_index.size(); i-- > 0;) input[mesh.welded_index[i]] = i;
    return input;
}

// Torus (R, r) with outward normals: across the tube k = 1/r everywhere; along the ring
// k = cos v / (R + r cos v) — positive outside, negative in the hole, zero on the top and
// bottom circles (v = ±π/2, where a relative error means nothing). With R > 2r the tube
// curvature is the larger in magnitude, so k1 = 1/r along the tube, k2 the ring one.
TEST(Curvature, TorusMatchesTheAnalyticCurvaturesAndDirections) {
    const float big = 3.0f, small = 1.0f;
    const int ring = 180, tube = 60;
    const WeldedMesh mesh = weld(make_torus(big, small, ring, tube));
    const SurfaceCurvature c = compute_curvature(mesh);
    const std::vector<size_t> input = input_vertex_of(mesh);
    Stats k1_err, k2_rel, k2_abs_flat, dir1_err, dir2_err, normal_err;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto [u, t] = torus_angles(input[v], ring, tube);
        const glm::vec3 n(std::cos(t) * std::cos(u), std::cos(t) * std::sin(u), std::sin(t));
        const glm::vec3 tube_dir(-std::sin(t) * std::cos(u), -std::sin(t) * std::sin(u), std::cos(t));
        const glm::vec3 ring_dir(-std::sin(u), std::cos(u), 0.0f);
        const double k_ring = std::cos(t) / (big + small * std::cos(t));
        normal_err.add(1.0 - glm::dot(c.normals[v], n));
        k1_err.add(std::fabs(c.k1[v] * small - 1.0));
        if (std::fabs(std::cos(t)) > 0.25)
            k2_rel.add(std::fabs(c.k2[v] / k_ring - 1.0));
        else
            k2_abs_flat.add(std::fabs(c.k2[v] - k_ring) * small);
        dir1_err.add(1.0 - std::fabs(glm::dot(c.pdir1[v], tube_dir)));
        dir2_err.add(1.0 - std::fabs(glm::dot(c.pdir2[v], ring_dir)));
    }
    report("torus R=3 r=1 180x60: 1 - n . n_analytic", normal_err);
    report("torus: |k1 r - 1| (tube)", k1_err);
    report("torus: |k2 / k_ring - 1| where |cos v| > 0.25", k2_rel);
    report("torus: |k2 - k_ring| r where |cos v| <= 0.25", k2_abs_flat);
    report("torus: 1 - |pdir1 . tube direction|", dir1_err);
    report("torus: 1 - |pdir2 . ring direction|", dir2_err);
    EXPECT_LT(normal_err.max, 1e-4);
    EXPECT_LT(k1_err.max, 0.05);
    EXPECT_LT(k2_rel.max, 0.05);
    EXPECT_LT(k2_abs_flat.max, 0.05 * (small / (big - small)));  // 5 % of the largest |k_ring|
    EXPECT_LT(dir1_err.max, 0.05);  // |dot| > 0.95 everywhere: the curvatures differ everywhere
    EXPECT_LT(dir2_err.max, 0.05);
}

// Principal curvatures of the graph z = h(x, y) from its first and second fundamental forms.
struct GraphCurvature {
    double kmax, kmin;
    glm::dvec3 dir_max;  // unit, tangent
};
GraphCurvature graph_curvature(double p, double q, double r, double s, double t) {
    const double w = std::sqrt(1.0 + p * p + q * q);
    const double e = 1.0 + p * p, f = p * q, g = 1.0 + q * q;
    // Second fundamental form with the upward normal, signed like trimesh2 (a peak is +).
    const double l = -r / w, m = -s / w, n = -t / w;
    const double det = e * g - f * f;
    const double mean = (e * n + g * l - 2.0 * f * m) / (2.0 * det), gauss = (l * n - m * m) / det;
    const double disc = std::sqrt(std::max(0.0, mean * mean - gauss));
    GraphCurvature out{mean + disc, mean - disc, {}};
    // (II − k I)(a, b) = 0: take the better-conditioned row.
    const double k = out.kmax;
    const glm::dvec2 row1(l - k * e, m - k * f), row2(m - k * f, n - k * g);
    const glm::dvec2 ab = glm::length(row1) > glm::length(row2) ? glm::dvec2(-row1.y, row1.x) : glm::dvec2(-row2.y, row2.x);
    out.dir_max = glm::normalize(glm::dvec3(ab.x, ab.y, p * ab.x + q * ab.y));
    return out;
}

TEST(Curvature, GaussianBumpsMatchTheAnalyticCurvatures) {
    const std::vector<GaussianBump> bumps = {{{-0.4, -0.2}, 0.5, 0.5}, {{0.5, 0.3}, -0.3, 0.4}, {{0.1, 0.6}, 0.25, 0.3}};
    const int cells = 240;
    const glm::vec2 lo(-1.5f), hi(1.5f);
    const WeldedMesh mesh =
        weld(make_height_field([&](double x, double y) { return gaussian_bumps_height(bumps, x, y); }, lo, hi, cells, cells));
    const SurfaceCurvature c = compute_curvature(mesh);
    std::vector<GraphCurvature> truth(mesh.positions.size());
    double kscale = 0.0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const double x = mesh.positions[v].x, y = mesh.positions[v].y;
        double p = 0, q = 0, r = 0, s = 0, t = 0;
        for (const auto& b : bumps) {  // derivatives of a·exp(−ρ²/w²)
            const double dx = x - b.center.x, dy = y - b.center.y, w2 = b.width * b.width;
            const double z = b.amplitude * std::exp(-(dx * dx + dy * dy) / w2);
            p += -2.0 * dx / w2 * z;
            q += -2.0 * dy / w2 * z;
            r += (4.0 * dx * dx / (w2 * w2) - 2.0 / w2) * z;
            s += 4.0 * dx * dy / (w2 * w2) * z;
            t += (4.0 * dy * dy / (w2 * w2) - 2.0 / w2) * z;
        }
        truth[v] = graph_curvature(p, q, r, s, t);
        kscale = std::max({kscale, std::fabs(truth[v].kmax), std::fabs(truth[v].kmin)});
    }
    Stats kmax_err, kmin_err, dir_err;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const int i = static_cast<int>(v % (cells + 1)), j = static_cast<int>(v / (cells + 1));
        if (i < 3 || j < 3 || i > cells - 3 || j > cells - 3) continue;  // away from the border
        const bool first_is_max = c.k1[v] >= c.k2[v];
        const double kmax = first_is_max ? c.k1[v] : c.k2[v], kmin = first_is_max ? c.k2[v] : c.k1[v];
        kmax_err.add(std::fabs(kmax - truth[v].kmax) / kscale);
        kmin_err.add(std::fabs(kmin - truth[v].kmin) / kscale);
        if (truth[v].kmax - truth[v].kmin > 0.1 * kscale)
            dir_err.add(1.0 - std::fabs(glm::dot(glm::dvec3(first_is_max ? c.pdir1[v] : c.pdir2[v]), truth[v].dir_max)));
    }
    std::printf("[ measured ] bumps: largest |k| %.3f, grid step %.4f\n", kscale, 3.0 / cells);
    report("bumps: |kmax - analytic| / max|k|", kmax_err);
    report("bumps: |kmin - analytic| / max|k|", kmin_err);
    report("bumps: 1 - |dir . analytic| where kmax - kmin > 0.1 max|k|", dir_err);
    EXPECT_LT(kmax_err.max, 0.03);
    EXPECT_LT(kmin_err.max, 0.03);
    EXPECT_LT(kmax_err.mean(), 0.005);
    EXPECT_LT(dir_err.max, 0.05);
}

// --- derivative tensor --------------------------------------------------------------------

TEST(Curvature, DerivativeTensorVanishesOnASphere) {
    for (float r : {0.5f, 20.0f}) {
        const WeldedMesh mesh = weld(make_icosphere(r, 5));
        const SurfaceCurvature c = compute_curvature(mesh);
        Stats mag;
        for (const auto& d : c.dcurv) mag.add(double(glm::length(d)) * r * r);  // C scales as 1/r²
        char label[80];
        std::snprintf(label, sizeof label, "icosphere L5 r = %g: |C| r^2", double(r));
        report(label, mag);
        EXPECT_LT(mag.max, 0.02);
    }
}

// On the torus only the ring curvature varies, and only across the tube:
// C(t_v, t_u, t_u) = d k_ring / d s_v = −R sin v / (r (R + r cos v)²); C(t_v,t_v,t_v) = C(t_v,t_v,t_u)
// = C(t_u,t_u,t_u) = 0 (k_tube is constant, k_ring does not change along the ring).
TEST(Curvature, DerivativeTensorOnATorus) {
    const double big = 3.0, small = 1.0;
    const int ring = 180, tube = 60;
    const WeldedMesh mesh = weld(make_torus(float(big), float(small), ring, tube));
    const SurfaceCurvature c = compute_curvature(mesh);
    double scale = 0.0;
    for (int j = 0; j < 3600; ++j) {
        const double t = 2.0 * kPi * j / 3600;
        scale = std::max(scale, std::fabs(big * std::sin(t) / (small * std::pow(big + small * std::cos(t), 2.0))));
    }
    Stats c122_err, others;
    const std::vector<size_t> input = input_vertex_of(mesh);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto [u, t] = torus_angles(input[v], ring, tube);
        const glm::vec3 tv(-std::sin(t) * std::cos(u), -std::sin(t) * std::sin(u), std::cos(t));
        const glm::vec3 tu(-std::sin(u), std::cos(u), 0.0f);
        const double expected = -big * std::sin(t) / (small * std::pow(big + small * std::cos(t), 2.0));
        const glm::vec3 e1 = c.pdir1[v], e2 = c.pdir2[v];
        c122_err.add(std::fabs(eval_c(c.dcurv[v], e1, e2, tv, tu, tu) - expected) / scale);
        others.add(std::fabs(eval_c(c.dcurv[v], e1, e2, tv, tv, tv)) / scale);
        others.add(std::fabs(eval_c(c.dcurv[v], e1, e2, tv, tv, tu)) / scale);
        others.add(std::fabs(eval_c(c.dcurv[v], e1, e2, tu, tu, tu)) / scale);
    }
    std::printf("[ measured ] torus: max |dk_ring/ds_v| = %.4f\n", scale);
    report("torus: |C(tv,tu,tu) - analytic| / max", c122_err);
    report("torus: |C(tv,tv,tv)|, |C(tv,tv,tu)|, |C(tu,tu,tu)| / max", others);
    EXPECT_LT(c122_err.max, 0.05);
    EXPECT_LT(c122_err.mean(), 0.02);
    EXPECT_LT(others.max, 0.05);
}

// z = a x³ − y²/2: at the origin k = 1 along y and 0 along x, and the only third derivative
// is z_xxx = 6a, so C_xxx = −6a (normal up, sign as II = −Hessian there), all others 0.
TEST(Curvature, DerivativeTensorOfACubicHeightField) {
    const double a = 0.5;
    const int cells = 100;
    const WeldedMesh mesh = weld(make_height_field([&](double x, double y) { return a * x * x * x - 0.5 * y * y; },
                                                   glm::vec2(-0.5f), glm::vec2(0.5f), cells, cells));
    const SurfaceCurvature c = compute_curvature(mesh);
    const size_t origin = size_t(cells / 2) * (cells + 1) + cells / 2;
    ASSERT_EQ(mesh.positions[origin], glm::vec3(0.0f));
    const glm::vec3 x(1, 0, 0), y(0, 1, 0), e1 = c.pdir1[origin], e2 = c.pdir2[origin];
    const glm::vec4 d = c.dcurv[origin];
    const double cxxx = eval_c(d, e1, e2, x, x, x), cxxy = eval_c(d, e1, e2, x, x, y);
    const double cxyy = eval_c(d, e1, e2, x, y, y), cyyy = eval_c(d, e1, e2, y, y, y);
    std::printf("[ measured ] cubic at origin: k1 %.5f k2 %.5f |pdir1.y| %.5f\n", c.k1[origin], c.k2[origin],
                std::fabs(glm::dot(e1, y)));
    std::printf("[ measured ] cubic at origin: C_xxx %.5f (analytic %.5f), C_xxy %.2e, C_xyy %.2e, C_yyy %.2e\n", cxxx,
                -6.0 * a, cxxy, cxyy, cyyy);
    EXPECT_NEAR(c.k1[origin], 1.0, 0.01);
    EXPECT_NEAR(c.k2[origin], 0.0, 0.01);
    EXPECT_NEAR(cxxx, -6.0 * a, 0.02 * 6.0 * a);
    for (double other : {cxxy, cxyy, cyyy}) EXPECT_LT(std::fabs(other), 0.02 * 6.0 * a);
}

// --- conventions --------------------------------------------------------------------------

TEST(Curvature, FramesAreRightHandedAndOrderedByMagnitude) {
    const std::vector<GaussianBump> bumps = {{{0.0, 0.0}, 0.6, 0.5}, {{0.6, 0.2}, -0.4, 0.3}};
    for (const TriangleMesh& tri : {make_torus(3.0f, 1.0f, 90, 30), make_icosphere(1.0f, 3),
                                    make_height_field([&](double x, double y) { return gaussian_bumps_height(bumps, x, y); },
                                                      glm::vec2(-1.0f), glm::vec2(1.0f), 60, 60)}) {
        const WeldedMesh mesh = weld(tri);
        const SurfaceCurvature c = compute_curvature(mesh);
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            ASSERT_GE(std::fabs(c.k1[v]), std::fabs(c.k2[v]));
            ASSERT_NEAR(glm::length(c.pdir1[v]), 1.0f, 1e-5f);
            ASSERT_NEAR(glm::length(c.pdir2[v]), 1.0f, 1e-5f);
            ASSERT_NEAR(glm::dot(c.pdir1[v], c.normals[v]), 0.0f, 1e-5f);
            ASSERT_NEAR(glm::dot(glm::cross(c.pdir1[v], c.pdir2[v]), c.normals[v]), 1.0f, 1e-5f);
        }
    }
}

TEST(Curvature, IsDeterministic) {
    const WeldedMesh mesh = weld(make_torus(3.0f, 1.2f, 64, 24));
    const SurfaceCurvature a = compute_curvature(mesh), b = compute_curvature(mesh);
    auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    EXPECT_TRUE(same(a.k1, b.k1) && same(a.k2, b.k2) && same(a.pdir1, b.pdir1) && same(a.dcurv, b.dcurv) &&
                same(a.normals, b.normals) && same(a.point_areas, b.point_areas));
    EXPECT_EQ(feature_size(mesh, a), feature_size(mesh, b));
}

// An isolated vertex, a zero-area (collinear) face and a vertex used only by it: everything
// stays finite, and what has no area gets no curvature.
TEST(Curvature, DegenerateInputStaysFinite) {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.2f}, {1, 1, 0.1f},  // two proper faces
                   {5, 5, 5},                                          // in no face
                   {2, 0, 0}, {3, 0, 0}};                              // collinear with vertex 1
    m.normals.assign(m.positions.size(), glm::vec3(0, 0, 1));
    m.indices = {0, 1, 2, 1, 3, 2, 1, 5, 6};
    const WeldedMesh mesh = weld(m);
    ASSERT_EQ(mesh.faces.size(), 3u);
    const SurfaceCurvature c = compute_curvature(mesh);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        for (float x : {c.k1[v], c.k2[v], c.point_areas[v], c.dcurv[v].x, c.dcurv[v].y, c.dcurv[v].z, c.dcurv[v].w})
            ASSERT_TRUE(std::isfinite(x)) << "vertex " << v;
        ASSERT_NEAR(glm::length(c.normals[v]), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(glm::cross(c.pdir1[v], c.pdir2[v]), c.normals[v]), 1.0f, 1e-5f) << "vertex " << v;
    }
    for (size_t v : {4u, 5u, 6u}) {
        EXPECT_EQ(c.point_areas[v], 0.0f);
        EXPECT_EQ(c.k1[v], 0.0f);
        EXPECT_EQ(c.dcurv[v], glm::vec4(0.0f));
    }
    EXPECT_EQ(c.normals[4], glm::vec3(0, 0, 1));
    EXPECT_TRUE(std::isfinite(feature_size(mesh, c)));
}

// The newer trimesh2's 3×3 shortcut (CurvatureOptions) is not a least-squares solve: the
// difference it makes is measured here; on a mesh of isosceles faces whose first edge is the
// base (Σuv = 0 in the face frame) it changes nothing.
TEST(Curvature, Trimesh2LdltShortcutOption) {
    const WeldedMesh mesh = weld(make_torus(3.0f, 1.0f, 180, 60));
    const SurfaceCurvature exact = compute_curvature(mesh);
    const SurfaceCurvature quirk = compute_curvature(mesh, {.trimesh2_ldlt_shortcut = true});
    Stats dk1, dk2, quirk_k1_err;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        dk1.add(std::fabs(quirk.k1[v] - exact.k1[v]));
        dk2.add(std::fabs(quirk.k2[v] - exact.k2[v]));
        quirk_k1_err.add(std::fabs(quirk.k1[v] - 1.0));
    }
    report("torus: |k1(shortcut) - k1(exact)|", dk1);
    report("torus: |k2(shortcut) - k2(exact)|", dk2);
    report("torus: |k1(shortcut) r - 1|", quirk_k1_err);
    EXPECT_GT(dk1.max, 0.0);

    TriangleMesh iso;  // two isosceles triangles, each listed base first (corner 0 = apex)
    iso.positions = {{0, 0, 0}, {1, 0, 0.1f}, {0.5f, 0.8f, 0.05f}, {0.48f, -0.7f, 0.25f}};
    iso.normals.assign(4, glm::vec3(0, 0, 1));
    iso.indices = {2, 0, 1, 3, 1, 0};
    const WeldedMesh iso_mesh = weld(iso);
    const SurfaceCurvature a = compute_curvature(iso_mesh), b = compute_curvature(iso_mesh, {.trimesh2_ldlt_shortcut = true});
    for (size_t v = 0; v < 4; ++v) {
        EXPECT_NEAR(a.k1[v], b.k1[v], 1e-4f * (1.0f + std::fabs(a.k1[v])));
        EXPECT_NEAR(a.k2[v], b.k2[v], 1e-4f * (1.0f + std::fabs(a.k2[v])));
    }
}

// --- feature size and bounding sphere -----------------------------------------------------

TEST(Curvature, FeatureSizeOfASphereIsOnePercentOfItsRadius) {
    for (float r : {0.2f, 1.0f, 50.0f}) {
        const WeldedMesh mesh = weld(make_icosphere(r, 4));
        const SurfaceCurvature c = compute_curvature(mesh);
        const float fs = feature_size(mesh, c);
        // rtsc's rule written out again: 500 LCG draws, |k1| and |k2|, the 10th percentile.
        std::vector<float> samples;
        uint32_t state = 0;
        for (int i = 0; i < 500; ++i) {
            state = 1664525u * state + 1013904223u;
            const uint32_t v = state % uint32_t(mesh.positions.size());
            samples.push_back(std::fabs(c.k1[v]));
            samples.push_back(std::fabs(c.k2[v]));
        }
        std::sort(samples.begin(), samples.end());
        const float expected = std::min(0.01f / samples[100], 0.05f * minimal_bounding_sphere(mesh.positions).radius);
        std::printf("[ measured ] sphere r = %g: feature size %.6g = %.5f r (cap 0.05 r)\n", double(r), double(fs),
                    double(fs / r));
        EXPECT_EQ(fs, expected);
        EXPECT_NEAR(fs / r, 0.01, 0.01 * 0.02);  // 10th-percentile |k| = 1/r within 2 %
    }
}

// Half the samples of a cylinder are |k2| ≈ 0, so the cap applies: 5 % of the minimal
// enclosing sphere's radius √(r² + (h/2)²) — not of the bounding box's half-diagonal.
TEST(Curvature, FeatureSizeOfACylinderIsCappedByTheMinimalSphere) {
    const float r = 1.0f, h = 6.0f;
    const WeldedMesh mesh = weld(make_open_cylinder(r, h, 64, 40));
    const float fs = feature_size(mesh, compute_curvature(mesh));
    const double sphere = std::sqrt(r * r + 0.25 * h * h);
    std::printf("[ measured ] cylinder: feature size %.6f, 0.05 x minimal sphere %.6f, 0.05 x box radius %.6f\n",
                double(fs), 0.05 * sphere, 0.05 * double(compute_bounds(mesh.positions).radius()));
    EXPECT_NEAR(fs, 0.05 * sphere, 1e-5);
}

TEST(Curvature, MinimalBoundingSphereMatchesBruteForce) {
    std::mt19937 rng(7);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<glm::vec3> pts(3 + trial % 12);
        for (auto& p : pts) p = glm::vec3(gauss(rng), gauss(rng), 0.3f * gauss(rng)) + glm::vec3(5.0f);
        const BoundingSphere s = minimal_bounding_sphere(pts);
        // Brute force: the smallest enclosing ball through 2, 3 or 4 of the points (its centre
        // in their affine hull), by double-precision solves.
        double best = 1e30;
        const size_t n = pts.size();
        auto try_ball = [&](const std::vector<glm::dvec3>& q) {
            const size_t k = q.size() - 1;
            double m[3][4] = {};
            for (size_t i = 0; i < k; ++i) {
                for (size_t j = 0; j < k; ++j) m[i][j] = 2.0 * glm::dot(q[i + 1] - q[0], q[j + 1] - q[0]);
                m[i][k] = glm::dot(q[i + 1] - q[0], q[i + 1] - q[0]);
            }
            for (size_t col = 0; col < k; ++col) {  // Gauss–Jordan, no pivoting needed for random points
                if (std::fabs(m[col][col]) < 1e-12) return;
                for (size_t row = 0; row < k; ++row) {
                    if (row == col) continue;
                    const double f = m[row][col] / m[col][col];
                    for (size_t j = 0; j <= k; ++j) m[row][j] -= f * m[col][j];
                }
            }
            glm::dvec3 center = q[0];
            for (size_t i = 0; i < k; ++i) center += m[i][k] / m[i][i] * (q[i + 1] - q[0]);
            double r2 = 0.0;
            for (const auto& p : pts) r2 = std::max(r2, glm::dot(glm::dvec3(p) - center, glm::dvec3(p) - center));
            if (glm::dot(q[0] - center, q[0] - center) >= r2 * (1 - 1e-9)) best = std::min(best, r2);
        };
        for (size_t a = 0; a < n; ++a)
            for (size_t b = a + 1; b < n; ++b) {
                try_ball({pts[a], pts[b]});
                for (size_t cc = b + 1; cc < n; ++cc) {
                    try_ball({pts[a], pts[b], pts[cc]});
                    for (size_t d = cc + 1; d < n; ++d) try_ball({pts[a], pts[b], pts[cc], pts[d]});
                }
            }
        ASSERT_NEAR(s.radius, std::sqrt(best), 1e-5 * std::sqrt(best)) << "trial " << trial;
        for (const auto& p : pts) ASSERT_LE(glm::distance(p, s.center), s.radius * (1 + 1e-6f));
    }
}

// --- cost ---------------------------------------------------------------------------------

// The time bound holds for optimised builds without sanitizers (LINEWORK_SANITIZE makes it
// about 10× slower); other builds still run the computation but only report its time.
#if defined(__SANITIZE_ADDRESS__) || !defined(__OPTIMIZE__)
constexpr bool kTimingIsMeaningful = false;
#else
constexpr bool kTimingIsMeaningful = true;
#endif

TEST(Curvature, AMillionTrianglesTakeWellUnderTwoSeconds) {
    const WeldedMesh mesh = weld(make_torus(3.0f, 1.0f, 1000, 500));
    ASSERT_EQ(mesh.faces.size(), 1000000u);
    const auto start = std::chrono::steady_clock::now();
    const SurfaceCurvature c = compute_curvature(mesh);
    const auto mid = std::chrono::steady_clock::now();
    const float fs = feature_size(mesh, c);
    const auto end = std::chrono::steady_clock::now();
    const double curvature_ms = std::chrono::duration<double, std::milli>(mid - start).count();
    const double fs_ms = std::chrono::duration<double, std::milli>(end - mid).count();
    std::printf("[ measured ] 1M-triangle torus (%zu vertices): compute_curvature %.0f ms, feature_size %.1f ms (fs %.5f)\n",
                mesh.positions.size(), curvature_ms, fs_ms, double(fs));
    if (!kTimingIsMeaningful) GTEST_SKIP() << "unoptimised or sanitized build: time not checked";
    EXPECT_LT(curvature_ms + fs_ms, 4000.0);  // the budget is ~1 s; slack for a loaded machine
}

}  // namespace
}  // namespace lw
