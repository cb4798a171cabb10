#include "coherence/ransac_gpu.h"

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

RansacFitter::RansacFitter(const Context& ctx)
    : ctx_(&ctx),
      pipeline_(ctx, {.spirv = LW_SPIRV(coherence_ransac_comp_spv),
                      .storage_buffers = 3,
                      .push_constant_size = sizeof(RansacPush),
                      .name = "coherence ransac"}) {}

std::vector<PathFit> RansacFitter::fit(const VoteSet& set, const RansacParams& params, GpuTimer* timer) const {
    const auto paths = static_cast<uint32_t>(set.path_count());
    std::vector<PathFit> out(paths);
    if (paths == 0) return out;
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    // Buffers may not be empty: pad an empty vote list with one unused vote.
    std::vector<Vote> votes = set.votes.empty() ? std::vector<Vote>{Vote{0.0f, 0.0f}} : set.votes;
    Buffer vote_buffer = upload_buffer(*ctx_, votes, usage, "ransac votes");
    Buffer offset_buffer = upload_buffer(*ctx_, set.offsets, usage, "ransac offsets");
    Buffer fit_buffer(*ctx_, {.size = paths * sizeof(GpuFit), .usage = usage, .name = "ransac fits"});
    const RansacPush push{params.outlier_ratio, params.target_probability, params.inlier_px,
                          params.max_iterations, params.seed, paths};
    ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
        if (timer) {
            timer->reset(cmd);
            timer->begin(cmd, "ransac");
        }
        pipeline_.dispatch(*ctx_, cmd, {&vote_buffer, &offset_buffer, &fit_buffer}, &push, paths);
        if (timer) timer->end(cmd);
    });
    const auto fits = read_buffer_as<GpuFit>(*ctx_, fit_buffer);
    for (uint32_t p = 0; p < paths; ++p)
        out[p] = PathFit{fits[p].rho, fits[p].phi, fits[p].votes, fits[p].inliers, fits[p].iterations, fits[p].fitted != 0};
    return out;
}

}  // namespace lw
