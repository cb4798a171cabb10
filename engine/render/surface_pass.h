// engine/render/surface_pass.h — the shaded surface and its depth, rendered offscreen.
//
// Input:  a world-space `TriangleMesh` (uploaded once as a `GpuMesh`, render/
//         surface_materials.h), camera matrices, a `SurfaceStyle` and, when the scene uses
//         them, the mesh's `GpuMaterials`.
// Output: an RGBA8 colour image and a D32 depth image in a `RenderTarget` (see
//         frame_renderer.h for reading them back). The depth image is also what the
//         visibility stage tests line samples against.
//
// Antialiasing: with a multisampled target (RenderTarget::samples 4 or 8) the surface is
// drawn into the target's multisampled images and resolved at the end of the pass: colour
// by the average of the samples, depth by their maximum where the device can (the farthest
// surface in the pixel, as the visibility test's 3×3 neighbourhood takes it), else sample 0.
// Depth-only frames are multisampled too, so that a frame's depth does not depend on
// whether it is drawn.
//
// Materials (glTF 2.0 §3.9): each draw of the mesh takes its material's base colour and
// texture. MASK cuts holes: those pixels get neither colour nor depth, in shaded and
// depth-only frames alike, so lines behind them are visible. BLEND is composited over the
// opaque surface after it and writes no depth: glass and lenses tint what is behind them
// but hide no lines (Freestyle and Line Art treat such faces as transparent too). Blended
// faces are not sorted among themselves.
//
// Back faces: drawn (glTF's single-sided faces too), except in a draw whose faces all belong
// to closed surfaces from whose inside no pixel sees out in this view
// (geometry/closed_surfaces.h, `BackFaceCulling`): there no back face is the first surface
// of a pixel, so skipping them changes neither colour nor depth — the depth the lines'
// visibility reads — but halves the faces lavapipe rasterizes. The pixels that can differ
// are the unculled pass's depth ties, where a back face drawn later wins (LESS_OR_EQUAL): at
// a contour, where a back face folds behind a front one (tests/test_back_faces.cpp allows
// those pixels, and only those), or a closed part thinner than the depth's precision.
//
// Headless is the only platform here: render into VkImages with dynamic rendering, copy
// to a host-visible buffer, read back (STYLE.md: lavapipe has no headless surface).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "geometry/closed_surfaces.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "gpu/timestamps.h"
#include "gpu/render_target.h"
#include "render/surface_materials.h"
#include "scene/camera.h"
#include "scene/style.h"
#include "scene/triangle_mesh.h"

namespace lw {

// What the culling decision needs of each draw, found once per mesh (a pass over its faces):
// the closed-surface components its faces belong to, and whether one of them is to be drawn
// both ways (ClosedSurfaces::face_both_ways). `face_order` maps the index buffer's
// triangles to the mesh's (GpuMesh::face_order). Empty when `surfaces` does not fit.
struct DrawSurfaces {
    std::vector<int32_t> components;  // sorted, distinct; faces with no area (-1) left out
    bool both_ways = false;
};
[[nodiscard]] std::vector<DrawSurfaces> draw_surfaces(const std::vector<MeshDraw>& draws,
                                                      const std::vector<uint32_t>& face_order,
                                                      const ClosedSurfaces& surfaces);

// The faces a view may skip: the mesh's closed surfaces (found once per mesh) and, per
// component, whether its back faces are hidden from this view (`back_faces_hidden`).
// `draws`: draw_surfaces of the mesh's draws, found beforehand so that a frame does not walk
// the faces again (without it, or if it does not fit the draws, cullable_draws finds it).
struct BackFaceCulling {
    const ClosedSurfaces* surfaces = nullptr;
    std::vector<uint8_t> hidden;
    const std::vector<DrawSurfaces>* draws = nullptr;
};

// Per draw, whether it may skip its back faces in this view: the draw is opaque (`opaque`,
// per draw), none of its faces is to be drawn both ways, and every face of the components
// its faces belong to is drawn opaque, each component hidden from the view. `face_order`
// maps the index buffer's triangles to the mesh's (GpuMesh::face_order). Nothing is culled
// when `culling` does not fit the draws.
[[nodiscard]] std::vector<uint8_t> cullable_draws(const std::vector<MeshDraw>& draws,
                                                  const std::vector<uint32_t>& face_order,
                                                  const std::vector<uint8_t>& opaque, const BackFaceCulling* culling);

class SurfacePass {
public:
    // `samples`: the sample count of the targets it draws into (1, 4 or 8).
    explicit SurfacePass(const Context& ctx, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM, uint32_t samples = 1);
    uint32_t samples() const { return samples_; }

    // Records the pass: clears, draws, and leaves both images in TRANSFER_SRC_OPTIMAL. With
    // `style.draw_surface` off, the colour is only cleared and the mesh drawn depth-only.
    // `materials` (indexed by the mesh's draws) colour and cut the surface unless
    // `style.materials` is off; without them every face takes `style.color`.
    // `culling`, when given, lets the draws skip back faces where that changes no pixel.
    void record(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh& mesh, const CameraMatrices& camera,
                const glm::vec3& eye, const SurfaceStyle& style, const GpuMaterials* materials = nullptr,
                const BackFaceCulling* culling = nullptr) const;

    // The same with nothing to draw (a scene of vector layers only): background and far depth.
    void record_clear(VkCommandBuffer cmd, RenderTarget& target, const SurfaceStyle& style) const {
        record_depth_only(cmd, target, nullptr, {}, style);
    }

private:
    void record_depth_only(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh* mesh,
                           const CameraMatrices& camera, const SurfaceStyle& style,
                           const GpuMaterials* materials = nullptr, const BackFaceCulling* culling = nullptr) const;
    // Every draw of the mesh with its material's constants and texture; `depth_only` draws
    // skip blended materials and test masked ones' alpha.
    void draw_materials(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh& mesh, const CameraMatrices& camera,
                        const glm::vec3& eye, const SurfaceStyle& style, const GpuMaterials* materials,
                        bool depth_only, const BackFaceCulling* culling) const;
    // Points `depth` at the multisampled depth, resolved into the target's (samples > 1).
    void resolve_depth(VkCommandBuffer cmd, RenderTarget& target, VkRenderingAttachmentInfo& depth) const;

    uint32_t samples_ = 1;
    VkResolveModeFlagBits depth_resolve_ = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;
    const Context* ctx_;
    GraphicsPipeline pipeline_;    // opaque and masked faces
    GraphicsPipeline blend_;       // blended faces: composited, no depth written
    GraphicsPipeline depth_only_;  // lines over the background: depth, no shading
    GraphicsPipeline depth_mask_;  // the same for masked faces: their alpha test alone
    Image white_;                  // bound where a draw has no texture
    Handle<VkSampler> white_sampler_;
};


// The key light: from the upper left of the view and in front, fixed to the camera so that
// every view of a model is lit the same way.
[[nodiscard]] glm::vec3 key_light_direction(const CameraMatrices& camera);

}  // namespace lw
