#include "lines/chaining.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <tuple>

#include "core/parallel.h"

namespace lw {

namespace {

PathVertex endpoint(const LineSegment& s, int end) {
    const glm::vec4& p = end == 0 ? s.p0 : s.p1;
    const glm::vec3& b = end == 0 ? s.bary0 : s.bary1;
    return PathVertex{glm::vec3(p), s.face, b, p.w, s.other_face};
}

uint32_t key_of(const LineSegment& s, int end) { return end == 0 ? s.key0 : s.key1; }

bool canonical_less(const LineSegment& a, const LineSegment& b) {
    return std::tie(a.type, a.face, a.key0, a.key1) < std::tie(b.type, b.face, b.key0, b.key1);
}

// Chains the segments of one line type: `all[order[i]]` for i in [0, count).
void chain_type(const std::vector<LineSegment>& all, const uint32_t* order, size_t count, LineType type,
                std::vector<LinePath>& out) {
    struct View {  // segments[i] = all[order[i]], without copying them
        const std::vector<LineSegment>& all;
        const uint32_t* order;
        size_t count;
        const LineSegment& operator[](size_t i) const { return all[order[i]]; }
        size_t size() const { return count; }
    } segments{all, order, count};
    // Link endpoints through their keys: the first endpoint seen with a key waits in
    // `slot[key]`; the second becomes its partner; a third marks the key a junction, which
    // links nothing. Keys are mesh edge or vertex indices, so a flat array indexes them.
    uint32_t max_key = 0;
    for (size_t i = 0; i < segments.size(); ++i)
        for (int end = 0; end < 2; ++end)
            if (key_of(segments[i], end) != kNoKey) max_key = std::max(max_key, key_of(segments[i], end));
    constexpr int64_t kEmpty = -1, kJunction = -2;
    std::vector<int64_t> slot(size_t(max_key) + 1, kEmpty);
    std::vector<int64_t> partner_of(segments.size() * 2, -1);
    for (size_t i = 0; i < segments.size(); ++i)
        for (int end = 0; end < 2; ++end) {
            const uint32_t key = key_of(segments[i], end);
            if (key == kNoKey) continue;
            const auto endpoint = int64_t(2 * i + size_t(end));
            int64_t& waiting = slot[key];
            if (waiting == kEmpty) {
                waiting = endpoint;
            } else if (waiting == kJunction) {
                continue;
            } else if (partner_of[size_t(waiting)] < 0) {
                partner_of[size_t(waiting)] = endpoint;
                partner_of[size_t(endpoint)] = waiting;
            } else {  // a third endpoint: undo the pair, the key is a junction
                partner_of[size_t(partner_of[size_t(waiting)])] = -1;
                partner_of[size_t(waiting)] = -1;
                waiting = kJunction;
            }
        }
    // The other endpoint sharing this endpoint's key, or {-1, -1}.
    auto partner = [&](uint32_t segment, int end) -> std::pair<int64_t, int> {
        const int64_t other = partner_of[2 * size_t(segment) + size_t(end)];
        if (other < 0) return {-1, -1};
        return {other / 2, int(other % 2)};
    };

    std::vector<bool> used(segments.size(), false);
    // Walks from `start`, leaving through end `exit_end`, appending the far endpoints.
    auto walk = [&](uint32_t start, int exit_end, LinePath& path) {
        uint32_t current = start;
        int exit = exit_end;
        for (;;) {
            auto [next, enter] = partner(current, exit);
            if (next < 0 || used[size_t(next)]) return next >= 0 && uint32_t(next) == start;
            used[size_t(next)] = true;
            current = uint32_t(next);
            exit = 1 - enter;
            path.vertices.push_back(endpoint(segments[current], exit));
        }
    };

    // Open paths first: start at every endpoint that links to nothing.
    for (uint32_t i = 0; i < segments.size(); ++i)
        for (int end = 0; end < 2 && !used[i]; ++end) {
            if (partner(i, end).first >= 0) continue;
            used[i] = true;
            LinePath path{.type = type};
            path.vertices.push_back(endpoint(segments[i], end));
            path.vertices.push_back(endpoint(segments[i], 1 - end));
            walk(i, 1 - end, path);
            out.push_back(std::move(path));
        }
    // What is left are loops.
    for (uint32_t i = 0; i < segments.size(); ++i) {
        if (used[i]) continue;
        used[i] = true;
        LinePath path{.type = type};
        path.vertices.push_back(endpoint(segments[i], 0));
        path.vertices.push_back(endpoint(segments[i], 1));
        path.closed = walk(i, 1, path);
        if (path.closed) path.vertices.pop_back();  // the walk came back to the first vertex
        out.push_back(std::move(path));
    }
}

}  // namespace

void sort_segments(std::vector<LineSegment>& segments) {
    std::sort(segments.begin(), segments.end(), canonical_less);
}

std::vector<LinePath> chain_segments(const std::vector<LineSegment>& segments) {
    // Canonical order by index (cheaper than moving 80-byte segments), then one type at a time.
    // Canonical order (type, face, key0, key1) by counting sorts — linear, unlike a
    // comparison sort: bucket by face, settle the few segments of one face by insertion,
    // then a stable bucket by type.
    uint32_t face_count = 0;
    for (const LineSegment& s : segments) face_count = std::max(face_count, s.face + 1);
    std::vector<uint32_t> face_start(size_t(face_count) + 1, 0);
    for (const LineSegment& s : segments) ++face_start[s.face + 1];
    for (size_t f = 0; f < face_count; ++f) face_start[f + 1] += face_start[f];
    std::vector<uint32_t> by_face(segments.size());
    {
        std::vector<uint32_t> fill(face_start.begin(), face_start.end() - 1);
        for (uint32_t i = 0; i < segments.size(); ++i) by_face[fill[segments[i].face]++] = i;
    }
    for (size_t f = 0; f < face_count; ++f)
        for (uint32_t a = face_start[f] + 1; a < face_start[f + 1]; ++a)
            for (uint32_t b = a; b > face_start[f] && canonical_less(segments[by_face[b]], segments[by_face[b - 1]]); --b)
                std::swap(by_face[b], by_face[b - 1]);
    std::array<uint32_t, kLineTypeCount + 1> type_start{};
    for (const LineSegment& s : segments) ++type_start[std::min<uint32_t>(s.type, kLineTypeCount - 1) + 1];
    for (int t = 0; t < kLineTypeCount; ++t) type_start[size_t(t) + 1] += type_start[size_t(t)];
    std::vector<uint32_t> order(segments.size());
    {
        std::array<uint32_t, kLineTypeCount> fill{};
        std::copy(type_start.begin(), type_start.end() - 1, fill.begin());
        for (uint32_t i : by_face) order[fill[std::min<uint32_t>(segments[i].type, kLineTypeCount - 1)]++] = i;
    }

    // Types chain independently: one task per type, concatenated in type order.
    std::vector<std::pair<size_t, size_t>> ranges;  // [begin, end) of each type in `order`
    for (size_t begin = 0; begin < order.size();) {
        size_t end = begin;
        while (end < order.size() && segments[order[end]].type == segments[order[begin]].type) ++end;
        ranges.push_back({begin, end});
        begin = end;
    }
    std::vector<std::vector<LinePath>> per_type(ranges.size());
    parallel_for(ranges.size(), 1, [&](size_t first, size_t last, size_t) {
        for (size_t r = first; r < last; ++r) {
            const auto [begin, end] = ranges[r];
            chain_type(segments, order.data() + begin, end - begin, static_cast<LineType>(segments[order[begin]].type),
                       per_type[r]);
        }
    });
    std::vector<LinePath> paths;
    for (auto& list : per_type) std::move(list.begin(), list.end(), std::back_inserter(paths));
    return paths;
}

}  // namespace lw
