// engine/pattern/cluster.h — perceptual grouping of strokes into elements at scale ε
// (Barla et al. 2006, §2.2).
//
// Input:  strokes in drawing order, the scale ε (drawing units: "the minimum distance at
//         which two elements are perceived separately") and the fitting mode.
// Output: elements (pattern/element.h), each the PCA box of its strokes, ordered by their
//         first stroke.
//
// Two elements are clustered when
//   proximity:    prox(E1, E2) = min(dH(E1, E2), dH(E2, E1)) < ε   (§2.2.1), or
//   continuation: for one of the four axes (A1, B1 against E2; A2, B2 against E1) both boxes
//                 lie within ε/2 of the axis line ("E2 is near-collinear to E1 iff ∀p ∈ E2,
//                 d(p, A1) < ε/2"; E1 too, so that an element wider than ε is no line at this
//                 scale — the authors' code has the same parallelism test) and the gap between
//                 their projections on it is below ε (§2.2.2).
// Both measures use the boxes, as the paper does "to speed up this computation".
// Greedy order (§2.2): pop E*, merge every queued element that clusters with the growing E*
// (refitting its box after each merge), push E* back if anything merged, else output it.
#pragma once

#include <vector>

#include "pattern/element.h"

namespace lw {

[[nodiscard]] float proximity(const Element& e1, const Element& e2);
// The smallest continuation gap over the four configurations whose near-collinearity test
// passes at ε; +∞ when none does.
[[nodiscard]] float continuation(const Element& e1, const Element& e2, float epsilon);
[[nodiscard]] bool should_cluster(const Element& e1, const Element& e2, float epsilon);

[[nodiscard]] std::vector<Element> cluster_strokes(const std::vector<Stroke>& strokes, float epsilon, FitMode mode);

}  // namespace lw
