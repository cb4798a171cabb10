// engine/pattern/element.h — pattern elements and their oriented boxes (Barla et al. 2006, §2.1).
//
// Input:  strokes (vector/stroke.h) and the indices of the strokes that make one element.
// Output: `Element`: the oriented bounding box of the element's points — centre c, unit
//         principal axis A (B ⟂ A), half extents along A and B — and its mean colour.
//
// §2.1: "we first fit a gaussian distribution to the points to compute the two principal
// elongation directions given by the eigenvectors A and B of the points' covariance matrix.
// Each point is then projected onto each axis to compute the size and center c of the box."
// The points are the stroke skeletons (the gesture) or their contours (the gesture with its
// width: each skeleton point offset by ±w/2 along the normal), as the user chooses. Points
// are weighted by the polyline length around them so that densely sampled curves (flattened
// Béziers) do not pull the axes.
//
// The box distances of §2.2 and §3.1 treat boxes as filled rectangles: the directed Hausdorff
// distance from box 1 to box 2 is then the largest distance from a corner of box 1 to box 2
// (the distance to a convex set is convex, so its maximum over a rectangle is at a corner),
// and nested boxes are at distance 0 (the paper: "nested, or very close objects are clustered").
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "vector/stroke.h"

namespace lw {

enum class FitMode { Skeleton, Contour };

struct Element {
    std::vector<int> strokes;  // indices into the stroke list the element was fitted to
    glm::vec2 center{0.0f};
    glm::vec2 axis{1.0f, 0.0f};  // A, unit; B = (−A.y, A.x)
    float half_length = 0.0f;    // half extent along A (the larger one)
    float half_width = 0.0f;     // half extent along B
    glm::vec3 color{0.0f};       // length-weighted mean of the strokes' colours

    glm::vec2 minor_axis() const { return {-axis.y, axis.x}; }
    float length() const { return 2.0f * half_length; }  // |A|
    float width() const { return 2.0f * half_width; }    // |B|
    // Orientation of A in [0, π).
    float angle() const;
    std::array<glm::vec2, 4> corners() const;
};

// The points an element is fitted to, with their weights.
struct WeightedPoints {
    std::vector<glm::vec2> points;
    std::vector<float> weights;
};
[[nodiscard]] WeightedPoints element_points(const std::vector<Stroke>& strokes, const std::vector<int>& ids, FitMode mode);

// PCA box of the strokes `ids` (at least one, each with at least one point).
[[nodiscard]] Element fit_element(const std::vector<Stroke>& strokes, std::vector<int> ids, FitMode mode);

// Distance from p to the filled box (0 inside).
[[nodiscard]] float box_distance(const Element& e, glm::vec2 p);
// Directed Hausdorff distance dH(E1, E2) between filled boxes; `shift` moves E2 first.
[[nodiscard]] float directed_hausdorff(const Element& e1, const Element& e2, glm::vec2 shift = glm::vec2(0.0f));

// Angle between two axes as undirected lines, in [0, π/2].
[[nodiscard]] float axis_angle(glm::vec2 a, glm::vec2 b);

}  // namespace lw
