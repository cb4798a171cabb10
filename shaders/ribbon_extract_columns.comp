#version 450
#extension GL_GOOGLE_include_directive : require
// extractColumns (Zhou et al. 2013, §2): gathers R̄, the C colours along the tilted right
// edge of piece `row`, for every valid position of that piece; one invocation per position
// ("one thread per column"). The edge's texel offsets come from engine/ribbon/problem.h.
#include "ribbon_shared.glsl"

layout(local_size_x = RIBBON_GROUP) in;

layout(std430, binding = 0) readonly buffer Exemplar { uint texels[]; };
layout(std430, binding = 1) readonly buffer Probes { ivec2 probes[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };
layout(std430, binding = 3) writeonly buffer Columns { uint columns[]; };

layout(push_constant) uniform ExtractPush {
    int width, height, samples, count;  // count: valid positions of the piece
    int right_offset, pad0, pad1, pad2;
} pc;

uint texel(ivec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) return 0u;
    return texels[p.y * pc.width + p.x];
}

void main() {
    int j = int(gl_GlobalInvocationID.x);
    if (j >= pc.count) return;
    int p = int(valid[j]);
    ivec2 u = ivec2(p % pc.width, p / pc.width - pc.samples);
    for (int k = 0; k < pc.samples; ++k) columns[j * pc.samples + k] = texel(u + probes[pc.right_offset + k]);
}
