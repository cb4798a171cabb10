// shaders/lines_ridges_math.glsl — dot and cross products and trimesh2's normalize written
// out with `precise`, so that they round as engine/lines/ridge_lines.cpp's (built-in dot,
// cross and normalize may fuse or reorder).
#ifndef LINES_RIDGES_MATH_GLSL
#define LINES_RIDGES_MATH_GLSL

float dot3(vec3 a, vec3 b) {
    precise float d = a.x * b.x + a.y * b.y + a.z * b.z;
    return d;
}

vec3 cross3(vec3 a, vec3 b) {
    precise vec3 c = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
    return c;
}

// trimesh2's normalize: times 1/length; (0, 0, 1) for a zero or NaN length.
vec3 unit3(vec3 v) {
    precise float len = sqrt(dot3(v, v));
    if (!(len > 0.0)) return vec3(0.0, 0.0, 1.0);
    precise float inv = 1.0 / len;
    precise vec3 u = vec3(v.x * inv, v.y * inv, v.z * inv);
    return u;
}

#endif
