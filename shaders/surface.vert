#version 450
#extension GL_GOOGLE_include_directive : require
// Surface pass, vertex stage: the mesh is already in world space (scene/triangle_mesh.h),
// so only the view-projection is applied.
#include "surface_shared.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_uv;

void main() {
    out_world = in_position;
    out_normal = in_normal;
    out_uv = in_uv;
    gl_Position = pc.view_proj * vec4(in_position, 1.0);
}
