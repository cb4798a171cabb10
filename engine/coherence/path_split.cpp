#include "coherence/path_split.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace lw {

namespace {

constexpr uint32_t kMinRun = 8;  // consecutive rejected votes that make a piece of their own

// The runs of at least `min_run` consecutive votes of [first, last) that `fit` rejects (farther
// than inlier_px along the path), as inclusive vote ranges. Where a run borders accepted
// votes and joins them at a seam between two phases, its end is moved to the middle of the
// seam. The splat blends the two earlier paths' T over the sprite radius there, so the first
// rejected vote lies a few pixels before the seam, on the fit's side; cutting there moves
// the seam along the path by up to a sprite radius each frame, and the samples it passes jump
// between the two phases. The run's own residual near the seam is a line in s through
// kPlateau votes (within inlier_px) starting within kBlendVotes of the end: a constant for a
// piece that ran the same way a frame earlier, a ramp for one that ran the other way. Going
// in from the end, the seam is the first vote whose residual is at least half of that
// line's value there, or the vote before it if that one's is nearer half. (Not half the
// run's median: a run may join several earlier paths, and the one at its end is what the
// seam divides from the fit.) Without such a line, or if moving both ends would leave no
// run, the ends stay where the fit's rejection put them.
std::vector<std::pair<uint32_t, uint32_t>> rejected_runs(const VoteSet& votes, uint32_t first, uint32_t last,
                                                         const PathFit& fit, float inlier_px, uint32_t min_run,
                                                         uint32_t min_end_run) {
    constexpr int64_t kPlateau = 4, kBlendVotes = 6;
    auto residual = [&](int64_t v) { return votes.votes[size_t(v)].t - (fit.rho * votes.votes[size_t(v)].s + fit.phi); };
    const float limit = inlier_px * std::abs(fit.rho);
    // The seam at the run's end `end` (next to accepted votes), the run going on to `inner`.
    auto seam = [&](int64_t end, int64_t inner) {
        const int64_t step = inner >= end ? 1 : -1;
        const int64_t starts = std::min(kBlendVotes, std::abs(inner - end) - kPlateau + 2);
        auto s_of = [&](int64_t v) { return votes.votes[size_t(v)].s; };
        for (int64_t i = 0; i < starts; ++i) {
            // The run's own residual from u on: kPlateau votes on one line in s (a constant
            // for a piece that ran the same way, a ramp for one that ran the other way).
            const int64_t u = end + step * i, u_far = u + step * (kPlateau - 1);
            const float ds = s_of(u_far) - s_of(u);
            if (ds == 0.0f) continue;
            const float slope = (residual(u_far) - residual(u)) / ds;
            auto own = [&](int64_t w) { return residual(u) + slope * (s_of(w) - s_of(u)); };
            bool straight = true;
            for (int64_t j = 1; j + 1 < kPlateau && straight; ++j)
                straight = std::abs(residual(u + step * j) - own(u + step * j)) <= limit;
            // Extended back to the end (and the accepted vote before it), the line stays
            // clear of 0 on one side, so that the shares below are finite and mean a blend.
            for (int64_t w = end - step; w != u && straight; w += step)
                straight = std::abs(own(w)) > limit && (own(w) > 0.0f) == (own(u) > 0.0f);
            if (!straight) continue;
            // Where the blend is even, the residual is half the run's own there.
            auto share = [&](int64_t w) { return residual(w) / own(w); };
            int64_t cut = end;
            while (cut != u && share(cut) < 0.5f) cut += step;
            // The pieces share the seam's sample and both splat it: the vote whose blend is
            // the most even is where the next frame finds the seam again.
            if (cut != end && std::abs(share(cut - step) - 0.5f) < std::abs(share(cut) - 0.5f)) cut -= step;
            return cut;
        }
        return end;
    };
    std::vector<std::pair<uint32_t, uint32_t>> runs;
    uint32_t run_start = last;
    for (uint32_t v = first; v <= last; ++v) {
        const bool outlier = v < last && std::abs(residual(v)) > limit;
        if (outlier && run_start == last) run_start = v;
        if (outlier || run_start == last) continue;
        int64_t a = run_start, b = int64_t(v) - 1;
        run_start = last;
        // Fewer than min_run rejected votes are noise (min_end_run at the path's ends); all of
        // them, a fit that explains none of its own votes (splitting would give the same piece back).
        const bool at_end = a == int64_t(first) || b + 1 == int64_t(last);
        if (b + 1 - a < int64_t(at_end ? min_end_run : min_run) || (a == int64_t(first) && b + 1 == int64_t(last)))
            continue;
        const int64_t a_seam = a > int64_t(first) ? seam(a, b) : a;
        const int64_t b_seam = b + 1 < int64_t(last) ? seam(b, a) : b;
        if (b_seam > a_seam)
            runs.push_back({uint32_t(a_seam), uint32_t(b_seam)});
        else
            runs.push_back({uint32_t(a), uint32_t(b)});
    }
    return runs;
}

// At a path's end, fewer rejected votes than kMinRun make a piece: there a run of them is most
// often a piece of another earlier path that this one has grown into (a gap between two
// pieces of a line, or a junction, moving along it as the view turns), and absorbed into
// this path's phase its samples pop. The splat's blend at a seam rejects at most the shared
// seam sample and the votes within a sprite radius of it, so one more than that is a piece of
// its own: with the default radius of two sample spacings, 4. Measured on the 640×480 orbits
// of docs/BENCHMARKS.md (pops against the tiling policy, 8 → 4): the speeder's suggestive
// contours 0.41 → 0.00 and silhouettes 0.11 → 0.02, the truck's creases 0.62 → 0.00; 2, 3
// and 5 were also better than 8 on most figures.
uint32_t min_end_run(const ScreenPath& path, float splat_radius_px) {
    const size_t n = path.samples.size();
    const float spacing = n > 1 ? (path.samples.back().s - path.samples.front().s) / float(n - 1) : 0.0f;
    if (!(spacing > 0.0f) || !(splat_radius_px > 0.0f)) return kMinRun;
    const float within = std::floor(splat_radius_px / spacing + 1e-3f);
    return uint32_t(std::clamp(within + 2.0f, 2.0f, float(kMinRun)));
}

// One round: the paths with `examine` set are looked at; returns, per path after, whether it
// is a piece fitted on its own (the next round looks at those).
std::vector<bool> split_round(std::vector<ScreenPath>& paths, VoteSet& votes, std::vector<PathFit>& fits,
                              const RansacParams& ransac, float splat_radius_px, const std::vector<bool>& examine,
                              const RansacFitter& fitter, std::vector<PieceOrigin>& origins) {
    std::vector<ScreenPath> out_paths;
    VoteSet out_votes;
    std::vector<PathFit> out_fits;
    std::vector<PieceOrigin> out_origins;
    std::vector<size_t> refit;  // pieces fitted on their own below
    // Samples [from, to] of path p; a whole path's samples are moved. A loop left whole stays
    // closed (opened, its two tapered ends would leave a gap at the seam); a piece of one is
    // open.
    auto add_piece = [&](ScreenPath& path, size_t p, size_t from, size_t to, const PathFit* keep) {
        const float shift = path.samples[from].s - path.samples.front().s;  // new arclength origin
        const bool whole = from == 0 && to + 1 == path.samples.size();
        ScreenPath piece = empty_like(path, whole && path.closed);
        if (whole)
            piece.samples = std::move(path.samples);
        else
            piece.samples.assign(path.samples.begin() + std::ptrdiff_t(from), path.samples.begin() + std::ptrdiff_t(to + 1));
        for (uint32_t v = votes.offsets[p]; v < votes.offsets[p + 1]; ++v)
            if (votes.sample[v] >= from && votes.sample[v] <= to) {
                out_votes.votes.push_back({votes.votes[v].t, votes.votes[v].s - shift});
                out_votes.sample.push_back(uint32_t(votes.sample[v] - from));
            }
        out_votes.offsets.push_back(uint32_t(out_votes.votes.size()));
        PathFit fit = keep ? *keep : PathFit{};
        fit.votes = out_votes.offsets.back() - out_votes.offsets[out_votes.offsets.size() - 2];
        if (keep)
            fit.phi = keep->phi + keep->rho * shift;
        else
            refit.push_back(out_paths.size());
        out_origins.push_back({origins[p].path, origins[p].first + uint32_t(from), uint32_t(to + 1 - from)});
        out_paths.push_back(std::move(piece));
        out_fits.push_back(fit);
    };
    for (size_t p = 0; p < paths.size(); ++p) {
        const PathFit& fit = fits[p];
        const uint32_t first = votes.offsets[p], last = votes.offsets[p + 1];
        // Runs of consecutive votes the fit rejects, as sample ranges.
        std::vector<std::pair<size_t, size_t>> runs;
        // (A run reaching the first or last vote was also tried taking the vote-less samples
        // beyond it, so that no piece of a sample or two stays at the end: mixed, e.g.
        // FlightHelmet's silhouette median 0.33 → 0.35, the bunny's p90 0.09 → 0.08.)
        if (examine[p] && fit.fitted && last - first >= 2 * kMinRun)
            for (const auto& [a, b] : rejected_runs(votes, first, last, fit, ransac.inlier_px, kMinRun,
                                                    min_end_run(paths[p], splat_radius_px)))
                runs.push_back({votes.sample[a], votes.sample[b]});
        if (runs.empty()) {
            add_piece(paths[p], p, 0, paths[p].samples.size() - 1, &fit);
            out_fits.back() = fit;  // unchanged (also when it has no fit)
            continue;
        }
        // Alternate kept and rejected pieces; neighbours share their boundary sample.
        if (paths[p].closed) paths[p] = opened(paths[p]);  // the last piece reaches back to the first
        size_t from = 0;
        for (const auto& [a, b] : runs) {
            if (a > from) add_piece(paths[p], p, from, a, &fit);
            add_piece(paths[p], p, a, b, nullptr);
            from = b;
        }
        if (from + 1 < paths[p].samples.size()) add_piece(paths[p], p, from, paths[p].samples.size() - 1, &fit);
    }
    if (!refit.empty()) {
        VoteSet pieces;
        for (size_t i : refit) {
            for (uint32_t v = out_votes.offsets[i]; v < out_votes.offsets[i + 1]; ++v) pieces.votes.push_back(out_votes.votes[v]);
            pieces.offsets.push_back(uint32_t(pieces.votes.size()));
        }
        const std::vector<PathFit> piece_fits = fitter.fit(pieces, ransac);
        for (size_t k = 0; k < refit.size(); ++k) out_fits[refit[k]] = piece_fits[k];
    }
    paths = std::move(out_paths);
    votes = std::move(out_votes);
    fits = std::move(out_fits);
    origins = std::move(out_origins);
    std::vector<bool> fitted_alone(paths.size(), false);
    for (size_t i : refit) fitted_alone[i] = true;
    return fitted_alone;
}

}  // namespace

void split_merged_paths(std::vector<ScreenPath>& paths, VoteSet& votes, std::vector<PathFit>& fits,
                        const RansacParams& ransac, float splat_radius_px, const RansacFitter& fitter,
                        std::vector<PieceOrigin>* origins) {
    // A path joining n earlier ones needs at most n − 1 rounds; more than 9 pieces of
    // different earlier paths in one path is rarer than the cost of looking again.
    constexpr int kRounds = 8;
    std::vector<PieceOrigin> from(paths.size());
    for (size_t p = 0; p < paths.size(); ++p) from[p] = {uint32_t(p), 0, uint32_t(paths[p].samples.size())};
    std::vector<bool> examine(paths.size(), true);
    for (int round = 0; round < kRounds && std::ranges::find(examine, true) != examine.end(); ++round)
        examine = split_round(paths, votes, fits, ransac, splat_radius_px, examine, fitter, from);
    if (origins) *origins = std::move(from);
}

}  // namespace lw
