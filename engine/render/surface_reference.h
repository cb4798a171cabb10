// engine/render/surface_reference.h — plain C++ reference for the surface pass's materials.
//
// Input:  a world-space mesh (with texture coordinates), its `SurfaceMaterials` with the
//         textures decoded, camera matrices, an image size and the scene colour.
// Output: the unlit surface pass at one sample per pixel: at each pixel centre the nearest
//         triangle's colour — the scene colour without a material, else the base colour
//         factor times the base colour texture, filtered as the GPU sampler does (bilinear
//         on the sRGB-decoded texels, trilinear between the mip levels of srgb_mip_chain at
//         λ = log₂ of the texture footprint of one pixel, glTF's wrap modes), encoded to
//         sRGB. Masked faces below their cutoff are not there (what lies behind shows).
//         Blended faces are left out (the GPU composites them unsorted; tests draw none).
// Pixels no face covers hold the background. Tests compare the GPU's unlit frame to this.
#pragma once

#include <glm/glm.hpp>

#include "core/image.h"
#include "scene/camera.h"
#include "scene/material.h"
#include "scene/triangle_mesh.h"

namespace lw {

[[nodiscard]] ImageRGBA8 surface_reference(const TriangleMesh& mesh, const SurfaceMaterials& materials,
                                           const CameraMatrices& camera, int width, int height,
                                           const glm::vec3& scene_color, const glm::vec3& background);

}  // namespace lw
