#include "platform/swapchain.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

namespace {

VkSurfaceFormatKHR choose_format(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t count = 0;
    LW_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    LW_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()));
    if (formats.empty()) throw Error("the window surface offers no formats");
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const auto& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    return formats.front();
}

VkPresentModeKHR choose_present_mode(VkPhysicalDevice device, VkSurfaceKHR surface, bool vsync) {
    if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always offered
    uint32_t count = 0;
    LW_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    LW_VK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, modes.data()));
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
    return VK_PRESENT_MODE_FIFO_KHR;
}

Handle<VkRenderPass> create_overlay_render_pass(const Context& ctx, VkFormat format) {
    VkAttachmentDescription attachment{.format = format,
                                       .samples = VK_SAMPLE_COUNT_1_BIT,
                                       .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                       .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                       .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                       .initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                       .finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
                                 .colorAttachmentCount = 1,
                                 .pColorAttachments = &color};
    // The blit before (ordered by an explicit barrier) and a screenshot copy after.
    VkSubpassDependency dependencies[2] = {
        {.srcSubpass = VK_SUBPASS_EXTERNAL,
         .dstSubpass = 0,
         .srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
         .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
         .srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
         .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT},
        {.srcSubpass = 0,
         .dstSubpass = VK_SUBPASS_EXTERNAL,
         .srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
         .dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
         .srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
         .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT}};
    VkRenderPassCreateInfo info{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                                .attachmentCount = 1,
                                .pAttachments = &attachment,
                                .subpassCount = 1,
                                .pSubpasses = &subpass,
                                .dependencyCount = 2,
                                .pDependencies = dependencies};
    VkRenderPass pass = VK_NULL_HANDLE;
    LW_VK(vkCreateRenderPass(ctx.device(), &info, nullptr, &pass));
    ctx.set_name(VK_OBJECT_TYPE_RENDER_PASS, uint64_t(pass), "overlay render pass");
    return Handle<VkRenderPass>(ctx.device(), pass, vkDestroyRenderPass);
}

Handle<VkSemaphore> create_semaphore(const Context& ctx, const char* name) {
    VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    LW_VK(vkCreateSemaphore(ctx.device(), &info, nullptr, &semaphore));
    ctx.set_name(VK_OBJECT_TYPE_SEMAPHORE, uint64_t(semaphore), name);
    return Handle<VkSemaphore>(ctx.device(), semaphore, vkDestroySemaphore);
}

}  // namespace

Swapchain::Swapchain(const Context& ctx, const Window& window, const SwapchainDesc& desc) : ctx_(&ctx), desc_(desc) {
    surface_ = window.create_surface(ctx.instance());
    try {
        VkBool32 supported = VK_FALSE;
        LW_VK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physical_device(), ctx.queue_family(), surface_, &supported));
        if (!supported)
            throw Error(ctx.info().name + " cannot present to this window from its graphics queue (choose another device)");
        const VkSurfaceFormatKHR format = choose_format(ctx.physical_device(), surface_);
        format_ = format.format;
        color_space_ = format.colorSpace;
        present_mode_ = choose_present_mode(ctx.physical_device(), surface_, desc.vsync);
        render_pass_ = create_overlay_render_pass(ctx, format_);
        acquired_ = create_semaphore(ctx, "swapchain image acquired");

        VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO, .flags = VK_FENCE_CREATE_SIGNALED_BIT};
        VkFence fence = VK_NULL_HANDLE;
        LW_VK(vkCreateFence(ctx.device(), &fence_info, nullptr, &fence));
        in_flight_ = Handle<VkFence>(ctx.device(), fence, vkDestroyFence);

        VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                          .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                          .queueFamilyIndex = ctx.queue_family()};
        VkCommandPool pool = VK_NULL_HANDLE;
        LW_VK(vkCreateCommandPool(ctx.device(), &pool_info, nullptr, &pool));
        pool_ = Handle<VkCommandPool>(ctx.device(), pool, vkDestroyCommandPool);
        VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                          .commandPool = pool_,
                                          .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                          .commandBufferCount = 1};
        LW_VK(vkAllocateCommandBuffers(ctx.device(), &alloc, &cmd_));

        if (!recreate(window.framebuffer_size()))
            throw Error("the window has no drawable area (minimized at start?)");
    } catch (...) {
        vkDeviceWaitIdle(ctx.device());
        framebuffers_.clear();
        views_.clear();
        swapchain_.reset();
        vkDestroySurfaceKHR(ctx.instance(), surface_, nullptr);
        throw;
    }
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(ctx_->device());
    framebuffers_.clear();
    views_.clear();
    swapchain_.reset();
    vkDestroySurfaceKHR(ctx_->instance(), surface_, nullptr);
}

bool Swapchain::recreate(VkExtent2D size) {
    if (size.width == 0 || size.height == 0) return false;
    VkSurfaceCapabilitiesKHR caps{};
    LW_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_->physical_device(), surface_, &caps));
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) {  // the surface takes the swapchain's size
        extent.width = std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent.width == 0 || extent.height == 0) return false;

    vkDeviceWaitIdle(ctx_->device());  // nothing in flight uses the old images
    readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("the window surface does not accept transfers into its images");
    min_image_count_ = std::max(caps.minImageCount, 2u);
    uint32_t count = min_image_count_ + 1;
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
    VkSwapchainCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .surface = surface_,
        .minImageCount = count,
        .imageFormat = format_,
        .imageColorSpace = color_space_,
        .imageExtent = extent,
        .imageArrayLayers = 1,
        .imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                      (readable_ ? VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT) : VkImageUsageFlags(0)),
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .preTransform = caps.currentTransform,
        .compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                            ~(caps.supportedCompositeAlpha - 1)),
        .presentMode = present_mode_,
        .clipped = VK_TRUE,
        .oldSwapchain = swapchain_};
    VkSwapchainKHR raw = VK_NULL_HANDLE;
    LW_VK(vkCreateSwapchainKHR(ctx_->device(), &info, nullptr, &raw));
    framebuffers_.clear();
    views_.clear();
    swapchain_ = Handle<VkSwapchainKHR>(ctx_->device(), raw, vkDestroySwapchainKHR);  // destroys the old one
    ctx_->set_name(VK_OBJECT_TYPE_SWAPCHAIN_KHR, uint64_t(raw), "window swapchain");
    extent_ = extent;

    uint32_t image_count = 0;
    LW_VK(vkGetSwapchainImagesKHR(ctx_->device(), swapchain_, &image_count, nullptr));
    images_.resize(image_count);
    LW_VK(vkGetSwapchainImagesKHR(ctx_->device(), swapchain_, &image_count, images_.data()));
    for (VkImage image : images_) {
        VkImageViewCreateInfo view_info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                        .image = image,
                                        .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                        .format = format_,
                                        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
        VkImageView view = VK_NULL_HANDLE;
        LW_VK(vkCreateImageView(ctx_->device(), &view_info, nullptr, &view));
        views_.emplace_back(ctx_->device(), view, vkDestroyImageView);
        VkFramebufferCreateInfo fb_info{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                        .renderPass = render_pass_,
                                        .attachmentCount = 1,
                                        .pAttachments = &view,
                                        .width = extent.width,
                                        .height = extent.height,
                                        .layers = 1};
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        LW_VK(vkCreateFramebuffer(ctx_->device(), &fb_info, nullptr, &framebuffer));
        framebuffers_.emplace_back(ctx_->device(), framebuffer, vkDestroyFramebuffer);
    }
    while (render_done_.size() < images_.size()) render_done_.push_back(create_semaphore(*ctx_, "swapchain render done"));
    return true;
}

void Swapchain::record(VkCommandBuffer cmd, uint32_t index, const PresentDesc& desc, const Buffer* readback) const {
    const VkImage image = images_[index];
    // Copy, blit and clear all count as transfer stages.
    record_image_barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {.old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                          .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          .src_access = VK_ACCESS_2_NONE,
                          .dst_stage = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                          .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT});
    if (desc.frame) {
        // The renderer's last writes (attachment, then its own transfer) before the copy reads.
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        const VkExtent2D src = desc.frame->extent();
        const bool same = src.width == extent_.width && src.height == extent_.height;
        if (same && desc.frame->format() == format_) {
            // A frame rendered in the swapchain's own format and size: a plain copy (on lavapipe
            // 2.5 ms less than the blit's sampled, format-converting draw at 1280×720).
            VkImageCopy region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                               .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                               .extent = {extent_.width, extent_.height, 1}};
            vkCmdCopyImage(cmd, desc.frame->get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        } else {
            VkImageBlit region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                               .srcOffsets = {{0, 0, 0}, {int32_t(src.width), int32_t(src.height), 1}},
                               .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                               .dstOffsets = {{0, 0, 0}, {int32_t(extent_.width), int32_t(extent_.height), 1}}};
            vkCmdBlitImage(cmd, desc.frame->get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, same ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
        }
    } else {
        VkClearColorValue black{};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
    }
    record_image_barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                         {.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          .new_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          .src_stage = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                          .src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          .dst_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          .dst_access = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});

    VkRenderPassBeginInfo begin{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                .renderPass = render_pass_,
                                .framebuffer = framebuffers_[index],
                                .renderArea = {{0, 0}, extent_}};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    if (desc.overlay) desc.overlay(cmd);
    vkCmdEndRenderPass(cmd);  // now PRESENT_SRC_KHR

    if (readback) {
        record_image_barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                             {.old_layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                              .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              .src_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                              .src_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                              .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .dst_access = VK_ACCESS_2_TRANSFER_READ_BIT});
        VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .imageExtent = {extent_.width, extent_.height, 1}};
        vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback->get(), 1, &region);
        record_image_barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                             {.old_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              .new_layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                              .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .src_access = VK_ACCESS_2_NONE,
                              .dst_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                              .dst_access = VK_ACCESS_2_NONE});
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    }
}

bool Swapchain::present(const PresentDesc& desc) {
    const VkDevice device = ctx_->device();
    VkFence fence = in_flight_;
    LW_VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));

    uint32_t index = 0;
    const VkResult acquired = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) return false;
    if (acquired != VK_SUBOPTIMAL_KHR) vk_check(acquired, "vkAcquireNextImageKHR");
    LW_VK(vkResetFences(device, 1, &fence));

    // The screenshot: the swapchain image when it may be read, else the frame itself.
    const bool from_swapchain = desc.screenshot && readable_;
    Buffer readback;
    if (desc.screenshot)
        readback = Buffer(*ctx_, {.size = VkDeviceSize(extent_.width) * extent_.height * 4,
                                  .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  .purpose = MemoryPurpose::Readback,
                                  .name = "screenshot readback"});

    LW_VK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                   .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    LW_VK(vkBeginCommandBuffer(cmd_, &begin));
    record(cmd_, index, desc, from_swapchain ? &readback : nullptr);
    LW_VK(vkEndCommandBuffer(cmd_));

    VkSemaphoreSubmitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                               .semaphore = acquired_,
                               .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
    VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                 .semaphore = render_done_[index],
                                 .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
    VkCommandBufferSubmitInfo cmd_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO, .commandBuffer = cmd_};
    VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                         .waitSemaphoreInfoCount = 1,
                         .pWaitSemaphoreInfos = &wait,
                         .commandBufferInfoCount = 1,
                         .pCommandBufferInfos = &cmd_info,
                         .signalSemaphoreInfoCount = 1,
                         .pSignalSemaphoreInfos = &signal};
    LW_VK(vkQueueSubmit2(ctx_->queue(), 1, &submit, fence));

    VkSemaphore done = render_done_[index];
    VkSwapchainKHR swapchain = swapchain_;
    VkPresentInfoKHR present{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                             .waitSemaphoreCount = 1,
                             .pWaitSemaphores = &done,
                             .swapchainCount = 1,
                             .pSwapchains = &swapchain,
                             .pImageIndices = &index};
    const VkResult presented = vkQueuePresentKHR(ctx_->queue(), &present);
    if (presented != VK_ERROR_OUT_OF_DATE_KHR && presented != VK_SUBOPTIMAL_KHR) vk_check(presented, "vkQueuePresentKHR");

    if (desc.screenshot) {
        LW_VK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
        ImageRGBA8& shot = *desc.screenshot;
        if (from_swapchain) {
            shot = read_rgba8(*ctx_, readback, extent_.width, extent_.height, format_);
            for (size_t i = 3; i < shot.pixels.size(); i += 4) shot.pixels[i] = 255;  // the window is opaque
        } else if (desc.frame) {  // the frame alone, without the overlay
            const VkExtent2D e = desc.frame->extent();
            Buffer buffer(*ctx_, {.size = VkDeviceSize(e.width) * e.height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  .purpose = MemoryPurpose::Readback, .name = "screenshot readback"});
            ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
                record_image_to_buffer(cmd, *desc.frame, buffer);
                record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                      VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
            });
            shot = read_rgba8(*ctx_, buffer, e.width, e.height, desc.frame->format());
        }
    }
    return acquired == VK_SUCCESS && presented == VK_SUCCESS;
}

}  // namespace lw
