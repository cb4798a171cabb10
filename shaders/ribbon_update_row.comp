#version 450
#extension GL_GOOGLE_include_directive : require
// updateTableRow (Zhou et al. 2013, §2, eq. 1): P[i, u] = min_v P[i−1, v] + D(v, u), one
// invocation per entry u of the row (a chunk [u_begin, u_begin + u_count) of it), v visited
// in ascending order and the lowest argmin kept, as the C++ reference does.
#include "ribbon_shared.glsl"

layout(local_size_x = RIBBON_GROUP) in;

layout(std430, binding = 0) readonly buffer Table { float table[]; };      // prev_count × u_count
layout(std430, binding = 1) readonly buffer PrevCosts { float prev_costs[]; };
layout(std430, binding = 2) buffer Costs { float costs[]; };
layout(std430, binding = 3) buffer Back { uint back[]; };

layout(push_constant) uniform UpdatePush {
    int prev_count, u_begin, u_count, pad;
} pc;

void main() {
    int u = int(gl_GlobalInvocationID.x);
    if (u >= pc.u_count) return;
    float best = uintBitsToFloat(0x7f800000u);  // +∞
    uint arg = 0u;
    for (int v = 0; v < pc.prev_count; ++v) {
        precise float c = prev_costs[v] + table[v * pc.u_count + u];
        if (c < best) {
            best = c;
            arg = uint(v);
        }
    }
    costs[pc.u_begin + u] = best;
    back[pc.u_begin + u] = arg;
}
