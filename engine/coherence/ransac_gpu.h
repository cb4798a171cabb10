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
    explicit RansacFitter(const Context& ctx);

    // Uploads the votes, dispatches, waits and reads the fits back; `timer` (optional)
    // gets "ransac".
    [[nodiscard]] std::vector<PathFit> fit(const VoteSet& set, const RansacParams& params,
                                           GpuTimer* timer = nullptr) const;

private:
    const Context* ctx_;
    ComputePipeline pipeline_;
};

}  // namespace lw
