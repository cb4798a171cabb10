// engine/render/surface_materials.h — a shaded mesh and its materials on the GPU.
//
// Input:  a world-space `TriangleMesh` and, optionally, its `SurfaceMaterials` (scene/
//         material.h: per-triangle material, base colours, decoded base colour textures).
// Output: `GpuMesh` — vertex and index buffers with the triangles grouped into one draw per
//         material (blended materials last, so that they composite over what is opaque);
//         `GpuMaterials` — each material's texture as an sRGB, mipmapped image with its
//         glTF sampler, each image uploaded once however many materials sample it.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/resources.h"
#include "scene/material.h"
#include "scene/triangle_mesh.h"

namespace lw {

// A run of the index buffer drawn with one material (-1: the scene colour).
struct MeshDraw {
    int material = -1;
    uint32_t first_index = 0;
    uint32_t index_count = 0;
};

// Vertex and index buffers of a mesh on the GPU (interleaved position, normal, texture
// coordinates), and the draws that cover its index buffer.
struct GpuMesh {
    Buffer vertices;
    Buffer indices;
    uint32_t index_count = 0;
    std::vector<MeshDraw> draws;  // one per material present, in drawing order
    std::vector<uint32_t> face_order;  // per triangle of the index buffer: the input mesh's triangle
};

// Triangles reordered by material when `face_material` has one entry per triangle (else one
// draw of everything with -1): opaque and masked materials in index order, then blended ones.
// The order within a material is the mesh's, except that the triangles `both_ways` marks
// (one byte per triangle: ClosedSurfaces::face_both_ways) follow the others in a draw of
// their own, so that the rest of the material may skip back faces (render/surface_pass.h).
[[nodiscard]] GpuMesh upload_mesh(const Context& ctx, const TriangleMesh& mesh,
                                  const SurfaceMaterials* materials = nullptr,
                                  const std::vector<uint8_t>* both_ways = nullptr);

class GpuMaterials {
public:
    GpuMaterials(const Context& ctx, const SurfaceMaterials& materials);

    size_t size() const { return materials_.size(); }
    const Material& material(size_t m) const { return materials_[m]; }
    bool textured(size_t m) const { return image_of_[m] >= 0; }
    // The texture of a textured material.
    VkImageView view(size_t m) const { return images_[size_t(image_of_[m])].view(); }
    VkSampler sampler(size_t m) const { return samplers_[m].get(); }

private:
    std::vector<Material> materials_;
    std::vector<int32_t> image_of_;  // per material: index in images_, -1: none
    std::vector<Image> images_;
    std::vector<Handle<VkSampler>> samplers_;  // per textured material: its glTF sampler
};

// A 1 × 1 white texture (the image bound where no material texture is).
[[nodiscard]] Image white_texture(const Context& ctx);

}  // namespace lw
