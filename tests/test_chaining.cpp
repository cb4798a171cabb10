// Chaining segments into brush paths.
#include <algorithm>
#include <random>

#include "lines/chaining.h"
#include "test_support.h"

namespace lw {
namespace {

LineSegment segment(glm::vec3 a, glm::vec3 b, uint32_t key0, uint32_t key1, uint32_t face,
                    LineType type = LineType::Silhouette) {
    LineSegment s{};
    s.p0 = glm::vec4(a, 1.0f);
    s.p1 = glm::vec4(b, 1.0f);
    s.bary0 = glm::vec3(1, 0, 0);
    s.bary1 = glm::vec3(0, 1, 0);
    s.face = face;
    s.type = uint32_t(type);
    s.key0 = key0;
    s.key1 = key1;
    return s;
}

// A square loop of four segments with alternating orientations (as neighbouring faces
// produce them): keys are the shared "edges" 10..13.
std::vector<LineSegment> square_loop() {
    const glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    return {segment(p[0], p[1], 10, 11, 0), segment(p[2], p[1], 12, 11, 1), segment(p[2], p[3], 12, 13, 2),
            segment(p[0], p[3], 10, 13, 3)};
}

TEST(Chaining, LoopStaysClosed) {
    const auto paths = chain_segments(square_loop());
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_TRUE(paths[0].closed);
    EXPECT_EQ(paths[0].vertices.size(), 4u);  // no repeated end vertex
    // Consecutive vertices are one unit apart, also across the closing edge.
    for (size_t i = 0; i < 4; ++i)
        EXPECT_FLOAT_EQ(glm::length(paths[0].vertices[i].position - paths[0].vertices[(i + 1) % 4].position), 1.0f);
}

TEST(Chaining, OpenChainRunsEndToEnd) {
    // A polyline of 5 segments over keys 1..4, ends keyed kNoKey (cut inside faces).
    std::vector<LineSegment> segments;
    for (uint32_t i = 0; i < 5; ++i)
        segments.push_back(segment(glm::vec3(float(i), 0, 0), glm::vec3(float(i + 1), 0, 0), i == 0 ? kNoKey : i,
                                   i == 4 ? kNoKey : i + 1, 100 + i));
    std::swap(segments[1], segments[3]);
    std::swap(segments[1].p0, segments[1].p1);  // reverse one segment
    std::swap(segments[1].key0, segments[1].key1);
    const auto paths = chain_segments(segments);
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_FALSE(paths[0].closed);
    ASSERT_EQ(paths[0].vertices.size(), 6u);
    const float direction = paths[0].vertices[1].position.x - paths[0].vertices[0].position.x;
    for (size_t i = 0; i + 1 < 6; ++i)
        EXPECT_FLOAT_EQ(paths[0].vertices[i + 1].position.x - paths[0].vertices[i].position.x, direction);
}

TEST(Chaining, OrderDoesNotMatter) {
    auto segments = square_loop();
    for (uint32_t i = 0; i < 6; ++i)
        segments.push_back(segment(glm::vec3(5 + float(i), 0, 0), glm::vec3(6 + float(i), 0, 0), 100 + i, 101 + i, 50 + i,
                                   LineType::Suggestive));
    const auto reference = chain_segments(segments);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 10; ++trial) {
        std::shuffle(segments.begin(), segments.end(), rng);
        const auto paths = chain_segments(segments);
        ASSERT_EQ(paths.size(), reference.size());
        for (size_t p = 0; p < paths.size(); ++p) {
            EXPECT_EQ(paths[p].type, reference[p].type);
            EXPECT_EQ(paths[p].closed, reference[p].closed);
            ASSERT_EQ(paths[p].vertices.size(), reference[p].vertices.size());
            for (size_t v = 0; v < paths[p].vertices.size(); ++v)
                EXPECT_EQ(paths[p].vertices[v].position, reference[p].vertices[v].position);
        }
    }
}

TEST(Chaining, TypesDoNotMix) {
    // Same keys, different types: two separate paths.
    std::vector<LineSegment> segments{segment({0, 0, 0}, {1, 0, 0}, 1, 2, 0, LineType::Silhouette),
                                      segment({1, 0, 0}, {2, 0, 0}, 2, 3, 1, LineType::Suggestive)};
    const auto paths = chain_segments(segments);
    ASSERT_EQ(paths.size(), 2u);
    EXPECT_NE(paths[0].type, paths[1].type);
}

TEST(Chaining, JunctionsEndPaths) {
    // Three segments meeting at key 7 (non-manifold): none links through it.
    std::vector<LineSegment> segments{segment({0, 0, 0}, {1, 0, 0}, 1, 7, 0), segment({1, 0, 0}, {2, 0, 0}, 7, 2, 1),
                                      segment({1, 0, 0}, {1, 1, 0}, 7, 3, 2)};
    EXPECT_EQ(chain_segments(segments).size(), 3u);
}

}  // namespace
}  // namespace lw
