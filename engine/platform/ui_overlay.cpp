#include "platform/ui_overlay.h"

#include <algorithm>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

namespace {

void check_imgui_vk(VkResult result) {
    if (result < 0) vk_check(result, "Dear ImGui Vulkan backend call");
}

}  // namespace

UiOverlay::UiOverlay(const Context& ctx, const Window& window, VkRenderPass render_pass, uint32_t min_image_count,
                     uint32_t image_count) {
    // The backend needs one combined image sampler (the font atlas).
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                         .flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT,
                                         .maxSets = 4,
                                         .poolSizeCount = 1,
                                         .pPoolSizes = &size};
    VkDescriptorPool pool = VK_NULL_HANDLE;
    LW_VK(vkCreateDescriptorPool(ctx.device(), &pool_info, nullptr, &pool));
    ctx.set_name(VK_OBJECT_TYPE_DESCRIPTOR_POOL, uint64_t(pool), "imgui descriptor pool");
    pool_ = Handle<VkDescriptorPool>(ctx.device(), pool, vkDestroyDescriptorPool);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.92f;
    if (!ImGui_ImplGlfw_InitForVulkan(window.get(), true)) {
        ImGui::DestroyContext();
        throw Error("ImGui_ImplGlfw_InitForVulkan failed");
    }
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance();
    info.PhysicalDevice = ctx.physical_device();
    info.Device = ctx.device();
    info.QueueFamily = ctx.queue_family();
    info.Queue = ctx.queue();
    info.DescriptorPool = pool_;
    info.Subpass = 0;
    info.MinImageCount = std::max(min_image_count, 2u);
    info.ImageCount = std::max(image_count, info.MinImageCount);
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = &check_imgui_vk;
    if (!ImGui_ImplVulkan_Init(&info, render_pass)) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw Error("ImGui_ImplVulkan_Init failed");
    }
    try {
        ctx.submit_and_wait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    } catch (...) {
        ImGui_ImplVulkan_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw;
    }
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

UiOverlay::~UiOverlay() {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void UiOverlay::begin_frame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ended_ = false;
}

void UiOverlay::end_frame() {
    ImGui::Render();
    ended_ = true;
}

void UiOverlay::record(VkCommandBuffer cmd) const {
    if (!ended_) return;
    ImDrawData* data = ImGui::GetDrawData();
    if (data && data->CmdListsCount > 0) ImGui_ImplVulkan_RenderDrawData(data, cmd);
}

bool UiOverlay::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool UiOverlay::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace lw
