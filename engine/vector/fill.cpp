// The second file that includes CGAL (see CMakeLists.txt: -frounding-math, no GMP).
#include "vector/fill.h"

#include <queue>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

namespace lw {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<Kernel>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;  // crossings from outside; -1 unvisited
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: crossing constraints are split at (rounded) intersection points.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

}  // namespace

std::vector<glm::vec2> triangulate_even_odd(const std::vector<std::vector<glm::vec2>>& loops) {
    Cdt cdt;
    for (const auto& loop : loops) {
        if (loop.size() < 3) continue;
        for (size_t i = 0; i < loop.size(); ++i) {
            const glm::vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
            if (a != b) cdt.insert_constraint(Cdt::Point(a.x, a.y), Cdt::Point(b.x, b.y));
        }
    }
    std::vector<glm::vec2> triangles;
    if (cdt.dimension() < 2) return triangles;
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    // Breadth-first from the infinite face: crossing a constrained edge adds one.
    std::queue<Cdt::Face_handle> queue;
    cdt.infinite_face()->info() = 0;
    queue.push(cdt.infinite_face());
    // Level by level, so that every face gets its smallest count: faces reachable without a
    // crossing take the current level, those across a constrained edge wait for the next.
    std::vector<Cdt::Face_handle> next_level;
    for (int level = 0; !queue.empty(); ++level) {
        while (!queue.empty()) {
            const Cdt::Face_handle f = queue.front();
            queue.pop();
            for (int i = 0; i < 3; ++i) {
                const Cdt::Face_handle g = f->neighbor(i);
                if (g->info() != -1) continue;
                if (cdt.is_constrained(Cdt::Edge(f, i))) {
                    next_level.push_back(g);
                } else {
                    g->info() = level;
                    queue.push(g);
                }
            }
        }
        for (const Cdt::Face_handle g : next_level)
            if (g->info() == -1) {
                g->info() = level + 1;
                queue.push(g);
            }
        next_level.clear();
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (f->info() % 2 != 1) continue;
        for (int i = 0; i < 3; ++i) {
            const Cdt::Point& p = f->vertex(i)->point();
            triangles.emplace_back(float(p.x()), float(p.y()));
        }
    }
    return triangles;
}

}  // namespace lw
