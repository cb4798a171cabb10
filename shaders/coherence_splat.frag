#version 450
// Parameterization splat, fragment stage: w = clamp(1 − d/δ, 0, 1) at distance d from the
// sample; the attachment (RGBA32F, additive blending) accumulates (Σ w·t, Σ w) as §4.1 says,
// and Σ w·(c − pixel), the weighted centre of the sprites that reached the pixel: a vote then knows
// where along the path its average Σwt/Σw was taken (coherence.cpp, gather_votes).
layout(push_constant) uniform SplatPush {
    vec2 viewport;
    float radius;
    float pad;
} pc;

layout(location = 0) in vec2 in_center;
layout(location = 1) in float in_t;

layout(location = 0) out vec4 out_sum;

void main() {
    float d = distance(gl_FragCoord.xy, in_center);
    float w = clamp(1.0 - d / pc.radius, 0.0, 1.0);
    if (w <= 0.0) discard;
    out_sum = vec4(w * in_t, w, w * (in_center - gl_FragCoord.xy));
}
