// engine/ribbon/stitch.h — stitching: aligning each seam's right edge to the next left edge
// (Zhou et al. 2013, §3.2).
//
// For the seam between DP rows r−1 and r (piece r−1's tilted right edge R̄, piece r's left
// edge L̄, C samples each) a table M is filled by dynamic programming (eq. 2):
//   M[s, t] = min( M[s−1, t−1],
//                  M[s−1, t] + β(L̄[s], R̄[t]),
//                  M[s, t−1] + β(L̄[s], R̄[t]) ) + c(L̄[s], R̄[t])
// with β = P = 32 when L̄[s] or R̄[t] is opaque, else 0 (eq. 3: stretching opaque segments is
// penalized), from M[0, 0] to M[C−1, C−1]. Backtracking gives T: T[s] is the right-edge
// sample shown in front of left-edge sample s — for each s, the cheapest t the path visits.
// In absence of deformation T[s] = s. The drawing (ribbon_draw.h) moves texture coordinates
// by x/(x+r)·(T[i] − i)·w inside piece r−1, so its right edge shows R̄[T[s]] at sample s.
//
// c is the paper's pixel matching cost ξ (with γ for opaque against transparent), not the
// bare RGB distance eq. 2 prints: with a transparent background stored as black and dark
// ink, the RGB distance cannot tell ink from background and the alignment would see nothing.
// Every seam's error is reported before (Σ_s ξ(L̄[s], R̄[s]) = the DP's D) and after
// (Σ_s ξ(L̄[s], R̄[T[s]])); after ≤ before, since the identity path is one of the candidates.
//
// GPU: shaders/ribbon_stitch.comp, one invocation per seam ("each GPU thread handling one
// piece"), the same float operations in the same order: results equal the reference. Each
// invocation keeps two rows of M and 2 bits per cell of moves in scratch memory; seams are
// dispatched in batches whose scratch stays under max_scratch_bytes.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "ribbon/problem.h"

namespace lw {

struct StitchResult {
    std::vector<std::vector<int32_t>> remap;  // per seam r = 1..rows−1 at [r−1]: T, C entries
    std::vector<float> error_before;          // per seam
    std::vector<float> error_after;
    float total_before() const;
    float total_after() const;
};

[[nodiscard]] StitchResult stitch_reference(const DpProblem& problem, const std::vector<glm::ivec2>& positions);

class RibbonStitcherGpu {
public:
    explicit RibbonStitcherGpu(const Context& ctx);
    [[nodiscard]] StitchResult stitch(const DpProblem& problem, const std::vector<glm::ivec2>& positions,
                                      size_t max_scratch_bytes = size_t(256) << 20) const;

private:
    const Context* ctx_;
    ComputePipeline pipeline_;
};

}  // namespace lw
