#include "coherence/ransac_gpu.h"

#include <algorithm>
#include <cstring>

#include "coherence_ransac_comp.h"

namespace lw {

namespace {

// Mirrors Fit and RansacPush in shaders/coherence_ransac.comp.
struct GpuFit {
    float rho, phi;
    uint32_t votes, inliers, iterations, fitted, pad0, pad1;
};
struct RansacPush {
    float outlier_ratio, target_probability, inlier_px;
    uint32_t max_iterations, seed, path_count;
};

}  // namespace

RansacFitter::RansacFitter(const Context& ctx, ComputeSite site)
    : ctx_(&ctx),
      site_(site),
      pipeline_(ctx, {.spirv = LW_SPIRV(coherence_ransac_comp_spv),
                      .storage_buffers = 3,
                      .push_constant_size = sizeof(RansacPush),
                      .name = "coherence ransac"}) {}

std::vector<PathFit> RansacFitter::fit(const VoteSet& set, const RansacParams& params, GpuTimer* timer) const {
    if (site_ == ComputeSite::Host) return fit_paths_reference(set, params);
    const auto paths = static_cast<uint32_t>(set.path_count());
    std::vector<PathFit> out(paths);
    if (paths == 0) return out;
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    // Buffers may not be empty: an empty vote list still gets room for one unused vote.
    const size_t vote_count = std::max<size_t>(set.votes.size(), 1);
    ensure_buffer(*ctx_, votes_, {.size = vote_count * sizeof(Vote), .usage = usage, .purpose = MemoryPurpose::Upload,
                                  .name = "ransac votes"});
    ensure_buffer(*ctx_, offsets_, {.size = set.offsets.size() * sizeof(uint32_t), .usage = usage,
                                    .purpose = MemoryPurpose::Upload, .name = "ransac offsets"});
    ensure_buffer(*ctx_, fits_, {.size = paths * sizeof(GpuFit), .usage = usage, .purpose = MemoryPurpose::Readback,
                                 .name = "ransac fits"});
    if (!set.votes.empty()) std::memcpy(votes_.mapped(), set.votes.data(), set.votes.size() * sizeof(Vote));
    std::memcpy(offsets_.mapped(), set.offsets.data(), set.offsets.size() * sizeof(uint32_t));
    const RansacPush push{params.outlier_ratio, params.target_probability, params.inlier_px,
                          params.max_iterations, params.seed, paths};
    ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
        if (timer) {
            timer->reset(cmd);
            timer->begin(cmd, "ransac");
        }
        pipeline_.dispatch(*ctx_, cmd, {&votes_, &offsets_, &fits_}, &push, paths);
        if (timer) timer->end(cmd);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    fits_.invalidate(*ctx_);
    const auto* fits = static_cast<const GpuFit*>(fits_.mapped());
    for (uint32_t p = 0; p < paths; ++p)
        out[p] = PathFit{fits[p].rho, fits[p].phi, fits[p].votes, fits[p].inliers, fits[p].iterations, fits[p].fitted != 0};
    return out;
}

}  // namespace lw
