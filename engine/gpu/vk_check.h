// engine/gpu/vk_check.h — turn a failed VkResult into an lw::Error naming the call.
//
// Vulkan calls that should never fail in a correct program (out of memory, device lost)
// still get a readable message: "vkCreateBuffer failed: VK_ERROR_OUT_OF_DEVICE_MEMORY".
#pragma once

#include <vulkan/vulkan.h>

#include "core/error.h"

namespace lw {

const char* vk_result_name(VkResult result);

inline void vk_check(VkResult result, const char* call) {
    if (result != VK_SUCCESS) throw Error(std::string(call) + " failed: " + vk_result_name(result));
}

}  // namespace lw

// LW_VK(vkCreateBuffer(device, &info, nullptr, &buffer)) — the error names vkCreateBuffer.
#define LW_VK_NAME_(call) #call
#define LW_VK(call) ::lw::vk_check((call), ::lw::detail_vk_call_name(LW_VK_NAME_(call)).c_str())

namespace lw {
// "vkCreateBuffer(device, ...)" -> "vkCreateBuffer"
inline std::string detail_vk_call_name(const char* expression) {
    std::string text(expression);
    const auto paren = text.find('(');
    return paren == std::string::npos ? text : text.substr(0, paren);
}
}  // namespace lw
