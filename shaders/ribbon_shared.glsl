// shaders/ribbon_shared.glsl — constants and helpers of the ribbon passes (Zhou, Lasram and
// Lefebvre 2013, "By-example synthesis of curvilinear structured patterns"), included by the
// GLSL kernels and by engine/ribbon (C++) so that both sides use the same numbers.
//
// Texels are RGBA8 packed in one uint, R in the low byte, A in the high byte. A texel is
// opaque (the paper's α(p) = 1) when A ≥ 128, i.e. when bit 31 is set. Texels outside the
// exemplar read as 0: transparent black.
#ifndef RIBBON_SHARED_GLSL
#define RIBBON_SHARED_GLSL

// Paper, "Input exemplars, comparing pixels": γ penalizes matching opaque with transparent.
#define RIBBON_GAMMA 1024.0f
// Paper §3.2, eq. 3: P penalizes stretching opaque segments in the stitching alignment.
#define RIBBON_STITCH_P 32.0f

// Workgroup sizes.
#define RIBBON_GROUP 64            // one-dimensional kernels
#define RIBBON_SCAN_BLOCK 512      // elements per workgroup of the prefix scan (256 threads × 2)
#define RIBBON_TILE 16             // computeCostTable: 16 × 16 (v, u) pairs per workgroup
#define RIBBON_TILE_K 32           // … and 32 edge samples staged in shared memory at a time

// Stitching alignment moves, stored per cell for the backtrack (paper §3.2, eq. 2).
#define RIBBON_MOVE_DIAGONAL 0u    // from M[s-1, t-1]
#define RIBBON_MOVE_S 1u           // from M[s-1, t]: left pixel s also faces right pixel t
#define RIBBON_MOVE_T 2u           // from M[s, t-1]

#ifndef __cplusplus

bool ribbon_opaque(uint texel) { return (texel >> 31) != 0u; }

// ‖p − q‖ over RGB in [0, 255]³.
float ribbon_rgb_distance(uint p, uint q) {
    ivec3 a = ivec3(int(p & 0xffu), int((p >> 8) & 0xffu), int((p >> 16) & 0xffu));
    ivec3 b = ivec3(int(q & 0xffu), int((q >> 8) & 0xffu), int((q >> 16) & 0xffu));
    ivec3 d = a - b;
    return sqrt(float(d.x * d.x + d.y * d.y + d.z * d.z));
}

// The matching cost ξ(p, q): ‖p − q‖ when both are opaque or both transparent, else γ.
float ribbon_xi(uint p, uint q) {
    return ribbon_opaque(p) == ribbon_opaque(q) ? ribbon_rgb_distance(p, q) : RIBBON_GAMMA;
}

#endif  // !__cplusplus

#endif  // RIBBON_SHARED_GLSL
