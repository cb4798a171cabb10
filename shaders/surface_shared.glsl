// shaders/surface_shared.glsl — push constants of the surface pass, shared with C++
// (engine/render/surface_pass.cpp mirrors this layout in `SurfacePush`).
#ifndef SURFACE_SHARED_GLSL
#define SURFACE_SHARED_GLSL

#define SHADING_FLAT 0
#define SHADING_TOON 1
#define SHADING_UNLIT 2

layout(push_constant) uniform SurfacePush {
    mat4 view_proj;
    vec4 eye;          // xyz: eye position (world)
    vec4 light_dir;    // xyz: unit direction towards the light (world)
    vec4 base_color;   // rgb: surface colour; w: shading mode
} pc;

#endif
