#include "render/surface_materials.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "core/error.h"
#include "core/log.h"

namespace lw {

namespace {

// Mirrors the vertex inputs of shaders/surface.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

VkSamplerAddressMode address_mode(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case TextureWrap::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case TextureWrap::Repeat: break;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

// The texture with its mip chain (averaged in linear light, core/image.h) in one upload.
// A texture larger than the device takes is drawn from its first mip level that fits (a
// warning naming `what`), not refused: the rest of the scene does not depend on it.
Image upload_texture(const Context& ctx, const ImageRGBA8& texels, bool mipmaps, const std::string& what) {
    const auto max_dim = int(ctx.properties().limits.maxImageDimension2D);
    const bool too_large = texels.width > max_dim || texels.height > max_dim;
    std::vector<ImageRGBA8> levels = mipmaps || too_large ? srgb_mip_chain(texels) : std::vector<ImageRGBA8>{texels};
    if (too_large) {
        size_t first = 0;
        while (levels[first].width > max_dim || levels[first].height > max_dim) ++first;  // 1 × 1 always fits
        log_warning(what + ": its " + std::to_string(texels.width) + "x" + std::to_string(texels.height) +
                    " texture exceeds the device's " + std::to_string(max_dim) + "; drawn from its " +
                    std::to_string(levels[first].width) + "x" + std::to_string(levels[first].height) + " mip level");
        levels.erase(levels.begin(), levels.begin() + std::ptrdiff_t(first));
        if (!mipmaps) levels.resize(1);
    }
    std::vector<std::byte> bytes;
    for (const ImageRGBA8& level : levels) {
        const auto* p = reinterpret_cast<const std::byte*>(level.pixels.data());
        bytes.insert(bytes.end(), p, p + level.pixels.size());
    }
    Image image(ctx, {.width = uint32_t(levels[0].width),
                      .height = uint32_t(levels[0].height),
                      .format = VK_FORMAT_R8G8B8A8_SRGB,
                      .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                      .name = "material texture",
                      .mip_levels = uint32_t(levels.size())});
    upload_image(ctx, image, bytes);
    return image;
}

}  // namespace

GpuMesh upload_mesh(const Context& ctx, const TriangleMesh& mesh, const SurfaceMaterials* materials,
                    const std::vector<uint8_t>* both_ways) {
    const bool textured = mesh.texcoords.size() == mesh.positions.size();
    std::vector<Vertex> vertices(mesh.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {mesh.positions[i], mesh.normals[i], textured ? mesh.texcoords[i] : glm::vec2(0.0f)};

    const size_t triangles = mesh.triangle_count();
    std::vector<uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    const bool grouped = materials && materials->face_material.size() == triangles;
    const bool split = both_ways && both_ways->size() == triangles;
    const auto material_of = [&](uint32_t t) { return grouped ? materials->face_material[t] : -1; };
    const auto kept_apart = [&](uint32_t t) { return split && (*both_ways)[t] != 0; };
    const auto blended = [&](int m) {
        return grouped && m >= 0 && size_t(m) < materials->materials.size() &&
               materials->materials[size_t(m)].alpha_mode == AlphaMode::Blend;
    };
    if (grouped || split)
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            const int ma = material_of(a), mb = material_of(b);
            return std::tuple(blended(ma), ma, kept_apart(a)) < std::tuple(blended(mb), mb, kept_apart(b));
        });
    std::vector<uint32_t> indices;
    indices.reserve(mesh.indices.size());
    GpuMesh out;
    bool apart = false;
    for (uint32_t t : order) {
        const int m = material_of(t);
        if (out.draws.empty() || out.draws.back().material != m || apart != kept_apart(t))
            out.draws.push_back({.material = m, .first_index = uint32_t(indices.size())});
        apart = kept_apart(t);
        for (int c = 0; c < 3; ++c) indices.push_back(mesh.indices[size_t(t) * 3 + size_t(c)]);
        out.draws.back().index_count += 3;
    }
    out.vertices = upload_buffer(ctx, vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "mesh vertices");
    out.indices = upload_buffer(ctx, indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "mesh indices");
    out.index_count = uint32_t(indices.size());
    out.face_order = std::move(order);
    return out;
}

Image white_texture(const Context& ctx) {
    return upload_texture(ctx, ImageRGBA8{1, 1, {255, 255, 255, 255}}, false, "white texture");
}

GpuMaterials::GpuMaterials(const Context& ctx, const SurfaceMaterials& materials)
    : materials_(materials.materials), image_of_(materials.material_image) {
    image_of_.resize(materials_.size(), -1);
    for (int32_t image : image_of_)
        if (image >= 0 && size_t(image) >= materials.images.size())
            throw Error("surface materials: a material names image " + std::to_string(image) + " of " +
                        std::to_string(materials.images.size()));
    // Each image once, with its mip chain if any material that samples it minifies through it.
    images_.resize(materials.images.size());
    for (size_t i = 0; i < images_.size(); ++i) {
        std::string users;
        bool mipmaps = false;
        for (size_t m = 0; m < materials_.size(); ++m)
            if (image_of_[m] == int32_t(i)) {
                users += (users.empty() ? "material \"" : ", \"") + materials_[m].name + "\"";
                mipmaps = mipmaps || materials_[m].base_color_texture.mipmaps;
            }
        if (!users.empty()) images_[i] = upload_texture(ctx, materials.images[i], mipmaps, users);
    }
    samplers_.resize(materials_.size());
    for (size_t m = 0; m < materials_.size(); ++m) {
        if (!textured(m)) continue;
        const TextureRef& ref = materials_[m].base_color_texture;
        // One level (minFilter NEAREST or LINEAR without mipmaps, or a 1 × 1 image): max_lod
        // 0.25 keeps λ > 0 minified by minFilter while NEAREST mip selection stays on level 0
        // (resources.h).
        const uint32_t levels = ref.mipmaps ? images_[size_t(image_of_[m])].mip_levels() : 1;
        samplers_[m] = create_sampler(
            ctx, {.filter = ref.nearest_mag ? VK_FILTER_NEAREST : VK_FILTER_LINEAR,
                  .min_filter = ref.nearest_min ? VK_FILTER_NEAREST : VK_FILTER_LINEAR,
                  .address_u = address_mode(ref.wrap_s),
                  .address_v = address_mode(ref.wrap_t),
                  .max_lod = levels > 1 ? float(levels - 1) : 0.25f,
                  .mipmap_mode = ref.nearest_mip || levels == 1 ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                                : VK_SAMPLER_MIPMAP_MODE_LINEAR});
    }
}

}  // namespace lw
