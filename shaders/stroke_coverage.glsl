// shaders/stroke_coverage.glsl — a pixel's coverage by a stroke, from the coverage coordinates
// its vertices carry (engine/stroke/stroke_geometry.h, `StrokeVertex::edge`; `square_cdf` and
// `stroke_coverage` there are the same expressions, the CPU reference the tests compare with):
// the box-filter share of the pixel inside the stroke's outline, across the stroke (or
// radially round ends and joins) and before square and butt ends.
#ifndef STROKE_COVERAGE_GLSL
#define STROKE_COVERAGE_GLSL

// P(u·n ≤ t) for u uniform on the pixel's square [−½, ½]² and n a unit vector.
float square_cdf(float t, vec2 n) {
    float a = max(abs(n.x), abs(n.y)), b = min(abs(n.x), abs(n.y));
    float flat_half = 0.5 * (a - b), reach = 0.5 * (a + b), at = abs(t);
    float upper = at <= flat_half ? 0.5 + at / a
                  : at < reach    ? 1.0 - (reach - at) * (reach - at) / (2.0 * a * b)
                                  : 1.0;
    return t >= 0.0 ? upper : 1.0 - upper;
}

// `dxy_dx`, `dxy_dy`, `dz`: screen derivatives of edge.xy and edge.z (taken before any discard).
float stroke_coverage(vec4 edge, vec2 dxy_dx, vec2 dxy_dy, vec2 dz) {
    float r = length(edge.xy), half_width = max(edge.w, 0.0);
    vec2 grad = r > 1e-4 ? vec2(dot(edge.xy, dxy_dx), dot(edge.xy, dxy_dy)) / r : vec2(dxy_dx.x, dxy_dy.x);
    float g = length(grad);
    vec2 n = g > 1e-6 ? grad / g : vec2(1.0, 0.0);
    if (!(g > 1e-6)) g = 1.0;
    float gz = length(dz);
    float across = clamp(square_cdf((half_width - r) / g, n) - square_cdf((-half_width - r) / g, n), 0.0, 1.0);
    float before_end = gz > 1e-6 ? square_cdf((half_width - edge.z) / gz, dz / gz) : (edge.z <= half_width ? 1.0 : 0.0);
    return across * before_end;
}

// The same for the fragment being shaded.
float fragment_coverage(vec4 edge) {
    return stroke_coverage(edge, dFdx(edge.xy), dFdy(edge.xy), vec2(dFdx(edge.z), dFdy(edge.z)));
}

#endif
