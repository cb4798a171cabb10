// engine/ribbon/dp_gpu.h — the ribbon dynamic program as Vulkan compute, one kernel per step
// of Zhou et al. 2013, §2:
//
//   findValidPositions   shaders/ribbon_find_valid.comp       one invocation per position of U
//   compactValidPositions shaders/ribbon_compact.comp         parallel prefix scan (3 dispatches)
//   extractColumns       shaders/ribbon_extract_columns.comp  one invocation per valid position
//   computeCostTable     shaders/ribbon_cost_table.comp       one invocation per (v, u) pair
//   updateTableRow       shaders/ribbon_update_row.comp       one invocation per row entry
//
// Input:  a `DpProblem` (probe offsets from problem.h, uploaded once per run) and options.
// Output: the same `DpTables` as run_dp_reference (exactly: same valid lists, same float
//         costs summed in the same order, same argmin), so `solve_ribbon` backtracks either.
//
// Per row two submissions: (extractColumns(i−1), findValidPositions(i), compaction) then,
// once the number of valid positions is known on the host, the cost table and the row update
// — in chunks of new-piece positions when V_i−1 × V_i floats would exceed max_table_bytes —
// and the copy of the row's valid list and back pointers to host memory. row_ms is the wall
// time of both. Backtracking runs on the host (paper: "After iterating over all pieces we
// backtrack").
#pragma once

#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "ribbon/dp.h"

namespace lw {

class RibbonDpGpu {
public:
    explicit RibbonDpGpu(const Context& ctx);

    // A `DpRunner`. Throws lw::Error naming the piece when a row has no valid position.
    [[nodiscard]] DpTables run(const DpProblem& problem, const DpRunOptions& options = {});
    DpRunner runner() {
        return [this](const DpProblem& p, const DpRunOptions& o) { return run(p, o); };
    }

private:
    const Context* ctx_;
    ComputePipeline find_valid_, compact_, extract_, cost_, update_;
};

}  // namespace lw
