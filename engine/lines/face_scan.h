// engine/lines/face_scan.h — which faces a contour or suggestive contour may cross.
//
// Input:  faces (three corner indices each), a range [begin, end) of them, and one sign byte
//         per vertex (`SignByte`, from the per-vertex view quantities), the array readable
//         3 bytes past its last vertex.
// Output: the faces of the range, in order, where rtsc's face tests (rtsc-lines.md §2.1)
//         can draw a suggestive contour, and those where they can draw a contour.
//
// The byte's bits and the tests are shaders/lines_signs.glsl's, which the GPU passes share.
// The scan is the hot loop of the host extraction (every face, every view): eight faces at
// a time with AVX2 where the CPU has it, else one by one; both give the same lists
// (tests/test_lines.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "../../shaders/lines_signs.glsl"

namespace lw {

// The byte of one vertex; products of comparisons rather than branches, so that the vertex
// loop vectorizes. The same expressions as shaders/lines_vertex.comp.
inline uint8_t sign_byte(float ndotv, float kr, float test_num) {
    const auto bit = [](bool on, unsigned b) { return unsigned(on) * b; };
    return uint8_t(bit(ndotv > 0.0f, SIGN_NDOTV_POSITIVE) | bit(ndotv < 0.0f, SIGN_NDOTV_NEGATIVE) |
                   bit(kr > 0.0f, SIGN_KR_POSITIVE) | bit(kr < 0.0f, SIGN_KR_NEGATIVE) |
                   bit(!(ndotv <= 0.0f), SIGN_NOT_BACK_FACING) |
                   bit((test_num <= 0.0f) & (ndotv >= 0.0f), SIGN_TEST_BELOW) |
                   bit((test_num >= 0.0f) & (ndotv <= 0.0f), SIGN_TEST_ABOVE) | bit(!(kr <= 0.0f), SIGN_KR_NOT_NEGATIVE));
}

// Bytes past the last vertex the sign array must have (zeros): the vector scan reads four
// bytes at each vertex.
constexpr size_t kSignPadding = 3;

struct FaceCandidates {
    size_t suggestive = 0, contour = 0;  // how many faces each list got
};

// Fills `suggestive` and `contour` (room for end − begin + 8 entries each: the scan writes
// past the count it returns) with the candidate faces of [begin, end).
FaceCandidates scan_faces(const glm::uvec3* faces, uint32_t begin, uint32_t end, const uint8_t* signs,
                          uint32_t* suggestive, uint32_t* contour);

// The one-face-at-a-time scan (the reference the vector scan is tested against).
FaceCandidates scan_faces_scalar(const glm::uvec3* faces, uint32_t begin, uint32_t end, const uint8_t* signs,
                                 uint32_t* suggestive, uint32_t* contour);

}  // namespace lw
