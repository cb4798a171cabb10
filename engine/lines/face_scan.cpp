#include "lines/face_scan.h"

#include <immintrin.h>

#include <array>
#include <bit>

namespace lw {

namespace {

constexpr unsigned kSuggestiveAny = SUGGESTIVE_ANY, kSuggestiveRejected = SUGGESTIVE_REJECTED;
constexpr unsigned kContourAny = CONTOUR_ANY;

// For each 8-bit mask, the lanes whose bit is set, first, one byte each: the permutation
// that packs the selected lanes of a vector to its front (AVX2 has no compress).
constexpr std::array<uint64_t, 256> kPackLanes = [] {
    std::array<uint64_t, 256> table{};
    for (unsigned mask = 0; mask < 256; ++mask) {
        uint64_t lanes = 0;
        int out = 0;
        for (unsigned lane = 0; lane < 8; ++lane)
            if (mask & (1u << lane)) lanes |= uint64_t(lane) << (8 * out++);
        table[mask] = lanes;
    }
    return table;
}();

__attribute__((target("avx2"))) inline void pack_store(uint32_t* out, __m256i values, unsigned mask) {
    const __m256i lanes = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(int64_t(kPackLanes[mask])));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_permutevar8x32_epi32(values, lanes));
}

// Eight faces at a time: their 24 corner indices are three loads, put in x, y, z order by
// blends and a permutation each; the corners' sign bytes are gathered (four bytes read per
// corner, the low one used); the two tests are lane masks, packed to the lists' ends.
__attribute__((target("avx2"))) FaceCandidates scan_faces_avx2(const glm::uvec3* faces, uint32_t begin, uint32_t end,
                                                               const uint8_t* signs, uint32_t* suggestive,
                                                               uint32_t* contour) {
    static_assert(sizeof(glm::uvec3) == 12, "faces are three packed indices");
    const __m256i order_x = _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5);
    const __m256i order_y = _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6);
    const __m256i order_z = _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i suggestive_any = _mm256_set1_epi32(kSuggestiveAny), rejected = _mm256_set1_epi32(kSuggestiveRejected);
    const __m256i contour_any = _mm256_set1_epi32(kContourAny);
    const int* bytes = reinterpret_cast<const int*>(signs);
    FaceCandidates n;
    uint32_t f = begin;
    for (; f + 8 <= end; f += 8) {
        const auto* p = reinterpret_cast<const __m256i*>(faces + f);
        const __m256i v0 = _mm256_loadu_si256(p), v1 = _mm256_loadu_si256(p + 1), v2 = _mm256_loadu_si256(p + 2);
        // Element e of the 24 is in vector e / 8, lane e % 8; x of face k is element 3k.
        const __m256i x = _mm256_permutevar8x32_epi32(_mm256_blend_epi32(_mm256_blend_epi32(v0, v1, 0x92), v2, 0x24), order_x);
        const __m256i y = _mm256_permutevar8x32_epi32(_mm256_blend_epi32(_mm256_blend_epi32(v0, v1, 0x24), v2, 0x49), order_y);
        const __m256i z = _mm256_permutevar8x32_epi32(_mm256_blend_epi32(_mm256_blend_epi32(v0, v1, 0x49), v2, 0x92), order_z);
        const __m256i s0 = _mm256_i32gather_epi32(bytes, x, 1);
        const __m256i s1 = _mm256_i32gather_epi32(bytes, y, 1);
        const __m256i s2 = _mm256_i32gather_epi32(bytes, z, 1);
        const __m256i any = _mm256_or_si256(_mm256_or_si256(s0, s1), s2);
        const __m256i all = _mm256_and_si256(_mm256_and_si256(s0, s1), s2);
        const __m256i sug = _mm256_and_si256(
            _mm256_cmpeq_epi32(_mm256_and_si256(any, suggestive_any), suggestive_any),
            _mm256_cmpeq_epi32(_mm256_and_si256(all, rejected), _mm256_setzero_si256()));
        const __m256i con = _mm256_cmpeq_epi32(_mm256_and_si256(any, contour_any), contour_any);
        const unsigned sug_mask = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(sug)));
        const unsigned con_mask = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(con)));
        const __m256i ids = _mm256_add_epi32(_mm256_set1_epi32(int(f)), lane);
        pack_store(suggestive + n.suggestive, ids, sug_mask);
        pack_store(contour + n.contour, ids, con_mask);
        n.suggestive += size_t(std::popcount(sug_mask));
        n.contour += size_t(std::popcount(con_mask));
    }
    const FaceCandidates tail = scan_faces_scalar(faces, f, end, signs, suggestive + n.suggestive, contour + n.contour);
    return {n.suggestive + tail.suggestive, n.contour + tail.contour};
}

}  // namespace

FaceCandidates scan_faces_scalar(const glm::uvec3* faces, uint32_t begin, uint32_t end, const uint8_t* signs,
                                 uint32_t* suggestive, uint32_t* contour) {
    // Each face is written, the count advances only for a candidate: no branch to mispredict.
    FaceCandidates n;
    for (uint32_t f = begin; f < end; ++f) {
        const glm::uvec3 c = faces[f];
        const unsigned s0 = signs[c.x], s1 = signs[c.y], s2 = signs[c.z];
        const unsigned any = s0 | s1 | s2, all = s0 & s1 & s2;
        suggestive[n.suggestive] = f;
        n.suggestive += ((any & kSuggestiveAny) == kSuggestiveAny) & !(all & kSuggestiveRejected);
        contour[n.contour] = f;
        n.contour += (any & kContourAny) == kContourAny;
    }
    return n;
}

FaceCandidates scan_faces(const glm::uvec3* faces, uint32_t begin, uint32_t end, const uint8_t* signs,
                          uint32_t* suggestive, uint32_t* contour) {
    static const bool avx2 = __builtin_cpu_supports("avx2");
    return avx2 ? scan_faces_avx2(faces, begin, end, signs, suggestive, contour)
                : scan_faces_scalar(faces, begin, end, signs, suggestive, contour);
}

}  // namespace lw
