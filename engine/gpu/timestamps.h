// engine/gpu/timestamps.h — GPU time per pass from timestamp queries.
//
// Usage: record `begin(cmd, "surface")` … `end(cmd)` around each pass inside one command
// buffer (after `reset(cmd)`), submit and wait, then `results()` gives milliseconds per
// pass. On a queue without timestamps every figure is reported as unavailable (-1).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace lw {

struct PassTime {
    std::string name;
    double ms = -1.0;  // -1 when the device has no timestamps
};

class GpuTimer {
public:
    GpuTimer(const Context& ctx, uint32_t max_passes = 16);

    void reset(VkCommandBuffer cmd);
    void begin(VkCommandBuffer cmd, const std::string& pass);
    void end(VkCommandBuffer cmd);
    // Reads the queries of the last submitted, completed command buffer.
    [[nodiscard]] std::vector<PassTime> results() const;

private:
    const Context* ctx_;
    Handle<VkQueryPool> pool_;
    uint32_t max_passes_;
    std::vector<std::string> names_;
    bool open_ = false;
};

}  // namespace lw
