#version 450
#extension GL_GOOGLE_include_directive : require
// findValidPositions (Zhou et al. 2013, §2): one invocation per position u of U = W·(H + C)
// flags whether piece `row` may be placed there (§1.3, §3.1), under one of the validity
// rules engine/ribbon/problem.h lists (the host retries a row with the next rule when none
// passed). The piece's probe texels are
// offsets relative to u computed once on the CPU (engine/ribbon/problem.h); this kernel adds
// u and samples E. Mirrors position_valid() in engine/ribbon/problem.cpp.
#include "ribbon_shared.glsl"

layout(local_size_x = RIBBON_GROUP) in;

layout(std430, binding = 0) readonly buffer Exemplar { uint texels[]; };
layout(std430, binding = 1) readonly buffer Probes { ivec2 probes[]; };
layout(std430, binding = 2) writeonly buffer Flags { uint flags[]; };

layout(push_constant) uniform FindValidPush {
    int width, height, samples, count;
    int top_offset, top_count, interior_offset, interior_count;
    int forbidden_offset, forbidden_count, min_dx, max_dx;
    int touches_forbidden, bottom_offset, bottom_count, rule;  // rule: ValidityRule (problem.h)
    int band_top, band_bottom, pad1, pad2;  // first and last row of E with an opaque texel
} pc;

uint texel(ivec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= pc.width || p.y >= pc.height) return 0u;
    return texels[p.y * pc.width + p.x];
}

bool any_opaque(ivec2 u, int offset, int n) {
    for (int i = 0; i < n; ++i)
        if (ribbon_opaque(texel(u + probes[offset + i]))) return true;
    return false;
}

void main() {
    int p = int(gl_GlobalInvocationID.x);
    if (p >= pc.count) return;
    ivec2 u = ivec2(p % pc.width, p / pc.width - pc.samples);
    // 4. inside E horizontally; 3. no opaque texel on a forbidden canvas pixel (§3.1)
    bool valid = u.x + pc.min_dx >= 0 && u.x + pc.max_dx < pc.width;
    valid = valid && !any_opaque(u, pc.forbidden_offset, pc.forbidden_count);
    if (valid) {
        if (pc.rule == 0) {
            // 1. the piece slices the pattern completely: its top edge passes above the
            //    pattern's band, its bottom edge below; 2. it is not empty
            for (int i = 0; valid && i < pc.top_count; ++i) valid = u.y + probes[pc.top_offset + i].y < pc.band_top;
            for (int i = 0; valid && i < pc.bottom_count; ++i)
                valid = u.y + probes[pc.bottom_offset + i].y > pc.band_bottom;
            valid = valid && any_opaque(u, pc.interior_offset, pc.interior_count);
        } else if (pc.rule == 1) {
            // a piece touching a forbidden region, empty: the one position wholly above E
            valid = pc.touches_forbidden != 0 && u == ivec2(-pc.min_dx, -pc.samples);
        } else if (pc.rule == 2) {
            // the paper's literal test: the edges meet no opaque texel; not empty
            valid = !any_opaque(u, pc.top_offset, pc.top_count) && !any_opaque(u, pc.bottom_offset, pc.bottom_count) &&
                    any_opaque(u, pc.interior_offset, pc.interior_count);
        }  // rule 3: 3 and 4 only
    }
    flags[p] = valid ? 1u : 0u;
}
