// Occlusion levels by ray casting with CGAL's AABB tree (compiled with -frounding-math, as
// its interval filters need, and without GMP).
#include "lines/occlusion.h"

#include <algorithm>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace lw {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using TrianglePrimitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, TrianglePrimitive>>;

constexpr double kAtThePoint = 1e-3;   // of the way: the point's own surface
constexpr double kSameCrossing = 1e-6;  // of the way: one crossing hit on several triangles

}  // namespace

struct OcclusionCounter::Index {
    std::vector<Triangle> triangles;     // per welded face (degenerate ones left out of the tree)
    std::vector<glm::uvec3> faces;
    Tree tree;
};

OcclusionCounter::OcclusionCounter() = default;
OcclusionCounter::~OcclusionCounter() = default;
OcclusionCounter::OcclusionCounter(OcclusionCounter&&) noexcept = default;
OcclusionCounter& OcclusionCounter::operator=(OcclusionCounter&&) noexcept = default;

bool OcclusionCounter::empty() const { return !index_; }

void OcclusionCounter::set_mesh(const LineMesh& mesh) {
    if (index_ && generation_ == mesh.generation && mesh.generation != 0) return;
    auto index = std::make_unique<Index>();
    const WeldedMesh& m = mesh.mesh;
    index->faces = m.faces;
    index->triangles.reserve(m.faces.size());
    const auto point = [&](uint32_t v) { return Point(m.positions[v].x, m.positions[v].y, m.positions[v].z); };
    for (const glm::uvec3& f : m.faces) index->triangles.emplace_back(point(f.x), point(f.y), point(f.z));
    for (auto t = index->triangles.cbegin(); t != index->triangles.cend(); ++t)
        if (!t->is_degenerate()) index->tree.insert(TrianglePrimitive(t));
    index->tree.build();  // now, not lazily: queries come from several threads
    index_ = std::move(index);
    generation_ = mesh.generation;
}

uint32_t OcclusionCounter::surfaces_in_front(const glm::vec3& eye, const glm::vec3& point, uint32_t face,
                                             bool contour) const {
    if (!index_) return 0;
    const Point from(eye.x, eye.y, eye.z), to(point.x, point.y, point.z);
    if (from == to) return 0;
    const Segment ray(from, to);
    std::vector<Tree::Intersection_and_primitive_id<Segment>::Type> hits;
    index_->tree.all_intersections(ray, std::back_inserter(hits));
    const glm::uvec3 own = contour && face < index_->faces.size() ? index_->faces[face] : glm::uvec3(~0u);
    const auto beside = [&](const glm::uvec3& f) {
        for (int i = 0; i < 3; ++i)
            if (f[i] == own.x || f[i] == own.y || f[i] == own.z) return true;
        return false;
    };
    const double length2 = CGAL::to_double(ray.squared_length());
    std::vector<double> along;  // hit distances as fractions of the way
    for (const auto& [where, id] : hits) {
        if (beside(index_->faces[size_t(id - index_->triangles.cbegin())])) continue;
        Point p;
        if (const Point* hit = boost::get<Point>(&where)) {
            p = *hit;
        } else if (const Segment* in_plane = boost::get<Segment>(&where)) {  // grazing: where it starts
            p = CGAL::has_smaller_distance_to_point(from, in_plane->source(), in_plane->target()) ? in_plane->source()
                                                                                                 : in_plane->target();
        } else {
            continue;
        }
        const double t = std::sqrt(CGAL::to_double(CGAL::squared_distance(from, p)) / length2);
        if (t < 1.0 - kAtThePoint) along.push_back(t);
    }
    std::sort(along.begin(), along.end());
    uint32_t crossings = 0;
    for (size_t i = 0; i < along.size(); ++i)
        if (i == 0 || along[i] - along[i - 1] > kSameCrossing) ++crossings;
    return crossings;
}

}  // namespace lw
