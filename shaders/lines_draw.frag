#version 450
// Line drawing pass, fragment stage: flat colour with the path's fade alpha; hidden lines
// drawn dashed skip every other half period of arc length.
layout(push_constant) uniform LineDrawPush {
    vec2 viewport;
    float dash_period;
    float pad;
} pc;

layout(location = 0) in vec4 in_color;
layout(location = 1) in vec2 in_arc;

layout(location = 0) out vec4 out_color;

void main() {
    if (in_arc.y > 0.5 && fract(in_arc.x / pc.dash_period) > 0.5) discard;
    out_color = in_color;
}
