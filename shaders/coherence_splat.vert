#version 450
// Parameterization splat (Bénard et al. 2010, §4.1), vertex stage: one instance per sample,
// a square of half side δ around it (the fragment stage keeps the disc of radius δ).
layout(push_constant) uniform SplatPush {
    vec2 viewport;
    float radius;  // δ, pixels
    float pad;
} pc;

layout(location = 0) in vec2 in_center;  // pixels
layout(location = 1) in float in_t;      // T(s) of the sample

layout(location = 0) out vec2 out_center;
layout(location = 1) out float out_t;

const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(-1, 1), vec2(1, -1), vec2(1, 1));

void main() {
    vec2 pixel = in_center + corners[gl_VertexIndex] * (pc.radius + 1.0);
    out_center = in_center;
    out_t = in_t;
    gl_Position = vec4(pixel / pc.viewport * 2.0 - 1.0, 0.0, 1.0);
}
