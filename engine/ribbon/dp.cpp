#include "ribbon/dp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/parallel.h"
#include "core/random.h"

namespace lw {

namespace {

// Row indices of the path ending at entry `j` of the last row.
std::vector<uint32_t> backtrack(const DpTables& t, uint32_t j) {
    std::vector<uint32_t> idx(t.valid.size());
    idx.back() = j;
    for (size_t r = t.valid.size() - 1; r > 0; --r) idx[r - 1] = t.back[r][idx[r]];
    return idx;
}

// Among `candidates` (indices into last_costs), those of minimal cost, one drawn by the seed.
std::optional<uint32_t> pick_cheapest(const std::vector<float>& costs, const std::vector<uint32_t>& candidates,
                                      uint64_t seed) {
    if (candidates.empty()) return std::nullopt;
    float best = std::numeric_limits<float>::infinity();
    for (uint32_t j : candidates) best = std::min(best, costs[j]);
    std::vector<uint32_t> ties;
    for (uint32_t j : candidates)
        if (costs[j] == best) ties.push_back(j);
    return ties[mix64(seed) % ties.size()];
}

RibbonSolution make_solution(const DpProblem& problem, const DpTables& t, uint32_t end) {
    RibbonSolution s;
    const std::vector<uint32_t> idx = backtrack(t, end);
    for (size_t r = 0; r < idx.size(); ++r) s.positions.push_back(problem.position(t.valid[r][idx[r]]));
    for (size_t r = 1; r < idx.size(); ++r) s.seam_costs.push_back(seam_cost(problem, r, s.positions[r - 1], s.positions[r]));
    s.total_cost = t.last_costs[end];
    for (const auto& v : t.valid) s.valid_counts.push_back(uint32_t(v.size()));
    s.rules = t.rules;
    s.row_ms = t.row_ms;
    return s;
}

}  // namespace

float seam_cost(const DpProblem& problem, size_t row, glm::ivec2 prev, glm::ivec2 cur) {
    const Exemplar& e = *problem.exemplar;
    const PieceProbes &before = problem.rows[row - 1], &after = problem.rows[row];
    float d = 0.0f;
    for (int k = 0; k < problem.samples; ++k) {
        const glm::ivec2 r = prev + before.right[size_t(k)], l = cur + after.left[size_t(k)];
        d += xi(e.at(r.x, r.y), e.at(l.x, l.y));
    }
    return d;
}

float path_cost(const DpProblem& problem, const std::vector<glm::ivec2>& positions) {
    float total = 0.0f;
    for (size_t r = 1; r < positions.size(); ++r) total += seam_cost(problem, r, positions[r - 1], positions[r]);
    return total;
}

namespace {

// The entry of the cheapest path over `t`'s rows (a free start), one of equals by the seed.
uint32_t cheapest_end(const DpTables& t, uint64_t seed) {
    std::vector<uint32_t> all(t.valid.back().size());
    for (uint32_t j = 0; j < all.size(); ++j) all[j] = j;
    return *pick_cheapest(t.last_costs, all, seed);
}

// The rows of a closed problem twice round, the terminal piece after the second lap, as an
// open problem.
DpProblem two_laps(const DpProblem& problem) {
    DpProblem laps = problem;
    laps.closed = false;
    laps.rows.clear();
    const size_t pieces = problem.rows.size() - 1;
    for (int lap = 0; lap < 2; ++lap) laps.rows.insert(laps.rows.end(), problem.rows.begin(), problem.rows.begin() + long(pieces));
    laps.rows.push_back(problem.rows.back());
    return laps;
}

// The entry of the last row at `position`; a fixed start always has one (dp.h).
uint32_t end_at(const DpTables& t, uint32_t position) {
    const auto it = std::find(t.valid.back().begin(), t.valid.back().end(), position);
    if (it == t.valid.back().end()) throw Error("closed ribbon: the terminal piece cannot take the first piece's position");
    return uint32_t(it - t.valid.back().begin());
}

// Adds a run's row times onto `into`, row by row (a run twice round folds onto the rows).
void add_row_times(std::vector<double>& into, const std::vector<double>& from) {
    if (into.empty()) return;
    for (size_t r = 0; r < from.size(); ++r) into[r % into.size()] += from[r];
}

}  // namespace

RibbonSolution solve_ribbon(const DpProblem& problem, const DpRunner& runner, uint64_t seed,
                            const DpRunOptions& options) {
    const size_t rows = problem.rows.size();
    if (!problem.closed || rows < 2) {
        DpTables t = runner(problem, options);
        return make_solution(problem, t, cheapest_end(t, seed));
    }
    if (options.first_position) {  // piece 0 given: the loop closes there
        DpTables t = runner(problem, options);
        return make_solution(problem, t, end_at(t, *options.first_position));
    }
    // A closed curve runs three DPs, one after the other; progress counts their rows together.
    const size_t total = rows + (2 * rows - 1) + rows;
    const auto pass = [&](size_t offset) {
        DpRunOptions o = options;
        if (options.progress)
            o.progress = [&, offset](size_t row, size_t, uint32_t valid) { options.progress(offset + row, total, valid); };
        return o;
    };

    // §1.5: the single DP; backtrack from every terminal position, keep those that come back
    // to themselves.
    DpTables t = runner(problem, pass(0));
    const std::vector<uint32_t>& last = t.valid.back();
    std::vector<uint32_t> cycles;
    for (uint32_t j = 0; j < last.size(); ++j) {
        const std::vector<uint32_t> idx = backtrack(t, j);
        if (t.valid[0][idx[0]] == last[j]) cycles.push_back(j);
    }
    const std::optional<uint32_t> first_cycle = pick_cheapest(t.last_costs, cycles, seed);

    // A second candidate, the start of the wrap-around heuristic for tail-biting trellises
    // (Viterbi decoding of a cyclic code): the cheapest path twice round the loop from a free
    // start has forgotten that start when it comes round again, so where it passes the first
    // piece the second time is a good place to fix piece 0. The single DP misses cycles that
    // start where none of its terminal positions leads back: a chain around a circle of
    // radius 60 px closed on half links repeated (seam cost 4171) where the fixed start finds
    // 3394, and the six banded exemplars of RibbonDp.ClosedCurveEndsWhereItStarts close at the
    // optimum with it, three of them without. The terminal piece is a copy of piece 0, so a
    // fixed start always closes.
    const DpProblem laps = two_laps(problem);
    const DpTables w = runner(laps, pass(rows));
    const uint32_t start = w.valid[rows - 1][backtrack(w, cheapest_end(w, seed))[rows - 1]];
    DpRunOptions fixed = pass(rows + laps.rows.size());
    fixed.first_position = start;
    DpTables f = runner(problem, fixed);
    const uint32_t fixed_end = end_at(f, start);

    // The cheaper cycle; the single DP's on a tie. Its row times are all three runs' (the
    // two-lap run folded onto the rows), whichever is kept; the valid counts are the first's.
    const bool first_kept = first_cycle && !(f.last_costs[fixed_end] < t.last_costs[*first_cycle]);
    RibbonSolution s = first_kept ? make_solution(problem, t, *first_cycle) : make_solution(problem, f, fixed_end);
    s.closed_by_first_dp = first_kept;
    add_row_times(s.row_ms, first_kept ? f.row_ms : t.row_ms);
    add_row_times(s.row_ms, w.row_ms);
    s.valid_counts[0] = uint32_t(t.valid[0].size());
    return s;
}

std::vector<glm::ivec2> greedy_positions(const DpProblem& problem, const std::vector<std::vector<uint32_t>>& valid,
                                         glm::ivec2 first) {
    std::vector<glm::ivec2> out{first};
    const size_t rows = problem.rows.size();
    for (size_t r = 1; r < rows; ++r) {
        if (problem.closed && r + 1 == rows) {
            out.push_back(first);
            break;
        }
        const std::vector<uint32_t>& cand = valid[r];
        const glm::ivec2 prev = out.back();
        std::vector<std::pair<float, size_t>> best(worker_count(), {std::numeric_limits<float>::infinity(), 0});
        parallel_for(cand.size(), 64, [&](size_t begin, size_t end, size_t chunk) {
            for (size_t j = begin; j < end; ++j) {
                const float c = seam_cost(problem, r, prev, problem.position(cand[j]));
                if (c < best[chunk].first) best[chunk] = {c, j};
            }
        });
        std::pair<float, size_t> b = best[0];
        for (const auto& c : best)
            if (c.first < b.first) b = c;
        out.push_back(problem.position(cand[b.second]));
    }
    return out;
}

std::vector<glm::ivec2> random_positions(const DpProblem& problem, const std::vector<std::vector<uint32_t>>& valid,
                                         uint64_t seed) {
    std::vector<glm::ivec2> out;
    uint64_t state = mix64(seed ^ 0x72616e646f6dull);
    for (size_t r = 0; r < problem.rows.size(); ++r) {
        if (problem.closed && r + 1 == problem.rows.size()) {
            out.push_back(out.front());
            break;
        }
        state = mix64(state);
        out.push_back(problem.position(valid[r][state % valid[r].size()]));
    }
    return out;
}

LooserRows looser_rows(const RibbonSolution& solution) {
    LooserRows rows;
    for (size_t r = 0; r < solution.rules.size(); ++r) {
        if (solution.rules[r] == ValidityRule::Empty) rows.empty.push_back(r);
        if (solution.rules[r] > ValidityRule::Empty) rows.cut.push_back(r);
    }
    return rows;
}

std::optional<std::string> blank_ribbon_reason(const RibbonSolution& solution, const std::string& avoid) {
    if (solution.rules.empty() || looser_rows(solution).empty.size() < solution.rules.size()) return std::nullopt;
    return "the ribbon drew nothing: every piece lies where the ribbon overlaps itself" +
           (avoid.empty() ? std::string(" (a curve that doubles back within the ribbon's width)")
                          : " or where " + avoid + " forbids ink");
}

}  // namespace lw
