#version 450
#extension GL_GOOGLE_include_directive : require
// Feature-line extraction: one invocation per face appends that face's contour,
// suggestive-contour, crease and border segments with an atomic counter.
// Mirrors engine/lines/extract_reference.cpp and view_quantities.h line by line, with
// `precise` so that no multiply-add is fused and results match the CPU reference
// (rtsc's rules: docs/research/rtsc-lines.md §1–2).
#include "lines_shared.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Vertices { CurvVertex vertices[]; };
layout(std430, binding = 1) readonly buffer Faces { uvec4 faces[]; };        // corners, w: feature-edge mask
layout(std430, binding = 2) readonly buffer FaceEdges { uvec4 face_edges[]; };  // edge opposite each corner
layout(std430, binding = 3) buffer Output {
    uint count;      // segments wanted (may exceed capacity: the host then retries larger)
    uint capacity;
    uint pad0, pad1;
    LineSegment segments[];
} out_buf;

layout(push_constant) uniform LinesPush {
    vec4 eye;        // xyz: eye (world), w: sug_thresh / fs²
    float fade;      // 0.03 / fs², or 0 without fading
    uint flags;
    uint face_count;
    uint pad;
} pc;

// The cheap per-view quantities first; the suggestive test only for faces that need it
// (most faces have no zero crossing at all). Same expressions as view_quantities.h.
struct View {
    float ndotv, kr, u, w;
};

View vertex_view(uint i) {
    CurvVertex cv = vertices[i];
    precise vec3 v = pc.eye.xyz - cv.position.xyz;
    precise float inv_len = 1.0 / sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    v = vec3(v.x * inv_len, v.y * inv_len, v.z * inv_len);
    vec3 n = cv.normal.xyz, e1 = cv.pdir1_k1.xyz, e2 = cv.pdir2_k2.xyz;
    float k1 = cv.pdir1_k1.w, k2 = cv.pdir2_k2.w;
    precise float ndotv = n.x * v.x + n.y * v.y + n.z * v.z;
    precise float u = v.x * e1.x + v.y * e1.y + v.z * e1.z;
    precise float w = v.x * e2.x + v.y * e2.y + v.z * e2.z;
    precise float u2 = u * u;
    precise float w2 = w * w;
    precise float kr = k1 * u2 + k2 * w2;
    return View(ndotv, kr, u, w);
}

// The suggestive-contour test numerator (threshold subtracted); the denominator is n·v.
float test_numerator(uint i, View b) {
    CurvVertex cv = vertices[i];
    float k1 = cv.pdir1_k1.w, k2 = cv.pdir2_k2.w;
    vec4 C = cv.dcurv;
    float u = b.u, w = b.w, ndotv = b.ndotv;
    precise float u2 = u * u;
    precise float w2 = w * w;
    precise float csc2 = 1.0 / (u2 + w2);
    precise float num0 = (u2 * (u * C[0] + 3.0 * w * C[1]) + w2 * (3.0 * u * C[2] + w * C[3])) * csc2;
    precise float tr = (k2 - k1) * u * w * csc2;
    precise float num1 = num0 - 2.0 * ndotv * (tr * tr);
    precise float test_num = num1 - pc.eye.w * ndotv;
    return test_num;
}

void append(LineSegment s) {
    uint index = atomicAdd(out_buf.count, 1u);
    if (index < out_buf.capacity) out_buf.segments[index] = s;
}

bool has_both_signs(vec3 v) {
    return (v[0] > 0.0 || v[1] > 0.0 || v[2] > 0.0) && (v[0] < 0.0 || v[1] < 0.0 || v[2] < 0.0);
}

// rtsc's draw_face_isoline2 from the lone vertex, with the test trimming and fade alpha.
void face_isoline(uint f, uvec3 corners, vec3 val, vec3 num, vec3 den, bool has_den, float fade, uint type) {
    int a;
    if ((val[0] < 0.0 && val[1] >= 0.0 && val[2] >= 0.0) || (val[0] > 0.0 && val[1] <= 0.0 && val[2] <= 0.0))
        a = 0;
    else if ((val[1] < 0.0 && val[2] >= 0.0 && val[0] >= 0.0) || (val[1] > 0.0 && val[2] <= 0.0 && val[0] <= 0.0))
        a = 1;
    else
        a = 2;
    int b = (a + 1) % 3, c = (a + 2) % 3;

    vec3 xa = vertices[corners[a]].position.xyz;
    vec3 xb = vertices[corners[b]].position.xyz;
    vec3 xc = vertices[corners[c]].position.xyz;
    precise float s_ab = val[a] / (val[a] - val[b]);
    precise float s_ac = val[a] / (val[a] - val[c]);
    precise vec3 p1 = (1.0 - s_ab) * xa + s_ab * xb;
    precise vec3 p2 = (1.0 - s_ac) * xa + s_ac * xc;
    vec3 b1 = vec3(0.0), b2 = vec3(0.0);
    b1[a] = 1.0 - s_ab;
    b1[b] = s_ab;
    b2[a] = 1.0 - s_ac;
    b2[c] = s_ac;
    uint key1 = face_edges[f][c];
    uint key2 = face_edges[f][b];

    precise float n1 = (1.0 - s_ab) * num[a] + s_ab * num[b];
    precise float n2 = (1.0 - s_ac) * num[a] + s_ac * num[c];
    precise float d1 = has_den ? (1.0 - s_ab) * den[a] + s_ab * den[b] : 1.0;
    precise float d2 = has_den ? (1.0 - s_ac) * den[a] + s_ac * den[c] : 1.0;
    bool valid1 = (n1 >= 0.0) == (d1 >= 0.0);
    precise float z1 = (n1 >= 0.0) != (n2 >= 0.0) ? n1 / (n1 - n2) : 0.0;
    precise float z2 = (d1 >= 0.0) != (d2 >= 0.0) ? d1 / (d1 - d2) : 0.0;
    if (z1 == 0.0) {
        z1 = z2;
        z2 = 0.0;
    } else if (z2 != 0.0 && z2 < z1) {
        float t = z1;
        z1 = z2;
        z2 = t;
    }

    // P1 and P2 as computed (as rtsc emits them), the test's zero crossings interpolated.
    const int START = 0, INSIDE = 1, END = 2;
    float zs[4];
    int kinds[4];
    uint keys[4];
    int count = 0;
    if (valid1) { zs[count] = 0.0; kinds[count] = START; keys[count] = key1; count++; }
    if (z1 != 0.0) { zs[count] = z1; kinds[count] = INSIDE; keys[count] = NO_KEY; count++; }
    if (z2 != 0.0) { zs[count] = z2; kinds[count] = INSIDE; keys[count] = NO_KEY; count++; }
    if (count != 2) { zs[count] = 1.0; kinds[count] = END; keys[count] = key2; count++; }

    for (int i = 0; i + 1 < count; i += 2) {
        LineSegment s;
        for (int e = 0; e < 2; ++e) {
            precise float z = zs[i + e];
            int kind = kinds[i + e];
            precise vec3 x = kind == START ? p1 : kind == END ? p2 : (1.0 - z) * p1 + z * p2;
            precise float n = kind == START ? n1 : kind == END ? n2 : (1.0 - z) * n1 + z * n2;
            precise float d = kind == START ? d1 : kind == END ? d2 : (1.0 - z) * d1 + z * d2;
            precise float alpha = fade > 0.0 ? clamp(n / (d * fade + n), 0.0, 1.0) : 1.0;
            precise vec3 bary = kind == START ? b1 : kind == END ? b2 : (1.0 - z) * b1 + z * b2;
            if (e == 0) { s.p0 = vec4(x, alpha); s.bary0 = vec4(bary, 0.0); }
            else        { s.p1 = vec4(x, alpha); s.bary1 = vec4(bary, 0.0); }
        }
        s.face = f;
        s.type = type;
        s.key0 = keys[i];
        s.key1 = keys[i + 1];
        append(s);
    }
}

void main() {
    uint f = gl_GlobalInvocationID.x;
    if (f >= pc.face_count) return;
    uvec4 face = faces[f];
    uvec3 corners = face.xyz;
    View v0 = vertex_view(corners[0]);
    View v1 = vertex_view(corners[1]);
    View v2 = vertex_view(corners[2]);

    if ((pc.flags & FLAG_SUGGESTIVE) != 0u) {
        vec3 val = vec3(v0.kr, v1.kr, v2.kr);
        bool back_facing = v0.ndotv <= 0.0 && v1.ndotv <= 0.0 && v2.ndotv <= 0.0;
        if (has_both_signs(val) && !back_facing) {
            vec3 num = vec3(test_numerator(corners[0], v0), test_numerator(corners[1], v1),
                            test_numerator(corners[2], v2));
            vec3 den = vec3(v0.ndotv, v1.ndotv, v2.ndotv);
            bool rejected =
                (num[0] <= 0.0 && den[0] >= 0.0 && num[1] <= 0.0 && den[1] >= 0.0 && num[2] <= 0.0 && den[2] >= 0.0) ||
                (num[0] >= 0.0 && den[0] <= 0.0 && num[1] >= 0.0 && den[1] <= 0.0 && num[2] >= 0.0 && den[2] <= 0.0);
            if (!rejected) face_isoline(f, corners, val, num, den, true, pc.fade, LINE_SUGGESTIVE);
        }
    }
    if ((pc.flags & FLAG_SILHOUETTES) != 0u) {
        vec3 val = vec3(v0.ndotv, v1.ndotv, v2.ndotv);
        vec3 num = vec3(v0.kr, v1.kr, v2.kr);
        bool rejected = num[0] <= 0.0 && num[1] <= 0.0 && num[2] <= 0.0;
        if (has_both_signs(val) && !rejected)
            face_isoline(f, corners, val, num, vec3(1.0), false, 0.0, LINE_SILHOUETTE);
    }
    uint mask = face.w;
    for (int i = 0; i < 3; ++i) {
        bool crease = (pc.flags & FLAG_CREASES) != 0u && (mask & (1u << i)) != 0u;
        bool border = (pc.flags & FLAG_BORDERS) != 0u && (mask & (8u << i)) != 0u;
        if (!crease && !border) continue;
        int j = (i + 1) % 3, k = (i + 2) % 3;
        LineSegment s;
        s.p0 = vec4(vertices[corners[j]].position.xyz, 1.0);
        s.p1 = vec4(vertices[corners[k]].position.xyz, 1.0);
        s.bary0 = vec4(0.0);
        s.bary1 = vec4(0.0);
        s.bary0[j] = 1.0;
        s.bary1[k] = 1.0;
        s.face = f;
        s.type = border ? LINE_BORDER : LINE_CREASE;
        s.key0 = corners[j];
        s.key1 = corners[k];
        append(s);
    }
}
