#include "ribbon/dp_reference.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <tuple>

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

namespace {

// L̄ of every valid position of a row's piece, at its left-edge offsets; V × C texels,
// row-major (extract_columns' layout for the right edges).
std::vector<uint32_t> left_edges(const DpProblem& problem, size_t row, const std::vector<uint32_t>& valid) {
    const size_t C = size_t(problem.samples);
    const std::vector<glm::ivec2>& left = problem.rows[row].left;
    std::vector<uint32_t> texels(valid.size() * C);
    for (size_t u = 0; u < valid.size(); ++u) {
        const glm::ivec2 p = problem.position(valid[u]);
        for (size_t k = 0; k < C; ++k) texels[u * C + k] = problem.exemplar->at(p.x + left[k].x, p.y + left[k].y);
    }
    return texels;
}

// Texels of edges unpacked for ξ, by sample k then edge j (index k·count + j), so that the
// cost table's inner loop runs over positions with unit stride and the compiler vectorizes
// it (sqrt without errno: CMakeLists.txt). Each table entry still sums its C terms in k
// order, so the table is bit-identical to the scalar loop and to the GPU pass.
struct EdgeTexels {
    size_t count = 0;
    std::vector<float> r, g, b, opaque;
    void resize(size_t c, size_t samples) {
        count = c;
        for (std::vector<float>* v : {&r, &g, &b, &opaque}) v->assign(c * samples, 0.0f);
    }
    void set(size_t k, size_t j, uint32_t t) {
        const size_t i = k * count + j;
        r[i] = float(t & 0xffu);
        g[i] = float((t >> 8) & 0xffu);
        b[i] = float((t >> 16) & 0xffu);
        opaque[i] = texel_opaque(t) ? 1.0f : 0.0f;
    }
};

}  // namespace

std::vector<float> compute_cost_table(const DpProblem& problem, size_t row, const std::vector<uint32_t>& right_edges,
                                      const std::vector<uint32_t>& valid) {
    const size_t C = size_t(problem.samples);
    const size_t prev_count = right_edges.size() / C, count = valid.size();
    const std::vector<uint32_t> left_texels = left_edges(problem, row, valid);
    EdgeTexels left;
    left.resize(count, C);
    for (size_t u = 0; u < count; ++u)
        for (size_t k = 0; k < C; ++k) left.set(k, u, left_texels[u * C + k]);
    std::vector<float> table(prev_count * count, 0.0f);
    parallel_for(prev_count, 16, [&](size_t begin, size_t end, size_t) {
        for (size_t v = begin; v < end; ++v) {
            float* entries = table.data() + v * count;
            for (size_t k = 0; k < C; ++k) {
                // ξ(q, L̄_u[k]) for every u: the same terms as xi(), in the same order per entry.
                const uint32_t q = right_edges[v * C + k];
                const float qr = float(q & 0xffu), qg = float((q >> 8) & 0xffu), qb = float((q >> 16) & 0xffu);
                const float qo = texel_opaque(q) ? 1.0f : 0.0f;
                const float* lr = left.r.data() + k * count;
                const float* lg = left.g.data() + k * count;
                const float* lb = left.b.data() + k * count;
                const float* lo = left.opaque.data() + k * count;
                for (size_t u = 0; u < count; ++u) {
                    const float dr = qr - lr[u], dg = qg - lg[u], db = qb - lb[u];
                    const float distance = std::sqrt(dr * dr + dg * dg + db * db);
                    entries[u] += lo[u] == qo ? distance : kRibbonGamma;
                }
            }
        }
    });
    return table;
}

void update_table_row(const std::vector<float>& prev_costs, const std::vector<float>& table, size_t count,
                      std::vector<float>& costs, std::vector<uint32_t>& back) {
    costs.assign(count, std::numeric_limits<float>::infinity());
    back.assign(count, 0u);
    // Rows of the table in order (unit stride), each thread its own span of u; the strict <
    // keeps the first v of equal costs, as a loop over v per u does.
    parallel_for(count, 256, [&](size_t begin, size_t end, size_t) {
        for (size_t v = 0; v < prev_costs.size(); ++v) {
            const float base = prev_costs[v];
            const float* row = table.data() + v * count;
            for (size_t u = begin; u < end; ++u) {
                const float c = base + row[u];
                if (c < costs[u]) {
                    costs[u] = c;
                    back[u] = uint32_t(v);
                }
            }
        }
    });
}

namespace {

// A row of the bounded update. The previous positions are grouped by their right edge's
// opacity bits (a few hundred groups of 1,300-1,900 positions on spot_ribbons.json), so that
// one popcount bounds a whole group; within a group they are in order of their cost so far.
struct BoundedRow {
    size_t samples = 0, words = 0;
    std::vector<uint64_t> group_bits;     // per group, `words` words
    std::vector<uint32_t> group_begin;    // per group, its first member; one past the last at the end
    std::vector<float> cost;              // per member, P_prev (ascending within its group)
    std::vector<uint32_t> v;              // per member, the previous position
    const uint32_t* right_edges = nullptr;  // extract_columns' texels, by v
    std::vector<uint32_t> left;           // L̄ of each new position u (left_edges)
    std::vector<uint64_t> left_bits;
    size_t groups() const { return group_begin.size() - 1; }
};

void opacity_bits(const uint32_t* texels, size_t samples, size_t words, uint64_t* bits) {
    std::fill(bits, bits + words, 0);
    for (size_t k = 0; k < samples; ++k) bits[k / 64] |= uint64_t(texel_opaque(texels[k])) << (k % 64);
}

// Scratch of one thread: per group, its mismatch count against u and its lowest bound.
struct GroupScratch {
    std::vector<uint32_t> mismatched;
    std::vector<float> bound;
};

// u's minimum over the previous positions: (P[u], its v), the lowest v of equal costs as
// update_table_row's strict <. The group with the lowest bound is searched first, for a low
// best early; a group (or the rest of one) whose bound exceeds the best is passed over.
// Cloned for CPUs with POPCNT: without it a popcount is a library call.
__attribute__((target_clones("popcnt", "default"))) std::pair<float, uint32_t> best_predecessor(
    const BoundedRow& row, size_t u, GroupScratch& scratch) {
    const size_t C = row.samples, words = row.words, groups = row.groups();
    const uint64_t* left_bits = row.left_bits.data() + u * words;
    const uint32_t* l = row.left.data() + u * C;
    float best = std::numeric_limits<float>::infinity();
    uint32_t best_v = 0;
    if (groups == 0) return {best, best_v};
    size_t first = 0;
    for (size_t g = 0; g < groups; ++g) {
        uint32_t mismatched = 0;
        for (size_t w = 0; w < words; ++w) mismatched += uint32_t(std::popcount(row.group_bits[g * words + w] ^ left_bits[w]));
        scratch.mismatched[g] = mismatched;
        scratch.bound[g] = row.cost[row.group_begin[g]] + kRibbonGamma * float(mismatched);
        if (scratch.bound[g] < scratch.bound[first]) first = g;
    }
    const auto search = [&](size_t g) {
        const float gamma_m = kRibbonGamma * float(scratch.mismatched[g]);
        for (uint32_t i = row.group_begin[g]; i < row.group_begin[g + 1]; ++i) {
            const float base = row.cost[i], bound = base + gamma_m;
            const uint32_t v = row.v[i];
            if (bound > best) break;  // the group's later members cost at least this much
            if (bound == best && v > best_v) continue;
            // The entry as compute_cost_table sums it: ξ of each k in order, from 0.
            const uint32_t* q = row.right_edges + size_t(v) * C;
            float entry = 0.0f;
            for (size_t k = 0; k < C; ++k) entry += xi(q[k], l[k]);
            const float c = base + entry;
            if (c < best || (c == best && v < best_v)) {
                best = c;
                best_v = v;
            }
        }
    };
    search(first);
    for (size_t g = 0; g < groups; ++g)
        if (g != first && !(scratch.bound[g] > best)) search(g);
    return {best, best_v};
}

}  // namespace

void update_table_row_bounded(const DpProblem& problem, size_t row_index, const std::vector<uint32_t>& right_edges,
                              const std::vector<uint32_t>& valid, const std::vector<float>& prev_costs,
                              std::vector<float>& costs, std::vector<uint32_t>& back) {
    BoundedRow row;
    row.samples = size_t(problem.samples);
    row.words = (row.samples + 63) / 64;
    const size_t C = row.samples, words = row.words, count = valid.size();
    row.right_edges = right_edges.data();
    row.left = left_edges(problem, row_index, valid);
    row.left_bits.resize(count * words);
    for (size_t u = 0; u < count; ++u) opacity_bits(row.left.data() + u * C, C, words, row.left_bits.data() + u * words);
    // The previous positions (a NaN cost never wins a strict <: left out) by their opacity
    // bits, then by cost.
    std::vector<uint64_t> bits(prev_costs.size() * words);
    for (size_t v = 0; v < prev_costs.size(); ++v) opacity_bits(right_edges.data() + v * C, C, words, bits.data() + v * words);
    const auto bits_of = [&](uint32_t v) { return std::span<const uint64_t>(bits.data() + size_t(v) * words, words); };
    for (uint32_t v = 0; v < prev_costs.size(); ++v)
        if (!std::isnan(prev_costs[v])) row.v.push_back(v);
    std::stable_sort(row.v.begin(), row.v.end(), [&](uint32_t a, uint32_t b) {
        const auto x = bits_of(a), y = bits_of(b);
        if (!std::equal(x.begin(), x.end(), y.begin())) return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
        return prev_costs[a] < prev_costs[b];
    });
    row.cost.resize(row.v.size());
    for (size_t i = 0; i < row.v.size(); ++i) {
        row.cost[i] = prev_costs[row.v[i]];
        const auto b = bits_of(row.v[i]);
        if (i == 0 || !std::equal(b.begin(), b.end(), bits_of(row.v[i - 1]).begin())) {
            row.group_begin.push_back(uint32_t(i));
            row.group_bits.insert(row.group_bits.end(), b.begin(), b.end());
        }
    }
    row.group_begin.push_back(uint32_t(row.v.size()));
    costs.resize(count);
    back.resize(count);
    parallel_for(count, 64, [&](size_t begin, size_t end, size_t) {
        GroupScratch scratch{std::vector<uint32_t>(row.groups()), std::vector<float>(row.groups())};
        for (size_t u = begin; u < end; ++u) std::tie(costs[u], back[u]) = best_predecessor(row, u, scratch);
    });
}

std::string no_valid_position_message(const DpProblem& problem, size_t row) {
    const bool terminal = problem.closed && row + 1 == problem.rows.size();
    return "ribbon piece " + std::to_string(row) + (terminal ? " (terminal)" : "") + " of " +
           std::to_string(problem.rows.size()) +
           ": no valid position in the " + std::to_string(problem.exemplar->width) + "x" +
           std::to_string(problem.exemplar->height) +
           " exemplar E, even letting the piece cut the pattern — it must fit in E "
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
        if (options.keep_cost_tables) {
            t.cost_tables[i] = compute_cost_table(problem, i, right, t.valid[i]);
            update_table_row(costs, t.cost_tables[i], t.valid[i].size(), next, t.back[i]);
        } else {
            update_table_row_bounded(problem, i, right, t.valid[i], costs, next, t.back[i]);
        }
        costs.swap(next);
        t.row_ms.push_back(timer.elapsed_ms());
        if (options.progress) options.progress(i, rows, uint32_t(t.valid[i].size()));
    }
    t.last_costs = std::move(costs);
    return t;
}

}  // namespace lw
