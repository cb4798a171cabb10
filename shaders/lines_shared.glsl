// shaders/lines_shared.glsl — buffers of the line extraction pass, mirrored in C++ by
// engine/lines/line_types.h (LineSegment) and engine/lines/extract_gpu.cpp (the rest).
#ifndef LINES_SHARED_GLSL
#define LINES_SHARED_GLSL

#define LINE_SILHOUETTE 0u
#define LINE_SUGGESTIVE 1u
#define LINE_CREASE 2u
#define LINE_BORDER 3u
#define NO_KEY 0xffffffffu

// Bits of LinesPush.flags
#define FLAG_SILHOUETTES 1u
#define FLAG_SUGGESTIVE 2u
#define FLAG_CREASES 4u
#define FLAG_BORDERS 8u

struct CurvVertex {
    vec4 position;   // xyz
    vec4 normal;     // xyz
    vec4 pdir1_k1;   // xyz: e1, w: k1
    vec4 pdir2_k2;   // xyz: e2, w: k2
    vec4 dcurv;      // C0..C3
};

// A vertex's view quantities (lines_vertex.comp), as engine/lines/view_quantities.h.
struct VertexView {
    float ndotv;
    float kr;
    float test_num;  // the suggestive test's numerator, threshold subtracted
    uint signs;      // lines_signs.glsl
};

struct LineSegment {
    vec4 p0;     // xyz world, w alpha
    vec4 p1;
    vec4 bary0;
    vec4 bary1;
    uint face;
    uint type;
    uint key0;
    uint key1;
};

#endif
