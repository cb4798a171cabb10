// engine/gpu/handle.h — a move-only owner for one Vulkan object of a device.
//
// Every object the engine creates lives in a Handle (or a class built from Handles), so
// nothing leaks on an exception and destruction order follows C++ scope. The destroy
// function is the matching vkDestroy*/vkFree* call, all of which share one signature.
#pragma once

#include <utility>

#include <vulkan/vulkan.h>

namespace lw {

template <typename T>
class Handle {
public:
    using DestroyFn = void (*)(VkDevice, T, const VkAllocationCallbacks*);

    Handle() = default;
    Handle(VkDevice device, T handle, DestroyFn destroy) : device_(device), handle_(handle), destroy_(destroy) {}
    ~Handle() { reset(); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept { *this = std::move(other); }
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = std::exchange(other.device_, VK_NULL_HANDLE);
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
            destroy_ = std::exchange(other.destroy_, nullptr);
        }
        return *this;
    }

    void reset() {
        if (handle_ != VK_NULL_HANDLE && destroy_) destroy_(device_, handle_, nullptr);
        handle_ = VK_NULL_HANDLE;
    }

    // Gives the handle up: the caller destroys it.
    [[nodiscard]] T release() { return std::exchange(handle_, VK_NULL_HANDLE); }

    T get() const { return handle_; }
    operator T() const { return handle_; }  // NOLINT: pass straight to Vulkan calls
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    T handle_ = VK_NULL_HANDLE;
    DestroyFn destroy_ = nullptr;
};

}  // namespace lw
