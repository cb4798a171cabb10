// The pattern stage's one file that includes CGAL (header-only; compiled with
// -frounding-math, as CGAL's interval filters require, and without GMP: exact fallbacks use
// Boost.Multiprecision): the Delaunay triangulation and the simple-polygon test.
#include <map>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "pattern/distribution.h"
#include "pattern/lloyd.h"

namespace lw {

std::vector<std::array<int, 3>> delaunay_triangles(const std::vector<glm::vec2>& points) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb>;
    using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
    std::vector<std::array<int, 3>> out;
    if (points.size() < 3) return out;
    std::vector<std::pair<Kernel::Point_2, int>> input;
    input.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) input.emplace_back(Kernel::Point_2(points[i].x, points[i].y), int(i));
    // Spatially sorted insertion; a duplicate point keeps the info of the first inserted.
    Delaunay dt(input.begin(), input.end());
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
        out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    return out;
}

bool polygon_is_simple(const std::vector<glm::vec2>& polygon) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_2> corners;
    corners.reserve(polygon.size());
    for (const glm::vec2& p : polygon) {
        const Kernel::Point_2 q(p.x, p.y);
        if (corners.empty() || corners.back() != q) corners.push_back(q);
    }
    while (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
    return corners.size() >= 3 && CGAL::is_simple_2(corners.begin(), corners.end(), Kernel());
}

}  // namespace lw
