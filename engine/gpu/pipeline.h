// engine/gpu/pipeline.h — compute and graphics pipelines from embedded SPIR-V.
//
// Shaders are compiled by glslang at build time into C arrays (CMakeLists.txt), so the
// binary carries its SPIR-V and needs no shader files at run time. Resources are bound
// with push descriptors (lavapipe and the H100 both have VK_KHR_push_descriptor): a pass
// names its storage buffers per dispatch, with no descriptor pools to manage.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/resources.h"

namespace lw {

// Wraps a glslang `--vn` array: LW_SPIRV(surface_vert_spv).
#define LW_SPIRV(array) std::span<const uint32_t>(array, sizeof(array) / sizeof(uint32_t))

struct ComputePipelineDesc {
    std::span<const uint32_t> spirv;
    uint32_t storage_buffers = 0;     // bindings 0..n-1 of set 0, all storage buffers
    uint32_t push_constant_size = 0;  // bytes, at most 128
    const char* name = nullptr;
};

class ComputePipeline {
public:
    ComputePipeline() = default;
    ComputePipeline(const Context& ctx, const ComputePipelineDesc& desc);

    // Binds the pipeline, pushes the buffers to bindings 0.., pushes constants, dispatches.
    void dispatch(const Context& ctx, VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers,
                  const void* push_constants, uint32_t groups_x, uint32_t groups_y = 1, uint32_t groups_z = 1) const;

private:
    Handle<VkDescriptorSetLayout> set_layout_;
    Handle<VkPipelineLayout> layout_;
    Handle<VkPipeline> pipeline_;
    uint32_t storage_buffers_ = 0;
    uint32_t push_constant_size_ = 0;
};

struct VertexAttribute {
    uint32_t location = 0;
    VkFormat format = VK_FORMAT_R32G32B32_SFLOAT;
    uint32_t offset = 0;
};

enum class BlendMode { None, Alpha, Additive, Max, Premultiplied };

struct GraphicsPipelineDesc {
    std::span<const uint32_t> vertex_spirv;
    std::span<const uint32_t> fragment_spirv;  // empty: depth only (no colour attachment either)
    uint32_t vertex_stride = 0;                    // one interleaved vertex binding; 0 = none
    std::vector<VertexAttribute> attributes;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
    bool dynamic_cull_mode = false;  // set per draw with vkCmdSetCullMode (core in Vulkan 1.3)
    VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM;  // VK_FORMAT_UNDEFINED = depth only
    VkFormat depth_format = VK_FORMAT_D32_SFLOAT;      // VK_FORMAT_UNDEFINED = no depth
    bool depth_test = true;
    bool depth_write = true;
    // Alpha: src·α + dst·(1 − α) on colour, α `over` (α + dst·(1 − α)); Additive: src + dst
    // on every channel (splatting sums); Max: the larger of src and dst on every channel (a
    // coverage layer's union, gpu/coverage_layer.h); Premultiplied: src + dst·(1 − α) on
    // every channel (a premultiplied layer `over` the target).
    BlendMode blend = BlendMode::None;
    uint32_t storage_buffers = 0;  // bindings [0, S): storage buffers (vertex and fragment), pushed per draw
    uint32_t sampled_images = 0;   // bindings [S, S + I): combined image samplers (fragment), pushed per draw
    uint32_t push_constant_size = 0;
    const char* name = nullptr;
    bool per_instance = false;  // the vertex binding advances per instance, not per vertex
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // of the attachments it draws into
};

// A pipeline for dynamic rendering; viewport and scissor are dynamic state.
class GraphicsPipeline {
public:
    GraphicsPipeline() = default;
    GraphicsPipeline(const Context& ctx, const GraphicsPipelineDesc& desc);

    VkPipeline get() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }

    // Binds `view` with `sampler` at `binding` (push descriptor) for the following draws.
    void push_image(const Context& ctx, VkCommandBuffer cmd, uint32_t binding, VkImageView view,
                    VkSampler sampler) const;
    // Pushes the constants (vertex and fragment stages), binds `vertices` at binding 0 and
    // draws; the pipeline must be bound.
    void draw(VkCommandBuffer cmd, const Buffer& vertices, uint32_t vertex_count, const void* push,
              uint32_t push_size, uint32_t instance_count = 1) const {
        draw(cmd, {vertices.get(), 0}, vertex_count, push, push_size, instance_count);
    }
    // The same from a slice of an upload arena.
    void draw(VkCommandBuffer cmd, UploadArena::Slice vertices, uint32_t vertex_count, const void* push,
              uint32_t push_size, uint32_t instance_count = 1) const;
    // Draws `vertex_count` vertices that the vertex shader makes from gl_VertexIndex (no
    // vertex buffer: a full-screen triangle); the pipeline must be bound.
    void draw_generated(VkCommandBuffer cmd, uint32_t vertex_count, const void* push, uint32_t push_size) const;

    // Binds the storage buffers to bindings 0.. (push descriptors) for the following draws.
    void push_storage_buffers(const Context& ctx, VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers) const;

private:
    uint32_t storage_buffers_ = 0;
    Handle<VkDescriptorSetLayout> set_layout_;
    Handle<VkPipelineLayout> layout_;
    Handle<VkPipeline> pipeline_;
};

[[nodiscard]] Handle<VkShaderModule> create_shader_module(const Context& ctx, std::span<const uint32_t> spirv);

}  // namespace lw
