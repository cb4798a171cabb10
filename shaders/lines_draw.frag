#version 450
#extension GL_GOOGLE_include_directive : require
// Line drawing pass, fragment stage: flat colour with the path's fade alpha, times the
// pixel's coverage (antialiasing, stroke_coverage.glsl); hidden lines drawn dashed skip
// every other half period of arc length. Into a coverage layer (a translucent set drawn
// once, engine/gpu/coverage_layer.h) the colour is premultiplied.
#include "stroke_coverage.glsl"

layout(push_constant) uniform LineDrawPush {
    vec2 viewport;
    float dash_period;
    float premultiplied;  // 1: premultiplied colour (a coverage layer's pipeline)
} pc;

layout(location = 0) in vec4 in_color;
layout(location = 1) in vec2 in_arc;
layout(location = 2) in vec4 in_edge;

layout(location = 0) out vec4 out_color;

void main() {
    float coverage = fragment_coverage(in_edge);  // derivatives: before the discard
    if (in_arc.y > 0.5 && fract(in_arc.x / pc.dash_period) > 0.5) discard;
    const float alpha = in_color.a * coverage;
    out_color = pc.premultiplied > 0.5 ? vec4(in_color.rgb * alpha, alpha) : vec4(in_color.rgb, alpha);
}
