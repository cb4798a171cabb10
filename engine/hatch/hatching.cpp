#include "hatch/hatching.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lw {

std::vector<int> plausible_strokes(const HatchTraining& t, const std::vector<int>& history, int window, float c) {
    const size_t n = t.strokes.size();
    const int context = std::max(window, 1) - 1;
    if (size_t(context) >= n) throw Error("the window (" + std::to_string(window) + ") must be smaller than the training size (" +
                                          std::to_string(n) + ")");
    if (history.size() < size_t(context)) throw Error("N-gram: the history is shorter than the context");
    const int dim = t.vectors.dim;
    const size_t h0 = history.size() - size_t(context);
    thread_local std::vector<double> distance;
    distance.assign(n, INFINITY);
    double best = INFINITY;
    for (size_t i = size_t(context); i < n; ++i) {
        double d2 = 0.0;
        for (int m = 0; m < context; ++m) {
            const double* a = t.vectors.row(size_t(history[h0 + size_t(m)]));
            const double* b = t.vectors.row(i - size_t(context) + size_t(m));
            for (int k = 0; k < dim; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
        }
        distance[i] = context > 0 ? std::sqrt(d2 / double(context * dim)) : 0.0;
        best = std::min(best, distance[i]);
    }
    // p_i / p_max = e^(best − d_i) ≥ c  ⇔  d_i ≤ best − ln c.
    const double limit = best - std::log(double(std::clamp(c, 1e-6f, 1.0f))) + 1e-9;
    std::vector<int> out;
    for (size_t i = size_t(context); i < n; ++i)
        if (distance[i] <= limit) out.push_back(int(i));
    return out;
}

double random_block_kl2(const HatchTraining& t, int size, Rng& rng) {
    std::vector<double> values;
    for (int k = 0; k < 9; ++k) {
        std::vector<int> ids;
        for (int i = 0; i < size; ++i) ids.push_back(int(rng.index(t.strokes.size())));
        values.push_back(kl2_divergence(t.vectors, sequence_vectors(t, ids)));
    }
    std::sort(values.begin(), values.end());
    return values[4];
}

HatchSequence generate_hatching(const HatchTraining& t, const HatchDesc& desc, Rng& rng,
                                const std::function<void(const HatchBlock&, bool)>& on_block) {
    const int n = int(t.strokes.size());
    if (desc.window < 1 || desc.window >= n)
        throw Error("the window (" + std::to_string(desc.window) + ") must be between 1 and the training size − 1 (" +
                    std::to_string(n - 1) + ")");
    if (desc.block < 1) throw Error("the block size must be positive");
    HatchSequence out;
    std::vector<int> history(static_cast<size_t>(n));  // Z_temp ← Z_t
    for (int i = 0; i < n; ++i) history[size_t(i)] = i;
    const Samples training = t.vectors;
    // The automatic threshold is KL2's scale for the block's size, which grows as the sample
    // shrinks: a shorter last block is held to its own, not to a full block's.
    std::vector<std::pair<int, double>> thresholds;  // (block size, threshold), at most two
    const auto threshold_for = [&](int size) {
        if (desc.threshold >= 0.0) return desc.threshold;
        for (const auto& [n_strokes, value] : thresholds)
            if (n_strokes == size) return value;
        thresholds.emplace_back(size, 3.0 * random_block_kl2(t, size, rng));
        return thresholds.back().second;
    };
    out.threshold = threshold_for(std::min(desc.block, desc.count));
    int window = desc.window;
    int index = 0;
    while (int(out.ids.size()) < desc.count) {
        ++index;
        const int size = std::min(desc.block, desc.count - int(out.ids.size()));
        const double threshold = threshold_for(size);
        const int first_window = window;
        HatchBlock best_block;
        std::vector<int> best_ids;
        for (int attempt = 1;; ++attempt) {
            std::vector<int> ids;
            std::vector<int> h = history;
            for (int k = 0; k < size; ++k) {
                const std::vector<int> s = plausible_strokes(t, h, window, desc.plausible);
                const int pick = s[rng.index(s.size())];
                ids.push_back(pick);
                h.push_back(pick);
            }
            HatchBlock b{index, out.ids.size() + 1, out.ids.size() + size_t(size), window,
                         kl2_divergence(training, sequence_vectors(t, ids)), attempt, false, threshold};
            if (best_ids.empty() || b.kl2 < best_block.kl2) best_block = b, best_ids = ids;
            const bool over = threshold > 0.0 && b.kl2 > threshold;
            if (!over) {
                best_block = b, best_ids = ids;
                break;
            }
            const bool last_attempt = attempt > desc.max_restarts || window + 1 >= n;
            b.next_window = last_attempt ? 0 : std::min(window + 2, n - 1);  // a larger window (§3.1)
            if (on_block) on_block(b, false);
            if (last_attempt) {
                best_block.over_threshold = true;
                best_block.attempts = attempt;
                break;
            }
            window = b.next_window;
        }
        // The next block goes on with the window that passed; where no attempt passed, with
        // this block's first window: a window that only grew while every attempt failed would
        // climb block by block to the training's size, where the N-gram copies the training in
        // a loop (a run of 100,000 strokes reached 40 of 41).
        window = best_block.over_threshold ? first_window : best_block.window;
        history.insert(history.end(), best_ids.begin(), best_ids.end());
        out.ids.insert(out.ids.end(), best_ids.begin(), best_ids.end());
        out.blocks.push_back(best_block);
        if (on_block) on_block(best_block, true);
    }
    return out;
}

namespace {

Stroke moved(const HatchTraining& t, int id, glm::vec2 centre, glm::vec2 tangent) {
    Stroke s = t.strokes[size_t(id)];
    const glm::vec2 normal(-tangent.y, tangent.x);
    for (glm::vec2& p : s.points) {
        const glm::vec2 d = p - t.centers[size_t(id)];
        p = centre + glm::dot(d, t.u) * tangent + glm::dot(d, t.v) * normal;
    }
    return s;
}

}  // namespace

std::vector<Stroke> place_on_line(const HatchTraining& t, const std::vector<int>& ids) {
    std::vector<Stroke> out;
    float s = glm::dot(t.centers.front() - t.origin, t.u);
    for (size_t k = 0; k < ids.size(); ++k) {
        if (k > 0) s += t.step[size_t(ids[k])];
        const glm::vec2 centre = t.origin + s * t.u + t.offset[size_t(ids[k])] * t.v;
        out.push_back(moved(t, ids[k], centre, t.u));
    }
    return out;
}

std::vector<Stroke> place_along(const HatchTraining& t, const std::vector<int>& ids, const ArclengthCurve& path,
                                size_t* placed) {
    std::vector<Stroke> out;
    std::vector<float> steps(t.step);
    std::sort(steps.begin(), steps.end());
    const float median_step = std::max(steps[steps.size() / 2], 1e-3f);
    const float h = std::max(0.5f * median_step, 1e-3f);
    float s = 0.5f * median_step;
    for (size_t k = 0; k < ids.size(); ++k) {
        if (k > 0) s += t.step[size_t(ids[k])];
        if (s > path.length() || s < 0.0f) break;
        const glm::vec2 tangent = path.tangent_at(s, h);
        const glm::vec2 centre = path.point_at(s) + t.offset[size_t(ids[k])] * glm::vec2(-tangent.y, tangent.x);
        out.push_back(moved(t, ids[k], centre, tangent));
    }
    if (placed) *placed = out.size();
    return out;
}

Hatching hatch(const HatchTraining& t, const HatchDesc& desc, const std::vector<ArclengthCurve>& paths, Rng& rng,
                const std::function<void(const HatchBlock&, bool kept)>& on_block) {
    Hatching out;
    if (paths.empty()) {
        const HatchSequence seq = generate_hatching(t, desc, rng, on_block);
        out.threshold = seq.threshold;
        out.strokes = place_on_line(t, seq.ids);
        out.generated = seq.ids.size();
        return out;
    }
    std::vector<float> steps(t.step);
    std::sort(steps.begin(), steps.end());
    const float median_step = std::max(steps[steps.size() / 2], 1e-3f);
    int block_offset = 0;
    size_t stroke_offset = 0;
    const auto numbered = [&](const HatchBlock& b, bool kept) {
        if (!on_block) return;
        HatchBlock n = b;
        n.index += block_offset;
        n.first += stroke_offset;
        n.last += stroke_offset;
        on_block(n, kept);
    };
    for (const ArclengthCurve& path : paths) {
        HatchDesc d = desc;
        d.count = std::min(desc.count, int(std::ceil(path.length() / median_step)) + 2);
        const HatchSequence seq = generate_hatching(t, d, rng, numbered);
        out.threshold = seq.threshold;
        const std::vector<Stroke> placed = place_along(t, seq.ids, path);
        block_offset += int(seq.blocks.size());
        stroke_offset += seq.ids.size();
        out.strokes.insert(out.strokes.end(), placed.begin(), placed.end());
    }
    out.generated = stroke_offset;
    return out;
}

std::vector<ArclengthCurve> hatch_paths(const std::vector<Stroke>& strokes) {
    std::vector<ArclengthCurve> paths;
    for (size_t i = 0; i < strokes.size(); ++i) {
        try {
            paths.emplace_back(Curve2D{strokes[i].points, strokes[i].closed});
        } catch (const Error& e) {
            throw Error("path " + std::to_string(i + 1) + ": " + e.what());
        }
    }
    return paths;
}

}  // namespace lw
