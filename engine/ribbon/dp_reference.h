// engine/ribbon/dp_reference.h — the dynamic program in plain C++, one function per kernel of
// the paper's §2 (Zhou et al. 2013), in the loop the paper gives:
//
//   findValidPositions(0)
//   for i in 1 .. rows-1:
//       extractColumns(i - 1); findValidPositions(i); compactValidPositions(i)
//       computeCostTable(i); updateTableRow(i)
//   backtrack (dp.h)
//
// The GPU kernels (shaders/ribbon_*.comp, driven by dp_gpu.h) compute the same values in the
// same order of floating-point operations: tests compare them exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "ribbon/dp.h"

namespace lw {

// findValidPositions: one flag per position of U (problem.h lists the four conditions).
[[nodiscard]] std::vector<uint32_t> find_valid_positions(const DpProblem& problem, size_t row,
                                                         ValidityRule rule = ValidityRule::Band);
// compactValidPositions: the indices of the set flags, ascending (an exclusive prefix sum
// of the flags gives each its slot; sequential here).
[[nodiscard]] std::vector<uint32_t> compact_valid_positions(const std::vector<uint32_t>& flags);
// extractColumns: R̄_row for every valid position of `row`: V × C texels, row-major.
[[nodiscard]] std::vector<uint32_t> extract_columns(const DpProblem& problem, size_t row,
                                                    const std::vector<uint32_t>& valid);
// computeCostTable: D(v + R_row−1, u + L_row) for every valid v of row−1 (right edges from
// extract_columns) and u of `row`, at [v · V_row + u]; k summed from 0 to C−1.
[[nodiscard]] std::vector<float> compute_cost_table(const DpProblem& problem, size_t row,
                                                    const std::vector<uint32_t>& right_edges,
                                                    const std::vector<uint32_t>& valid);
// updateTableRow (eq. 1): P[u] = min_v P_prev[v] + table[v · V + u], argmin the lowest v.
void update_table_row(const std::vector<float>& prev_costs, const std::vector<float>& table, size_t count,
                      std::vector<float>& costs, std::vector<uint32_t>& back);

// computeCostTable and updateTableRow in one, the same costs and back pointers bit for bit,
// without summing most of the table: every term of an entry is ≥ 0 and an opacity mismatch
// costs γ, so P_prev[v] + γ·(mismatched opacities of the two edges, a popcount) bounds
// P_prev[v] + entry from below (rounded float addition is monotone), and an entry is summed
// only where that bound can still beat the best found for u (positions with the same
// opacity bits share one bound). On spot_ribbons.json 0.5 % of the entries can
// (docs/BENCHMARKS.md "The DP's rows bounded").
void update_table_row_bounded(const DpProblem& problem, size_t row, const std::vector<uint32_t>& right_edges,
                              const std::vector<uint32_t>& valid, const std::vector<float>& prev_costs,
                              std::vector<float>& costs, std::vector<uint32_t>& back);

// The whole table; a `DpRunner` (the bounded row update unless options.keep_cost_tables asks
// for the tables). Throws lw::Error naming the piece when a row has no valid
// position.
[[nodiscard]] DpTables run_dp_reference(const DpProblem& problem, const DpRunOptions& options = {});

// Shared by both runners: the message for a row without valid positions.
[[nodiscard]] std::string no_valid_position_message(const DpProblem& problem, size_t row);

}  // namespace lw
