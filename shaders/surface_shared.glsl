// shaders/surface_shared.glsl — push constants and material colour of the surface pass,
// shared with C++ (engine/render/surface_pass.cpp mirrors this layout in `SurfacePush`).
#ifndef SURFACE_SHARED_GLSL
#define SURFACE_SHARED_GLSL

#define SHADING_FLAT 0
#define SHADING_TOON 1
#define SHADING_UNLIT 2

layout(push_constant) uniform SurfacePush {
    mat4 view_proj;
    vec4 eye;          // xyz: eye position (world); w: shading mode
    vec4 light_dir;    // xyz: unit direction towards the light (world); w: alpha cutoff (< 0: none)
    vec4 base_color;   // the scene colour (rgb, as written; a = 1) or a material's factor (linear rgba)
    ivec4 material;    // x: 1 = base_color is a material's (linear: encoded to sRGB on output)
                       // y: 1 = modulated by base_texture; z: 1 = blended (its alpha kept)
} pc;

#ifdef SURFACE_FRAGMENT
// The material's base colour texture (sRGB format: sampled linear); a white texel when none.
layout(set = 0, binding = 0) uniform sampler2D base_texture;

// Base colour times texture, linear (glTF 2.0 §3.9.2), before any cut-out test.
vec4 material_color(vec2 uv) {
    vec4 c = pc.base_color;
    if (pc.material.y != 0) c *= texture(base_texture, uv);
    return c;
}

// glTF 2.0 §3.9.4 MASK: below the cutoff there is no surface (no colour, no depth).
void alpha_test(float alpha) {
    if (pc.light_dir.w >= 0.0 && alpha < pc.light_dir.w) discard;
}
#endif

#endif
