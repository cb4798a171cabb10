// engine/lines/face_scan.h — which faces a contour or suggestive contour may cross.
//
// Input:  faces (three corner indices each), a range [begin, end) of them, and one sign byte
//         per vertex (`SignByte`, from the per-vertex view quantities), the array readable
//         3 bytes past its last vertex.
// Output: the faces of the range, in order, where rtsc's face tests (rtsc-lines.md §2.1)
//         can draw a suggestive contour, and those where they can draw a contour.
//
// The byte holds exactly the comparisons the tests make (NaN included), so a face is left
// out only where the full test would reject it. The scan is the hot loop of the host
// extraction (every face, every view): eight faces at a time with AVX2 where the CPU has
// it, else one by one; both give the same lists (tests/test_lines.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace lw {

enum SignBit : uint8_t {
    kNdotvPositive = 1,    // n·v > 0
    kNdotvNegative = 2,    // n·v < 0
    kKrPositive = 4,       // kr > 0
    kKrNegative = 8,       // kr < 0
    kNotBackFacing = 16,   // !(n·v ≤ 0)
    kTestBelow = 32,       // test_num ≤ 0 and n·v ≥ 0: the suggestive test fails here …
    kTestAbove = 64,       // … test_num ≥ 0 and n·v ≤ 0: … or fails here (other sign of n·v)
    kKrNotNegative = 128,  // !(kr ≤ 0): the contour is kept here
};

// Products of comparisons rather than branches, so that the vertex loop vectorizes.
inline uint8_t sign_byte(float ndotv, float kr, float test_num) {
    const auto bit = [](bool on, SignBit b) { return unsigned(on) * unsigned(b); };
    return uint8_t(bit(ndotv > 0.0f, kNdotvPositive) | bit(ndotv < 0.0f, kNdotvNegative) | bit(kr > 0.0f, kKrPositive) |
                   bit(kr < 0.0f, kKrNegative) | bit(!(ndotv <= 0.0f), kNotBackFacing) |
                   bit((test_num <= 0.0f) & (ndotv >= 0.0f), kTestBelow) |
                   bit((test_num >= 0.0f) & (ndotv <= 0.0f), kTestAbove) | bit(!(kr <= 0.0f), kKrNotNegative));
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
