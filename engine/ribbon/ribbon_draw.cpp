#include "ribbon/ribbon_draw.h"

#include <cstddef>
#include <cstring>
#include <functional>
#include <string>

#include "core/error.h"
#include "core/image.h"
#include "gpu/render_target.h"
#include "ribbon/draw_reference.h"
#include "ribbon_avoid_frag.h"
#include "ribbon_draw_frag.h"
#include "ribbon_draw_vert.h"

namespace lw {

namespace {

struct RibbonVertex {
    glm::vec2 pixel;
    glm::vec2 texcoord;  // exemplar coordinates
    uint32_t piece;
};

struct RibbonDrawPush {
    glm::vec2 viewport;
    glm::ivec2 exemplar_size;
    int32_t samples, stitch, pad0, pad1;
};
static_assert(sizeof(RibbonDrawPush) == 32);

struct PieceDraw {  // mirrors shaders/ribbon_draw.frag
    glm::vec4 corners, edges, right, left;
    glm::ivec4 remap;
};

GraphicsPipelineDesc pipeline_desc(std::span<const uint32_t> fragment, uint32_t storage_buffers, BlendMode blend,
                                   const char* name) {
    return {.vertex_spirv = LW_SPIRV(ribbon_draw_vert_spv),
            .fragment_spirv = fragment,
            .vertex_stride = sizeof(RibbonVertex),
            .attributes = {{.location = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
                           {.location = 1, .format = VK_FORMAT_R32G32_SFLOAT, .offset = offsetof(RibbonVertex, texcoord)},
                           {.location = 2, .format = VK_FORMAT_R32_UINT, .offset = offsetof(RibbonVertex, piece)}},
            .depth_format = VK_FORMAT_UNDEFINED,
            .depth_test = false,
            .depth_write = false,
            .blend = blend,
            .storage_buffers = storage_buffers,
            .push_constant_size = sizeof(RibbonDrawPush),
            .name = name};
}

// Two triangles per piece; piece i placed at positions[i] (u = 0 for the avoidance pass).
std::vector<RibbonVertex> build_vertices(const Ribbon& ribbon, const std::vector<glm::ivec2>* positions) {
    std::vector<RibbonVertex> vertices;
    vertices.reserve(ribbon.pieces.size() * 6);
    for (size_t i = 0; i < ribbon.pieces.size(); ++i) {
        const RibbonPiece& p = ribbon.pieces[i];
        const glm::ivec2 u = positions ? (*positions)[i] : glm::ivec2(0);
        auto v = [&](glm::vec2 corner) { return RibbonVertex{corner, ribbon.to_exemplar(i, u, corner), uint32_t(i)}; };
        const RibbonVertex tl = v(p.top_left), bl = v(p.bottom_left), br = v(p.bottom_right), tr = v(p.top_right);
        vertices.insert(vertices.end(), {tl, bl, br, tl, br, tr});
    }
    return vertices;
}

// Clears the target, draws `vertices` with `pipeline` (buffers pushed by `bind`), reads back.
ImageRGBA8 render(const Context& ctx, const GraphicsPipeline& pipeline, const std::vector<RibbonVertex>& vertices,
                  const RibbonDrawPush& push, const std::function<void(VkCommandBuffer)>& bind, int width, int height) {
    if (width < 1 || height < 1 || width > kLargestImageSide || height > kLargestImageSide)
        throw Error("ribbon canvas " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
    const RenderTarget target(ctx, uint32_t(width), uint32_t(height));
    const VkDeviceSize pixels = VkDeviceSize(width) * VkDeviceSize(height);
    const Buffer readback(ctx, {.size = pixels * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                .purpose = MemoryPurpose::Readback, .name = "ribbon image readback"});
    Buffer vertex_buffer;
    if (!vertices.empty()) {
        vertex_buffer = Buffer(ctx, {.size = vertices.size() * sizeof(RibbonVertex),
                                     .usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, .purpose = MemoryPurpose::Upload,
                                     .name = "ribbon vertices"});
        std::memcpy(vertex_buffer.mapped(), vertices.data(), vertices.size() * sizeof(RibbonVertex));
    }
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        target.color_to_attachment(cmd, VK_IMAGE_LAYOUT_UNDEFINED);
        VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = target.color.view(),
                                        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                        .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 0.0f}}}};
        VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                  .renderArea = {{0, 0}, {target.width, target.height}},
                                  .layerCount = 1,
                                  .colorAttachmentCount = 1,
                                  .pColorAttachments = &color};
        vkCmdBeginRendering(cmd, &rendering);
        target.set_viewport(cmd);
        if (!vertices.empty()) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
            bind(cmd);
            vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(push), &push);
            VkDeviceSize offset = 0;
            VkBuffer vb = vertex_buffer.get();
            vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
            vkCmdDraw(cmd, uint32_t(vertices.size()), 1, 0, 0);
        }
        vkCmdEndRendering(cmd);
        target.color_to_transfer_src(cmd);
        record_image_to_buffer(cmd, target.color, readback);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    readback.invalidate(ctx);
    ImageRGBA8 image{width, height, std::vector<uint8_t>(size_t(pixels) * 4)};
    std::memcpy(image.pixels.data(), readback.mapped(), image.pixels.size());
    return image;
}

}  // namespace

RibbonRenderer::RibbonRenderer(const Context& ctx)
    : ctx_(&ctx),
      avoid_(ctx, pipeline_desc(LW_SPIRV(ribbon_avoid_frag_spv), 0, BlendMode::Additive, "ribbon avoidance map")),
      draw_(ctx, pipeline_desc(LW_SPIRV(ribbon_draw_frag_spv), 4, BlendMode::None, "ribbon draw")) {}

std::vector<uint8_t> RibbonRenderer::coverage_counts(const Ribbon& ribbon, int width, int height) const {
    const RibbonDrawPush push{{float(width), float(height)}, {1, 1}, ribbon.samples, 0, 0, 0};
    const ImageRGBA8 image =
        render(*ctx_, avoid_, build_vertices(ribbon, nullptr), push, [](VkCommandBuffer) {}, width, height);
    std::vector<uint8_t> counts(size_t(width) * size_t(height));
    for (size_t i = 0; i < counts.size(); ++i) counts[i] = image.pixels[i * 4];
    return counts;
}

ForbiddenMask RibbonRenderer::avoidance_map(const Ribbon& ribbon, int width, int height) const {
    const std::vector<uint8_t> counts = coverage_counts(ribbon, width, height);
    ForbiddenMask mask{width, height, std::vector<uint8_t>(counts.size())};
    for (size_t i = 0; i < counts.size(); ++i) mask.pixels[i] = counts[i] > 1 ? 1 : 0;
    return mask;
}

ImageRGBA8 RibbonRenderer::draw(const Ribbon& ribbon, const Exemplar& exemplar, const std::vector<glm::ivec2>& positions,
                                const StitchResult* stitch, const ForbiddenMask* forbidden, int width,
                                int height) const {
    const Context& ctx = *ctx_;
    if (positions.size() < ribbon.pieces.size()) throw Error("ribbon draw: fewer positions than pieces");
    const int C = ribbon.samples;
    std::vector<PieceDraw> pieces;
    std::vector<int32_t> remaps;
    for (size_t i = 0; i < ribbon.pieces.size(); ++i) {
        const PieceFrame f = piece_frame(ribbon, i, positions[i]);
        int32_t offset = -1;
        if (stitch && i < stitch->remap.size()) {  // seam i+1 deforms piece i's right side
            offset = int32_t(remaps.size());
            remaps.insert(remaps.end(), stitch->remap[i].begin(), stitch->remap[i].end());
        }
        pieces.push_back({glm::vec4(f.top_left, f.top_right), glm::vec4(f.top_edge, f.bottom_edge),
                          glm::vec4(f.right_edge, 0.0f, 0.0f), glm::vec4(f.left_edge, 0.0f, 0.0f),
                          glm::ivec4(offset, C, 0, 0)});
    }
    if (remaps.empty()) remaps.push_back(0);
    std::vector<uint32_t> mask(size_t(width) * size_t(height), 0u);
    if (forbidden) {
        if (forbidden->width != width || forbidden->height != height)
            throw Error("ribbon draw: the forbidden mask does not match the canvas");
        for (size_t i = 0; i < mask.size(); ++i) mask[i] = forbidden->pixels[i];
    }
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const Buffer texels = upload_buffer(ctx, exemplar.texels, usage, "ribbon draw exemplar");
    const Buffer piece_buffer = upload_buffer(ctx, pieces.empty() ? std::vector<PieceDraw>(1) : pieces, usage,
                                              "ribbon draw pieces");
    const Buffer remap_buffer = upload_buffer(ctx, remaps, usage, "ribbon draw remaps");
    const Buffer mask_buffer = upload_buffer(ctx, mask, usage, "ribbon draw forbidden");
    const RibbonDrawPush push{{float(width), float(height)}, {exemplar.width, exemplar.height}, C,
                              stitch ? 1 : 0, 0, 0};
    return render(ctx, draw_, build_vertices(ribbon, &positions), push,
                  [&](VkCommandBuffer cmd) {
                      draw_.push_storage_buffers(ctx, cmd, {&texels, &piece_buffer, &remap_buffer, &mask_buffer});
                  },
                  width, height);
}

}  // namespace lw
