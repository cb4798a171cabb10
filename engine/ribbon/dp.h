// engine/ribbon/dp.h — the shortest-path search over piece positions (Zhou et al. 2013, §1.3–1.5)
// and what it is compared with.
//
// Ω(u_0 … u_N) = Σ_i D(u_i + R_i, u_i+1 + L_i+1), D = Σ_k ξ(R̄_i[k], L̄_i+1[k])   (§1.3)
// P[i, u] = min_v P[i−1, v] + D(v + R_i−1, u + L_i)                               (eq. 1)
//
// A `DpRunner` fills the table row by row — the C++ reference (dp_reference.h) or the Vulkan
// kernels (dp_gpu.h), which must agree exactly — and returns what backtracking needs.
// `solve_ribbon` backtracks: from the cheapest last-row entry for an open curve; for a closed
// curve from every terminal position, keeping the cheapest path whose terminal position
// equals its first (§1.5's single DP). A closed curve also runs the DP over its pieces twice
// round from a free start, and once more with piece 0 fixed where that path passes piece 0
// the second time (the wrap-around start of tail-biting Viterbi decoding; solve_ribbon says
// why); the cheaper of the two cycles is kept. A fixed start always closes: the terminal
// piece is a copy of piece 0, so that start is valid for it too.
//
// Ties (common with periodic exemplars) are broken by the seed: the end is drawn among the
// equally cheap last-row entries, so different seeds give different, equally optimal results
// (for a loop the seed also picks the second candidate's start, so there the kept cycle's
// cost may differ from seed to seed).
// Inside the table, argmin keeps the lowest index, identically on CPU and GPU.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ribbon/problem.h"

namespace lw {

struct DpRunOptions {
    std::optional<uint32_t> first_position;  // fix piece 0 at this position index
    bool keep_cost_tables = false;           // tests: keep every row's table (memory heavy)
    size_t max_table_bytes = size_t(256) << 20;  // GPU: cost table built in chunks under this size
    // Called after each row: (row, rows, valid positions of the row).
    std::function<void(size_t, size_t, uint32_t)> progress;
};

struct DpTables {
    std::vector<std::vector<uint32_t>> valid;  // per row: valid position indices, ascending
    std::vector<std::vector<uint32_t>> back;   // per row (row 0 empty): argmin into the previous row's list
    std::vector<ValidityRule> rules;              // per row: the slicing rule its valid positions passed
    std::vector<float> last_costs;             // P[last row, ·], parallel to valid.back()
    std::vector<double> row_ms;                // rows 1..: wall time per row
    std::vector<std::vector<float>> cost_tables;  // keep_cost_tables: [row][v · V_row + u]
};

using DpRunner = std::function<DpTables(const DpProblem&, const DpRunOptions&)>;

struct RibbonSolution {
    std::vector<glm::ivec2> positions;  // one per DP row; closed: the last (terminal) equals the first
    std::vector<float> seam_costs;      // D between consecutive rows
    float total_cost = 0.0f;            // the DP's P at the chosen end (= Σ seam_costs, summed in order)
    std::vector<uint32_t> valid_counts;
    std::vector<ValidityRule> rules;       // per row (problem.h); rows above Band are reported
    std::vector<double> row_ms;
    bool closed_by_first_dp = true;     // closed curves: false when the fixed-start DP's cycle was kept
};

[[nodiscard]] RibbonSolution solve_ribbon(const DpProblem& problem, const DpRunner& runner, uint64_t seed,
                                          const DpRunOptions& options = {});

// The rows of a solution that needed a looser rule than Band, in row order: pieces left
// empty (Empty: no ink avoids the overlap there) and pieces that may cut the pattern (Edges,
// Any). What the command line prints and Python warns of and returns.
struct LooserRows {
    std::vector<size_t> empty, cut;
};
[[nodiscard]] LooserRows looser_rows(const RibbonSolution& solution);

// A solution whose every piece was left empty draws a blank image, which is no result: why,
// for the caller's error ("the ribbon drew nothing: …"); nothing while some piece has ink.
// `avoid`: how the caller names the user's avoidance map ("" for none).
[[nodiscard]] std::optional<std::string> blank_ribbon_reason(const RibbonSolution& solution, const std::string& avoid);

// D(prev + R_row−1, cur + L_row): the seam cost between rows row−1 and row.
[[nodiscard]] float seam_cost(const DpProblem& problem, size_t row, glm::ivec2 prev, glm::ivec2 cur);
// Σ of seam costs along `positions` (one per row), summed in row order as the DP does.
[[nodiscard]] float path_cost(const DpProblem& problem, const std::vector<glm::ivec2>& positions);

// Baselines for the quality report. Greedy: piece 0 where `first` is, then each piece at the
// valid position with the cheapest seam to the previous one (the terminal piece of a closed
// curve is forced to the first). Random: a uniformly drawn valid position per piece.
[[nodiscard]] std::vector<glm::ivec2> greedy_positions(const DpProblem& problem,
                                                       const std::vector<std::vector<uint32_t>>& valid,
                                                       glm::ivec2 first);
[[nodiscard]] std::vector<glm::ivec2> random_positions(const DpProblem& problem,
                                                       const std::vector<std::vector<uint32_t>>& valid, uint64_t seed);


}  // namespace lw
