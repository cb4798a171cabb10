// shaders/lines_shared.glsl — buffers of the line extraction pass, mirrored in C++ by
// engine/lines/line_types.h (LineSegment) and engine/lines/extract_gpu.cpp (the rest).
#ifndef LINES_SHARED_GLSL
#define LINES_SHARED_GLSL

#define NO_FACE 0xffffffffu
#define LINE_SILHOUETTE 0u
#define LINE_SUGGESTIVE 1u
#define LINE_CREASE 2u
#define LINE_BORDER 3u
#define LINE_RIDGE 4u
#define LINE_VALLEY 5u
#define LINE_APPARENT_RIDGE 6u
#define LINE_SUGGESTIVE_HIGHLIGHT 7u
#define LINE_PRINCIPAL_HIGHLIGHT 8u
#define LINE_MATERIAL_BOUNDARY 9u
#define NO_KEY 0xffffffffu

// Bits of LinesPush.flags: bit t draws LineType t; FLAG_FADE fades rtsc's other lines.
#define FLAG_SILHOUETTES 1u
#define FLAG_SUGGESTIVE 2u
#define FLAG_CREASES 4u
#define FLAG_BORDERS 8u
#define FLAG_RIDGES 16u
#define FLAG_VALLEYS 32u
#define FLAG_APPARENT_RIDGES 64u
#define FLAG_SUGGESTIVE_HIGHLIGHTS 128u
#define FLAG_PRINCIPAL_HIGHLIGHTS 256u
#define FLAG_MATERIAL_BOUNDARIES 512u
#define FLAG_FADE 1024u
#define FLAG_MESH_CONTOURS 2048u  // silhouettes from mesh edges on every face ...
#define FLAG_AUTO_CONTOURS 4096u  // ... or on faces with FACE_COARSE
#define FACE_COARSE 512u          // in a face's feature mask (faces[f].w): its model is coarse

// The push constants of every line extraction pass (LinesPush in extract_gpu.cpp).
#define LINES_PUSH_CONSTANTS                                                           \
    layout(push_constant) uniform LinesPush {                                         \
        vec4 eye;         /* xyz: eye (world), w: sug_thresh / fs² */                  \
        vec4 thresholds;  /* rv_thresh / fs, ar_thresh / fs², sh_thresh / fs², ph_thresh / fs² */ \
        float fade;       /* 0.03 / fs², or 0 without fading */                        \
        uint flags;                                                                    \
        uint count;       /* vertices or faces */                                      \
        uint edge_count;  /* lines_extract.comp: mesh contours key vertices past it */ \
    } pc;

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

// Apparent ridges' view-dependent curvature per vertex (engine/lines/ridge_lines.h).
struct ApparentVertex {
    float q1;
    float t1x, t1y;
    float dt1q1;
};

struct LineSegment {
    vec4 p0;     // xyz world, w alpha
    vec4 p1;
    vec3 bary0;
    uint other_face;  // intersection lines (CPU only): the other surface's face; else NO_FACE
    vec3 bary1;
    uint pad;
    uint face;
    uint type;
    uint key0;
    uint key1;
};

#endif
