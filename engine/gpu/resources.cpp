#include "gpu/resources.h"

#include <algorithm>
#include <cstring>
#include <utility>
#include <string>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

namespace {

// Picks a memory type allowed by `type_bits` for the purpose. Readback prefers cached host
// memory (fast CPU reads); Device prefers DEVICE_LOCAL; every purpose has a fallback so that
// unified-memory devices like lavapipe (all types host-visible) work too.
uint32_t find_memory_type(const Context& ctx, uint32_t type_bits, MemoryPurpose purpose, bool* coherent) {
    const auto& props = ctx.memory_properties();
    auto find = [&](VkMemoryPropertyFlags wanted) -> int {
        for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
            if ((type_bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & wanted) == wanted)
                return static_cast<int>(i);
        return -1;
    };
    int index = -1;
    switch (purpose) {
        case MemoryPurpose::Device:
            index = find(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
            if (index < 0) index = find(0);
            break;
        case MemoryPurpose::Upload:
            index = find(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
            break;
        case MemoryPurpose::Readback:
            index = find(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
            if (index < 0) index = find(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
            break;
    }
    if (index < 0) throw Error("no Vulkan memory type fits the request on " + ctx.info().name);
    if (coherent)
        *coherent = (props.memoryTypes[index].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    return static_cast<uint32_t>(index);
}

Handle<VkDeviceMemory> allocate(const Context& ctx, const VkMemoryRequirements& req, MemoryPurpose purpose,
                                bool* coherent) {
    VkMemoryAllocateInfo info{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                              .allocationSize = req.size,
                              .memoryTypeIndex = find_memory_type(ctx, req.memoryTypeBits, purpose, coherent)};
    VkDeviceMemory memory = VK_NULL_HANDLE;
    LW_VK(vkAllocateMemory(ctx.device(), &info, nullptr, &memory));
    return Handle<VkDeviceMemory>(ctx.device(), memory, vkFreeMemory);
}

}  // namespace

Buffer::Buffer(const Context& ctx, const BufferDesc& desc) : size_(desc.size) {
    if (desc.size == 0) throw Error(std::string("buffer ") + (desc.name ? desc.name : "") + ": size 0");
    VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                            .size = desc.size,
                            .usage = desc.usage,
                            .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    VkBuffer buffer = VK_NULL_HANDLE;
    LW_VK(vkCreateBuffer(ctx.device(), &info, nullptr, &buffer));
    buffer_ = Handle<VkBuffer>(ctx.device(), buffer, vkDestroyBuffer);
    ctx.set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer), desc.name);

    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(ctx.device(), buffer, &req);
    memory_ = allocate(ctx, req, desc.purpose, &coherent_);
    LW_VK(vkBindBufferMemory(ctx.device(), buffer, memory_, 0));
    if (desc.purpose != MemoryPurpose::Device) LW_VK(vkMapMemory(ctx.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

void Buffer::invalidate(const Context& ctx) const {
    if (coherent_ || !mapped_) return;
    VkMappedMemoryRange range{.sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, .memory = memory_, .size = VK_WHOLE_SIZE};
    LW_VK(vkInvalidateMappedMemoryRanges(ctx.device(), 1, &range));
}

Buffer& ensure_buffer(const Context& ctx, Buffer& buffer, const BufferDesc& desc) {
    if (buffer.get() != VK_NULL_HANDLE && buffer.size() >= desc.size) return buffer;
    BufferDesc grown = desc;
    grown.size = std::max(desc.size, buffer.size() + buffer.size() / 2);
    buffer = Buffer(ctx, grown);
    return buffer;
}

UploadArena::Slice UploadArena::push(const Context& ctx, std::span<const std::byte> bytes) {
    const VkDeviceSize start = (used_ + 15) / 16 * 16;
    if (buffer_.get() == VK_NULL_HANDLE || start + bytes.size() > buffer_.size()) {
        const VkDeviceSize size = std::max<VkDeviceSize>({VkDeviceSize(bytes.size()), 2 * buffer_.size(), 64 * 1024});
        if (buffer_.get() != VK_NULL_HANDLE) retired_.push_back(std::move(buffer_));
        buffer_ = Buffer(ctx, {.size = size, .usage = usage_, .purpose = MemoryPurpose::Upload, .name = name_});
        used_ = 0;
        return push(ctx, bytes);
    }
    std::memcpy(static_cast<std::byte*>(buffer_.mapped()) + start, bytes.data(), bytes.size());
    used_ = start + bytes.size();
    return {buffer_.get(), start};
}

void UploadArena::reset() {
    used_ = 0;
    retired_.clear();
}

Buffer upload_buffer(const Context& ctx, std::span<const std::byte> bytes, VkBufferUsageFlags usage, const char* name) {
    Buffer staging(ctx, {.size = bytes.size(), .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         .purpose = MemoryPurpose::Upload, .name = "staging"});
    std::memcpy(staging.mapped(), bytes.data(), bytes.size());
    Buffer buffer(ctx, {.size = bytes.size(), .usage = usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        .purpose = MemoryPurpose::Device, .name = name});
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{.size = bytes.size()};
        vkCmdCopyBuffer(cmd, staging.get(), buffer.get(), 1, &region);
    });
    return buffer;
}

ImageRGBA8 read_rgba8(const Context& ctx, const Buffer& readback, uint32_t width, uint32_t height, VkFormat format) {
    readback.invalidate(ctx);
    ImageRGBA8 image{int(width), int(height), std::vector<uint8_t>(size_t(width) * height * 4)};
    std::memcpy(image.pixels.data(), readback.mapped(), image.pixels.size());
    if (format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB)
        for (size_t i = 0; i < image.pixels.size(); i += 4) std::swap(image.pixels[i], image.pixels[i + 2]);
    return image;
}

std::vector<std::byte> read_buffer(const Context& ctx, const Buffer& buffer) {
    Buffer readback(ctx, {.size = buffer.size(), .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          .purpose = MemoryPurpose::Readback, .name = "readback"});
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferCopy region{.size = buffer.size()};
        vkCmdCopyBuffer(cmd, buffer.get(), readback.get(), 1, &region);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    readback.invalidate(ctx);
    std::vector<std::byte> out(buffer.size());
    std::memcpy(out.data(), readback.mapped(), out.size());
    return out;
}

uint32_t format_texel_size(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_R32_SFLOAT:
            return 4;
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        default:
            throw Error("format_texel_size: unsupported format " + std::to_string(static_cast<int>(format)));
    }
}

Image::Image(const Context& ctx, const ImageDesc& desc)
    : format_(desc.format), extent_{desc.width, desc.height}, depth_(desc.depth), mip_levels_(desc.mip_levels) {
    if (desc.width == 0 || desc.height == 0) throw Error("image size must be positive");
    if (desc.mip_levels == 0) throw Error("image: at least one mip level");
    const uint32_t max_dim = ctx.properties().limits.maxImageDimension2D;
    if (desc.width > max_dim || desc.height > max_dim)
        throw Error("image " + std::to_string(desc.width) + "x" + std::to_string(desc.height) + " exceeds the device limit " +
                    std::to_string(max_dim));
    const bool depth = desc.format == VK_FORMAT_D32_SFLOAT || desc.format == VK_FORMAT_D16_UNORM;
    aspect_ = depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    const bool volume = desc.depth > 1;
    VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                           .imageType = volume ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D,
                           .format = desc.format,
                           .extent = {desc.width, desc.height, desc.depth},
                           .mipLevels = desc.mip_levels,
                           .arrayLayers = 1,
                           .samples = desc.samples,
                           .tiling = VK_IMAGE_TILING_OPTIMAL,
                           .usage = desc.usage,
                           .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                           .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    VkImage image = VK_NULL_HANDLE;
    LW_VK(vkCreateImage(ctx.device(), &info, nullptr, &image));
    image_ = Handle<VkImage>(ctx.device(), image, vkDestroyImage);
    ctx.set_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image), desc.name);

    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(ctx.device(), image, &req);
    memory_ = allocate(ctx, req, MemoryPurpose::Device, nullptr);
    LW_VK(vkBindImageMemory(ctx.device(), image, memory_, 0));

    VkImageViewCreateInfo view_info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                    .image = image,
                                    .viewType = volume ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D,
                                    .format = desc.format,
                                    .subresourceRange = {aspect_, 0, desc.mip_levels, 0, 1}};
    VkImageView view = VK_NULL_HANDLE;
    LW_VK(vkCreateImageView(ctx.device(), &view_info, nullptr, &view));
    view_ = Handle<VkImageView>(ctx.device(), view, vkDestroyImageView);
}

void upload_image(const Context& ctx, const Image& image, std::span<const std::byte> bytes) {
    Buffer staging(ctx, {.size = bytes.size(), .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         .purpose = MemoryPurpose::Upload, .name = "image staging"});
    std::memcpy(staging.mapped(), bytes.data(), bytes.size());
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        record_image_barrier(cmd, image,
                             {.old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                              .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT});
        record_buffer_to_image(cmd, staging, image);
        record_image_barrier(cmd, image,
                             {.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              .new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              .dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                              .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    });
}

Handle<VkSampler> create_sampler(const Context& ctx, const SamplerDesc& desc) {
    VkSamplerCreateInfo info{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                             .magFilter = desc.filter,
                             .minFilter = desc.min_filter == VK_FILTER_MAX_ENUM ? desc.filter : desc.min_filter,
                             .mipmapMode = desc.mipmap_mode,
                             .addressModeU = desc.address_u,
                             .addressModeV = desc.address_v,
                             .addressModeW = desc.address_w,
                             .maxLod = desc.max_lod};
    VkSampler sampler = VK_NULL_HANDLE;
    LW_VK(vkCreateSampler(ctx.device(), &info, nullptr, &sampler));
    return Handle<VkSampler>(ctx.device(), sampler, vkDestroySampler);
}

void record_buffer_to_image(VkCommandBuffer cmd, const Buffer& buffer, const Image& image) {
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    uint32_t w = image.extent().width, h = image.extent().height, d = image.depth();
    for (uint32_t level = 0; level < image.mip_levels(); ++level) {
        regions.push_back({.bufferOffset = offset,
                           .imageSubresource = {image.aspect(), level, 0, 1},
                           .imageExtent = {w, h, d}});
        if (level + 1 < image.mip_levels()) offset += VkDeviceSize(w) * h * d * format_texel_size(image.format());
        w = std::max(1u, w / 2), h = std::max(1u, h / 2), d = std::max(1u, d / 2);
    }
    vkCmdCopyBufferToImage(cmd, buffer.get(), image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
}

void record_image_to_buffer(VkCommandBuffer cmd, const Image& image, const Buffer& buffer) {
    VkBufferImageCopy region{.bufferOffset = 0,
                             .bufferRowLength = 0,
                             .bufferImageHeight = 0,
                             .imageSubresource = {image.aspect(), 0, 0, 1},
                             .imageOffset = {0, 0, 0},
                             .imageExtent = {image.extent().width, image.extent().height, 1}};
    vkCmdCopyImageToBuffer(cmd, image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.get(), 1, &region);
}

void record_image_rows_to_buffer(VkCommandBuffer cmd, const Image& image, const Buffer& buffer, uint32_t first_row,
                                 uint32_t rows) {
    const VkExtent2D extent = image.extent();
    VkBufferImageCopy region{.bufferOffset = VkDeviceSize(first_row) * extent.width * format_texel_size(image.format()),
                             .bufferRowLength = 0,
                             .bufferImageHeight = 0,
                             .imageSubresource = {image.aspect(), 0, 0, 1},
                             .imageOffset = {0, int32_t(first_row), 0},
                             .imageExtent = {extent.width, rows, 1}};
    vkCmdCopyImageToBuffer(cmd, image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.get(), 1, &region);
}

void record_image_barrier(VkCommandBuffer cmd, const Image& image, const ImageBarrier& b) {
    record_image_barrier(cmd, image.get(), image.aspect(), b);
}

void record_image_barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, const ImageBarrier& b) {
    VkImageMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                                  .srcStageMask = b.src_stage,
                                  .srcAccessMask = b.src_access,
                                  .dstStageMask = b.dst_stage,
                                  .dstAccessMask = b.dst_access,
                                  .oldLayout = b.old_layout,
                                  .newLayout = b.new_layout,
                                  .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                  .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                  .image = image,
                                  .subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, 1}};
    VkDependencyInfo dep{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .imageMemoryBarrierCount = 1,
                         .pImageMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dep);
}

void record_memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                           VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                             .srcStageMask = src_stage,
                             .srcAccessMask = src_access,
                             .dstStageMask = dst_stage,
                             .dstAccessMask = dst_access};
    VkDependencyInfo dep{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1,
                         .pMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace lw
