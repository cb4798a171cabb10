#include "render/surface_pass.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"

#include "surface_frag.h"
#include "surface_mask_frag.h"
#include "surface_vert.h"

namespace lw {

namespace {

// Mirrors `SurfacePush` in shaders/surface_shared.glsl.
struct SurfacePush {
    glm::mat4 view_proj;
    glm::vec4 eye;        // w: shading mode
    glm::vec4 light_dir;  // w: alpha cutoff, < 0 for none
    glm::vec4 base_color;
    glm::ivec4 material;  // x: material colour (linear), y: textured, z: blended
};
static_assert(sizeof(SurfacePush) == 128, "push constant layout must match surface_shared.glsl");

// The vertex layout of upload_mesh (render/surface_materials.cpp): position, normal, uv.
constexpr uint32_t kVertexStride = 8 * sizeof(float);

// One pipeline of the pass: `fragment` empty for depth only, `blend` for blended faces.
GraphicsPipelineDesc pass_desc(const Context& ctx, std::span<const uint32_t> fragment, VkFormat color_format,
                               uint32_t samples, bool blend, const char* name) {
    return {.vertex_spirv = LW_SPIRV(surface_vert_spv),
            .fragment_spirv = fragment,
            .vertex_stride = kVertexStride,
            .attributes = {{.location = 0, .format = VK_FORMAT_R32G32B32_SFLOAT, .offset = 0},
                           {.location = 1, .format = VK_FORMAT_R32G32B32_SFLOAT, .offset = 3 * sizeof(float)},
                           {.location = 2, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 6 * sizeof(float)}},
            .dynamic_cull_mode = true,  // back faces only where no pixel can see one (draw_materials)
            .color_format = color_format,
            .depth_write = !blend,
            .blend = blend ? BlendMode::Alpha : BlendMode::None,
            .sampled_images = fragment.empty() ? 0u : 1u,
            .push_constant_size = sizeof(SurfacePush),
            .name = name,
            .samples = sample_count_bit(ctx, samples)};
}

}  // namespace

SurfacePass::SurfacePass(const Context& ctx, VkFormat color_format, uint32_t samples)
    : samples_(samples),
      depth_resolve_(ctx.depth_resolve_modes() & VK_RESOLVE_MODE_MAX_BIT ? VK_RESOLVE_MODE_MAX_BIT
                                                                         : VK_RESOLVE_MODE_SAMPLE_ZERO_BIT),
      ctx_(&ctx),
      pipeline_(ctx, pass_desc(ctx, LW_SPIRV(surface_frag_spv), color_format, samples, false, "surface")),
      blend_(ctx, pass_desc(ctx, LW_SPIRV(surface_frag_spv), color_format, samples, true, "surface blended")),
      depth_only_(ctx, pass_desc(ctx, {}, VK_FORMAT_UNDEFINED, samples, false, "surface depth only")),
      depth_mask_(ctx, pass_desc(ctx, LW_SPIRV(surface_mask_frag_spv), VK_FORMAT_UNDEFINED, samples, false,
                                 "surface depth only, masked")),
      white_(white_texture(ctx)),
      white_sampler_(create_sampler(ctx, {})) {}

glm::vec3 key_light_direction(const CameraMatrices& camera) {
    const glm::vec3 view_space = glm::normalize(glm::vec3(-0.4f, 0.6f, 0.7f));
    return glm::normalize(glm::vec3(glm::inverse(camera.view) * glm::vec4(view_space, 0.0f)));
}

namespace {

// Depth tests and writes, and (multisampled) the resolve, which writes the single-sample
// image in the colour-attachment-output stage with colour-attachment access (Vulkan spec,
// "Multisample resolve operations": for depth attachments too).
constexpr VkPipelineStageFlags2 kDepthStages = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                               VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT |
                                               VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags2 kDepthAccess = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;

// An attachment image from whatever it held (discarded) to attachment use.
void to_attachment(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, VkPipelineStageFlags2 stages,
                   VkAccessFlags2 access) {
    record_image_barrier(cmd, image,
                         {.old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                          .new_layout = layout,
                          .src_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          .src_access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                          .dst_stage = stages,
                          .dst_access = access});
}

// Depth: cleared to 1 (far), written by the mesh, then left readable by copies.
void begin_depth(VkCommandBuffer cmd, RenderTarget& target) {
    to_attachment(cmd, target.depth, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, kDepthStages, kDepthAccess);
}

void end_depth(VkCommandBuffer cmd, RenderTarget& target) {
    record_image_barrier(cmd, target.depth,
                         {.old_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                          .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          .src_stage = kDepthStages,
                          .src_access = kDepthAccess,
                          .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                          .dst_access = VK_ACCESS_2_TRANSFER_READ_BIT});
}

VkRenderingAttachmentInfo depth_attachment(RenderTarget& target) {
    VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                    .imageView = target.depth.view(),
                                    .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                    .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                    .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    depth.clearValue.depthStencil = {1.0f, 0};
    return depth;
}

// What a draw of one material pushes: the scene colour without materials, else its factor,
// texture, cutoff and blending.
SurfacePush material_push(const CameraMatrices& camera, const glm::vec3& eye, const SurfaceStyle& style,
                          const Material* material, bool textured) {
    SurfacePush push{.view_proj = camera.view_proj,
                     .eye = glm::vec4(eye, float(int(style.shading))),
                     .light_dir = glm::vec4(key_light_direction(camera), -1.0f),
                     .base_color = glm::vec4(style.color, 1.0f),
                     .material = glm::ivec4(0)};
    if (!material) return push;
    if (material->has_color) {
        push.base_color = material->base_color;
        push.material.x = 1;
        push.material.y = textured ? 1 : 0;
    }
    if (material->alpha_mode == AlphaMode::Mask) push.light_dir.w = material->alpha_cutoff;
    push.material.z = material->alpha_mode == AlphaMode::Blend ? 1 : 0;
    return push;
}

// The background, or nothing at all (premultiplied: no colour where there is no alpha).
VkClearColorValue clear_color(const SurfaceStyle& style) {
    if (style.transparent) return {{0.0f, 0.0f, 0.0f, 0.0f}};
    return {{style.background.r, style.background.g, style.background.b, 1.0f}};
}

}  // namespace

void SurfacePass::resolve_depth(VkCommandBuffer cmd, RenderTarget& target, VkRenderingAttachmentInfo& depth) const {
    to_attachment(cmd, target.msaa_depth, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, kDepthStages, kDepthAccess);
    depth.resolveMode = depth_resolve_;
    depth.resolveImageView = target.depth.view();
    depth.resolveImageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.imageView = target.msaa_depth.view();
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
}

std::vector<DrawSurfaces> draw_surfaces(const std::vector<MeshDraw>& draws, const std::vector<uint32_t>& face_order,
                                        const ClosedSurfaces& surfaces) {
    const std::vector<int32_t>& component = surfaces.face_component;
    const std::vector<uint8_t>& both_ways = surfaces.face_both_ways;
    if (component.size() != face_order.size() || both_ways.size() != component.size()) return {};
    std::vector<DrawSurfaces> out(draws.size());
    for (size_t d = 0; d < draws.size(); ++d) {
        DrawSurfaces& draw = out[d];
        for (size_t k = draws[d].first_index / 3; k < (size_t(draws[d].first_index) + draws[d].index_count) / 3; ++k) {
            const uint32_t face = face_order[k];
            draw.both_ways = draw.both_ways || both_ways[face] != 0;
            if (component[face] >= 0) draw.components.push_back(component[face]);
        }
        std::sort(draw.components.begin(), draw.components.end());
        draw.components.erase(std::unique(draw.components.begin(), draw.components.end()), draw.components.end());
    }
    return out;
}

std::vector<uint8_t> cullable_draws(const std::vector<MeshDraw>& draws, const std::vector<uint32_t>& face_order,
                                    const std::vector<uint8_t>& opaque, const BackFaceCulling* culling) {
    std::vector<uint8_t> cull(draws.size(), 0);
    if (!culling || !culling->surfaces || culling->hidden.size() != culling->surfaces->components.size() ||
        opaque.size() != draws.size())
        return cull;
    std::vector<DrawSurfaces> found;
    const std::vector<DrawSurfaces>* per_draw = culling->draws;
    if (!per_draw || per_draw->size() != draws.size()) {
        found = draw_surfaces(draws, face_order, *culling->surfaces);
        if (found.size() != draws.size()) return cull;
        per_draw = &found;
    }
    std::vector<uint8_t> ok = culling->hidden;
    for (size_t d = 0; d < draws.size(); ++d)
        if (!opaque[d])
            for (int32_t c : (*per_draw)[d].components) ok[size_t(c)] = 0;
    for (size_t d = 0; d < draws.size(); ++d) {
        const DrawSurfaces& draw = (*per_draw)[d];
        cull[d] = opaque[d] && !draw.both_ways &&
                  std::all_of(draw.components.begin(), draw.components.end(), [&](int32_t c) { return ok[size_t(c)] != 0; });
    }
    return cull;
}

void SurfacePass::draw_materials(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh& mesh,
                                 const CameraMatrices& camera, const glm::vec3& eye, const SurfaceStyle& style,
                                 const GpuMaterials* materials, bool depth_only,
                                 const BackFaceCulling* culling) const {
    target.set_viewport(cmd);
    VkDeviceSize offset = 0;
    VkBuffer vertex_buffer = mesh.vertices.get();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
    vkCmdBindIndexBuffer(cmd, mesh.indices.get(), 0, VK_INDEX_TYPE_UINT32);
    if (!style.materials) materials = nullptr;
    // Without materials the draws take the scene colour (their grouping still keeps apart the
    // faces that are drawn both ways, upload_mesh).
    const std::vector<MeshDraw> everything{{.material = -1, .first_index = 0, .index_count = mesh.index_count}};
    const std::vector<MeshDraw>& draws = !mesh.draws.empty() ? mesh.draws : everything;
    const auto material_of = [&](const MeshDraw& draw) -> const Material* {
        const bool known = materials && draw.material >= 0 && size_t(draw.material) < materials->size();
        return known ? &materials->material(size_t(draw.material)) : nullptr;
    };
    std::vector<uint8_t> opaque(draws.size());
    for (size_t d = 0; d < draws.size(); ++d) {
        const Material* material = material_of(draws[d]);
        opaque[d] = !material || material->alpha_mode == AlphaMode::Opaque;
    }
    const std::vector<uint8_t> cull = cullable_draws(draws, mesh.face_order, opaque, culling);
    for (size_t d = 0; d < draws.size(); ++d) {
        const MeshDraw& draw = draws[d];
        const Material* material = material_of(draw);
        const bool textured = material && materials->textured(size_t(draw.material));
        const AlphaMode mode = material ? material->alpha_mode : AlphaMode::Opaque;
        if (depth_only && mode == AlphaMode::Blend) continue;  // hides nothing
        const GraphicsPipeline& pipeline = depth_only ? (mode == AlphaMode::Mask ? depth_mask_ : depth_only_)
                                                      : (mode == AlphaMode::Blend ? blend_ : pipeline_);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
        vkCmdSetCullMode(cmd, cull[d] ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
        if (&pipeline != &depth_only_)
            pipeline.push_image(*ctx_, cmd, 0, textured ? materials->view(size_t(draw.material)) : white_.view(),
                                textured ? materials->sampler(size_t(draw.material)) : white_sampler_.get());
        const SurfacePush push = material_push(camera, eye, style, material, textured);
        vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(push), &push);
        vkCmdDrawIndexed(cmd, draw.index_count, 1, draw.first_index, 0, 0);
    }
}

void SurfacePass::record_depth_only(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh* mesh,
                                    const CameraMatrices& camera, const SurfaceStyle& style,
                                    const GpuMaterials* materials, const BackFaceCulling* culling) const {
    if (target.samples != samples_) throw Error("surface pass: the target's sample count differs from the pipeline's");
    // The colour is the background: a clear, no fragment shading (much cheaper on lavapipe).
    record_image_barrier(cmd, target.color,
                         {.old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                          .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          .src_access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                          .dst_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT,
                          .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkClearColorValue clear = clear_color(style);
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, target.color.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);
    record_image_barrier(cmd, target.color,
                         {.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT,
                          .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          .dst_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          .dst_access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT});
    begin_depth(cmd, target);
    VkRenderingAttachmentInfo depth = depth_attachment(target);
    // Multisampled like the shaded surface, so that a frame's depth (and so its lines) is the
    // same whether it is drawn or only tracked (a state-only farm run).
    if (samples_ > 1) resolve_depth(cmd, target, depth);
    VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = {{0, 0}, {target.width, target.height}},
                              .layerCount = 1,
                              .pDepthAttachment = &depth};
    vkCmdBeginRendering(cmd, &rendering);
    if (mesh) draw_materials(cmd, target, *mesh, camera, glm::vec3(0.0f), style, materials, true, culling);
    vkCmdEndRendering(cmd);
    end_depth(cmd, target);
}

void SurfacePass::record(VkCommandBuffer cmd, RenderTarget& target, const GpuMesh& mesh,
                         const CameraMatrices& camera, const glm::vec3& eye, const SurfaceStyle& style,
                         const GpuMaterials* materials, const BackFaceCulling* culling) const {
    if (!style.draw_surface) {
        record_depth_only(cmd, target, &mesh, camera, style, materials, culling);
        return;
    }
    if (target.samples != samples_) throw Error("surface pass: the target's sample count differs from the pipeline's");
    target.color_to_attachment(cmd, VK_IMAGE_LAYOUT_UNDEFINED);
    begin_depth(cmd, target);
    VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                    .imageView = target.color.view(),
                                    .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                    .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                    .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    color.clearValue.color = clear_color(style);
    VkRenderingAttachmentInfo depth = depth_attachment(target);
    if (samples_ > 1) {
        // Draw into the multisampled images, resolve into the target's (kept: STORE on the
        // resolve targets is implied, the samples themselves are discarded).
        to_attachment(cmd, target.msaa_color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = target.color.view();
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.imageView = target.msaa_color.view();
        color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        resolve_depth(cmd, target, depth);
    }
    VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = {{0, 0}, {target.width, target.height}},
                              .layerCount = 1,
                              .colorAttachmentCount = 1,
                              .pColorAttachments = &color,
                              .pDepthAttachment = &depth};
    vkCmdBeginRendering(cmd, &rendering);
    draw_materials(cmd, target, mesh, camera, eye, style, materials, false, culling);
    vkCmdEndRendering(cmd);
    target.color_to_transfer_src(cmd);
    end_depth(cmd, target);
}

}  // namespace lw
