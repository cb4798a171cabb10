#version 450
#extension GL_GOOGLE_include_directive : require
// Surface pass, fragment stage: flat (face normals from screen derivatives), toon (three
// bands of Lambert on the smooth normal, the usual backdrop for line drawings) or unlit.
// Toon bands are antialiased analytically: each step ramps over one pixel of the Lambert term
// (its screen derivative), since multisampling shades once per pixel and cannot smooth them.
// Faces are lit from whichever side faces the eye: open scans and single-sided parts of
// glTF models must not turn black from behind. A material's colour (glTF base colour, its
// texture; scene/material.h) is linear and is encoded to sRGB before the shading scales it,
// so that an unlit texture shows its texels as stored.
#define SURFACE_FRAGMENT
#include "surface_shared.glsl"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(location = 0) out vec4 out_color;

// 0 below the threshold t, 1 above, over one pixel's change of x around it.
float band_step(float x, float t) {
    float pixel = max(fwidth(x), 1e-5);
    return clamp((x - t) / pixel + 0.5, 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec4 color = material_color(in_uv);
    if (pc.material.x != 0) color.rgb = srgb_encode(color.rgb);
    int mode = int(pc.eye.w);
    vec3 to_eye = normalize(pc.eye.xyz - in_world);
    vec3 n;
    if (mode == SHADING_FLAT) {
        n = normalize(cross(dFdx(in_world), dFdy(in_world)));
    } else {
        n = normalize(in_normal);
    }
    if (dot(n, to_eye) < 0.0) n = -n;

    float lambert = max(dot(n, pc.light_dir.xyz), 0.0);
    float intensity;
    if (mode == SHADING_TOON) {
        intensity = 0.6 + 0.2 * band_step(lambert, 0.25) + 0.2 * band_step(lambert, 0.6);
    } else if (mode == SHADING_FLAT) {
        intensity = 0.35 + 0.65 * lambert;
    } else {
        intensity = 1.0;
    }
    alpha_test(color.a);  // last: derivatives above need the whole quad
    // Blended faces keep their alpha (the pipeline composites them over); the rest are opaque.
    out_color = vec4(color.rgb * intensity, pc.material.z != 0 ? color.a : 1.0);
}
