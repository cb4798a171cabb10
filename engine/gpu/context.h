// engine/gpu/context.h — the Vulkan instance, the chosen device and its queue.
//
// Input:  a `ContextDesc` — which device (`--device auto|cpu|gpu|N`) and whether the
//         Khronos validation layer is on.
// Output: a `Context` owning VkInstance, VkDevice, one graphics+compute queue and a
//         command pool; helpers to record-submit-wait one command buffer.
//
// Headless by default. A window (engine/platform) passes the instance extensions its
// surface needs (glfwGetRequiredInstanceExtensions) and asks for VK_KHR_swapchain; devices
// without it are then unsuitable. Presentation support of the queue is checked by the
// window's swapchain, which has the surface.
//
// Device choice (DESIGN.md "Contracts"): `auto` takes a discrete GPU when there is one,
// else an integrated or virtual GPU, else the CPU device (Mesa lavapipe). `cpu` and `gpu`
// insist on that kind and fail with a message listing the devices when none exists; `N` is
// an index into the list `linework devices` prints. Only Vulkan 1.3 devices with dynamic
// rendering and synchronization2 qualify.
//
// With validation on, every WARNING or ERROR message of the layer is recorded; tests and
// `LINEWORK_VALIDATION=1` runs fail when `validation_messages()` is not empty.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/handle.h"

namespace lw {

struct DeviceChoice {
    enum class Kind { Auto, Cpu, Gpu, Index };
    Kind kind = Kind::Auto;
    int index = -1;
};

// Parses "auto", "cpu", "gpu" or a device index; throws a usage error otherwise.
[[nodiscard]] DeviceChoice parse_device_choice(const std::string& text);

// Where a compute-shaped stage runs. On a CPU device (lavapipe) the "GPU" is the host's own
// cores, and Vulkan's submissions, barriers and float blending there cost more than the
// reference loops the tests compare the GPU code with (RANSAC 3.9 against 0.23 ms, the splat
// 5.5 against under 1 ms, line extraction 5.3 against 2.3 ms per frame at 70k triangles):
// on such a device the host runs those. The GPU paths stay tested against them everywhere.
enum class ComputeSite { Device, Host };

struct ContextDesc {
    DeviceChoice device{};
    bool validation = false;  // enable VK_LAYER_KHRONOS_validation and record its messages
    // For a window: instance extensions of the surface (VK_KHR_surface, VK_KHR_xcb_surface, …)
    // and the VK_KHR_swapchain device extension. Empty / false: headless.
    std::vector<std::string> instance_extensions;
    bool swapchain = false;
    std::optional<ComputeSite> compute_site;  // nullopt: Host on CPU devices, else Device
};
// "auto" (nullopt), "device" or "host" (a usage error otherwise, naming `option`).
inline constexpr const char* kComputeSiteHelp =
    "Where line extraction, the parameterization splat and RANSAC run: auto (the host on CPU devices "
    "such as lavapipe, where that is faster; the device on GPUs), device, or host";
[[nodiscard]] std::optional<ComputeSite> parse_compute_site(const std::string& text);

// LINEWORK_VALIDATION set (and not "0"): every program over the engine (the command line,
// the Python module, the tests) turns the validation layer on.
[[nodiscard]] bool validation_from_environment();

struct DeviceInfo {
    int index = 0;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    uint32_t api_version = 0;
    bool suitable = false;          // Vulkan 1.3 with the features we need
    std::string unsuitable_reason;  // why not, when !suitable

    std::string type_name() const;
    std::string describe() const;   // "llvmpipe (LLVM 15.0.6, 256 bits) [cpu, Vulkan 1.3.230]"
};

// Lists the physical devices the loader sees (creates and drops a bare instance).
[[nodiscard]] std::vector<DeviceInfo> list_devices();
// The index `--device auto` takes among `devices` (a discrete GPU, else an integrated one,
// else a virtual one, else the CPU device), or −1 when none is suitable.
[[nodiscard]] int auto_device_index(const std::vector<DeviceInfo>& devices);

class Context {
public:
    explicit Context(const ContextDesc& desc = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_device_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    const DeviceInfo& info() const { return info_; }
    // ContextDesc::compute_site, else Host on CPU devices and Device on others.
    ComputeSite preferred_compute_site() const {
        if (compute_site_) return *compute_site_;
        return info_.type == VK_PHYSICAL_DEVICE_TYPE_CPU ? ComputeSite::Host : ComputeSite::Device;
    }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }

    // Nanoseconds per timestamp tick, and whether the queue supports timestamps at all.
    double timestamp_period_ns() const { return properties_.limits.timestampPeriod; }
    bool has_timestamps() const { return timestamp_valid_bits_ > 0; }
    bool has_push_descriptors() const { return has_push_descriptors_; }
    // How a multisampled depth attachment may be resolved (Vulkan 1.2: SAMPLE_ZERO at least).
    VkResolveModeFlags depth_resolve_modes() const { return depth_resolve_modes_; }

    // A submitted command buffer and its fence: wait() blocks until the device is done
    // (the destructor waits too, so nothing in flight is ever freed).
    class Submission {
    public:
        Submission(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd, VkFence fence);
        Submission(Submission&& other) noexcept;
        Submission& operator=(Submission&&) = delete;
        ~Submission();
        void wait();

    private:
        VkDevice device_ = VK_NULL_HANDLE;
        VkCommandPool pool_ = VK_NULL_HANDLE;
        VkCommandBuffer cmd_ = VK_NULL_HANDLE;
        VkFence fence_ = VK_NULL_HANDLE;
    };

    // Records one command buffer with `record` and submits it; the host may work on while
    // the device runs it.
    [[nodiscard]] Submission submit(const std::function<void(VkCommandBuffer)>& record) const;
    // The same, waiting for completion.
    void submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const { submit(record).wait(); }

    // Gives a Vulkan object a name that validation messages and debuggers show.
    void set_name(VkObjectType type, uint64_t handle, const char* name) const;

    // WARNING and ERROR messages of the validation layer since creation (or the last clear).
    std::vector<std::string> validation_messages() const;
    void clear_validation_messages();

    // Loaded extension entry points.
    PFN_vkCmdPushDescriptorSetKHR cmd_push_descriptor_set = nullptr;

private:
    void destroy();
    static VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                          VkDebugUtilsMessageTypeFlagsEXT types,
                                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                          void* user);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    uint32_t timestamp_valid_bits_ = 0;
    bool has_push_descriptors_ = false;
    bool has_debug_utils_ = false;
    VkResolveModeFlags depth_resolve_modes_ = 0;
    DeviceInfo info_;
    std::optional<ComputeSite> compute_site_;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_properties_{};
    Handle<VkCommandPool> command_pool_;
    PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;

    mutable std::mutex messages_mutex_;
    std::vector<std::string> validation_messages_;
};

}  // namespace lw
