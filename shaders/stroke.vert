#version 450
// Stroke pass, vertex stage: triangles built on the CPU in pixels (engine/stroke/stroke_geometry.cpp).
layout(push_constant) uniform StrokePush {
    vec2 viewport;
    float levels;  // SLAM level count
    float premultiplied;  // 1: premultiplied colour (a coverage layer's pipeline)
} pc;

layout(location = 0) in vec2 in_pixel;
layout(location = 1) in vec3 in_tex;
layout(location = 2) in vec4 in_color;
layout(location = 3) in vec4 in_edge;

layout(location = 0) out vec3 out_tex;
layout(location = 1) out vec4 out_color;
layout(location = 2) out vec4 out_edge;

void main() {
    out_tex = in_tex;
    out_color = in_color;
    out_edge = in_edge;
    gl_Position = vec4(in_pixel / pc.viewport * 2.0 - 1.0, 0.0, 1.0);
}
