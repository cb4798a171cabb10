#include "render/coverage_reference.h"

#include <algorithm>
#include <cmath>

namespace lw {

std::vector<uint8_t> coverage_reference(const TriangleMesh& mesh, const CameraMatrices& camera, int width,
                                        int height) {
    std::vector<uint8_t> covered(size_t(width) * height, 0);
    std::vector<glm::vec3> pixel(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        pixel[i] = project_to_pixel(camera, mesh.positions[i], float(width), float(height));

    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = pixel[mesh.indices[t]], b = pixel[mesh.indices[t + 1]], c = pixel[mesh.indices[t + 2]];
        if (a.z <= 0.0f || b.z <= 0.0f || c.z <= 0.0f) continue;
        const double area = (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
        if (area == 0.0) continue;
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
        const int x1 = std::min(width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
        const int y1 = std::min(height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        // Edge functions at pixel centres; both windings count (the pass does not cull).
        auto edge = [](glm::vec3 p, glm::vec3 q, double x, double y) {
            return (double(q.x) - p.x) * (y - p.y) - (double(q.y) - p.y) * (x - p.x);
        };
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                const double e0 = edge(a, b, px, py), e1 = edge(b, c, px, py), e2 = edge(c, a, px, py);
                const bool inside = area > 0 ? (e0 >= 0 && e1 >= 0 && e2 >= 0) : (e0 <= 0 && e1 <= 0 && e2 <= 0);
                if (inside) covered[size_t(y) * width + x] = 1;
            }
    }
    return covered;
}

}  // namespace lw
