// engine/lines/view_quantities.h — rtsc's per-vertex, per-view quantities.
//
// Input:  one vertex's position, normal, principal frame and curvatures, derivative tensor,
//         and the eye; the suggestive-contour threshold already scaled by 1/fs².
// Output: n·v, radial curvature kr (times sin²θ) and the suggestive-contour test
//         numerator/denominator, exactly as rtsc's compute_perview defines them
//         (docs/research/rtsc-lines.md §1; DeCarlo et al. 2003, §3 and 2004, §3):
//   v        = normalize(eye − p)           direction to the eye, per vertex
//   u, w     = v·e1, v·e2                   not renormalized: u² + w² = sin²θ
//   kr       = k1·u² + k2·w²
//   num1     = [u²(u·C0 + 3w·C1) + w²(3u·C2 + w·C3)]/(u² + w²) − 2·(n·v)·τ²,
//   τ        = (k2 − k1)·u·w/(u² + w²)
//   test_num = num1 − thresh·(n·v),  test_den = n·v
// so test_num/test_den > 0 ⇔ tanθ·DwKr > sug_thresh/fs² for either sign of n·v.
//
// shaders/lines_extract.comp computes the same expressions in the same order with
// `precise`; this file is compiled with -ffp-contract=off so neither side fuses
// multiply-adds and the CPU reference matches the GPU.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace lw {

struct VertexView {
    float ndotv;
    float kr;
    float test_num;  // suggestive-contour test numerator (threshold subtracted)
    float test_den;  // = ndotv
    float num1;      // the numerator before the threshold (suggestive highlights' test negates it)
};

inline VertexView vertex_view(const glm::vec3& p, const glm::vec3& n, const glm::vec3& e1, const glm::vec3& e2,
                              float k1, float k2, const glm::vec4& C, const glm::vec3& eye, float scaled_thresh) {
    glm::vec3 v = eye - p;
    const float inv_len = 1.0f / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    v = glm::vec3(v.x * inv_len, v.y * inv_len, v.z * inv_len);
    const float ndotv = n.x * v.x + n.y * v.y + n.z * v.z;
    const float u = v.x * e1.x + v.y * e1.y + v.z * e1.z;
    const float w = v.x * e2.x + v.y * e2.y + v.z * e2.z;
    const float u2 = u * u, w2 = w * w;
    const float kr = k1 * u2 + k2 * w2;
    const float csc2 = 1.0f / (u2 + w2);
    const float num0 = (u2 * (u * C.x + 3.0f * w * C.y) + w2 * (3.0f * u * C.z + w * C.w)) * csc2;
    const float tr = (k2 - k1) * u * w * csc2;
    const float num1 = num0 - 2.0f * ndotv * (tr * tr);
    return VertexView{ndotv, kr, num1 - scaled_thresh * ndotv, ndotv, num1};
}

}  // namespace lw
