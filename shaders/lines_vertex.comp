#version 450
#extension GL_GOOGLE_include_directive : require
// Feature-line extraction, per vertex (the first of two passes; lines_extract.comp reads
// what this writes): n·v, kr and the suggestive test's numerator, and the byte of their
// signs the face tests read. The same expressions in the same order as
// engine/lines/view_quantities.h and face_scan.h, with `precise` so that no multiply-add is
// fused and the values are the CPU reference's.
#include "lines_shared.glsl"
#include "lines_signs.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Vertices { CurvVertex vertices[]; };
layout(std430, binding = 1) writeonly buffer Views { VertexView views[]; };
// Written only for the optional lines that read them (flags).
layout(std430, binding = 2) writeonly buffer HighlightNum { float highlight_num[]; };
layout(std430, binding = 3) writeonly buffer Apparent { ApparentVertex apparent[]; };

LINES_PUSH_CONSTANTS

uint bit(bool on, uint b) { return on ? b : 0u; }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    CurvVertex cv = vertices[i];
    precise vec3 v = pc.eye.xyz - cv.position.xyz;
    precise float inv_len = 1.0 / sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    v = vec3(v.x * inv_len, v.y * inv_len, v.z * inv_len);
    vec3 n = cv.normal.xyz, e1 = cv.pdir1_k1.xyz, e2 = cv.pdir2_k2.xyz;
    float k1 = cv.pdir1_k1.w, k2 = cv.pdir2_k2.w;
    vec4 C = cv.dcurv;
    precise float ndotv = n.x * v.x + n.y * v.y + n.z * v.z;
    precise float u = v.x * e1.x + v.y * e1.y + v.z * e1.z;
    precise float w = v.x * e2.x + v.y * e2.y + v.z * e2.z;
    precise float u2 = u * u;
    precise float w2 = w * w;
    precise float kr = k1 * u2 + k2 * w2;
    precise float csc2 = 1.0 / (u2 + w2);
    precise float num0 = (u2 * (u * C.x + 3.0 * w * C.y) + w2 * (3.0 * u * C.z + w * C.w)) * csc2;
    precise float tr = (k2 - k1) * u * w * csc2;
    precise float num1 = num0 - 2.0 * ndotv * (tr * tr);
    precise float test_num = num1 - pc.eye.w * ndotv;
    uint signs = bit(ndotv > 0.0, SIGN_NDOTV_POSITIVE) | bit(ndotv < 0.0, SIGN_NDOTV_NEGATIVE) |
                 bit(kr > 0.0, SIGN_KR_POSITIVE) | bit(kr < 0.0, SIGN_KR_NEGATIVE) |
                 bit(!(ndotv <= 0.0), SIGN_NOT_BACK_FACING) |
                 bit(test_num <= 0.0 && ndotv >= 0.0, SIGN_TEST_BELOW) |
                 bit(test_num >= 0.0 && ndotv <= 0.0, SIGN_TEST_ABOVE) | bit(!(kr <= 0.0), SIGN_KR_NOT_NEGATIVE);
    views[i] = VertexView(ndotv, kr, test_num, signs);

    // Suggestive highlights' test numerator: −num1 − sh_thresh/fs²·n·v (rtsc's shtest_num).
    if ((pc.flags & FLAG_SUGGESTIVE_HIGHLIGHTS) != 0u) {
        precise float num_sh = -num1 - pc.thresholds.z * ndotv;
        highlight_num[i] = num_sh;
    }
    // Apparent ridges: q1 and t1 of Q = S + (secθ − 1)·S·ŵŵᵀ (ridge_lines.cpp, apparent_curvature).
    if ((pc.flags & FLAG_APPARENT_RIDGES) != 0u) {
        precise float sec_minus_1 = 1.0 / abs(ndotv) - 1.0;
        precise float uu = u2 * csc2, uw = u * w * csc2, ww = w2 * csc2;
        precise float q11 = k1 * (1.0 + sec_minus_1 * uu);
        precise float q12 = k1 * (sec_minus_1 * uw);
        precise float q21 = k2 * (sec_minus_1 * uw);
        precise float q22 = k2 * (1.0 + sec_minus_1 * ww);
        precise float m1 = q11 * q11 + q21 * q21, m12 = q11 * q12 + q21 * q22, m2 = q12 * q12 + q22 * q22;
        precise float value = 0.5 * (m1 + m2);
        precise float root = sqrt(m12 * m12 + 0.25 * ((m2 - m1) * (m2 - m1)));
        if (value > 0.0)
            value += root;
        else
            value -= root;
        precise vec2 e = vec2(m2 - value, -m12);
        precise float len = sqrt(e.x * e.x + e.y * e.y);
        vec2 t1 = vec2(0.0, 1.0);
        if (len > 0.0) {
            precise float inv = 1.0 / len;
            t1 = vec2(e.x * inv, e.y * inv);
        }
        apparent[i] = ApparentVertex(value, t1.x, t1.y, 0.0);
    }
}
