#version 450
// Line drawing pass, vertex stage: the stroke builder's triangles in pixel coordinates
// (engine/render/line_pass.cpp), mapped to clip space here.
layout(push_constant) uniform LineDrawPush {
    vec2 viewport;  // width, height in pixels
    float dash_period;  // pixels; dashed hidden lines
    float premultiplied;  // 1: premultiplied colour (a coverage layer's pipeline)
} pc;

layout(location = 0) in vec2 in_pixel;
layout(location = 1) in vec3 in_tex;    // x: arc length (px), z: 1 = dashed
layout(location = 2) in vec4 in_color;  // rgb + alpha
layout(location = 3) in vec4 in_edge;   // coverage coordinates

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec2 out_arc;
layout(location = 2) out vec4 out_edge;

void main() {
    out_color = in_color;
    out_arc = in_tex.xz;
    out_edge = in_edge;
    gl_Position = vec4(in_pixel / pc.viewport * 2.0 - 1.0, 0.0, 1.0);
}
