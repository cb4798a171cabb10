#version 450
#extension GL_GOOGLE_include_directive : require
// computeCostTable (Zhou et al. 2013, §2): D(v + R_i−1, u + L_i) = Σ_k ξ(R̄[k], L̄[k]) for
// every pair of a valid position v of piece i−1 (right edges from extractColumns) and a valid
// position u of piece i (its left edge's offsets: tilted where the curve turns over the piece,
// engine/ribbon/ribbon.h, else a column of E), one invocation per pair, C samples each.
// A 16 × 16 tile of pairs stages 16 right edges and 16 left edges in shared memory, 32
// samples at a time, so that each texel is read from memory once per tile instead of 16
// times. k is summed from 0 to C−1 in every invocation, as the C++ reference does.
// The table may be built in chunks of u: entries [v · u_count + (u − u_begin)].
#include "ribbon_shared.glsl"

layout(local_size_x = RIBBON_TILE, local_size_y = RIBBON_TILE) in;

layout(std430, binding = 0) readonly buffer Exemplar { uint texels[]; };
layout(std430, binding = 1) readonly buffer Columns { uint columns[]; };  // R̄, prev_count × C
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };      // positions of piece i
layout(std430, binding = 3) readonly buffer Probes { ivec2 probes[]; };   // piece i's left-edge offsets at left_offset
layout(std430, binding = 4) writeonly buffer Table { float table[]; };

layout(push_constant) uniform CostPush {
    int width, height, samples, prev_count;
    int u_begin, u_count, left_offset, pad;
} pc;

shared uint right_tile[RIBBON_TILE][RIBBON_TILE_K];
shared uint left_tile[RIBBON_TILE][RIBBON_TILE_K];

uint texel(ivec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) return 0u;
    return texels[p.y * pc.width + p.x];
}

void main() {
    int lx = int(gl_LocalInvocationID.x), ly = int(gl_LocalInvocationID.y);
    int u0 = int(gl_WorkGroupID.x) * RIBBON_TILE, v0 = int(gl_WorkGroupID.y) * RIBBON_TILE;
    int flat_id = ly * RIBBON_TILE + lx;
    precise float d = 0.0;
    for (int k0 = 0; k0 < pc.samples; k0 += RIBBON_TILE_K) {
        for (int e = flat_id; e < RIBBON_TILE * RIBBON_TILE_K; e += RIBBON_TILE * RIBBON_TILE) {
            int row = e / RIBBON_TILE_K, kk = e % RIBBON_TILE_K, k = k0 + kk;
            int v = v0 + row, u = u0 + row;
            right_tile[row][kk] = (v < pc.prev_count && k < pc.samples) ? columns[v * pc.samples + k] : 0u;
            uint left = 0u;
            if (u < pc.u_count && k < pc.samples) {
                int p = int(valid[pc.u_begin + u]);
                ivec2 pos = ivec2(p % pc.width, p / pc.width - pc.samples);
                left = texel(pos + probes[pc.left_offset + k]);
            }
            left_tile[row][kk] = left;
        }
        barrier();
        int kn = min(RIBBON_TILE_K, pc.samples - k0);
        for (int kk = 0; kk < kn; ++kk) d += ribbon_xi(right_tile[ly][kk], left_tile[lx][kk]);
        barrier();
    }
    int u = u0 + lx, v = v0 + ly;
    if (u < pc.u_count && v < pc.prev_count) table[v * pc.u_count + u] = d;
}
