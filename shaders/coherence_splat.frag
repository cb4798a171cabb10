#version 450
// Parameterization splat, fragment stage: w = clamp(1 − d/δ, 0, 1) at distance d from the
// sample; the attachment (RG32F, additive blending) accumulates (Σ w·t, Σ w).
layout(push_constant) uniform SplatPush {
    vec2 viewport;
    float radius;
    float pad;
} pc;

layout(location = 0) in vec2 in_center;
layout(location = 1) in float in_t;

layout(location = 0) out vec2 out_sum;

void main() {
    float d = distance(gl_FragCoord.xy, in_center);
    float w = clamp(1.0 - d / pc.radius, 0.0, 1.0);
    if (w <= 0.0) discard;
    out_sum = vec2(w * in_t, w);
}
