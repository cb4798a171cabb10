#version 450
// Line drawing pass, vertex stage: quads expanded on the CPU in pixel coordinates
// (engine/render/line_pass.cpp), mapped to clip space here.
layout(push_constant) uniform LineDrawPush {
    vec2 viewport;  // width, height in pixels
    float dash_period;  // pixels; dashed hidden lines
    float pad;
} pc;

layout(location = 0) in vec2 in_pixel;
layout(location = 1) in vec4 in_color;  // rgb + alpha
layout(location = 2) in vec2 in_arc;    // x: arc length (px), y: 1 = dashed

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec2 out_arc;

void main() {
    out_color = in_color;
    out_arc = in_arc;
    gl_Position = vec4(in_pixel / pc.viewport * 2.0 - 1.0, 0.0, 1.0);
}
