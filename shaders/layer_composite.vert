#version 450
// Layer composite, vertex stage: one triangle covering the whole target (vertices 0, 1, 2
// at (−1, −1), (3, −1), (−1, 3) in clip space), made from gl_VertexIndex without a buffer.
void main() {
    const vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
