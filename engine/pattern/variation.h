// engine/pattern/variation.h — the variation post-process of Barla et al. 2006, §3.3.
//
// Input:  the synthesized elements as poses (which reference element, where in the frame, and
//         how it is turned and scaled), the reference analysis, the target distribution and
//         the amount v ∈ [0, 1].
// Output: the poses, varied.
//
// Parameters: "for each element, and for each of its parameters independently, we select a
// set of similar values in the reference pattern […] Then, we pick one value from this set".
// Similar means within v times the §3.1 threshold of the element's own value: orientation
// within v·σ_par, length ratio within 1 + v·(σ_ov − 1), width within v·σ_sup. The picked
// orientation turns the element, the picked length stretches it along A, the picked width
// scales it (and its strokes' widths) along B.
// Positions: each element with at least k neighbours (k = 2 along a path, 4 in a region)
// goes — all in parallel — to the barycentre of its neighbours plus its reference element's
// shift vector S_ref scaled by the ratio of neighbourhood sizes. The paper's factor
// A_Etar/(n·A_Eref) is a ratio of neighbourhood areas; ours is the ratio of mean neighbour
// distances, the same ratio as a length (a shift is a length). The move is blended by v.
#pragma once

#include <vector>

#include "core/random.h"
#include "pattern/synthesis.h"

namespace lw {

struct ElementPose {
    int source = -1;           // reference element
    glm::vec2 position{0.0f};  // frame coordinates (2D: x, y; 1D: s, t)
    float turn = 0.0f;         // radians, added to the reference element's orientation in the frame
    float stretch = 1.0f;      // along A
    float thicken = 1.0f;      // along B (and stroke widths)
};

void vary_parameters(std::vector<ElementPose>& poses, const PatternAnalysis& reference, float variation,
                     const PatternThresholds& sigma, Rng& rng);
void vary_positions(std::vector<ElementPose>& poses, const Distribution& target, const PatternAnalysis& reference,
                    float variation, bool along_path);

}  // namespace lw
