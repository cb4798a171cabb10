#version 450
// Ribbon drawing, vertex stage: each piece is two triangles in output pixels carrying the
// exemplar coordinates of their corners (a similarity of the piece, engine/ribbon/ribbon.h,
// so linear interpolation gives every pixel's exact exemplar point). Shared by the
// avoidance-map pass (ribbon_avoid.frag) and the pattern pass (ribbon_draw.frag).
layout(push_constant) uniform RibbonDrawPush {
    vec2 viewport;        // canvas width, height in pixels
    ivec2 exemplar_size;  // W, H
    int samples;          // C
    int stitch;           // 1: apply the stitching deformation
    int pad0, pad1;
} pc;

layout(location = 0) in vec2 in_pixel;
layout(location = 1) in vec2 in_texcoord;
layout(location = 2) in uint in_piece;

layout(location = 0) out vec2 out_texcoord;
layout(location = 1) flat out uint out_piece;

void main() {
    out_texcoord = in_texcoord;
    out_piece = in_piece;
    gl_Position = vec4(in_pixel / pc.viewport * 2.0 - 1.0, 0.0, 1.0);
}
