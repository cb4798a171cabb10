#include "gpu/vk_check.h"

namespace lw {

const char* vk_result_name(VkResult result) {
    switch (result) {
#define LW_CASE(name) \
    case name:        \
        return #name;
        LW_CASE(VK_SUCCESS)
        LW_CASE(VK_NOT_READY)
        LW_CASE(VK_TIMEOUT)
        LW_CASE(VK_EVENT_SET)
        LW_CASE(VK_EVENT_RESET)
        LW_CASE(VK_INCOMPLETE)
        LW_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        LW_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        LW_CASE(VK_ERROR_INITIALIZATION_FAILED)
        LW_CASE(VK_ERROR_DEVICE_LOST)
        LW_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        LW_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        LW_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        LW_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        LW_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        LW_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        LW_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        LW_CASE(VK_ERROR_FRAGMENTED_POOL)
        LW_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        LW_CASE(VK_ERROR_UNKNOWN)
#undef LW_CASE
        default:
            return "VK_ERROR (unlisted code)";
    }
}

}  // namespace lw
