// engine/render/surface_pass.h — the shaded surface and its depth, rendered offscreen.
//
// Input:  a world-space `TriangleMesh` (uploaded once as a `GpuMesh`), camera matrices and
//         a `SurfaceStyle`.
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
// Headless is the only platform here: render into VkImages with dynamic rendering, copy
// to a host-visible buffer, read back (STYLE.md: lavapipe has no headless surface).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "gpu/timestamps.h"
#include "gpu/render_target.h"
#include "scene/camera.h"
#include "scene/style.h"
#include "scene/triangle_mesh.h"

namespace lw {

// Vertex and index buffers of a mesh on the GPU (interleaved position + normal).
struct GpuMesh {
    Buffer vertices;
    Buffer indices;
    uint32_t index_count = 0;
};
[[nodiscard]] GpuMesh upload_mesh(const Context& ctx, const TriangleMesh& mesh);

class SurfacePass {
public:
    // `samples`: the sample count of the targets it draws into (1, 4 or 8).
    explicit SurfacePass(const Context& ctx, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM, uint32_t samples = 1);

    // Records the pass: clears, draws, and leaves both images in TRANSFER_SRC_OPTIMAL. With
    // `style.draw_surface` off, the colour is only cleared and the mesh drawn depth-only.
    void record(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh& mesh, const CameraMatrices& camera,
                const glm::vec3& eye, const SurfaceStyle& style) const;

    // The same with nothing to draw (a scene of vector layers only): background and far depth.
    void record_clear(VkCommandBuffer cmd, RenderTarget& target, const SurfaceStyle& style) const {
        record_depth_only(cmd, target, nullptr, {}, style);
    }

private:
    void record_depth_only(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh* mesh,
                           const CameraMatrices& camera, const SurfaceStyle& style) const;
    // Points `depth` at the multisampled depth, resolved into the target's (samples > 1).
    void resolve_depth(VkCommandBuffer cmd, RenderTarget& target, VkRenderingAttachmentInfo& depth) const;

    uint32_t samples_ = 1;
    VkResolveModeFlagBits depth_resolve_ = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;
    GraphicsPipeline pipeline_;
    GraphicsPipeline depth_only_;  // lines over the background: depth, no shading
};


// The key light: from the upper left of the view and in front, fixed to the camera so that
// every view of a model is lit the same way.
[[nodiscard]] glm::vec3 key_light_direction(const CameraMatrices& camera);

}  // namespace lw
