// engine/gpu/resources.h — buffers and images with their memory, asked for by purpose.
//
// Memory is requested by what the data is for (Granite's BufferDomain), not by raw flags:
//   Device   — GPU-only data (vertex, index, storage buffers, render targets);
//   Upload   — host-written, GPU-read (staging, small uniforms), persistently mapped;
//   Readback — GPU-written, host-read (image and buffer readback), persistently mapped.
// One allocation per resource: the engine holds few, large resources, so a sub-allocator
// would add code without adding speed.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/image.h"
#include "gpu/context.h"
#include "gpu/handle.h"

namespace lw {

enum class MemoryPurpose { Device, Upload, Readback };

struct BufferDesc {
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    MemoryPurpose purpose = MemoryPurpose::Device;
    const char* name = nullptr;  // debug name shown by validation messages
};

class Buffer {
public:
    Buffer() = default;
    Buffer(const Context& ctx, const BufferDesc& desc);

    VkBuffer get() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    // Host pointer of an Upload or Readback buffer (nullptr for Device memory).
    void* mapped() const { return mapped_; }
    // Makes GPU writes visible to the host (no-op on coherent memory). Call before reading.
    void invalidate(const Context& ctx) const;

private:
    Handle<VkBuffer> buffer_;
    Handle<VkDeviceMemory> memory_;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;
    bool coherent_ = true;
};

// A buffer kept from call to call (per-frame uploads and readbacks): replaced by a new one of
// `desc` when it is smaller than desc.size (grown by half again, so that slowly growing
// sizes do not reallocate every frame; the old contents are lost). Returns `buffer`.
Buffer& ensure_buffer(const Context& ctx, Buffer& buffer, const BufferDesc& desc);

// Per-draw data of a frame (vertex triangles of each line set and layer) packed into one
// host-visible buffer kept from frame to frame, so that no buffer is made per draw. A push
// that does not fit moves to a buffer twice as big; the old one stays alive until reset(),
// since draws already recorded read it. reset() once the frame's submission has completed.
class UploadArena {
public:
    UploadArena(VkBufferUsageFlags usage, const char* name) : usage_(usage), name_(name) {}
    struct Slice {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceSize offset = 0;
    };
    // Copies `bytes` in (16-byte aligned) and says where they are.
    [[nodiscard]] Slice push(const Context& ctx, std::span<const std::byte> bytes);
    void reset();

private:
    VkBufferUsageFlags usage_;
    const char* name_;
    Buffer buffer_;
    VkDeviceSize used_ = 0;
    std::vector<Buffer> retired_;  // outgrown this frame, still read by its draws
};

// A Device buffer filled with `bytes` through a staging buffer (waits for the copy).
[[nodiscard]] Buffer upload_buffer(const Context& ctx, std::span<const std::byte> bytes, VkBufferUsageFlags usage,
                                   const char* name);
template <typename T>
[[nodiscard]] Buffer upload_buffer(const Context& ctx, const std::vector<T>& data, VkBufferUsageFlags usage,
                                   const char* name) {
    return upload_buffer(ctx, std::as_bytes(std::span(data)), usage, name);
}

// The pixels of a width × height 8-bit RGBA or BGRA image copied into a Readback buffer
// (invalidated here), as RGBA: B8G8R8A8 formats have red and blue swapped back.
[[nodiscard]] ImageRGBA8 read_rgba8(const Context& ctx, const Buffer& readback, uint32_t width, uint32_t height,
                                    VkFormat format);

// Copies a Device buffer back to the host (waits for the copy).
[[nodiscard]] std::vector<std::byte> read_buffer(const Context& ctx, const Buffer& buffer);
template <typename T>
[[nodiscard]] std::vector<T> read_buffer_as(const Context& ctx, const Buffer& buffer) {
    const auto bytes = read_buffer(ctx, buffer);
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

struct ImageDesc {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t depth = 1;  // > 1: a 3D image (e.g. a SLAM's levels)
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkImageUsageFlags usage = 0;
    const char* name = nullptr;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // > 1: a multisampled attachment (2D)
    uint32_t mip_levels = 1;  // each level half the last (rounded down, at least 1)
};

// A 2D (or 3D, when depth > 1) image in Device memory with a view of its whole extent and
// every mip level.
class Image {
public:
    Image() = default;
    Image(const Context& ctx, const ImageDesc& desc);

    VkImage get() const { return image_; }
    VkImageView view() const { return view_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    uint32_t depth() const { return depth_; }
    uint32_t mip_levels() const { return mip_levels_; }
    VkImageAspectFlags aspect() const { return aspect_; }

private:
    Handle<VkImage> image_;
    Handle<VkDeviceMemory> memory_;
    Handle<VkImageView> view_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    uint32_t depth_ = 1;
    uint32_t mip_levels_ = 1;
    VkImageAspectFlags aspect_ = 0;
};

// Fills a colour image created with TRANSFER_DST | SAMPLED usage from `bytes` (tightly
// packed texels, every mip level after the one before) and leaves it in
// SHADER_READ_ONLY_OPTIMAL (waits for the copy).
void upload_image(const Context& ctx, const Image& image, std::span<const std::byte> bytes);

struct SamplerDesc {
    VkFilter filter = VK_FILTER_LINEAR;       // magnification, and minification unless min_filter says
    VkFilter min_filter = VK_FILTER_MAX_ENUM; // MAX_ENUM: as `filter`
    VkSamplerAddressMode address_u = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    VkSamplerAddressMode address_v = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSamplerAddressMode address_w = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    // Vulkan picks minFilter only where the clamped λ > 0, so a one-level image that should
    // minify with its own filter needs max_lod > 0 and NEAREST mip selection (level 0 for λ ≤ 0.5).
    float max_lod = 0.0f;
    VkSamplerMipmapMode mipmap_mode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
};
[[nodiscard]] Handle<VkSampler> create_sampler(const Context& ctx, const SamplerDesc& desc);

// Bytes per texel of the formats the engine reads back.
uint32_t format_texel_size(VkFormat format);

// Records a copy of a tightly packed buffer into the whole of `image` (2D or 3D, its mip
// levels one after another), which is in TRANSFER_DST_OPTIMAL layout.
void record_buffer_to_image(VkCommandBuffer cmd, const Buffer& buffer, const Image& image);
// Records a copy of `image` (in TRANSFER_SRC_OPTIMAL layout) into a Readback buffer.
void record_image_to_buffer(VkCommandBuffer cmd, const Image& image, const Buffer& buffer);
// Rows [first_row, first_row + rows) of a 2D image to the same rows of a buffer laid out
// like the whole image (row-major, tightly packed): byte offset first_row · width · texel.
void record_image_rows_to_buffer(VkCommandBuffer cmd, const Image& image, const Buffer& buffer, uint32_t first_row,
                                 uint32_t rows);

// One synchronization2 image layout transition on the whole image.
struct ImageBarrier {
    VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 src_stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dst_stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
};
void record_image_barrier(VkCommandBuffer cmd, const Image& image, const ImageBarrier& barrier);
// The same for an image this module does not own (a swapchain's), mip 0, layer 0.
void record_image_barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, const ImageBarrier& barrier);

// A global memory barrier (e.g. compute writes -> transfer reads).
void record_memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                           VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

}  // namespace lw
