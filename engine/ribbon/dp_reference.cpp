#include "ribbon/dp_reference.h"

#include <algorithm>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"

namespace lw {

std::vector<uint32_t> find_valid_positions(const DpProblem& problem, size_t row, ValidityRule rule) {
    std::vector<uint32_t> flags(problem.position_count());
    parallel_for(flags.size(), 1024, [&](size_t begin, size_t end, size_t) {
        for (size_t p = begin; p < end; ++p)
            flags[p] = position_valid(problem, row, problem.position(uint32_t(p)), rule) ? 1u : 0u;
    });
    return flags;
}

namespace {

// The valid positions of `row` under the strictest slicing rule that leaves any.
std::vector<uint32_t> valid_positions(const DpProblem& problem, size_t row, ValidityRule& rule) {
    for (int r = 0; r <= int(ValidityRule::Any); ++r) {
        rule = ValidityRule(r);
        std::vector<uint32_t> valid = compact_valid_positions(find_valid_positions(problem, row, rule));
        if (!valid.empty()) return valid;
    }
    throw Error(no_valid_position_message(problem, row));
}

}  // namespace

std::vector<uint32_t> compact_valid_positions(const std::vector<uint32_t>& flags) {
    std::vector<uint32_t> valid;
    for (uint32_t p = 0; p < flags.size(); ++p)
        if (flags[p]) valid.push_back(p);
    return valid;
}

std::vector<uint32_t> extract_columns(const DpProblem& problem, size_t row, const std::vector<uint32_t>& valid) {
    const size_t C = size_t(problem.samples);
    const PieceProbes& probes = problem.rows[row];
    std::vector<uint32_t> columns(valid.size() * C);
    for (size_t j = 0; j < valid.size(); ++j) {
        const glm::ivec2 u = problem.position(valid[j]);
        for (size_t k = 0; k < C; ++k) {
            const glm::ivec2 t = u + probes.right[k];
            columns[j * C + k] = problem.exemplar->at(t.x, t.y);
        }
    }
    return columns;
}

std::vector<float> compute_cost_table(const DpProblem& problem, const std::vector<uint32_t>& right_edges,
                                      const std::vector<uint32_t>& valid) {
    const size_t C = size_t(problem.samples);
    const size_t prev_count = right_edges.size() / C, count = valid.size();
    // Left edges L̄ of the new piece: column x of E from row y, at the left-edge offsets.
    std::vector<uint32_t> left(count * C);
    for (size_t u = 0; u < count; ++u) {
        const glm::ivec2 p = problem.position(valid[u]);
        for (size_t k = 0; k < C; ++k) left[u * C + k] = problem.exemplar->at(p.x, p.y + problem.left_dy[k]);
    }
    std::vector<float> table(prev_count * count);
    parallel_for(prev_count, 16, [&](size_t begin, size_t end, size_t) {
        for (size_t v = begin; v < end; ++v)
            for (size_t u = 0; u < count; ++u) {
                float d = 0.0f;
                for (size_t k = 0; k < C; ++k) d += xi(right_edges[v * C + k], left[u * C + k]);
                table[v * count + u] = d;
            }
    });
    return table;
}

void update_table_row(const std::vector<float>& prev_costs, const std::vector<float>& table, size_t count,
                      std::vector<float>& costs, std::vector<uint32_t>& back) {
    costs.assign(count, 0.0f);
    back.assign(count, 0u);
    parallel_for(count, 64, [&](size_t begin, size_t end, size_t) {
        for (size_t u = begin; u < end; ++u) {
            float best = std::numeric_limits<float>::infinity();
            uint32_t arg = 0;
            for (size_t v = 0; v < prev_costs.size(); ++v) {
                const float c = prev_costs[v] + table[v * count + u];
                if (c < best) {
                    best = c;
                    arg = uint32_t(v);
                }
            }
            costs[u] = best;
            back[u] = arg;
        }
    });
}

std::string no_valid_position_message(const DpProblem& problem, size_t row) {
    const bool terminal = problem.closed && row + 1 == problem.rows.size();
    return "ribbon piece " + std::to_string(row) + (terminal ? " (terminal)" : "") + " of " +
           std::to_string(problem.rows.size()) +
           ": no valid position in the exemplar, even letting the piece cut the pattern — it must fit in E "
           "horizontally and keep ink off forbidden pixels (C = " + std::to_string(problem.samples) +
           " exemplar pixels across the ribbon: try a shorter piece length δ or another scale s)";
}

DpTables run_dp_reference(const DpProblem& problem, const DpRunOptions& options) {
    DpTables t;
    const size_t rows = problem.rows.size();
    t.valid.resize(rows);
    t.back.resize(rows);
    t.rules.resize(rows);
    if (options.keep_cost_tables) t.cost_tables.resize(rows);

    t.valid[0] = valid_positions(problem, 0, t.rules[0]);
    if (options.first_position) {
        if (std::find(t.valid[0].begin(), t.valid[0].end(), *options.first_position) == t.valid[0].end())
            throw Error("ribbon: the fixed first position is not valid for piece 0");
        t.valid[0] = {*options.first_position};
    }
    std::vector<float> costs(t.valid[0].size(), 0.0f), next;
    if (options.progress) options.progress(0, rows, uint32_t(t.valid[0].size()));

    for (size_t i = 1; i < rows; ++i) {
        Timer timer;
        const std::vector<uint32_t> right = extract_columns(problem, i - 1, t.valid[i - 1]);
        t.valid[i] = valid_positions(problem, i, t.rules[i]);
        std::vector<float> table = compute_cost_table(problem, right, t.valid[i]);
        update_table_row(costs, table, t.valid[i].size(), next, t.back[i]);
        costs.swap(next);
        if (options.keep_cost_tables) t.cost_tables[i] = std::move(table);
        t.row_ms.push_back(timer.elapsed_ms());
        if (options.progress) options.progress(i, rows, uint32_t(t.valid[i].size()));
    }
    t.last_costs = std::move(costs);
    return t;
}

}  // namespace lw
