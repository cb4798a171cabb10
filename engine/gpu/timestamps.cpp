#include "gpu/timestamps.h"

#include "core/error.h"
#include "gpu/vk_check.h"

namespace lw {

GpuTimer::GpuTimer(const Context& ctx, uint32_t max_passes) : ctx_(&ctx), max_passes_(max_passes) {
    if (!ctx.has_timestamps()) return;
    VkQueryPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                               .queryType = VK_QUERY_TYPE_TIMESTAMP,
                               .queryCount = 2 * max_passes};
    VkQueryPool pool = VK_NULL_HANDLE;
    LW_VK(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool));
    pool_ = Handle<VkQueryPool>(ctx.device(), pool, vkDestroyQueryPool);
}

void GpuTimer::reset(VkCommandBuffer cmd) {
    names_.clear();
    open_ = false;
    if (pool_) vkCmdResetQueryPool(cmd, pool_, 0, 2 * max_passes_);
}

void GpuTimer::begin(VkCommandBuffer cmd, const std::string& pass) {
    if (open_) throw Error("GpuTimer: pass \"" + names_.back() + "\" still open when \"" + pass + "\" begins");
    if (names_.size() >= max_passes_) throw Error("GpuTimer: more than " + std::to_string(max_passes_) + " passes");
    const auto index = static_cast<uint32_t>(names_.size());
    names_.push_back(pass);
    open_ = true;
    if (pool_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool_, 2 * index);
}

void GpuTimer::end(VkCommandBuffer cmd) {
    if (!open_) throw Error("GpuTimer: end without begin");
    open_ = false;
    const auto index = static_cast<uint32_t>(names_.size() - 1);
    if (pool_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool_, 2 * index + 1);
}

std::vector<PassTime> GpuTimer::results() const {
    std::vector<PassTime> out;
    for (const auto& name : names_) out.push_back({name, -1.0});
    if (!pool_ || names_.empty()) return out;
    std::vector<uint64_t> ticks(2 * names_.size());
    LW_VK(vkGetQueryPoolResults(ctx_->device(), pool_, 0, static_cast<uint32_t>(ticks.size()),
                                ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    for (size_t i = 0; i < names_.size(); ++i)
        out[i].ms = static_cast<double>(ticks[2 * i + 1] - ticks[2 * i]) * ctx_->timestamp_period_ns() * 1e-6;
    return out;
}

}  // namespace lw
