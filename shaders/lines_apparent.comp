#version 450
#extension GL_GOOGLE_include_directive : require
// Feature-line extraction, apparent ridges' second vertex pass (between lines_vertex.comp,
// which wrote every vertex's q1 and t1, and lines_extract.comp): D_t1 q1 per vertex, the
// derivative of q1 along t1 from the first two faces around the vertex (in face order)
// where the line along t1 leaves through the opposite edge — rtsc's compute_Dt1q1, the
// same operations in the same order as engine/lines/ridge_lines.cpp (apparent_derivative,
// which finds the crossed faces in chunks), with `precise`.
#include "lines_shared.glsl"
#include "lines_ridges_math.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Vertices { CurvVertex vertices[]; };
layout(std430, binding = 1) readonly buffer Views { VertexView views[]; };
layout(std430, binding = 2) buffer Apparent { ApparentVertex apparent[]; };  // writes only dt1q1
layout(std430, binding = 3) readonly buffer VertexFaceOffsets { uint vertex_face_offsets[]; };
layout(std430, binding = 4) readonly buffer VertexFaces { uint vertex_faces[]; };
layout(std430, binding = 5) readonly buffer Faces { uvec4 faces[]; };  // corners, w: feature-edge mask

LINES_PUSH_CONSTANTS

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    CurvVertex cv = vertices[i];
    vec3 v0 = cv.position.xyz;
    float q1 = apparent[i].q1;
    precise vec3 t1 = apparent[i].t1x * cv.pdir1_k1.xyz + apparent[i].t1y * cv.pdir2_k2.xyz;
    vec3 t2 = cross3(cv.normal.xyz, t1);
    float v0_t2 = dot3(v0, t2);
    float ndotv = views[i].ndotv;
    precise float derivative = 0.0;
    int estimates = 0;
    for (uint j = vertex_face_offsets[i]; j < vertex_face_offsets[i + 1u]; ++j) {
        uvec3 corner = faces[vertex_faces[j]].xyz;
        int at = corner.x == i ? 0 : corner.y == i ? 1 : 2;
        uint i1 = corner[(at + 1) % 3], i2 = corner[(at + 2) % 3];
        vec3 x1 = vertices[i1].position.xyz, x2 = vertices[i2].position.xyz;
        float v1_t2 = dot3(x1, t2), v2_t2 = dot3(x2, t2);
        precise float w1 = (v2_t2 - v0_t2) / (v2_t2 - v1_t2);
        if (w1 < 0.0 || w1 >= 1.0) continue;
        precise float w2 = 1.0 - w1;
        precise vec3 p = w1 * x1 + w2 * x2;
        precise float q1_p = w1 * apparent[i1].q1 + w2 * apparent[i2].q1;
        precise float distance = dot3(p - v0, t1);
        distance *= abs(ndotv);
        derivative += (q1_p - q1) / distance;
        if (++estimates == 2) {
            derivative *= 0.5;
            break;
        }
    }
    apparent[i].dt1q1 = derivative;
}
