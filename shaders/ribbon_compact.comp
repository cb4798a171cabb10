#version 450
#extension GL_GOOGLE_include_directive : require
// compactValidPositions (Zhou et al. 2013, §2): gathers the valid positions into a dense,
// ascending list with a parallel prefix scan, in three dispatches of this kernel:
//   phase 0: each workgroup scans RIBBON_SCAN_BLOCK flags (work-efficient up/down sweep in
//            shared memory), writes the exclusive prefix and the block's total;
//   phase 1: one workgroup scans the block totals, RIBBON_SCAN_BLOCK at a time with a
//            carry, and writes the number of valid positions to header[0];
//   phase 2: every set flag writes its position index to valid[block offset + prefix].
#include "ribbon_shared.glsl"

layout(local_size_x = RIBBON_SCAN_BLOCK / 2) in;

layout(std430, binding = 0) readonly buffer Flags { uint flags[]; };
layout(std430, binding = 1) buffer Prefix { uint prefix[]; };
layout(std430, binding = 2) buffer BlockSums { uint block_sums[]; };
layout(std430, binding = 3) writeonly buffer Valid { uint valid[]; };
layout(std430, binding = 4) buffer Header { uint header[]; };

layout(push_constant) uniform CompactPush {
    uint phase;
    uint count;   // U
    uint blocks;  // ⌈U / RIBBON_SCAN_BLOCK⌉
    uint pad;
} pc;

shared uint temp[RIBBON_SCAN_BLOCK];
shared uint carry;

// Exclusive scan of temp[] in place (Blelloch); returns the total to every invocation.
uint scan_block(uint t) {
    uint offset = 1u;
    for (uint d = RIBBON_SCAN_BLOCK / 2; d > 0u; d >>= 1) {
        barrier();
        if (t < d) {
            uint ai = offset * (2u * t + 1u) - 1u, bi = offset * (2u * t + 2u) - 1u;
            temp[bi] += temp[ai];
        }
        offset *= 2u;
    }
    barrier();
    uint total = temp[RIBBON_SCAN_BLOCK - 1];
    barrier();
    if (t == 0u) temp[RIBBON_SCAN_BLOCK - 1] = 0u;
    for (uint d = 1u; d < RIBBON_SCAN_BLOCK; d *= 2u) {
        offset >>= 1;
        barrier();
        if (t < d) {
            uint ai = offset * (2u * t + 1u) - 1u, bi = offset * (2u * t + 2u) - 1u;
            uint x = temp[ai];
            temp[ai] = temp[bi];
            temp[bi] += x;
        }
    }
    barrier();
    return total;
}

void main() {
    uint t = gl_LocalInvocationID.x;
    if (pc.phase == 0u) {
        uint base = gl_WorkGroupID.x * RIBBON_SCAN_BLOCK;
        uint a = base + 2u * t, b = a + 1u;
        temp[2u * t] = a < pc.count ? flags[a] : 0u;
        temp[2u * t + 1u] = b < pc.count ? flags[b] : 0u;
        uint total = scan_block(t);
        if (a < pc.count) prefix[a] = temp[2u * t];
        if (b < pc.count) prefix[b] = temp[2u * t + 1u];
        if (t == 0u) block_sums[gl_WorkGroupID.x] = total;
    } else if (pc.phase == 1u) {
        if (t == 0u) carry = 0u;
        for (uint base = 0u; base < pc.blocks; base += RIBBON_SCAN_BLOCK) {
            uint a = base + 2u * t, b = a + 1u;
            barrier();
            temp[2u * t] = a < pc.blocks ? block_sums[a] : 0u;
            temp[2u * t + 1u] = b < pc.blocks ? block_sums[b] : 0u;
            uint total = scan_block(t);
            uint c = carry;
            if (a < pc.blocks) block_sums[a] = temp[2u * t] + c;
            if (b < pc.blocks) block_sums[b] = temp[2u * t + 1u] + c;
            barrier();
            if (t == 0u) carry = c + total;
        }
        barrier();
        if (t == 0u) header[0] = carry;
    } else {
        uint base = gl_WorkGroupID.x * RIBBON_SCAN_BLOCK;
        for (uint i = 0u; i < 2u; ++i) {
            uint p = base + 2u * t + i;
            if (p < pc.count && flags[p] != 0u) valid[block_sums[gl_WorkGroupID.x] + prefix[p]] = p;
        }
    }
}
