// engine/hatch/hatching.h — hatching by example: N-gram sequences of strokes with a KL2 watch
// (Jodoin, Epstein, Granger-Piché & Ostromoukhov 2002, "Hatching by Example: a Statistical
// Approach").
//
// Input:  a `HatchTraining` (engine/hatch/training.h) and `HatchDesc`.
// Output: a generated sequence (training indices) with a report per block, and its strokes
//         laid out on the training's own line or along user paths (the paper's Fig. 8).
//
// N-gram step (§2.1, GENERATE STROKES): the generated sequence continues the training one
// (Z_temp ← Z_t). For the last N − 1 strokes z_l, every training position i with N − 1
// predecessors is a candidate; its context z_c = x_{i−N+1..i−1} is at distance
// d = ‖z_c − z_l‖ / √((N − 1)·d_x) (the Euclidean distance as a root mean square over the
// context's coordinates, so that one constant c fits every window and stroke dimension; with
// the plain norm, 11–14 standardized coordinates put the nearest context so far ahead of the
// others that S holds one stroke and the sequence loops at the training's end) and has the
// Gibbs probability p ∝ e^(−d) (eq. 6). The plausible set is
// S = {x_i : p_i ≥ c · max p} (eq. 5 with the constant taken relative to the best match, so
// that S is never empty; c = 0.5 by default) and the next stroke is a seeded uniform pick
// from S.
// Blocks (§3.1, §4, Fig. 6): the sequence is generated in blocks (50 strokes by default); each
// block's KL2 against the training (engine/hatch/kl2.h) is measured, and when it passes the
// threshold (by default 3 × random_block_kl2) "the synthesis process is stopped and the
// problematic curves are eliminated. The
// process can then be restarted over the last strokes so far generated with […] a larger
// window size N": the block is discarded and generated again with N + 2, up to N = n − 1 or
// four restarts; the larger window stays for the following blocks. When every attempt
// passes the threshold, the attempt with the lowest KL2 is kept and marked.
#pragma once

#include <functional>
#include <vector>

#include "core/random.h"
#include "hatch/training.h"
#include "vector/curve.h"

namespace lw {

// The plausible set for the context `history` (training indices; its last window − 1 are
// used): training positions whose next stroke may follow. window ≥ 1 (1: every stroke).
[[nodiscard]] std::vector<int> plausible_strokes(const HatchTraining& training, const std::vector<int>& history,
                                                 int window, float c);

struct HatchDesc {
    int count = 100;          // strokes to generate
    int window = 6;           // N (the context is N − 1 strokes)
    int block = 50;           // strokes per KL2 block
    double threshold = -1.0;  // KL2 above which a block is generated again; 0: never; < 0: automatic,
                              // 3 × the median KL2 of 9 blocks drawn from the training at random
    int max_restarts = 4;     // per block
    float plausible = 0.5f;   // c
};

struct HatchBlock {
    int index = 0;            // 1-based
    size_t first = 0, last = 0;  // 1-based stroke numbers in the generated sequence, inclusive
    int window = 0;           // the window of the kept attempt
    double kl2 = 0.0;
    int attempts = 1;
    bool over_threshold = false;  // kept although above the threshold (every attempt was)
    double threshold = 0.0;   // the KL2 threshold for a block of this size (0: none)
    int next_window = 0;      // a rejected attempt: the window of the next one
};

struct HatchSequence {
    std::vector<int> ids;  // training indices, in order
    std::vector<HatchBlock> blocks;
    double threshold = 0.0;  // the KL2 threshold used (0: none)
};

// The median KL2 of 9 blocks of `size` strokes drawn uniformly from the training: what a
// sequence that keeps the training's proportions scores with this many strokes and
// dimensions (KL2's scale depends on both; the paper: the threshold "depends on the stroke's
// form and the sequence complexity").
[[nodiscard]] double random_block_kl2(const HatchTraining& training, int size, Rng& rng);

// `on_block` (optional) hears each attempt whose KL2 passed the threshold and was discarded
// (kept = false), and each kept block (kept = true).
[[nodiscard]] HatchSequence generate_hatching(const HatchTraining& training, const HatchDesc& desc, Rng& rng,
                                              const std::function<void(const HatchBlock&, bool kept)>& on_block = {});

// The generated strokes on the training's line, starting at its first stroke's place.
[[nodiscard]] std::vector<Stroke> place_on_line(const HatchTraining& training, const std::vector<int>& ids);
// Along a path (Fig. 8): centres advance by the strokes' steps in arc length, offsets go
// along the path's normal, and each stroke turns with the tangent. Strokes whose centre
// would pass the path's end are left out; `placed` (optional) gets how many were placed.
[[nodiscard]] std::vector<Stroke> place_along(const HatchTraining& training, const std::vector<int>& ids,
                                              const ArclengthCurve& path, size_t* placed = nullptr);

// A whole hatching, as `linework hatch` and the Python module make it: on the training's line
// without paths, else (Fig. 8) one sequence per path, each long enough to fill it (the path's
// length over the training's median step, at most desc.count strokes), all from one
// generator. `on_block` hears every block as generate_hatching reports it, numbered across
// the paths (block indices and stroke numbers go on from one path to the next).
struct Hatching {
    std::vector<Stroke> strokes;
    double threshold = 0.0;  // the KL2 threshold used (the last sequence's; 0: none)
    // Strokes generated (and numbered in the blocks on_block hears): along paths, each
    // path's sequence is generated a little past its length, and the strokes past its end
    // are not placed, so `strokes` may hold fewer.
    size_t generated = 0;
};
[[nodiscard]] Hatching hatch(const HatchTraining& training, const HatchDesc& desc, const std::vector<ArclengthCurve>& paths,
                             Rng& rng, const std::function<void(const HatchBlock&, bool kept)>& on_block = {});

// The paths to hatch along, from strokes (a stroke file's): "path N: problem" for one that
// cannot be parameterized by arc length.
[[nodiscard]] std::vector<ArclengthCurve> hatch_paths(const std::vector<Stroke>& strokes);

}  // namespace lw
