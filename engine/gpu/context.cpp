#include <utility>
#include "gpu/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_instance_layer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_instance_extension(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool has_device_extension(VkPhysicalDevice device, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// The first queue family that does graphics and compute (and so transfers), or -1.
int find_queue_family(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & needed) == needed) return static_cast<int>(i);
    }
    return -1;
}

DeviceInfo describe_device(VkPhysicalDevice device, int index, bool need_swapchain = false) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(device, &props);
    DeviceInfo info{.index = index, .name = props.deviceName, .type = props.deviceType, .api_version = props.apiVersion};

    VkPhysicalDeviceVulkan13Features features13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &features13};
    if (props.apiVersion >= VK_API_VERSION_1_3) vkGetPhysicalDeviceFeatures2(device, &features);

    if (props.apiVersion < VK_API_VERSION_1_3)
        info.unsuitable_reason = "needs Vulkan 1.3";
    else if (!features13.dynamicRendering || !features13.synchronization2 || !features13.maintenance4)
        info.unsuitable_reason = "lacks dynamicRendering, synchronization2 or maintenance4";
    else if (find_queue_family(device) < 0)
        info.unsuitable_reason = "has no graphics+compute queue";
    else if (need_swapchain && !has_device_extension(device, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
        info.unsuitable_reason = "lacks VK_KHR_swapchain (needed for a window)";
    info.suitable = info.unsuitable_reason.empty();
    return info;
}

// Preference of `auto`: discrete, integrated, virtual GPU, then the CPU device.
int type_rank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
        default: return 4;
    }
}

std::string list_for_message(const std::vector<DeviceInfo>& devices) {
    if (devices.empty()) return "no Vulkan devices found (is mesa-vulkan-drivers installed?)";
    std::string text = "devices:";
    for (const auto& d : devices) {
        text += " [" + std::to_string(d.index) + "] " + d.describe();
        if (!d.suitable) text += " (unsuitable: " + d.unsuitable_reason + ")";
        text += ";";
    }
    text.pop_back();
    return text;
}

int choose_device(const std::vector<DeviceInfo>& devices, const DeviceChoice& choice) {
    if (choice.kind == DeviceChoice::Kind::Index) {
        if (choice.index < 0 || choice.index >= static_cast<int>(devices.size()))
            throw ParameterError("device", " " + std::to_string(choice.index) + ": no such device; " + list_for_message(devices), 1);
        const DeviceInfo& d = devices[static_cast<size_t>(choice.index)];
        if (!d.suitable)
            throw ParameterError("device", " " + std::to_string(choice.index) + ": " + d.name + " " + d.unsuitable_reason, 1);
        return choice.index;
    }
    int best = -1;
    for (const auto& d : devices) {
        if (!d.suitable) continue;
        const bool is_cpu = d.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
        if (choice.kind == DeviceChoice::Kind::Cpu && !is_cpu) continue;
        if (choice.kind == DeviceChoice::Kind::Gpu && (is_cpu || d.type == VK_PHYSICAL_DEVICE_TYPE_OTHER)) continue;
        if (best < 0 || type_rank(d.type) < type_rank(devices[static_cast<size_t>(best)].type)) best = d.index;
    }
    if (best < 0) {
        if (choice.kind == DeviceChoice::Kind::Cpu)
            throw ParameterError("device", " cpu: no CPU Vulkan device (lavapipe) found; " + list_for_message(devices), 1);
        if (choice.kind == DeviceChoice::Kind::Gpu)
            throw ParameterError("device", " gpu: no GPU Vulkan device found; " + list_for_message(devices), 1);
        throw Error("no suitable Vulkan device found; " + list_for_message(devices));
    }
    return best;
}

VkInstance create_instance(bool validation, bool debug_utils, const std::vector<std::string>& wanted = {}) {
    VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                          .pApplicationName = "linework",
                          .applicationVersion = VK_MAKE_VERSION(0, 1, 0),
                          .pEngineName = "linework",
                          .engineVersion = VK_MAKE_VERSION(0, 1, 0),
                          .apiVersion = VK_API_VERSION_1_3};
    std::vector<const char*> layers;
    if (validation) layers.push_back(kValidationLayer);
    std::vector<const char*> extensions;
    if (debug_utils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    for (const std::string& name : wanted) {
        if (!has_instance_extension(name.c_str()))
            throw Error("the Vulkan instance lacks " + name + " (needed for a window; is a display available?)");
        extensions.push_back(name.c_str());
    }
    // Synchronization validation too: a missing barrier is as real a bug as a bad parameter
    // (the layer provides VK_EXT_validation_features itself).
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    const VkValidationFeaturesEXT features{.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
                                           .enabledValidationFeatureCount = 1,
                                           .pEnabledValidationFeatures = enables};
    if (validation) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                              .pNext = validation ? &features : nullptr,
                              .pApplicationInfo = &app,
                              .enabledLayerCount = static_cast<uint32_t>(layers.size()),
                              .ppEnabledLayerNames = layers.data(),
                              .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                              .ppEnabledExtensionNames = extensions.data()};
    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error("vkCreateInstance failed: no Vulkan driver found (install mesa-vulkan-drivers for lavapipe)");
    vk_check(result, "vkCreateInstance");
    return instance;
}

std::vector<VkPhysicalDevice> enumerate(VkInstance instance) {
    uint32_t count = 0;
    LW_VK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    LW_VK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    return devices;
}

}  // namespace

int auto_device_index(const std::vector<DeviceInfo>& devices) {
    try {
        return choose_device(devices, {DeviceChoice::Kind::Auto});
    } catch (const Error&) {
        return -1;
    }
}

DeviceChoice parse_device_choice(const std::string& text) {
    if (text == "auto") return {DeviceChoice::Kind::Auto};
    if (text == "cpu") return {DeviceChoice::Kind::Cpu};
    if (text == "gpu") return {DeviceChoice::Kind::Gpu};
    if (!text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
        text.size() < 6)
        return {DeviceChoice::Kind::Index, std::stoi(text)};
    throw ParameterError("device", ": expected auto, cpu, gpu or a device index, got \"" + text + "\"");
}

std::optional<ComputeSite> parse_compute_site(const std::string& text) {
    if (text == "auto") return std::nullopt;
    if (text == "device") return ComputeSite::Device;
    if (text == "host") return ComputeSite::Host;
    throw ParameterError("compute", ": expected auto, device or host, got \"" + text + "\"");
}

std::string DeviceInfo::type_name() const {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete gpu";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated gpu";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual gpu";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

std::string DeviceInfo::describe() const {
    return name + " [" + type_name() + ", Vulkan " + std::to_string(VK_API_VERSION_MAJOR(api_version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(api_version)) + "." + std::to_string(VK_API_VERSION_PATCH(api_version)) +
           "]";
}

std::vector<DeviceInfo> list_devices() {
    VkInstance instance = create_instance(false, false);
    std::vector<DeviceInfo> infos;
    try {
        const auto devices = enumerate(instance);
        for (size_t i = 0; i < devices.size(); ++i) infos.push_back(describe_device(devices[i], static_cast<int>(i)));
    } catch (...) {
        vkDestroyInstance(instance, nullptr);
        throw;
    }
    vkDestroyInstance(instance, nullptr);
    return infos;
}

Context::Context(const ContextDesc& desc) : compute_site_(desc.compute_site) {
    if (desc.validation && !has_instance_layer(kValidationLayer))
        throw Error("validation requested but VK_LAYER_KHRONOS_validation is not installed "
                    "(apt-get install vulkan-validationlayers)");
    has_debug_utils_ = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    instance_ = create_instance(desc.validation, has_debug_utils_, desc.instance_extensions);

    try {
        if (desc.validation && has_debug_utils_) {
            auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
            VkDebugUtilsMessengerCreateInfoEXT info{
                .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
                .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
                .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
                .pfnUserCallback = &Context::debug_callback,
                .pUserData = this};
            LW_VK(create_messenger(instance_, &info, nullptr, &messenger_));
        }
        if (has_debug_utils_)
            set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
                vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));

        const auto devices = enumerate(instance_);
        std::vector<DeviceInfo> infos;
        for (size_t i = 0; i < devices.size(); ++i)
            infos.push_back(describe_device(devices[i], static_cast<int>(i), desc.swapchain));
        const int chosen = choose_device(infos, desc.device);
        physical_device_ = devices[static_cast<size_t>(chosen)];
        info_ = infos[static_cast<size_t>(chosen)];
        vkGetPhysicalDeviceProperties(physical_device_, &properties_);
        VkPhysicalDeviceDepthStencilResolveProperties resolve{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_STENCIL_RESOLVE_PROPERTIES};
        VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &resolve};
        vkGetPhysicalDeviceProperties2(physical_device_, &properties2);
        depth_resolve_modes_ = resolve.supportedDepthResolveModes;
        vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);

        queue_family_ = static_cast<uint32_t>(find_queue_family(physical_device_));
        {
            uint32_t count = 0;
            vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, nullptr);
            std::vector<VkQueueFamilyProperties> families(count);
            vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, families.data());
            timestamp_valid_bits_ = families[queue_family_].timestampValidBits;
        }

        std::vector<const char*> extensions;
        has_push_descriptors_ = has_device_extension(physical_device_, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
        if (has_push_descriptors_) extensions.push_back(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
        if (desc.swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                           .queueFamilyIndex = queue_family_,
                                           .queueCount = 1,
                                           .pQueuePriorities = &priority};
        VkPhysicalDeviceVulkan13Features features13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                                    .synchronization2 = VK_TRUE,
                                                    .dynamicRendering = VK_TRUE,
                                                    // glslang's Vulkan 1.3 target emits LocalSizeId.
                                                    .maintenance4 = VK_TRUE};
        VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &features13};
        VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                       .pNext = &features,
                                       .queueCreateInfoCount = 1,
                                       .pQueueCreateInfos = &queue_info,
                                       .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                                       .ppEnabledExtensionNames = extensions.data()};
        LW_VK(vkCreateDevice(physical_device_, &device_info, nullptr, &device_));
        vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
        if (has_push_descriptors_)
            cmd_push_descriptor_set = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
                vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));

        VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                          .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                          .queueFamilyIndex = queue_family_};
        VkCommandPool pool = VK_NULL_HANDLE;
        LW_VK(vkCreateCommandPool(device_, &pool_info, nullptr, &pool));
        command_pool_ = Handle<VkCommandPool>(device_, pool, vkDestroyCommandPool);
    } catch (...) {
        destroy();  // members already built are destroyed by C++; raw handles are ours
        throw;
    }
}

Context::~Context() { destroy(); }

void Context::destroy() {
    if (device_) vkDeviceWaitIdle(device_);
    command_pool_.reset();
    if (device_) vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
    if (messenger_) {
        auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy_messenger(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
}

Context::Submission::Submission(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd, VkFence fence)
    : device_(device), pool_(pool), cmd_(cmd), fence_(fence) {}

Context::Submission::Submission(Submission&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      pool_(other.pool_),
      cmd_(std::exchange(other.cmd_, VK_NULL_HANDLE)),
      fence_(std::exchange(other.fence_, VK_NULL_HANDLE)) {}

void Context::Submission::wait() {
    if (fence_ == VK_NULL_HANDLE) return;
    const VkResult waited = vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
    vkDestroyFence(device_, fence_, nullptr);
    fence_ = VK_NULL_HANDLE;
    vkFreeCommandBuffers(device_, pool_, 1, &cmd_);
    cmd_ = VK_NULL_HANDLE;
    vk_check(waited, "vkWaitForFences");
}

Context::Submission::~Submission() {
    if (fence_ == VK_NULL_HANDLE) return;
    // Unwinding past a submission still in flight: wait without throwing, then free.
    vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
    vkDestroyFence(device_, fence_, nullptr);
    vkFreeCommandBuffers(device_, pool_, 1, &cmd_);
}

Context::Submission Context::submit(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                      .commandPool = command_pool_,
                                      .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                      .commandBufferCount = 1};
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    LW_VK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
    // Free the command buffer if recording or submitting fails.
    struct FreeUnlessSubmitted {
        VkDevice device;
        VkCommandPool pool;
        VkCommandBuffer cmd;
        ~FreeUnlessSubmitted() {
            if (cmd) vkFreeCommandBuffers(device, pool, 1, &cmd);
        }
    } guard{device_, command_pool_, cmd};

    VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                   .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    LW_VK(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    LW_VK(vkEndCommandBuffer(cmd));

    VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence raw_fence = VK_NULL_HANDLE;
    LW_VK(vkCreateFence(device_, &fence_info, nullptr, &raw_fence));
    Handle<VkFence> fence(device_, raw_fence, vkDestroyFence);
    VkCommandBufferSubmitInfo cmd_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO, .commandBuffer = cmd};
    VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                         .commandBufferInfoCount = 1,
                         .pCommandBufferInfos = &cmd_info};
    LW_VK(vkQueueSubmit2(queue_, 1, &submit, raw_fence));
    guard.cmd = VK_NULL_HANDLE;
    return Submission(device_, command_pool_, cmd, fence.release());
}

void Context::set_name(VkObjectType type, uint64_t handle, const char* name) const {
    if (!set_object_name_ || !name) return;
    VkDebugUtilsObjectNameInfoEXT info{.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT,
                                       .objectType = type,
                                       .objectHandle = handle,
                                       .pObjectName = name};
    set_object_name_(device_, &info);
}

std::vector<std::string> Context::validation_messages() const {
    std::lock_guard lock(messages_mutex_);
    return validation_messages_;
}

bool validation_from_environment() {
    const char* value = std::getenv("LINEWORK_VALIDATION");
    return value && *value && std::string(value) != "0";
}

void Context::clear_validation_messages() {
    std::lock_guard lock(messages_mutex_);
    validation_messages_.clear();
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                        VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    // The loader and layer also report INFO/VERBOSE; only WARNING and ERROR count (STYLE.md).
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    auto* self = static_cast<Context*>(user);
    const std::string text = std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "ERROR " : "WARNING ") +
                             (data && data->pMessage ? data->pMessage : "(no message)");
    std::fprintf(stderr, "validation: %s\n", text.c_str());
    std::lock_guard lock(self->messages_mutex_);
    self->validation_messages_.push_back(text);
    return VK_FALSE;
}

}  // namespace lw
