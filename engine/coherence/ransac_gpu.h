// engine/coherence/ransac_gpu.h — the RANSAC fit of every path in one compute dispatch.
//
// Input:  a `VoteSet` (votes of all paths, with offsets) and `RansacParams`.
// Output: one `PathFit` per path, the same as fit_paths_reference up to float rounding
//         of the final least squares (shaders/coherence_ransac.comp, one workgroup per path).
#pragma once

#include <vector>

#include "coherence/ransac.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/timestamps.h"

namespace lw {

class RansacFitter {
public:
    // `site` Host: fit() is fit_paths_reference (on lavapipe a dispatch of one 64-invocation
    // workgroup per path, with its barriers, costs ~17× that loop; see ComputeSite).
    explicit RansacFitter(const Context& ctx, ComputeSite site = ComputeSite::Device);

    // Device: writes the votes to host-visible buffers, dispatches, waits and reads the fits
    // in place (one submission; the buffers are kept for the next call, so fit() is not
    // reentrant); `timer` (optional) gets "ransac". Host: fit_paths_reference.
    [[nodiscard]] std::vector<PathFit> fit(const VoteSet& set, const RansacParams& params,
                                           GpuTimer* timer = nullptr) const;

private:
    const Context* ctx_;
    ComputeSite site_;
    ComputePipeline pipeline_;
    // Scratch kept between calls: four submissions and six allocations per call (staging
    // uploads, a readback) cost more than the dispatch on lavapipe.
    mutable Buffer votes_, offsets_, fits_;
};

}  // namespace lw
