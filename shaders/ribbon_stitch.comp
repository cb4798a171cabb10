#version 450
#extension GL_GOOGLE_include_directive : require
// Stitching (Zhou et al. 2013, §3.2): one invocation per seam fills the alignment table M of
// eq. 2 (two rows kept, every move stored in 2 bits for the backtrack), backtracks from
// M[C−1, C−1] and writes T and the seam error before and after. Mirrors
// stitch_reference() in engine/ribbon/stitch.cpp operation by operation.
#include "ribbon_shared.glsl"

layout(local_size_x = RIBBON_GROUP) in;

layout(std430, binding = 0) readonly buffer Exemplar { uint texels[]; };
layout(std430, binding = 1) readonly buffer Probes { ivec2 probes[]; };
layout(std430, binding = 2) readonly buffer Seams { ivec4 seams[]; };  // 2 per seam: (prev.xy, cur.xy), (right, left offset, -, -)
layout(std430, binding = 3) buffer Rows { float rows[]; };             // 2 × C per seam of the batch
layout(std430, binding = 4) buffer Moves { uint moves[]; };            // ⌈C² / 16⌉ per seam of the batch
layout(std430, binding = 5) buffer Remap { int remap[]; };             // C per seam
layout(std430, binding = 6) writeonly buffer Errors { float errors[]; };  // before, after per seam

layout(push_constant) uniform StitchPush {
    int width, height, samples, seam_count;
    int pad, moves_per_seam, seam_begin, batch;  // this dispatch: seams [begin, begin + batch)
} pc;

uint texel(ivec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) return 0u;
    return texels[p.y * pc.width + p.x];
}

float beta(uint l, uint r) { return (ribbon_opaque(l) || ribbon_opaque(r)) ? RIBBON_STITCH_P : 0.0; }

void main() {
    int local = int(gl_GlobalInvocationID.x), seam = pc.seam_begin + local;
    if (local >= pc.batch || seam >= pc.seam_count) return;
    int C = pc.samples;
    ivec4 pos = seams[2 * seam];
    int right_offset = seams[2 * seam + 1].x, left_offset = seams[2 * seam + 1].y;
    ivec2 prev = pos.xy, cur = pos.zw;
    int row_base = local * 2 * C;
    int move_base = local * pc.moves_per_seam;

    for (int s = 0; s < C; ++s) {
        uint l = texel(cur + probes[left_offset + s]);
        int here = row_base + (s & 1) * C, above = row_base + ((s + 1) & 1) * C;
        uint packed = 0u;
        for (int t = 0; t < C; ++t) {
            uint r = texel(prev + probes[right_offset + t]);
            float c = ribbon_xi(l, r), b = beta(l, r);
            precise float best;
            uint move;
            if (s == 0 && t == 0) {
                best = 0.0;
                move = RIBBON_MOVE_DIAGONAL;
            } else if (s == 0) {
                best = rows[here + t - 1] + b;
                move = RIBBON_MOVE_T;
            } else if (t == 0) {
                best = rows[above + t] + b;
                move = RIBBON_MOVE_S;
            } else {
                best = rows[above + t - 1];
                move = RIBBON_MOVE_DIAGONAL;
                precise float from_s = rows[above + t] + b;
                precise float from_t = rows[here + t - 1] + b;
                if (from_s < best) { best = from_s; move = RIBBON_MOVE_S; }
                if (from_t < best) { best = from_t; move = RIBBON_MOVE_T; }
            }
            precise float value = best + c;
            rows[here + t] = value;
            int cell = s * C + t;
            int word = move_base + cell / 16, shift = (cell % 16) * 2;
            moves[word] = (moves[word] & ~(3u << shift)) | (move << shift);
        }
    }

    // Backtrack: for each s, the cheapest right sample t on the path (lowest t on ties).
    int s = C - 1, t = C - 1;
    float best_c = uintBitsToFloat(0x7f800000u);
    int best_t = t;
    while (true) {
        uint l = texel(cur + probes[left_offset + s]);
        uint r = texel(prev + probes[right_offset + t]);
        float c = ribbon_xi(l, r);
        if (c <= best_c) { best_c = c; best_t = t; }
        if (s == 0 && t == 0) break;
        int cell = s * C + t;
        uint move = (moves[move_base + cell / 16] >> ((cell % 16) * 2)) & 3u;
        if (move != RIBBON_MOVE_T) {  // leaving row s
            remap[seam * C + s] = best_t;
            best_c = uintBitsToFloat(0x7f800000u);
        }
        if (move == RIBBON_MOVE_DIAGONAL) { --s; --t; }
        else if (move == RIBBON_MOVE_S) { --s; }
        else { --t; }
    }
    remap[seam * C] = best_t;

    precise float before = 0.0, after = 0.0;
    for (int k = 0; k < C; ++k) {
        uint l = texel(cur + probes[left_offset + k]);
        before += ribbon_xi(l, texel(prev + probes[right_offset + k]));
    }
    for (int k = 0; k < C; ++k) {
        uint l = texel(cur + probes[left_offset + k]);
        after += ribbon_xi(l, texel(prev + probes[right_offset + remap[seam * C + k]]));
    }
    errors[2 * seam] = before;
    errors[2 * seam + 1] = after;
}
