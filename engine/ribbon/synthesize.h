// engine/ribbon/synthesize.h — one ribbon synthesis from start to finish, as the `linework
// ribbon` command and the benchmark run it (Zhou et al. 2013):
//
//   curve → ribbon of width b sliced every δ (§1.2) → avoidance map drawn off-screen from
//   fold-overs and self-overlaps, merged with the user's map (§3.1) → probes per piece →
//   DP (§1.4, §2) with the closed-curve search (§1.5) → greedy and random baselines →
//   optional stitching (§3.2) → drawing with the deformation. The DP and the stitching run
//   as Vulkan compute or as their plain C++ references (identical results, tests/
//   test_ribbon_gpu.cpp), by default where the context prefers: the host on CPU devices,
//   where the threaded C++ DP is faster than lavapipe's compute (docs/BENCHMARKS.md).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "core/image.h"
#include "gpu/context.h"
#include "ribbon/dp.h"
#include "ribbon/ribbon.h"
#include "ribbon/stitch.h"

namespace lw {

struct RibbonSynthesisDesc {
    RibbonParams params;
    int width = 0, height = 0;               // canvas, output pixels
    uint64_t seed = 1;                        // ties between optimal ends, random baseline
    bool stitch = false;
    bool avoid_overlaps = true;               // §3.1 avoidance of fold-overs and self-overlaps
    const ForbiddenMask* user_forbidden = nullptr;  // the user's avoidance map (canvas size)
    // Where the DP and stitching run: Host is the C++ reference; nullopt: the context's
    // preferred site (ContextDesc::compute_site, else the host on CPU devices).
    std::optional<ComputeSite> site;
    std::function<void(size_t, size_t, uint32_t)> progress;  // (row, rows, valid positions)
};

struct RibbonSynthesis {
    Ribbon ribbon;
    ForbiddenMask forbidden;          // what the pieces avoided (canvas size)
    RibbonSolution solution;
    float greedy_cost = 0.0f, random_cost = 0.0f;
    std::optional<StitchResult> stitch;
    ImageRGBA8 image;                 // RGBA, transparent background
    double dp_ms = 0.0, stitch_ms = 0.0, draw_ms = 0.0;
    bool dp_on_host = false;          // the C++ DP ran (else the device's)
};

[[nodiscard]] RibbonSynthesis synthesize_ribbon(const Context& ctx, const Exemplar& exemplar,
                                                const ArclengthCurve& curve, const RibbonSynthesisDesc& desc);

}  // namespace lw
