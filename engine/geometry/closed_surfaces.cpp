// engine/geometry/closed_surfaces.cpp — components, their holes and caps, and the view test.
#include "geometry/closed_surfaces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>

#include "core/error.h"
#include "geometry/face_pairs.h"
#include "geometry/welded_mesh.h"

namespace lw {

namespace {

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// How each edge of the weld (WeldedMesh::edges) is used: by how many faces running
// v[0]→v[1] and v[1]→v[0].
struct EdgeUse {
    uint32_t forward = 0, backward = 0;
    // One face (an open edge) or one face each way (a consistently oriented interior edge):
    // anything else — a fold of the orientation, a fin of three faces, a face and its
    // reverse — leaves no single "outside" to reason about.
    bool closable() const { return forward + backward == 1 || (forward == 1 && backward == 1); }
};

// Face f's edge from corner c to corner c + 1 (the weld names an edge by its opposite corner).
uint32_t edge_from(const WeldedMesh& welded, uint32_t f, int c) { return uint32_t(welded.face_edges[f][(c + 2) % 3]); }

std::vector<EdgeUse> edge_uses(const WeldedMesh& welded) {
    std::vector<EdgeUse> uses(welded.edges.size());
    for (uint32_t f = 0; f < welded.faces.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t e = edge_from(welded, f, c);
            (welded.faces[f][c] == welded.edges[e].v[0] ? uses[e].forward : uses[e].backward) += 1;
        }
    return uses;
}

// Faces joined across their interior edges (one face each way), numbered in order of their
// first face. Shells that meet only at a vertex, or along an edge of another kind, are apart.
std::vector<int32_t> face_components(const WeldedMesh& welded, const std::vector<EdgeUse>& uses, size_t& count) {
    std::vector<uint32_t> parent(welded.faces.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t e = 0; e < welded.edges.size(); ++e) {
        const MeshEdge& edge = welded.edges[e];
        if (uses[e].forward == 1 && uses[e].backward == 1 && edge.face_count == 2)
            parent[find_root(parent, uint32_t(edge.f[0]))] = find_root(parent, uint32_t(edge.f[1]));
    }
    std::vector<int32_t> component(welded.faces.size()), of_root(welded.faces.size(), -1);
    count = 0;
    for (uint32_t f = 0; f < welded.faces.size(); ++f) {
        const uint32_t root = find_root(parent, f);
        if (of_root[root] < 0) of_root[root] = int32_t(count++);
        component[f] = of_root[root];
    }
    return component;
}

// The open edges of each closable component as cycles of welded vertices, each running as its
// face runs along it. The boundary of a surface whose edges are all open or used once each
// way is itself closed (as many open edges leave each vertex as enter it), so a walk along
// unused open edges from a vertex comes back to it; a component with other edges (a face
// wound the other way, a fin) has no such boundary and is left out. Edges are taken in
// order of first use by the faces; a walk stays in its component.
std::vector<std::pair<int32_t, std::vector<uint32_t>>> boundary_cycles(const WeldedMesh& welded,
                                                                       const std::vector<EdgeUse>& uses,
                                                                       const std::vector<int32_t>& component,
                                                                       const std::vector<bool>& closable) {
    const auto node = [](int32_t c, uint32_t v) { return uint64_t(uint32_t(c)) << 32 | v; };
    std::unordered_map<uint64_t, std::vector<uint32_t>> out;  // (component, vertex) → open edges leaving it
    std::vector<uint64_t> starts;
    for (uint32_t f = 0; f < welded.faces.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t a = welded.faces[f][c], b = welded.faces[f][(c + 1) % 3];
            const EdgeUse& use = uses[edge_from(welded, f, c)];
            if (use.forward + use.backward != 1 || !closable[size_t(component[f])]) continue;
            std::vector<uint32_t>& leaving = out[node(component[f], a)];
            if (leaving.empty()) starts.push_back(node(component[f], a));
            leaving.push_back(b);
        }
    for (auto& [key, leaving] : out) std::reverse(leaving.begin(), leaving.end());  // taken from the back
    std::vector<std::pair<int32_t, std::vector<uint32_t>>> cycles;
    for (uint64_t start : starts) {
        const auto c = int32_t(start >> 32);
        while (!out[start].empty()) {
            std::vector<uint32_t> cycle;
            uint32_t v = uint32_t(start);
            do {
                cycle.push_back(v);
                std::vector<uint32_t>& leaving = out[node(c, v)];
                if (leaving.empty()) {  // cannot happen (see above); an empty cycle refuses the component
                    cycle.clear();
                    out[start].clear();
                    break;
                }
                v = leaving.back();
                leaving.pop_back();
            } while (v != uint32_t(start));
            cycles.emplace_back(c, std::move(cycle));
        }
    }
    return cycles;
}

// The winding number of a point about one component's closed surface (its faces and caps),
// by the signed crossings of the ray from it along +x: w(p) counts the faces the ray leaves
// through their back minus those it leaves through their front (w = 0 far away). The
// triangles are listed in a grid over (y, z), so a ray reads only those over its cell.
class WindingGrid {
public:
    struct Triangle {
        glm::dvec3 a, b, c;
        int32_t component;
        uint32_t face;
    };
    explicit WindingGrid(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
        if (triangles_.empty()) return;
        lo_ = hi_ = glm::dvec2(triangles_[0].a.y, triangles_[0].a.z);
        for (const Triangle& t : triangles_)
            for (const glm::dvec3& p : {t.a, t.b, t.c}) {
                lo_ = glm::min(lo_, glm::dvec2(p.y, p.z));
                hi_ = glm::max(hi_, glm::dvec2(p.y, p.z));
            }
        n_ = std::max(1, int(std::sqrt(double(triangles_.size()))));
        cells_.resize(size_t(n_) * size_t(n_));
        for (uint32_t i = 0; i < triangles_.size(); ++i) {
            const Triangle& t = triangles_[i];
            const glm::ivec2 from = cell(glm::min(glm::dvec2(t.a.y, t.a.z), glm::min(glm::dvec2(t.b.y, t.b.z), glm::dvec2(t.c.y, t.c.z))));
            const glm::ivec2 to = cell(glm::max(glm::dvec2(t.a.y, t.a.z), glm::max(glm::dvec2(t.b.y, t.b.z), glm::dvec2(t.c.y, t.c.z))));
            for (int y = from.x; y <= to.x; ++y)
                for (int z = from.y; z <= to.y; ++z) cells_[size_t(y) * size_t(n_) + size_t(z)].push_back(i);
        }
    }

    // Empty where the ray grazes an edge or a vertex (the caller takes it as unknown). Face
    // `skip` is not counted (the ray starts on it).
    std::optional<int> winding(const glm::dvec3& p, int32_t component, uint32_t skip) const {
        if (triangles_.empty()) return 0;
        const glm::dvec2 q(p.y, p.z);
        if (q.x < lo_.x || q.y < lo_.y || q.x > hi_.x || q.y > hi_.y) return 0;
        const glm::ivec2 c = cell(q);
        int w = 0;
        for (uint32_t i : cells_[size_t(c.x) * size_t(n_) + size_t(c.y)]) {
            const Triangle& t = triangles_[i];
            if (t.component != component || t.face == skip) continue;
            const auto orient = [&](const glm::dvec3& u, const glm::dvec3& v) {
                return (u.y - q.x) * (v.z - q.y) - (u.z - q.y) * (v.y - q.x);
            };
            const double o0 = orient(t.b, t.c), o1 = orient(t.c, t.a), o2 = orient(t.a, t.b);
            if (o0 == 0.0 || o1 == 0.0 || o2 == 0.0) {
                if ((o0 >= 0.0 && o1 >= 0.0 && o2 >= 0.0) || (o0 <= 0.0 && o1 <= 0.0 && o2 <= 0.0)) return std::nullopt;
                continue;
            }
            if ((o0 > 0.0) != (o1 > 0.0) || (o1 > 0.0) != (o2 > 0.0)) continue;
            const double x = (o0 * t.a.x + o1 * t.b.x + o2 * t.c.x) / (o0 + o1 + o2);
            if (x == p.x) return std::nullopt;
            // The projected area's sign is the sign of the face normal's x: > 0, the ray
            // leaves through the front (inside to outside).
            if (x > p.x) w += o0 + o1 + o2 > 0.0 ? 1 : -1;
        }
        return w;
    }

private:
    glm::ivec2 cell(const glm::dvec2& q) const {
        const glm::dvec2 f = (q - lo_) / glm::max(hi_ - lo_, glm::dvec2(1e-300)) * double(n_);
        return glm::clamp(glm::ivec2(glm::floor(f)), glm::ivec2(0), glm::ivec2(n_ - 1));
    }

    std::vector<Triangle> triangles_;
    glm::dvec2 lo_{0.0}, hi_{0.0};
    int n_ = 1;
    std::vector<std::vector<uint32_t>> cells_;
};

// Where two faces of one component meet without sharing a vertex, the surface passes through
// itself and may enclose a pocket inside out (winding number −1: a dent pushed through the
// far wall), where a ray's first face can be a back face: one whose front side has a
// negative winding number. So, in a component that meets itself, the faces that meet
// another beyond what they share (CGAL's exact predicates; caps included) are drawn both
// ways, and so is every other face whose front side has a negative winding number (a ray
// from its centroid). On a face that meets no other the winding number of its front side is the same
// all over it, so the others may skip their back faces. Folds that only reach a winding
// number of 2 — a scan's surface overlapping itself — cost only the faces of the fold.
void mark_faces_near_pockets(const WeldedMesh& closed, const std::vector<int32_t>& component,
                             const std::vector<uint32_t>& source_face, ClosedSurfaces& out) {
    const size_t mesh_faces = source_face.size();  // the caps come after them in `closed`
    std::vector<uint8_t> meets(closed.faces.size(), 0);
    std::vector<bool> crossed(out.components.size(), false);
    for_each_box_pair(
        closed,
        [&](uint32_t a, uint32_t b) {
            if (component[a] != component[b] || !out.components[size_t(component[a])].closable ||
                !triangles_meet(closed, a, b))
                return;
            meets[a] = meets[b] = 1;
            crossed[size_t(component[a])] = true;
        },
        true);
    std::vector<WindingGrid::Triangle> triangles;
    const auto corner = [&](uint32_t f, int k) { return glm::dvec3(closed.positions[closed.faces[f][k]]); };
    for (uint32_t f = 0; f < closed.faces.size(); ++f)
        if (crossed[size_t(component[f])]) triangles.push_back({corner(f, 0), corner(f, 1), corner(f, 2), component[f], f});
    if (triangles.empty()) return;
    const WindingGrid grid(std::move(triangles));
    for (uint32_t f = 0; f < mesh_faces; ++f) {
        if (!crossed[size_t(component[f])]) continue;
        bool both_ways = meets[f] != 0;
        if (!both_ways) {
            // The ray from the centroid along +x, the face itself left out, counts the winding
            // number of the side it leaves into: the front when the normal points along +x,
            // else the back, one more than the front (w = 1 inside an outward surface).
            const glm::dvec3 a = corner(f, 0), b = corner(f, 1), c = corner(f, 2);
            const double nx = glm::cross(b - a, c - a).x;
            const std::optional<int> w = nx == 0.0 ? std::nullopt : grid.winding((a + b + c) / 3.0, component[f], f);
            both_ways = !w || (nx > 0.0 ? *w : *w - 1) < 0;
        }
        if (both_ways) out.face_both_ways[source_face[f]] = 1;
    }
}

// A component wound inside out that lies inside an outward one is the wall of a cavity (a
// hollow solid's inner shell faces into the hollow by right): not `inward`. Decided by the
// winding number, about each outward component whose bounds hold it, of a point of it (the
// centroid of one of its first faces whose ray grazes no edge).
void clear_cavity_walls(const WeldedMesh& closed, const std::vector<int32_t>& component, ClosedSurfaces& out) {
    if (std::ranges::none_of(out.components, &ClosedSurfaces::Component::inward)) return;
    std::vector<WindingGrid::Triangle> triangles;
    const auto corner = [&](uint32_t f, int k) { return glm::dvec3(closed.positions[closed.faces[f][k]]); };
    for (uint32_t f = 0; f < closed.faces.size(); ++f)
        if (out.components[size_t(component[f])].outward)
            triangles.push_back({corner(f, 0), corner(f, 1), corner(f, 2), component[f], f});
    if (triangles.empty()) return;
    const WindingGrid grid(std::move(triangles));
    std::vector<int> tries(out.components.size(), 0);  // faces of each inward component looked at
    for (uint32_t f = 0; f < closed.faces.size(); ++f) {
        ClosedSurfaces::Component& c = out.components[size_t(component[f])];
        if (!c.inward || tries[size_t(component[f])]++ >= 4) continue;
        const glm::dvec3 p = (corner(f, 0) + corner(f, 1) + corner(f, 2)) / 3.0;
        for (size_t o = 0; o < out.components.size() && c.inward; ++o) {
            const ClosedSurfaces::Component& outer = out.components[o];
            if (!outer.outward || glm::any(glm::lessThan(p, glm::dvec3(outer.min))) ||
                glm::any(glm::greaterThan(p, glm::dvec3(outer.max))))
                continue;
            if (const std::optional<int> w = grid.winding(p, int32_t(o), UINT32_MAX); w && *w >= 1) c.inward = false;
        }
    }
}

}  // namespace

ClosedSurfaces find_closed_surfaces(const TriangleMesh& mesh) {
    const WeldedMesh welded = weld(mesh);
    const std::vector<EdgeUse> uses = edge_uses(welded);
    size_t count = 0;
    const std::vector<int32_t> component = face_components(welded, uses, count);
    ClosedSurfaces out;
    out.components.resize(count);
    out.face_component.assign(mesh.triangle_count(), -1);
    // The faces with their caps (a fan from each hole's centroid, wound the other way), as one
    // mesh for the self-intersection search; the components of its faces.
    WeldedMesh closed{.positions = welded.positions, .faces = welded.faces};
    std::vector<int32_t> closed_component = component;
    for (uint32_t f = 0; f < welded.faces.size(); ++f) {
        out.face_component[welded.source_face[f]] = component[f];
        for (int k = 0; k < 3; ++k)
            if (!uses[edge_from(welded, f, k)].closable())
                out.components[size_t(component[f])].closable = false;
    }
    std::vector<bool> closable(count);
    for (size_t c = 0; c < count; ++c) closable[c] = out.components[c].closable;
    for (const auto& [c, hole] : boundary_cycles(welded, uses, component, closable)) {
        if (hole.empty()) {
            out.components[size_t(c)].closable = false;
            continue;
        }
        glm::dvec3 sum(0.0);
        for (uint32_t v : hole) sum += glm::dvec3(welded.positions[v]);
        const auto centre = uint32_t(closed.positions.size());
        closed.positions.push_back(glm::vec3(sum / double(hole.size())));
        for (size_t k = 0; k < hole.size(); ++k) {
            closed.faces.emplace_back(centre, hole[(k + 1) % hole.size()], hole[k]);
            closed_component.push_back(c);
        }
    }
    // Bounds and the closed volume by the divergence theorem, about the bounds' centre (the
    // same for a closed surface whatever the origin; the centre keeps the products small).
    // Against the sum of its terms' sizes: a surface with no volume (a face and its reverse,
    // a flat sheet and its cap) comes out as rounding noise of either sign.
    std::vector<bool> seen(count, false);
    for (uint32_t f = 0; f < closed.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            ClosedSurfaces::Component& in = out.components[size_t(closed_component[f])];
            const glm::vec3 p = closed.positions[closed.faces[f][k]];
            in.min = seen[size_t(closed_component[f])] ? glm::min(in.min, p) : p;
            in.max = seen[size_t(closed_component[f])] ? glm::max(in.max, p) : p;
            seen[size_t(closed_component[f])] = true;
        }
    std::vector<double> volume(count, 0.0), size(count, 0.0);
    for (uint32_t f = 0; f < closed.faces.size(); ++f) {
        const auto c = size_t(closed_component[f]);
        const glm::dvec3 origin = 0.5 * (glm::dvec3(out.components[c].min) + glm::dvec3(out.components[c].max));
        const auto at = [&](int k) { return glm::dvec3(closed.positions[closed.faces[f][k]]) - origin; };
        const double term = glm::dot(at(0), glm::cross(at(1), at(2)));
        volume[c] += term;
        size[c] += std::abs(term);
        if (f >= welded.faces.size())
            for (int k = 0; k < 3; ++k) out.components[c].caps.push_back(closed.positions[closed.faces[f][k]]);
    }
    out.face_both_ways.assign(mesh.triangle_count(), 0);
    mark_faces_near_pockets(closed, closed_component, welded.source_face, out);
    for (size_t c = 0; c < count; ++c) {
        ClosedSurfaces::Component& in = out.components[c];
        in.outward = in.closable && volume[c] > 1e-6 * size[c];
        in.inward = in.closable && in.caps.empty() && volume[c] < -1e-6 * size[c];
    }
    clear_cavity_walls(closed, closed_component, out);
    return out;
}

std::vector<uint8_t> back_faces_hidden(const ClosedSurfaces& surfaces, const CameraMatrices& camera) {
    std::vector<uint8_t> hidden(surfaces.components.size(), 0);
    const glm::dmat4 view(camera.view);
    const glm::dvec3 eye(glm::inverse(view)[3]);
    for (size_t c = 0; c < surfaces.components.size(); ++c) {
        const ClosedSurfaces::Component& in = surfaces.components[c];
        if (!in.outward) continue;
        // Beyond the near plane with a margin for the device's float transform, whose error
        // grows with the size of the coordinates.
        const double scale = std::max(glm::length(glm::dvec3(in.min)), glm::length(glm::dvec3(in.max))) + glm::length(eye);
        const double near = double(camera.znear) * (1.0 + 1e-4) + 1e-5 * scale;
        bool beyond = true;
        for (int corner = 0; corner < 8 && beyond; ++corner) {
            const glm::dvec3 p((corner & 1) ? in.max.x : in.min.x, (corner & 2) ? in.max.y : in.min.y,
                               (corner & 4) ? in.max.z : in.min.z);
            beyond = -(view * glm::dvec4(p, 1.0)).z > near;
        }
        if (!beyond) continue;
        // A cap faces away when the eye (the view's origin) is on its inner side, by more
        // than an edge-on cap's rounding.
        bool caps_away = true;
        for (size_t k = 0; k + 2 < in.caps.size() && caps_away; k += 3) {
            const glm::dvec3 a(view * glm::dvec4(glm::dvec3(in.caps[k]), 1.0));
            const glm::dvec3 b(view * glm::dvec4(glm::dvec3(in.caps[k + 1]), 1.0));
            const glm::dvec3 d(view * glm::dvec4(glm::dvec3(in.caps[k + 2]), 1.0));
            const glm::dvec3 n = glm::cross(b - a, d - a);
            caps_away = glm::dot(n, -a) < -1e-6 * glm::length(n) * glm::length(a);
        }
        hidden[c] = caps_away ? 1 : 0;
    }
    return hidden;
}

}  // namespace lw
