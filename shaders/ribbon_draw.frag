#version 450
#extension GL_GOOGLE_include_directive : require
// Ribbon drawing, fragment stage: copies the exemplar under the pixel's exemplar point — the
// pieces copy E without distortion (§1.2), resampled bilinearly (premultiplied alpha, so that
// the transparent black around the pattern leaves no dark fringe) because pieces are rotated.
// Forbidden pixels take the nearest texel instead: the DP validated exactly that texel as
// transparent there (§3.1), and a bilinear sample could pull in an opaque neighbour. With stitching
// (§3.2, "Propagation") the point first moves by x/(x + r)·Δ·w, Δ = T[i] − i:
//  - d interpolates the piece's top and bottom edge directions by p's position down the left
//    edge l (vertical where the piece is copied along its tangent, engine/ribbon/ribbon.h);
//  - p is projected along d onto the right edge (w), giving the edge position i (in samples);
//  - x and r are p's distances along d to the left and right edges, so the deformation is
//    full on the right edge and vanishes on the left edge.
// On forbidden pixels the point is left as the DP validated it (no opaque texel there).
// The C++ reference of this stage: engine/ribbon/draw_reference.cpp (the same expressions).
#include "ribbon_shared.glsl"

layout(push_constant) uniform RibbonDrawPush {
    vec2 viewport;
    ivec2 exemplar_size;
    int samples;
    int stitch;
    int pad0, pad1;
} pc;

struct PieceDraw {
    vec4 corners;  // xy: top-left corner A in E (piece placed), zw: top-right corner
    vec4 edges;    // xy: top edge (A → top right), zw: bottom edge (bottom left → bottom right)
    vec4 right;    // xy: right edge w (top right → bottom right)
    vec4 left;     // xy: left edge l (A → bottom left)
    ivec4 remap;   // x: offset of T in Remaps (−1: none), y: C
};

layout(std430, binding = 0) readonly buffer Exemplar { uint texels[]; };
layout(std430, binding = 1) readonly buffer Pieces { PieceDraw pieces[]; };
layout(std430, binding = 2) readonly buffer Remaps { int remaps[]; };
layout(std430, binding = 3) readonly buffer Forbidden { uint forbidden[]; };  // one per canvas pixel

layout(location = 0) in vec2 in_texcoord;
layout(location = 1) flat in uint in_piece;

layout(location = 0) out vec4 out_color;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

vec2 deformation(vec2 p, PieceDraw pd) {
    vec2 A = pd.corners.xy, D = pd.corners.zw, w = pd.right.xy, l = pd.left.xy;
    int C = pd.remap.y;
    vec2 d = mix(pd.edges.xy, pd.edges.zw, clamp(dot(p - A, l) / dot(l, l), 0.0, 1.0));
    float across = cross2(d, l);  // d's component across the left edge, times |l|
    if (abs(across) < 1e-4 * length(l)) return vec2(0.0);
    // p + a·d = D + m·w
    float det = w.x * d.y - d.x * w.y;
    if (abs(det) < 1e-6) return vec2(0.0);
    vec2 q = D - p;
    float a = (w.x * q.y - q.x * w.y) / det;
    float m = (d.x * q.y - q.x * d.y) / det;
    float x = cross2(p - A, l) / across;  // p − x·d lies on the left edge
    if (x + a <= 1e-6) return vec2(0.0);
    float ratio = clamp(x / (x + a), 0.0, 1.0);
    float i = clamp(m * float(C) - 0.5, 0.0, float(C - 1));
    int k0 = int(floor(i)), k1 = min(k0 + 1, C - 1);
    float delta = mix(float(remaps[pd.remap.x + k0] - k0), float(remaps[pd.remap.x + k1] - k1), i - float(k0));
    return ratio * delta * (w / float(C));
}

vec4 fetch(ivec2 t) {
    if (t.x < 0 || t.y < 0 || t.x >= pc.exemplar_size.x || t.y >= pc.exemplar_size.y) return vec4(0.0);
    return unpackUnorm4x8(texels[t.y * pc.exemplar_size.x + t.x]);
}

vec4 premultiplied(vec4 c) { return vec4(c.rgb * c.a, c.a); }

void main() {
    PieceDraw pd = pieces[in_piece];
    vec2 e = in_texcoord;
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    bool forbidden_pixel = forbidden[pixel.y * int(pc.viewport.x) + pixel.x] != 0u;
    if (pc.stitch != 0 && pd.remap.x >= 0 && !forbidden_pixel) e += deformation(e, pd);
    // Sampled at e + (½, 0): engine/ribbon/ribbon.h (a piece shows columns x+1 … x+w).
    vec2 q = e + vec2(0.5, 0.0);
    if (forbidden_pixel) {
        out_color = fetch(ivec2(floor(q)));
        return;
    }
    vec2 g = q - 0.5;
    ivec2 i0 = ivec2(floor(g));
    vec2 f = g - vec2(i0);
    vec4 c = mix(mix(premultiplied(fetch(i0)), premultiplied(fetch(i0 + ivec2(1, 0))), f.x),
                 mix(premultiplied(fetch(i0 + ivec2(0, 1))), premultiplied(fetch(i0 + ivec2(1, 1))), f.x), f.y);
    out_color = c.a > 0.0 ? vec4(c.rgb / c.a, c.a) : vec4(0.0);
}
