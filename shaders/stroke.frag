#version 450
#extension GL_GOOGLE_include_directive : require
// Stroke pass, fragment stage: ink from the SLAM, a 3D texture with trilinear filtering
// (Bénard et al. 2010, §4.3), times the pixel's coverage (antialiasing, stroke_coverage.glsl).
// u repeats along the stroke, v spans its width (clamped in the coverage margin outside it), and the level coordinate w = 2l − 1 ∈ [0, 1] maps onto the texel centres of the level
// stack.
#include "stroke_coverage.glsl"

layout(push_constant) uniform StrokePush {
    vec2 viewport;
    float levels;
    float premultiplied;  // 1: premultiplied colour (a coverage layer's pipeline)
} pc;

layout(binding = 0) uniform sampler3D slam;

layout(location = 0) in vec3 in_tex;
layout(location = 1) in vec4 in_color;
layout(location = 2) in vec4 in_edge;

layout(location = 0) out vec4 out_color;

void main() {
    float level = (in_tex.z * (pc.levels - 1.0) + 0.5) / pc.levels;
    float ink = texture(slam, vec3(in_tex.x, clamp(in_tex.y, 0.0, 1.0), level)).r;
    const float alpha = in_color.a * ink * fragment_coverage(in_edge);
    // Into a coverage layer (a translucent set drawn once, engine/gpu/coverage_layer.h): premultiplied.
    out_color = pc.premultiplied > 0.5 ? vec4(in_color.rgb * alpha, alpha) : vec4(in_color.rgb, alpha);
}
