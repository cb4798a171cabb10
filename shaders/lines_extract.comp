#version 450
#extension GL_GOOGLE_include_directive : require
// Feature-line extraction, per face (the second of two passes; lines_vertex.comp wrote each
// vertex's view quantities and sign byte): the corners' bytes decide whether a line can
// cross the face (most faces: none), then that face's contour, suggestive-contour, crease
// and border segments, and those of rtsc's other lines that the flags turn on
// (lines_ridges.glsl), are appended with an atomic counter. Mirrors
// engine/lines/extract_reference.cpp line by line, with `precise` so that no multiply-add
// is fused and results match the CPU reference (rtsc's rules: docs/research/rtsc-lines.md
// §1–2).
#include "lines_shared.glsl"
#include "lines_signs.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Vertices { CurvVertex vertices[]; };
layout(std430, binding = 1) readonly buffer Faces { uvec4 faces[]; };        // corners, w: feature-edge mask
layout(std430, binding = 2) readonly buffer FaceEdges { uvec4 face_edges[]; };  // edge opposite each corner, w: strip corners
layout(std430, binding = 3) buffer Output {
    uint count;      // segments wanted (may exceed capacity: the host then retries larger)
    uint capacity;
    uint pad0, pad1;
    LineSegment segments[];
} out_buf;
layout(std430, binding = 4) readonly buffer Views { VertexView views[]; };
// Read only for the optional lines that need them (flags).
layout(std430, binding = 5) readonly buffer HighlightNum { float highlight_num[]; };
layout(std430, binding = 6) readonly buffer Apparent { ApparentVertex apparent[]; };
layout(std430, binding = 7) readonly buffer FaceNeighbors { ivec4 face_neighbors[]; };  // across each edge, -1: none

LINES_PUSH_CONSTANTS

void append(LineSegment s) {
    s.other_face = NO_FACE;
    s.pad = 0u;
    uint index = atomicAdd(out_buf.count, 1u);
    if (index < out_buf.capacity) out_buf.segments[index] = s;
}

#include "lines_ridges.glsl"

// Whether face g faces the eye, as extract_reference.cpp's facing_pass.
bool front_facing(uint g) {
    uvec3 c = faces[g].xyz;
    vec3 x0 = vertices[c.x].position.xyz, x1 = vertices[c.y].position.xyz, x2 = vertices[c.z].position.xyz;
    precise vec3 a = x1 - x0, b = x2 - x0, v = pc.eye.xyz - x0;
    precise vec3 n = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
    precise float d = n.x * v.x + n.y * v.y + n.z * v.z;
    return d > 0.0;
}

bool mesh_contours_at(uint f) {
    return (pc.flags & FLAG_MESH_CONTOURS) != 0u ||
           ((pc.flags & FLAG_AUTO_CONTOURS) != 0u && (faces[f].w & FACE_COARSE) != 0u);
}

// The key of a mesh contour's end at corner `corner` of front face `face`: the fan of
// front faces round the vertex, named by its smallest face (extract_reference.h,
// mesh_contour_key).
uint mesh_contour_key(uint face, int corner) {
    uint v = faces[face][corner];
    uint smallest = face;
    for (int way = 1; way <= 2; ++way) {
        uint at = face;
        int c = corner;
        for (int step = 0; step < 64; ++step) {
            int next = face_neighbors[at][(c + way) % 3];
            if (next < 0 || uint(next) == face || !front_facing(uint(next))) break;
            at = uint(next);
            uvec3 g = faces[at].xyz;
            c = g.x == v ? 0 : g.y == v ? 1 : 2;
            smallest = min(smallest, at);
        }
    }
    uvec3 g = faces[smallest].xyz;
    uint c = g.x == v ? 0u : g.y == v ? 1u : 2u;
    return pc.edge_count + 3u * smallest + c;
}

// The edge opposite corner i of face f as a segment with the given end keys.
void edge_segment(uint f, uvec3 corners, int i, uint type, uint key0, uint key1) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    LineSegment s;
    s.p0 = vec4(vertices[corners[j]].position.xyz, 1.0);
    s.p1 = vec4(vertices[corners[k]].position.xyz, 1.0);
    s.bary0 = vec3(0.0);
    s.bary1 = vec3(0.0);
    s.bary0[j] = 1.0;
    s.bary1[k] = 1.0;
    s.face = f;
    s.type = type;
    s.key0 = key0;
    s.key1 = key1;
    append(s);
}

// Creases, borders and boundaries are keyed by their vertices.
void feature_edge(uint f, uvec3 corners, int i, uint type) {
    edge_segment(f, corners, i, type, corners[(i + 1) % 3], corners[(i + 2) % 3]);
}

// A mesh contour edge: the edge opposite corner i of front face f, keyed by its fans.
void mesh_contour_edge(uint f, uvec3 corners, int i) {
    edge_segment(f, corners, i, LINE_SILHOUETTE, mesh_contour_key(f, (i + 1) % 3), mesh_contour_key(f, (i + 2) % 3));
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
            if (e == 0) { s.p0 = vec4(x, alpha); s.bary0 = bary; }
            else        { s.p1 = vec4(x, alpha); s.bary1 = bary; }
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
    if (f >= pc.count) return;
    uvec4 face = faces[f];
    uvec3 corners = face.xyz;
    VertexView v0 = views[corners[0]];
    VertexView v1 = views[corners[1]];
    VertexView v2 = views[corners[2]];
    uint any_sign = v0.signs | v1.signs | v2.signs;
    uint all_signs = v0.signs & v1.signs & v2.signs;

    if ((pc.flags & FLAG_SUGGESTIVE) != 0u && (any_sign & SUGGESTIVE_ANY) == SUGGESTIVE_ANY &&
        (all_signs & SUGGESTIVE_REJECTED) == 0u)
        face_isoline(f, corners, vec3(v0.kr, v1.kr, v2.kr), vec3(v0.test_num, v1.test_num, v2.test_num),
                     vec3(v0.ndotv, v1.ndotv, v2.ndotv), true, pc.fade, LINE_SUGGESTIVE);
    bool mesh_contours = (pc.flags & FLAG_SILHOUETTES) != 0u && mesh_contours_at(f);
    if (mesh_contours && front_facing(f))
        for (int i = 0; i < 3; ++i) {
            int g = face_neighbors[f][i];
            if (g >= 0 && !front_facing(uint(g))) mesh_contour_edge(f, corners, i);
        }
    if ((pc.flags & FLAG_SILHOUETTES) != 0u && !mesh_contours && (any_sign & CONTOUR_ANY) == CONTOUR_ANY)
        face_isoline(f, corners, vec3(v0.ndotv, v1.ndotv, v2.ndotv), vec3(v0.kr, v1.kr, v2.kr), vec3(1.0), false, 0.0,
                     LINE_SILHOUETTE);
    uint mask = face.w;
    for (int i = 0; i < 3; ++i) {
        bool crease = (pc.flags & FLAG_CREASES) != 0u && (mask & (1u << i)) != 0u;
        bool border = (pc.flags & FLAG_BORDERS) != 0u && (mask & (8u << i)) != 0u;
        bool boundary = (pc.flags & FLAG_MATERIAL_BOUNDARIES) != 0u && (mask & (64u << i)) != 0u;
        if (crease || border) feature_edge(f, corners, i, border ? LINE_BORDER : LINE_CREASE);
        if (boundary) feature_edge(f, corners, i, LINE_MATERIAL_BOUNDARY);  // also: either nature may be selected
    }

    // rtsc's other lines (off by default).
    if ((pc.flags & FLAG_SUGGESTIVE_HIGHLIGHTS) != 0u && (any_sign & SUGGESTIVE_ANY) == SUGGESTIVE_ANY) {
        vec3 num = vec3(highlight_num[corners[0]], highlight_num[corners[1]], highlight_num[corners[2]]);
        vec3 den = vec3(v0.ndotv, v1.ndotv, v2.ndotv);
        bool all_below = true, all_above = true;
        for (int i = 0; i < 3; ++i) {
            all_below = all_below && num[i] <= 0.0 && den[i] >= 0.0;
            all_above = all_above && num[i] >= 0.0 && den[i] <= 0.0;
        }
        if (!all_below && !all_above)
            face_isoline(f, corners, vec3(v0.kr, v1.kr, v2.kr), num, den, true, pc.fade, LINE_SUGGESTIVE_HIGHLIGHT);
    }
    bool fade = (pc.flags & FLAG_FADE) != 0u;
    bool back_facing = v0.ndotv <= 0.0 && v1.ndotv <= 0.0 && v2.ndotv <= 0.0;
    if ((pc.flags & FLAG_RIDGES) != 0u && !back_facing) ridge_face(f, true, pc.thresholds.x, fade);
    if ((pc.flags & FLAG_VALLEYS) != 0u && !back_facing) ridge_face(f, false, pc.thresholds.x, fade);
    if ((pc.flags & FLAG_APPARENT_RIDGES) != 0u) apparent_ridge_face(f, pc.thresholds.y, fade);
    if ((pc.flags & FLAG_PRINCIPAL_HIGHLIGHTS) != 0u && !back_facing)
        principal_highlight_face(f, pc.eye.xyz, pc.thresholds.w, fade);
}
