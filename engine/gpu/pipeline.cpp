#include "gpu/pipeline.h"

#include <array>
#include <cstring>
#include <string>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

Handle<VkShaderModule> create_shader_module(const Context& ctx, std::span<const uint32_t> spirv) {
    VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                  .codeSize = spirv.size_bytes(),
                                  .pCode = spirv.data()};
    VkShaderModule module = VK_NULL_HANDLE;
    LW_VK(vkCreateShaderModule(ctx.device(), &info, nullptr, &module));
    return Handle<VkShaderModule>(ctx.device(), module, vkDestroyShaderModule);
}

namespace {

Handle<VkPipelineLayout> create_layout(const Context& ctx, VkDescriptorSetLayout set_layout, uint32_t push_size,
                                       VkShaderStageFlags push_stages) {
    VkPushConstantRange range{.stageFlags = push_stages, .offset = 0, .size = push_size};
    VkPipelineLayoutCreateInfo info{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                    .setLayoutCount = set_layout ? 1u : 0u,
                                    .pSetLayouts = set_layout ? &set_layout : nullptr,
                                    .pushConstantRangeCount = push_size ? 1u : 0u,
                                    .pPushConstantRanges = push_size ? &range : nullptr};
    VkPipelineLayout layout = VK_NULL_HANDLE;
    LW_VK(vkCreatePipelineLayout(ctx.device(), &info, nullptr, &layout));
    return Handle<VkPipelineLayout>(ctx.device(), layout, vkDestroyPipelineLayout);
}

// A push-descriptor set layout: `storage` storage buffers at bindings [0, storage) for
// `stages`, then `images` combined image samplers for the fragment stage (none if both 0).
Handle<VkDescriptorSetLayout> create_push_set_layout(const Context& ctx, uint32_t storage, VkShaderStageFlags stages,
                                                     uint32_t images = 0) {
    if (storage + images == 0) return {};
    if (!ctx.has_push_descriptors())
        throw Error(ctx.info().name + " lacks VK_KHR_push_descriptor, which this pass needs");
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t i = 0; i < storage; ++i)
        bindings.push_back({.binding = i,
                            .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                            .descriptorCount = 1,
                            .stageFlags = stages});
    for (uint32_t i = 0; i < images; ++i)
        bindings.push_back({.binding = storage + i,
                            .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            .descriptorCount = 1,
                            .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT});
    VkDescriptorSetLayoutCreateInfo info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                         .flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR,
                                         .bindingCount = static_cast<uint32_t>(bindings.size()),
                                         .pBindings = bindings.data()};
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    LW_VK(vkCreateDescriptorSetLayout(ctx.device(), &info, nullptr, &set_layout));
    return Handle<VkDescriptorSetLayout>(ctx.device(), set_layout, vkDestroyDescriptorSetLayout);
}

void push_buffers(const Context& ctx, VkCommandBuffer cmd, VkPipelineBindPoint bind_point, VkPipelineLayout layout,
                  uint32_t expected, std::initializer_list<const Buffer*> buffers) {
    if (buffers.size() != expected)
        throw Error("push descriptors: " + std::to_string(buffers.size()) + " buffers for " +
                    std::to_string(expected) + " bindings");
    if (expected == 0) return;
    std::vector<VkDescriptorBufferInfo> infos;
    for (const Buffer* b : buffers) infos.push_back({.buffer = b->get(), .offset = 0, .range = VK_WHOLE_SIZE});
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t i = 0; i < expected; ++i)
        writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                          .dstBinding = i,
                          .descriptorCount = 1,
                          .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                          .pBufferInfo = &infos[i]});
    ctx.cmd_push_descriptor_set(cmd, bind_point, layout, 0, static_cast<uint32_t>(writes.size()), writes.data());
}

}  // namespace

ComputePipeline::ComputePipeline(const Context& ctx, const ComputePipelineDesc& desc)
    : storage_buffers_(desc.storage_buffers), push_constant_size_(desc.push_constant_size) {
    if (desc.push_constant_size > 128) throw Error("push constants over 128 bytes are not portable");

    set_layout_ = create_push_set_layout(ctx, desc.storage_buffers, VK_SHADER_STAGE_COMPUTE_BIT);
    layout_ = create_layout(ctx, set_layout_.get(), desc.push_constant_size, VK_SHADER_STAGE_COMPUTE_BIT);

    auto module = create_shader_module(ctx, desc.spirv);
    VkComputePipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                  .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                  .module = module,
                  .pName = "main"},
        .layout = layout_};
    VkPipeline pipeline = VK_NULL_HANDLE;
    LW_VK(vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    pipeline_ = Handle<VkPipeline>(ctx.device(), pipeline, vkDestroyPipeline);
    ctx.set_name(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(pipeline), desc.name);
}

void ComputePipeline::dispatch(const Context& ctx, VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers,
                               const void* push_constants, uint32_t groups_x, uint32_t groups_y,
                               uint32_t groups_z) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    push_buffers(ctx, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, storage_buffers_, buffers);
    if (push_constant_size_ > 0)
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_size_, push_constants);
    vkCmdDispatch(cmd, groups_x, groups_y, groups_z);
}

GraphicsPipeline::GraphicsPipeline(const Context& ctx, const GraphicsPipelineDesc& desc)
    : storage_buffers_(desc.storage_buffers) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    // Push descriptors: storage buffers at bindings [0, S), sampled images at [S, S + I).
    set_layout_ = create_push_set_layout(ctx, desc.storage_buffers, stages, desc.sampled_images);
    layout_ = create_layout(ctx, set_layout_.get(), desc.push_constant_size, stages);

    auto vertex = create_shader_module(ctx, desc.vertex_spirv);
    // No fragment shader: a depth-only pipeline.
    Handle<VkShaderModule> fragment;
    if (!desc.fragment_spirv.empty()) fragment = create_shader_module(ctx, desc.fragment_spirv);
    std::array<VkPipelineShaderStageCreateInfo, 2> shader_stages{{
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_VERTEX_BIT,
         .module = vertex, .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
         .module = fragment, .pName = "main"},
    }};

    VkVertexInputBindingDescription binding{
        .binding = 0,
        .stride = desc.vertex_stride,
        .inputRate = desc.per_instance ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX};
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (const auto& a : desc.attributes)
        attributes.push_back({.location = a.location, .binding = 0, .format = a.format, .offset = a.offset});
    VkPipelineVertexInputStateCreateInfo vertex_input{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = desc.vertex_stride ? 1u : 0u,
        .pVertexBindingDescriptions = desc.vertex_stride ? &binding : nullptr,
        .vertexAttributeDescriptionCount = static_cast<uint32_t>(attributes.size()),
        .pVertexAttributeDescriptions = attributes.data()};
    VkPipelineInputAssemblyStateCreateInfo input_assembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO, .topology = desc.topology};
    VkPipelineViewportStateCreateInfo viewport{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                               .viewportCount = 1,
                                               .scissorCount = 1};
    VkPipelineRasterizationStateCreateInfo raster{.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                  .polygonMode = VK_POLYGON_MODE_FILL,
                                                  .cullMode = desc.cull_mode,
                                                  .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
                                                  .lineWidth = 1.0f};
    VkPipelineMultisampleStateCreateInfo multisample{.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                     .rasterizationSamples = desc.samples};
    VkPipelineDepthStencilStateCreateInfo depth{.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
                                                .depthTestEnable = desc.depth_test,
                                                .depthWriteEnable = desc.depth_write,
                                                .depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL};
    // Factors per mode (Max ignores them: VK_BLEND_OP_MAX takes the larger value as is).
    const bool additive = desc.blend == BlendMode::Additive, premultiplied = desc.blend == BlendMode::Premultiplied;
    const VkBlendOp op = desc.blend == BlendMode::Max ? VK_BLEND_OP_MAX : VK_BLEND_OP_ADD;
    VkPipelineColorBlendAttachmentState blend_attachment{
        .blendEnable = desc.blend != BlendMode::None,
        .srcColorBlendFactor = additive || premultiplied ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_SRC_ALPHA,
        .dstColorBlendFactor = additive ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
        .colorBlendOp = op,
        // Alpha `over` too (a + (1 − a)·dst): an opaque frame stays opaque, a transparent
        // one gets the coverage a compositor needs.
        .srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE,
        .dstAlphaBlendFactor = additive ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
        .alphaBlendOp = op,
        .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                          VK_COLOR_COMPONENT_A_BIT};
    const bool has_color = desc.color_format != VK_FORMAT_UNDEFINED;
    VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                              .attachmentCount = has_color ? 1u : 0u,
                                              .pAttachments = has_color ? &blend_attachment : nullptr};
    std::array<VkDynamicState, 3> dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                                 VK_DYNAMIC_STATE_CULL_MODE};
    VkPipelineDynamicStateCreateInfo dynamic{.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                             .dynamicStateCount = desc.dynamic_cull_mode ? 3u : 2u,
                                             .pDynamicStates = dynamic_states.data()};
    VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                            .colorAttachmentCount = has_color ? 1u : 0u,
                                            .pColorAttachmentFormats = has_color ? &desc.color_format : nullptr,
                                            .depthAttachmentFormat = desc.depth_format};
    VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                      .pNext = &rendering,
                                      .stageCount = fragment ? 2u : 1u,
                                      .pStages = shader_stages.data(),
                                      .pVertexInputState = &vertex_input,
                                      .pInputAssemblyState = &input_assembly,
                                      .pViewportState = &viewport,
                                      .pRasterizationState = &raster,
                                      .pMultisampleState = &multisample,
                                      .pDepthStencilState = &depth,
                                      .pColorBlendState = &blend,
                                      .pDynamicState = &dynamic,
                                      .layout = layout_};
    VkPipeline pipeline = VK_NULL_HANDLE;
    LW_VK(vkCreateGraphicsPipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    pipeline_ = Handle<VkPipeline>(ctx.device(), pipeline, vkDestroyPipeline);
    ctx.set_name(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(pipeline), desc.name);
}

void GraphicsPipeline::push_image(const Context& ctx, VkCommandBuffer cmd, uint32_t binding, VkImageView view,
                                  VkSampler sampler) const {
    VkDescriptorImageInfo image{.sampler = sampler, .imageView = view,
                                .imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                               .dstBinding = binding,
                               .descriptorCount = 1,
                               .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                               .pImageInfo = &image};
    ctx.cmd_push_descriptor_set(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &write);
}

void GraphicsPipeline::draw(VkCommandBuffer cmd, UploadArena::Slice vertices, uint32_t vertex_count, const void* push,
                            uint32_t push_size, uint32_t instance_count) const {
    if (push_size > 0)
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, push_size, push);
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &vertices.offset);
    vkCmdDraw(cmd, vertex_count, instance_count, 0, 0);
}

void GraphicsPipeline::draw_generated(VkCommandBuffer cmd, uint32_t vertex_count, const void* push,
                                      uint32_t push_size) const {
    if (push_size > 0)
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, push_size, push);
    vkCmdDraw(cmd, vertex_count, 1, 0, 0);
}

void GraphicsPipeline::push_storage_buffers(const Context& ctx, VkCommandBuffer cmd,
                                            std::initializer_list<const Buffer*> buffers) const {
    push_buffers(ctx, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, storage_buffers_, buffers);
}

}  // namespace lw
