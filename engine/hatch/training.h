// engine/hatch/training.h — a hatching training sequence as fixed-length parameter vectors
// (Jodoin et al. 2002, §1.3, §2.1: "each stroke x_i is defined as a parametrical curve and is
// represented by a vector of dimension d […] all strokes in Z have to have the same dimension").
//
// Input:  training strokes in the order they were drawn (the sequence, §1.2).
// Output: `HatchTraining`: the sequence frame — u along the sequence (the principal direction
//         of the stroke centres, pointing from the first to the last), v its left normal — and
//         per stroke the vector
//           [du, v, (q_0 − a)·(u, v), …, (q_3 − a)·(u, v), w, r, g, b]
//         with a the stroke's centre (mean of its points resampled by arc length), du the step
//         from the previous stroke's centre along u (the first stroke takes the median step), v
//         the centre's offset across the sequence, q_k four points at equal arc length from
//         end to end, w the mean width and (r, g, b) the colour; d = 14 before dropping
//         constant dimensions. Each dimension is scaled by the training spread (zero mean,
//         unit variance) so that the Gibbs distance and the Parzen windows weigh them alike;
//         dimensions that do not vary in the training are dropped.
// Generated strokes are copies of training strokes (§3.1: "the generated strokes are always
// picked up in the training set and copied"), so a generated sequence is a list of training
// indices, and its vectors are the training vectors.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "hatch/kl2.h"
#include "vector/stroke.h"

namespace lw {

struct HatchTraining {
    std::vector<Stroke> strokes;
    glm::vec2 origin{0.0f};  // the mean stroke centre
    glm::vec2 u{1.0f, 0.0f}, v{0.0f, 1.0f};
    std::vector<glm::vec2> centers;  // a_i, drawing coordinates
    std::vector<float> step;         // du_i
    std::vector<float> offset;       // v_i = (a_i − origin)·v
    Samples vectors;                 // standardized, one row per stroke
    int raw_dim = 14;                // before dropping constant dimensions
};

// At least 3 strokes; throws lw::Error otherwise.
[[nodiscard]] HatchTraining make_training(std::vector<Stroke> strokes);

// The standardized vectors of a sequence of training indices.
[[nodiscard]] Samples sequence_vectors(const HatchTraining& training, const std::vector<int>& ids);

}  // namespace lw
