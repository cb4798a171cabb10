// shaders/lines_signs.glsl — the bits of a vertex's sign byte and the face tests built on
// them, shared by the host extraction (engine/lines/face_scan.h includes this file) and the
// GPU passes (lines_vertex.comp writes the byte, lines_extract.comp tests it). The byte holds
// exactly the comparisons rtsc's face tests make (docs/research/rtsc-lines.md §2.1), NaN
// included, so that a face is skipped only where the full test would reject it.
#ifndef LINES_SIGNS_GLSL
#define LINES_SIGNS_GLSL

#define SIGN_NDOTV_POSITIVE 1u     // n·v > 0
#define SIGN_NDOTV_NEGATIVE 2u     // n·v < 0
#define SIGN_KR_POSITIVE 4u        // kr > 0
#define SIGN_KR_NEGATIVE 8u        // kr < 0
#define SIGN_NOT_BACK_FACING 16u   // !(n·v <= 0)
#define SIGN_TEST_BELOW 32u        // test_num <= 0 and n·v >= 0: the suggestive test fails here ...
#define SIGN_TEST_ABOVE 64u        // ... test_num >= 0 and n·v <= 0: ... or here (other sign of n·v)
#define SIGN_KR_NOT_NEGATIVE 128u  // !(kr <= 0): the contour is kept here

// A face may hold a suggestive contour where some corner has kr > 0, some kr < 0 and some
// does not face away, unless the DwKr test fails at all three (rtsc's early rejection):
// (any & SUGGESTIVE_ANY) == SUGGESTIVE_ANY and (all & SUGGESTIVE_REJECTED) == 0, with `any`
// and `all` the OR and the AND of its corners' bytes.
#define SUGGESTIVE_ANY (SIGN_KR_POSITIVE | SIGN_KR_NEGATIVE | SIGN_NOT_BACK_FACING)
#define SUGGESTIVE_REJECTED (SIGN_TEST_BELOW | SIGN_TEST_ABOVE)
// A contour where n·v changes sign, unless kr <= 0 at all three corners.
#define CONTOUR_ANY (SIGN_NDOTV_POSITIVE | SIGN_NDOTV_NEGATIVE | SIGN_KR_NOT_NEGATIVE)

#endif
