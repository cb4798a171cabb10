// engine/coherence/path_split.h — paths that merged pieces of different earlier paths, split.
//
// Bénard et al. 2010 §4.2 notes that "popping can occur when two paths merge": one (ρ, φ) per
// path cannot keep the phases of several earlier paths. Input: this frame's paths, their votes
// (with the sample each came from), RANSAC's fits and the splat's sprite radius. Where a run
// of at least 8 consecutive votes disagrees with a path's fit (at either end of the path,
// one more than the sprite radius spans in samples, plus the seam's own: 4 by default), the
// path is cut there, at the middle of each seam; the agreeing pieces keep the fit and the
// others are fitted on their own (RANSAC again) and looked at again, so that a path joining
// three or more earlier ones keeps all their phases. Output: the pieces, their votes and
// fits, in place (neighbouring pieces share their seam's sample; a piece of a loop is open, a
// loop left whole stays closed).
#pragma once

#include <vector>

#include "coherence/ransac.h"
#include "coherence/ransac_gpu.h"
#include "types/screen_path.h"

namespace lw {

// Where a piece came from: samples [first, first + count) of path `path` of the input (for a
// loop that was cut, of the loop `opened`: its first sample repeated at its end, so that the
// last piece reaches back to the first; pieces are open, and the closing segment was drawn by
// none).
struct PieceOrigin {
    uint32_t path, first, count;
};

// `origins` (optional) receives each piece's origin.
void split_merged_paths(std::vector<ScreenPath>& paths, VoteSet& votes, std::vector<PathFit>& fits,
                        const RansacParams& ransac, float splat_radius_px, const RansacFitter& fitter,
                        std::vector<PieceOrigin>* origins = nullptr);

}  // namespace lw
