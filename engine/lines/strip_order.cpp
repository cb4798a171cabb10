#include "lines/strip_order.h"

#include <algorithm>

namespace lw {

namespace {

int index_of(const glm::uvec3& face, uint32_t v) { return face.x == v ? 0 : face.y == v ? 1 : face.z == v ? 2 : -1; }

StripCorners pack(int c0, int c1, int c2) { return StripCorners(c0 | c1 << 2 | c2 << 4); }

struct StripBuilder {
    const WeldedMesh& mesh;
    std::vector<glm::ivec3> across;  // trimesh2's across_edge: the face across the edge opposite each corner
    std::vector<int8_t> available;   // free neighbours; −1 once in a strip
    std::vector<uint32_t> todo;      // faces left with one free neighbour, taken last first
    std::vector<StripCorners> order;

    // One strip from face f, as trimesh2's tstrip_build.
    void build(uint32_t f) {
        const glm::uvec3 start = mesh.faces[f];
        if (available[f] == 0) {  // no free neighbour: a strip of its own, corners as stored
            order[f] = pack(0, 1, 2);
            available[f] = -1;
            return;
        }
        // Start across the edge whose far side can run on longest.
        int score[3];
        for (int i = 0; i < 3; ++i) {
            score[i] = 0;
            const int ae = across[f][i];
            if (ae == -1 || available[size_t(ae)] < 0) continue;
            ++score[i];
            const int next_edge = index_of(mesh.faces[size_t(ae)], start[(i + 1) % 3]);
            const int nae = next_edge < 0 ? -1 : across[size_t(ae)][next_edge];
            if (nae == -1 || available[size_t(nae)] < 0) continue;
            ++score[i];
            if (available[size_t(ae)] == 2) ++score[i];
        }
        const int best_score = std::max({score[0], score[1], score[2]});
        const int best = score[0] == best_score ? 0 : score[1] == best_score ? 1 : 2;
        uint32_t last2 = start[best], last1 = start[(best + 1) % 3], next = start[(best + 2) % 3];
        int dir = 1;
        for (;;) {
            const glm::uvec3 face = mesh.faces[f];
            order[f] = pack(index_of(face, last2), index_of(face, last1), index_of(face, next));
            available[f] = -1;
            for (int j = 0; j < 3; ++j) {
                const int ae = across[f][j];
                if (ae == -1) continue;
                if (available[size_t(ae)] > 0) --available[size_t(ae)];
                if (available[size_t(ae)] == 1) todo.push_back(uint32_t(ae));
            }
            const int at = index_of(face, last2);
            if (at < 0) break;
            const int following = across[f][at];
            if (following == -1 || available[size_t(following)] < 0) break;
            f = uint32_t(following);
            last2 = last1;
            last1 = next;
            next = mesh.faces[f][size_t((index_of(mesh.faces[f], last2) + 3 + dir) % 3)];
            dir = -dir;
        }
    }
};

}  // namespace

std::vector<StripCorners> strip_corner_order(const WeldedMesh& mesh, const std::vector<uint32_t>& offsets,
                                             const std::vector<uint32_t>& vertex_faces) {
    const size_t nf = mesh.faces.size();
    StripBuilder b{mesh, std::vector<glm::ivec3>(nf, glm::ivec3(-1)), std::vector<int8_t>(nf), {}, std::vector<StripCorners>(nf)};
    for (size_t i = 0; i < nf; ++i)
        for (int j = 0; j < 3; ++j) {
            const uint32_t v1 = mesh.faces[i][(j + 1) % 3], v2 = mesh.faces[i][(j + 2) % 3];
            for (uint32_t k = offsets[v1]; k < offsets[v1 + 1]; ++k) {
                const uint32_t other = vertex_faces[k];
                if (other == i) continue;
                const int at = index_of(mesh.faces[other], v2);
                if (at < 0 || mesh.faces[other][(at + 1) % 3] != v1) continue;
                b.across[i][j] = int(other);
                break;
            }
        }
    for (size_t i = 0; i < nf; ++i) {
        b.available[i] = int8_t((b.across[i][0] != -1) + (b.across[i][1] != -1) + (b.across[i][2] != -1));
        if (b.available[i] == 1) b.todo.push_back(uint32_t(i));
    }
    size_t i = 0;
    while (i < nf) {
        uint32_t next;
        if (b.todo.empty()) {
            next = uint32_t(i++);
        } else {
            next = b.todo.back();
            b.todo.pop_back();
        }
        if (b.available[next] < 0) continue;
        b.build(next);
    }
    return b.order;
}

}  // namespace lw
