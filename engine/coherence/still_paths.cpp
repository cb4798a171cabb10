#include "coherence/still_paths.h"

#include <algorithm>
#include <bit>

#include "core/random.h"

namespace lw {

namespace {

uint64_t bits(float a, float b) {
    return uint64_t(std::bit_cast<uint32_t>(a)) << 32 | std::bit_cast<uint32_t>(b);
}

// The pieces of `path` (a path equal to the recorded one), appended to `paths` and their
// parameters to `params`.
void append_still_pieces(ScreenPath&& path, const StillPath& recorded, const StillRecord& record,
                         std::vector<ScreenPath>& paths, std::vector<PathParam>& params) {
    rotate_loop(path, recorded.rotation);
    const size_t n = path.samples.size();
    // As path_split cuts a loop: opened first, its first sample repeated at its end.
    if (path.closed && !(recorded.pieces == 1 && record.pieces[recorded.first_piece].count == n)) path = opened(path);
    for (uint32_t i = recorded.first_piece; i < recorded.first_piece + recorded.pieces; ++i) {
        const StillPiece& piece = record.pieces[i];
        // As path_split's pieces: open unless the whole loop, the other fields kept.
        const bool whole = piece.first == 0 && piece.count == n;
        ScreenPath out = empty_like(path, whole && path.closed);
        const size_t first = std::min<size_t>(piece.first, path.samples.size());
        const size_t last = std::min<size_t>(size_t(piece.first) + piece.count, path.samples.size());
        out.samples.assign(path.samples.begin() + std::ptrdiff_t(first), path.samples.begin() + std::ptrdiff_t(last));
        paths.push_back(std::move(out));
        params.push_back(piece.param);
    }
}

}  // namespace

// The word combined with the key so far (shifts of it, so that the order of the words
// counts), then mixed (splitmix64's finalizer): paths a rounding apart get unrelated keys.
uint64_t still_key_step(uint64_t h, uint64_t word) { return mix64(h ^ (word + (h << 6) + (h >> 2))); }

uint64_t still_path_key(const ScreenPath& path) {
    uint64_t h = still_key_step(0, uint64_t(path.type) << 2 | uint64_t(path.closed) << 1 | uint64_t(path.visible));
    h = still_key_step(h, path.samples.size());
    for (const ScreenSample& s : path.samples) {
        h = still_key_step(h, bits(s.pixel.x, s.pixel.y));
        h = still_key_step(h, bits(s.s, s.position.x));
        h = still_key_step(h, bits(s.position.y, s.position.z));
    }
    return h;
}

const StillPath* find_still_path(const StillRecord& record, uint64_t key) {
    const auto it = std::ranges::lower_bound(record.paths, key, {}, &StillPath::key);
    return it != record.paths.end() && it->key == key ? &*it : nullptr;
}

void rotate_loop(ScreenPath& path, size_t start) {
    const size_t n = path.samples.size();
    if (start == 0 || start >= n) return;
    const float loop_length = path.samples.back().s - path.samples.front().s + closing_length(path);
    const float s_start = path.samples[start].s, s0 = path.samples.front().s;
    std::vector<ScreenSample> rotated;
    rotated.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const size_t original = (start + i) % n;
        ScreenSample sample = path.samples[original];
        sample.s = s0 + (original >= start ? sample.s - s_start : sample.s - s0 + loop_length - (s_start - s0));
        rotated.push_back(sample);
    }
    path.samples = std::move(rotated);
}

StillRecord assemble_still_frame(std::vector<ScreenPath>& paths, const std::vector<uint64_t>& keys,
                                 const std::vector<const StillPath*>& kept, const StillRecord& previous,
                                 MovedPaths& moved, std::vector<PathParam>& params) {
    StillRecord record;
    std::vector<ScreenPath> pieces;
    params.clear();
    size_t m = 0, piece = 0;  // the next moved path, and its first piece
    for (size_t p = 0; p < paths.size(); ++p) {
        StillPath entry{.key = keys[p], .first_piece = uint32_t(record.pieces.size())};
        const size_t before = params.size();
        if (kept[p]) {
            entry.rotation = kept[p]->rotation;
            append_still_pieces(std::move(paths[p]), *kept[p], previous, pieces, params);
            for (uint32_t i = 0; i < kept[p]->pieces; ++i)
                record.pieces.push_back(previous.pieces[kept[p]->first_piece + i]);
        } else {
            entry.rotation = moved.rotations[m];
            for (; piece < moved.pieces.size() && moved.origins[piece].path == m; ++piece) {
                record.pieces.push_back({moved.origins[piece].first, moved.origins[piece].count, moved.params[piece]});
                pieces.push_back(std::move(moved.pieces[piece]));
                params.push_back(moved.params[piece]);
            }
            ++m;
        }
        entry.pieces = uint32_t(params.size() - before);
        record.paths.push_back(entry);
    }
    // Sorted by key for find_still_path (stable: of equal keys, the first path's entry first).
    std::ranges::stable_sort(record.paths, {}, &StillPath::key);
    paths = std::move(pieces);
    return record;
}

}  // namespace lw
