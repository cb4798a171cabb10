#version 450
#extension GL_GOOGLE_include_directive : require
// Surface pass, depth only, for alpha-masked materials (glTF MASK): the cut-out test alone,
// so that a frame that is only tracked has the same holes in its depth as a drawn one.
#define SURFACE_FRAGMENT
#include "surface_shared.glsl"

layout(location = 2) in vec2 in_uv;

void main() { alpha_test(material_color(in_uv).a); }
