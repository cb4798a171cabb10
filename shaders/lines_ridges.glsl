// shaders/lines_ridges.glsl — rtsc's ridge-like lines per face: ridges and valleys,
// principal highlights, apparent ridges. Included by lines_extract.comp, which declares
// `vertices`, `faces`, `face_edges` (w: the strip corners), `apparent` and `append` before it. Line by line the
// expressions of engine/lines/ridge_lines.cpp (the reference, where each rule is
// explained), with `precise` so that no multiply-add is fused and the values are the CPU's.
#ifndef LINES_RIDGES_GLSL
#define LINES_RIDGES_GLSL

#include "lines_ridges_math.glsl"

// A face as rtsc's loop sees it (engine/lines/strip_order.h): corner[i] is the face-local
// number of v_i, vertex[i] its vertex.
struct StripFace {
    uint face;
    ivec3 corner;
    uvec3 vertex;
};

StripFace strip_face(uint f) {
    uint packed = face_edges[f].w;
    StripFace sf;
    sf.face = f;
    uvec3 corners = faces[f].xyz;
    for (int i = 0; i < 3; ++i) {
        sf.corner[i] = int((packed >> (2 * i)) & 3u);
        sf.vertex[i] = corners[sf.corner[i]];
    }
    return sf;
}

// rtsc's draw_segment_ridge / compute_segment_app_ridge from v_r (ridge_segment).
void ridge_segment(StripFace sf, int r, vec3 e, vec3 k, float thresh, bool to_center, bool fade, bool test, vec3 tmax[3],
                   uint type) {
    int a = r, b = (r + 1) % 3, c = (r + 2) % 3;
    vec3 xa = vertices[sf.vertex[a]].position.xyz;
    vec3 xb = vertices[sf.vertex[b]].position.xyz;
    vec3 xc = vertices[sf.vertex[c]].position.xyz;
    precise float w10 = abs(e[a]) / (abs(e[a]) + abs(e[b]));
    precise float w01 = 1.0 - w10;
    precise vec3 p01 = w01 * xa + w10 * xb;
    precise float k01 = abs(w01 * k[a] + w10 * k[b]);
    vec4 bary01 = vec4(0.0), bary12 = vec4(0.0);
    bary01[sf.corner[a]] = w01;
    bary01[sf.corner[b]] = w10;
    precise vec3 p12;
    precise float k12;
    uint key12;
    if (to_center) {
        p12 = (xa + xb + xc) / 3.0;
        k12 = abs(k[a] + k[b] + k[c]) / 3.0;
        bary12 = vec4(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 0.0);
        key12 = NO_KEY;
    } else {
        precise float w21 = abs(e[b]) / (abs(e[b]) + abs(e[c]));
        precise float w12 = 1.0 - w21;
        p12 = w12 * xb + w21 * xc;
        k12 = abs(w12 * k[b] + w21 * k[c]);
        bary12[sf.corner[b]] = w12;
        bary12[sf.corner[c]] = w21;
        key12 = face_edges[sf.face][sf.corner[a]];
    }
    precise float sum = p01.x + p01.y + p01.z + p12.x + p12.y + p12.z;
    if (isnan(sum) || isinf(sum)) return;  // a 0/0 weight: rtsc's NaN vertex draws nothing
    k01 -= thresh;
    if (k01 < 0.0) k01 = 0.0;
    k12 -= thresh;
    if (k12 < 0.0) k12 = 0.0;
    if (k01 == 0.0 && k12 == 0.0) return;
    if (test) {
        precise vec3 normal = 0.5 * cross3(xb - xa, xc - xa);
        precise vec3 perp = cross3(normal, p01 - p12);
        if (dot3(tmax[a], perp) <= 0.0 || dot3(tmax[b], perp) >= 0.0 || dot3(tmax[c], perp) <= 0.0) return;
    }
    precise float alpha01 = 1.0, alpha12 = 1.0;
    if (fade) {
        alpha01 = k01 > 0.0 ? k01 / (k01 + thresh) : 0.0;
        alpha12 = k12 > 0.0 ? k12 / (k12 + thresh) : 0.0;
    }
    LineSegment s;
    s.p0 = vec4(p01, alpha01);
    s.p1 = vec4(p12, alpha12);
    s.bary0 = bary01.xyz;
    s.bary1 = bary12.xyz;
    s.face = sf.face;
    s.type = type;
    s.key0 = face_edges[sf.face][sf.corner[c]];
    s.key1 = key12;
    append(s);
}

int crossings(bool z01, bool z12, bool z20) { return int(z01) + int(z12) + int(z20); }

void crossed_face(StripFace sf, bool z01, bool z12, bool z20, vec3 e, vec3 k, float thresh, bool fade,
                  bool three_to_center, bool test, vec3 tmax[3], uint type) {
    if (crossings(z01, z12, z20) < 2) return;  // draws nothing
    if (!z01) {
        ridge_segment(sf, 1, e, k, thresh, false, fade, test, tmax, type);
    } else if (!z12) {
        ridge_segment(sf, 2, e, k, thresh, false, fade, test, tmax, type);
    } else if (!z20) {
        ridge_segment(sf, 0, e, k, thresh, false, fade, test, tmax, type);
    } else if (three_to_center) {
        ridge_segment(sf, 1, e, k, thresh, true, fade, test, tmax, type);
        ridge_segment(sf, 2, e, k, thresh, true, fade, test, tmax, type);
        ridge_segment(sf, 0, e, k, thresh, true, fade, test, tmax, type);
    }
}


void ridge_face(uint f, bool ridge, float thresh, bool fade) {
    StripFace sf = strip_face(f);
    vec3 k = vec3(vertices[sf.vertex[0]].pdir1_k1.w, vertices[sf.vertex[1]].pdir1_k1.w, vertices[sf.vertex[2]].pdir1_k1.w);
    if (ridge ? (k[0] <= 0.0 || k[1] <= 0.0 || k[2] <= 0.0) : (k[0] >= 0.0 || k[1] >= 0.0 || k[2] >= 0.0)) return;
    float sign = ridge ? 1.0 : -1.0;
    vec3 e;
    vec3 tmax[3], x[3];
    for (int i = 0; i < 3; ++i) {
        CurvVertex cv = vertices[sf.vertex[i]];
        e[i] = cv.dcurv.x;
        precise float se = sign * e[i];
        precise vec3 t = se * cv.pdir1_k1.xyz;
        tmax[i] = t;
        x[i] = cv.position.xyz;
    }
    bool z01 = dot3(tmax[0], tmax[1]) <= 0.0, z12 = dot3(tmax[1], tmax[2]) <= 0.0, z20 = dot3(tmax[2], tmax[0]) <= 0.0;
    if (crossings(z01, z12, z20) < 2) return;
    precise vec3 d01 = x[1] - x[0], d12 = x[2] - x[1], d20 = x[0] - x[2];
    z01 = z01 && (dot3(tmax[0], d01) >= 0.0 || dot3(tmax[1], d01) <= 0.0);
    z12 = z12 && (dot3(tmax[1], d12) >= 0.0 || dot3(tmax[2], d12) <= 0.0);
    z20 = z20 && (dot3(tmax[2], d20) >= 0.0 || dot3(tmax[0], d20) <= 0.0);
    crossed_face(sf, z01, z12, z20, e, k, thresh, fade, true, false, tmax, ridge ? LINE_RIDGE : LINE_VALLEY);
}

void principal_highlight_face(uint f, vec3 eye, float thresh, bool fade) {
    StripFace sf = strip_face(f);
    vec3 k = vec3(vertices[sf.vertex[0]].pdir1_k1.w, vertices[sf.vertex[1]].pdir1_k1.w, vertices[sf.vertex[2]].pdir1_k1.w);
    vec3 none[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
    for (int flavour = 0; flavour < 2; ++flavour) {
        bool convex = flavour == 0;
        // std::min / std::max's ternaries (a NaN first stays, as in rtsc), not GLSL's min/max.
        float lo = k[1] < k[0] ? k[1] : k[0], hi = k[0] < k[1] ? k[1] : k[0];
        lo = k[2] < lo ? k[2] : lo;
        hi = hi < k[2] ? k[2] : hi;
        if (convex ? lo < 0.0 : hi > 0.0) continue;
        vec3 reference = vertices[sf.vertex[0]].pdir1_k1.xyz;
        bool agree = true;
        vec3 along, strength;
        for (int i = 0; i < 3; ++i) {
            CurvVertex cv = vertices[sf.vertex[i]];
            vec3 d = cv.pdir1_k1.xyz;
            if (dot3(d, reference) < 0.0) d = -d;
            agree = agree && !(dot3(d, reference) <= 0.70710677);  // the float just below √½
            precise vec3 toward = eye - cv.position.xyz;
            vec3 view = unit3(toward);
            along[i] = dot3(view, d);
            float k1 = cv.pdir1_k1.w, k2 = cv.pdir2_k2.w;
            precise float diff = k1 * k1 - k2 * k2;
            precise vec3 scaled = diff * view;
            strength[i] = dot3(scaled, cv.normal.xyz);
        }
        if (!agree) continue;
        precise float a01 = along[0] * along[1], a12 = along[1] * along[2], a20 = along[2] * along[0];
        bool z01 = a01 <= 0.0, z12 = a12 <= 0.0, z20 = a20 <= 0.0;
        crossed_face(sf, z01, z12, z20, along, strength, thresh, fade, false, false, none, LINE_PRINCIPAL_HIGHLIGHT);
    }
}

void apparent_ridge_face(uint f, float thresh, bool fade) {
    StripFace sf = strip_face(f);
    // (Loaded one corner at a time: glslang 12 crashes on an array of these structs.)
    vec3 k, e, tmax[3];
    for (int i = 0; i < 3; ++i) {
        ApparentVertex q = apparent[sf.vertex[i]];
        k[i] = q.q1;
        e[i] = q.dt1q1;
        precise vec3 t1 = q.t1x * vertices[sf.vertex[i]].pdir1_k1.xyz + q.t1y * vertices[sf.vertex[i]].pdir2_k2.xyz;
        precise vec3 t = q.dt1q1 * t1;
        tmax[i] = t;
    }
    if (k[0] <= thresh && k[1] <= thresh && k[2] <= thresh) return;
    bool z01 = dot3(tmax[0], tmax[1]) <= 0.0, z12 = dot3(tmax[1], tmax[2]) <= 0.0, z20 = dot3(tmax[2], tmax[0]) <= 0.0;
    crossed_face(sf, z01, z12, z20, e, k, thresh, fade, true, true, tmax, LINE_APPARENT_RIDGE);
}

#endif
