#include "lines/chaining.h"

#include <algorithm>
#include <tuple>
#include <unordered_map>

namespace lw {

namespace {

PathVertex endpoint(const LineSegment& s, int end) {
    const glm::vec4& p = end == 0 ? s.p0 : s.p1;
    const glm::vec4& b = end == 0 ? s.bary0 : s.bary1;
    return PathVertex{glm::vec3(p), s.face, glm::vec3(b), p.w};
}

uint32_t key_of(const LineSegment& s, int end) { return end == 0 ? s.key0 : s.key1; }

// Chains the segments of one line type. `segments` holds only that type.
void chain_type(const std::vector<LineSegment>& segments, LineType type, std::vector<LinePath>& out) {
    // Endpoints by key; keys seen other than exactly twice do not link.
    std::unordered_map<uint32_t, std::vector<std::pair<uint32_t, int>>> by_key;
    by_key.reserve(segments.size() * 2);
    for (uint32_t i = 0; i < segments.size(); ++i)
        for (int end = 0; end < 2; ++end)
            if (key_of(segments[i], end) != kNoKey) by_key[key_of(segments[i], end)].push_back({i, end});

    // The other endpoint sharing this endpoint's key, or {-1, -1}.
    auto partner = [&](uint32_t segment, int end) -> std::pair<int64_t, int> {
        const uint32_t key = key_of(segments[segment], end);
        if (key == kNoKey) return {-1, -1};
        const auto& list = by_key.at(key);
        if (list.size() != 2) return {-1, -1};
        const auto& other = list[0].first == segment && list[0].second == end ? list[1] : list[0];
        return {other.first, other.second};
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
    std::sort(segments.begin(), segments.end(), [](const LineSegment& a, const LineSegment& b) {
        return std::tie(a.type, a.face, a.key0, a.key1) < std::tie(b.type, b.face, b.key0, b.key1);
    });
}

std::vector<LinePath> chain_segments(std::vector<LineSegment> segments) {
    sort_segments(segments);
    std::vector<LinePath> paths;
    size_t begin = 0;
    while (begin < segments.size()) {
        size_t end = begin;
        while (end < segments.size() && segments[end].type == segments[begin].type) ++end;
        std::vector<LineSegment> same(segments.begin() + std::ptrdiff_t(begin), segments.begin() + std::ptrdiff_t(end));
        chain_type(same, static_cast<LineType>(segments[begin].type), paths);
        begin = end;
    }
    return paths;
}

}  // namespace lw
