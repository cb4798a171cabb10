#include "render/surface_reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/color.h"

namespace lw {

namespace {

// One mip chain in linear light (straight alpha), as the GPU's sRGB format reads it.
struct LinearLevel {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;
};

std::vector<LinearLevel> linear_chain(const ImageRGBA8& texels, bool mipmaps) {
    std::vector<LinearLevel> out;
    for (const ImageRGBA8& level : mipmaps ? srgb_mip_chain(texels) : std::vector<ImageRGBA8>{texels}) {
        LinearLevel l{level.width, level.height, std::vector<glm::vec4>(size_t(level.width) * size_t(level.height))};
        for (size_t i = 0; i < l.texels.size(); ++i) {
            const uint8_t* p = &level.pixels[i * 4];
            l.texels[i] = {srgb_to_linear(p[0] / 255.0f), srgb_to_linear(p[1] / 255.0f), srgb_to_linear(p[2] / 255.0f),
                           p[3] / 255.0f};
        }
        out.push_back(std::move(l));
    }
    return out;
}

// Vulkan's addressing of texel index i in [0, n) for each wrap mode.
int wrap_index(int i, int n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return std::clamp(i, 0, n - 1);
        case TextureWrap::MirroredRepeat: {
            const int period = 2 * n;
            int m = ((i % period) + period) % period;
            return m < n ? m : period - 1 - m;
        }
        case TextureWrap::Repeat: break;
    }
    return ((i % n) + n) % n;
}

glm::vec4 sample_level(const LinearLevel& l, glm::vec2 uv, bool nearest, const TextureRef& ref) {
    const auto texel = [&](int x, int y) {
        return l.texels[size_t(wrap_index(y, l.height, ref.wrap_t)) * size_t(l.width) +
                        size_t(wrap_index(x, l.width, ref.wrap_s))];
    };
    const float x = uv.x * float(l.width), y = uv.y * float(l.height);
    if (nearest) return texel(int(std::floor(x)), int(std::floor(y)));
    const float fx = x - 0.5f, fy = y - 0.5f;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const float ax = fx - float(x0), ay = fy - float(y0);
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), ax), glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), ax),
                    ay);
}

// Vulkan §16 "Texel Filtering": λ = log₂ ρ of the larger footprint axis; magnification at
// λ ≤ 0, else the nearest level (level ⌈d + ½⌉ − 1) or a linear blend of the two nearest.
glm::vec4 sample(const std::vector<LinearLevel>& chain, const TextureRef& ref, glm::vec2 uv, glm::vec2 dx, glm::vec2 dy) {
    const glm::vec2 size(chain[0].width, chain[0].height);
    const float rho = std::max(glm::length(dx * size), glm::length(dy * size));
    const float lambda = rho > 0.0f ? std::log2(rho) : -1.0f;
    if (lambda <= 0.0f) return sample_level(chain[0], uv, ref.nearest_mag, ref);
    const float d = std::min(lambda, float(chain.size() - 1));
    if (ref.nearest_mip) {
        const int level = d <= 0.5f ? 0 : int(std::ceil(d + 0.5f)) - 1;
        return sample_level(chain[size_t(level)], uv, ref.nearest_min, ref);
    }
    const int lo = int(std::floor(d));
    const int hi = std::min(lo + 1, int(chain.size()) - 1);
    return glm::mix(sample_level(chain[size_t(lo)], uv, ref.nearest_min, ref),
                    sample_level(chain[size_t(hi)], uv, ref.nearest_min, ref), d - float(lo));
}

uint8_t encode(float linear) { return unit_to_byte(linear_to_srgb(linear)); }

}  // namespace

ImageRGBA8 surface_reference(const TriangleMesh& mesh, const SurfaceMaterials& materials, const CameraMatrices& camera,
                             int width, int height, const glm::vec3& scene_color, const glm::vec3& background) {
    std::vector<std::vector<LinearLevel>> chains(materials.materials.size());
    for (size_t m = 0; m < chains.size() && m < materials.material_image.size(); ++m)
        if (const int32_t image = materials.material_image[m]; image >= 0)
            chains[m] = linear_chain(materials.images[size_t(image)], materials.materials[m].base_color_texture.mipmaps);
    const bool textured = mesh.texcoords.size() == mesh.positions.size();

    ImageRGBA8 out{width, height, std::vector<uint8_t>(size_t(width) * size_t(height) * 4)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            uint8_t* p = out.at(x, y);
            for (int c = 0; c < 3; ++c) p[c] = unit_to_byte(background[c]);
            p[3] = 255;
        }
    std::vector<float> nearest(size_t(width) * size_t(height), 0.0f);  // 1/w of what the pixel shows
    std::vector<glm::vec3> pixel(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        pixel[i] = project_to_pixel(camera, mesh.positions[i], float(width), float(height));

    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const std::array<uint32_t, 3> v{mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
        const glm::vec3 a = pixel[v[0]], b = pixel[v[1]], c = pixel[v[2]];
        if (a.z <= 0.0f || b.z <= 0.0f || c.z <= 0.0f) continue;
        const double area = (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
        if (area == 0.0) continue;
        const int m = t < materials.face_material.size() ? materials.face_material[t] : -1;
        const Material* material = m >= 0 && size_t(m) < materials.materials.size() ? &materials.materials[size_t(m)] : nullptr;
        if (material && material->alpha_mode == AlphaMode::Blend) continue;
        const std::vector<LinearLevel>* chain = material && !chains[size_t(m)].empty() && textured ? &chains[size_t(m)] : nullptr;
        // Screen barycentrics of a point, and the perspective-correct uv there.
        const auto barycentric = [&](double px, double py) {
            const double wa = ((double(b.x) - px) * (double(c.y) - py) - (double(b.y) - py) * (double(c.x) - px)) / area;
            const double wb = ((double(c.x) - px) * (double(a.y) - py) - (double(c.y) - py) * (double(a.x) - px)) / area;
            return glm::dvec3(wa, wb, 1.0 - wa - wb);
        };
        const glm::dvec3 inv_w(1.0 / a.z, 1.0 / b.z, 1.0 / c.z);
        const auto uv_at = [&](double px, double py) {
            const glm::dvec3 l = barycentric(px, py) * inv_w;
            const glm::dvec2 uv = (l.x * glm::dvec2(mesh.texcoords[v[0]]) + l.y * glm::dvec2(mesh.texcoords[v[1]]) +
                                   l.z * glm::dvec2(mesh.texcoords[v[2]])) / (l.x + l.y + l.z);
            return glm::vec2(uv);
        };
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
        const int x1 = std::min(width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
        const int y1 = std::min(height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                const glm::dvec3 l = barycentric(px, py);
                if (!(l.x >= 0 && l.y >= 0 && l.z >= 0)) continue;  // both windings: the pass does not cull
                const float depth = float(glm::dot(l, inv_w));
                float& here = nearest[size_t(y) * size_t(width) + size_t(x)];
                if (depth <= here) continue;
                glm::vec4 color(scene_color, 1.0f);
                bool linear = false;
                if (material && material->has_color) {
                    color = material->base_color;
                    linear = true;
                    if (chain) {
                        const glm::vec2 uv = uv_at(px, py);
                        color *= sample(*chain, material->base_color_texture, uv, uv_at(px + 1, py) - uv,
                                        uv_at(px, py + 1) - uv);
                    }
                }
                if (material && material->alpha_mode == AlphaMode::Mask && color.a < material->alpha_cutoff) continue;
                here = depth;
                uint8_t* p = out.at(x, y);
                for (int k = 0; k < 3; ++k) p[k] = linear ? encode(color[k]) : unit_to_byte(color[k]);
            }
    }
    return out;
}

}  // namespace lw
