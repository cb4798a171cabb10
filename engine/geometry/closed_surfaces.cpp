// engine/geometry/closed_surfaces.cpp — components, their holes and caps, and the view test.
#include "geometry/closed_surfaces.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "geometry/welded_mesh.h"

namespace lw {

namespace {

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// Connected components of the welded faces (through shared vertices), numbered in order of
// their first face; -1 for the vertices no face uses.
std::vector<int32_t> vertex_components(const WeldedMesh& welded, size_t& count) {
    std::vector<uint32_t> parent(welded.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const glm::uvec3& f : welded.faces) {
        const uint32_t r = find_root(parent, f[0]);
        parent[find_root(parent, f[1])] = r;
        parent[find_root(parent, f[2])] = r;
    }
    std::vector<int32_t> component(welded.positions.size(), -1), of_root(welded.positions.size(), -1);
    count = 0;
    for (const glm::uvec3& f : welded.faces) {
        const uint32_t root = find_root(parent, f[0]);
        if (of_root[root] < 0) of_root[root] = int32_t(count++);
        for (int c = 0; c < 3; ++c) component[f[c]] = of_root[root];
    }
    return component;
}

// The boundary of the faces as cycles of welded vertices: an edge used a→b more often than
// b→a is left open that many times. The boundary of a surface is itself closed (as many
// open edges leave each vertex as enter it), so a walk along unused open edges from a vertex
// always comes back to it. Edges are taken in order of first use by the faces.
std::vector<std::vector<uint32_t>> boundary_cycles(const WeldedMesh& welded) {
    std::unordered_map<uint64_t, int32_t> net;  // key (lo, hi): uses lo→hi minus uses hi→lo
    std::vector<uint64_t> order;
    for (const glm::uvec3& f : welded.faces)
        for (int c = 0; c < 3; ++c) {
            const uint32_t a = f[c], b = f[(c + 1) % 3];
            const uint64_t key = uint64_t{std::min(a, b)} << 32 | std::max(a, b);
            const auto [it, inserted] = net.try_emplace(key, 0);
            if (inserted) order.push_back(key);
            it->second += a < b ? 1 : -1;
        }
    std::unordered_map<uint32_t, std::vector<uint32_t>> out;  // open edges leaving a vertex
    std::vector<uint32_t> starts;
    for (uint64_t key : order) {
        const int32_t n = net[key];
        const uint32_t lo = uint32_t(key >> 32), hi = uint32_t(key);
        const uint32_t from = n > 0 ? lo : hi, to = n > 0 ? hi : lo;
        for (int32_t k = 0; k < std::abs(n); ++k) {
            std::vector<uint32_t>& leaving = out[from];
            if (leaving.empty()) starts.push_back(from);
            leaving.push_back(to);
        }
    }
    for (auto& [vertex, leaving] : out) std::reverse(leaving.begin(), leaving.end());  // taken from the back
    std::vector<std::vector<uint32_t>> cycles;
    for (uint32_t start : starts)
        while (!out[start].empty()) {
            std::vector<uint32_t> cycle;
            uint32_t v = start;
            do {
                cycle.push_back(v);
                std::vector<uint32_t>& leaving = out[v];
                v = leaving.back();
                leaving.pop_back();
            } while (v != start);
            cycles.push_back(std::move(cycle));
        }
    return cycles;
}

}  // namespace

ClosedSurfaces find_closed_surfaces(const TriangleMesh& mesh) {
    const WeldedMesh welded = weld(mesh);
    size_t count = 0;
    const std::vector<int32_t> component = vertex_components(welded, count);
    ClosedSurfaces out;
    out.components.resize(count);
    out.face_component.assign(mesh.triangle_count(), -1);
    for (size_t f = 0; f < welded.faces.size(); ++f) {
        const int32_t c = component[welded.faces[f][0]];
        out.face_component[welded.source_face[f]] = c;
        const glm::uvec3& w = welded.faces[f];
        out.components[size_t(c)].triangles.push_back(
            {welded.source_vertex[w[0]], welded.source_vertex[w[1]], welded.source_vertex[w[2]]});
    }
    for (size_t v = 0; v < welded.positions.size(); ++v)
        if (component[v] >= 0) out.components[size_t(component[v])].vertices.push_back(welded.source_vertex[v]);
    for (std::vector<uint32_t>& cycle : boundary_cycles(welded)) {
        const int32_t c = component[cycle.front()];
        for (uint32_t& v : cycle) v = welded.source_vertex[v];
        out.components[size_t(c)].holes.push_back(std::move(cycle));
    }
    std::vector<bool> used(mesh.positions.size(), false);
    for (uint32_t v : mesh.indices) used[v] = true;  // weld has checked the indices
    for (uint32_t v = 0; v < used.size(); ++v) {
        const uint32_t source = welded.source_vertex[welded.welded_index[v]];
        if (!used[v] || source == v) continue;
        out.copies.push_back(v);
        out.copy_of.push_back(source);
    }
    return out;
}

ClosedSurfacePose pose_closed_surfaces(const ClosedSurfaces& surfaces, const std::vector<glm::vec3>& positions) {
    ClosedSurfacePose pose;
    for (size_t i = 0; i < surfaces.copies.size(); ++i)
        if (positions[surfaces.copies[i]] != positions[surfaces.copy_of[i]]) pose.welds_hold = false;
    pose.components.resize(surfaces.components.size());
    for (size_t c = 0; c < surfaces.components.size(); ++c) {
        const ClosedSurfaces::Component& in = surfaces.components[c];
        ClosedSurfacePose::Component& out = pose.components[c];
        out.min = out.max = positions[in.vertices.front()];
        for (uint32_t v : in.vertices) {
            out.min = glm::min(out.min, positions[v]);
            out.max = glm::max(out.max, positions[v]);
        }
        for (const std::vector<uint32_t>& hole : in.holes) {
            glm::dvec3 sum(0.0);
            for (uint32_t v : hole) sum += glm::dvec3(positions[v]);
            const glm::vec3 centre = glm::vec3(sum / double(hole.size()));
            for (size_t k = 0; k < hole.size(); ++k) {
                out.cap_triangles.push_back(centre);
                out.cap_triangles.push_back(positions[hole[(k + 1) % hole.size()]]);
                out.cap_triangles.push_back(positions[hole[k]]);
            }
        }
        // The closed volume by the divergence theorem, about the bounds' centre (exact for a
        // closed surface whatever the origin; the centre keeps the products small).
        const glm::dvec3 origin = 0.5 * (glm::dvec3(out.min) + glm::dvec3(out.max));
        const auto volume_of = [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& d) {
            return glm::dot(glm::dvec3(a) - origin, glm::cross(glm::dvec3(b) - origin, glm::dvec3(d) - origin));
        };
        double volume = 0.0;
        for (const glm::uvec3& t : in.triangles) volume += volume_of(positions[t[0]], positions[t[1]], positions[t[2]]);
        for (size_t k = 0; k + 2 < out.cap_triangles.size(); k += 3)
            volume += volume_of(out.cap_triangles[k], out.cap_triangles[k + 1], out.cap_triangles[k + 2]);
        out.outward = volume > 0.0;
    }
    return pose;
}

std::vector<uint8_t> back_faces_hidden(const ClosedSurfacePose& pose, const CameraMatrices& camera) {
    std::vector<uint8_t> hidden(pose.components.size(), 0);
    if (!pose.welds_hold) return hidden;
    const glm::dmat4 view(camera.view);
    // A little beyond the near plane: the test must hold where the clip does.
    const double near = double(camera.znear) * (1.0 + 1e-4);
    for (size_t c = 0; c < pose.components.size(); ++c) {
        const ClosedSurfacePose::Component& in = pose.components[c];
        if (!in.outward) continue;
        bool beyond = true;
        for (int corner = 0; corner < 8 && beyond; ++corner) {
            const glm::dvec3 p((corner & 1) ? in.max.x : in.min.x, (corner & 2) ? in.max.y : in.min.y,
                               (corner & 4) ? in.max.z : in.min.z);
            beyond = -(view * glm::dvec4(p, 1.0)).z > near;
        }
        if (!beyond) continue;
        // A cap faces the eye when the eye (the view's origin) is on its outer side.
        bool caps_away = true;
        for (size_t k = 0; k + 2 < in.cap_triangles.size() && caps_away; k += 3) {
            const glm::dvec3 a(view * glm::dvec4(glm::dvec3(in.cap_triangles[k]), 1.0));
            const glm::dvec3 b(view * glm::dvec4(glm::dvec3(in.cap_triangles[k + 1]), 1.0));
            const glm::dvec3 d(view * glm::dvec4(glm::dvec3(in.cap_triangles[k + 2]), 1.0));
            caps_away = glm::dot(glm::cross(b - a, d - a), -a) <= 0.0;
        }
        hidden[c] = caps_away ? 1 : 0;
    }
    return hidden;
}

}  // namespace lw
