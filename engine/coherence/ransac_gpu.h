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

// Where fit() runs. On a CPU device (lavapipe) the "GPU" is the same cores, and a dispatch of
// one 64-invocation workgroup per path, with its barriers, costs ~17× the plain loop
// (3.9 ms against 0.23 ms for 450 paths, 1,900 votes): there the host runs the reference.
enum class FitBackend { Device, Host };
[[nodiscard]] FitBackend preferred_fit_backend(const Context& ctx);  // Host on CPU devices

class RansacFitter {
public:
    explicit RansacFitter(const Context& ctx, FitBackend backend = FitBackend::Device);
    FitBackend backend() const { return backend_; }

    // Device: writes the votes to host-visible buffers, dispatches, waits and reads the fits
    // in place (one submission; the buffers are kept for the next call, so fit() is not
    // reentrant); `timer` (optional) gets "ransac". Host: fit_paths_reference.
    [[nodiscard]] std::vector<PathFit> fit(const VoteSet& set, const RansacParams& params,
                                           GpuTimer* timer = nullptr) const;

private:
    const Context* ctx_;
    FitBackend backend_;
    ComputePipeline pipeline_;
    // Scratch kept between calls: four submissions and six allocations per call (staging
    // uploads, a readback) cost more than the dispatch on lavapipe.
    mutable Buffer votes_, offsets_, fits_;
};

}  // namespace lw
