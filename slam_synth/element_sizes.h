// slam_synth/element_sizes.h — the sizes of a stroke texture's elements (dots, dashes), as
// one more statistic, and the step that holds a synthesized image to them.
//
// Input: an ink plane (rows across the stroke, columns along it). Output: the range of the
// areas of its elements, and a step that erases the fragments and splits the merged pairs
// of a synthesized (periodic) plane whose elements fall outside the exemplar's range.
//
// An element is a connected component of ink > kElementInk (8-connected; the columns of a
// synthesized plane wrap), as slam_fidelity measures them. Here a component that touches the
// first or last row, goes all the way round a periodic plane, or (in the exemplar, which is
// not periodic) is cut by its first or last column is left alone: a line, a band or a piece
// of something whose size is not known. (slam_fidelity counts the first kind as elements;
// in the padded planes of the synthesis those rows are paper, so none touch them.)
//
// Why (issue 20, docs/research/slam-fidelity.md "Element sizes"): Portilla–Simoncelli's
// statistics are local and of second order. A row of identical dots synthesizes to dots,
// but also to a few specks and half dots (1–41 texels where a dot is 58) and merged pairs
// (72–111 texels), which the statistics cannot tell from the dots around them: the area's
// coefficient of variation at level 1.0 was 0.08–0.31 over seeds 1–6 against the
// exemplar's 0.02 (and 0.16 in the authors' own artmap). Which ink belongs to which element
// is, like enclosed paper (enclosed_ink.h), a property of whole elements; the exemplar's
// smallest and largest element are the statistic, and the last iteration imposes it:
// - an element under half the exemplar's smallest is erased with the ink that runs down
//   from it (its catchment: texels reached by steps that do not climb, within `reach`
//   texels of it, in no element; all elements flood at once and whole ones claim first, so
//   a neighbouring dot keeps its grey rim) — a speck is closer to paper than to a dot;
// - an element over the exemplar's largest is split where it is narrowest when it is two
//   or more blobs: the distance to paper has two or more peaks (maxima over 5 × 5 texels at
//   least 2 texels deep), a watershed of that distance from the peaks gives each texel its
//   blob, blobs whose boundary is within a texel of the lower peak's depth are one (taken
//   deepest boundary first against the peaks joined so far; a ridge of equal maxima along
//   a fat oval is not a neck), and the texels on one side of each boundary become paper.
//   Only when every piece the cut leaves is at least half the exemplar's smallest: a bump
//   on an element is not a second one;
// - else (one blob) it is trimmed: its opening by a disc of half the shallowest exemplar
//   element's depth keeps the body, and each piece outside it of 4 texels or more (a curl
//   stuck to the rim, not the odd texel of an edge) becomes paper.
//   Elements over 4 times the largest (a band, a smear: not a few elements grown together)
//   are left as they are.
// Only exemplars of like elements take part: two or more, the largest at most 1.5 times the
// smallest (a row of identical dots: 57–61 texels). The range of a varied set (dots of
// 37–131 texels, dashes, wedges, spatter, brush pieces) says little of any one element, and
// imposed there it broke what it should describe (brush: largest grain 12.6× the exemplar's,
// wedges' RMSE(1)/RMSE(16) doubled); lines and nets have no elements. For all of these
// impose_element_sizes returns before it reads the plane.
#pragma once

#include "fft.h"

namespace lw::synth {

inline constexpr float kElementInk = 0.5f;  // ink above this belongs to an element

struct ElementSizes {
    int count = 0;                    // whole elements found; under 2, no bound is imposed
    int min_area = 0, max_area = 0;   // texels
    float min_depth = 0;              // alike() only: the least, over elements, of the deepest texel's distance to paper
    // Two or more elements, the largest at most 1.5 times the smallest.
    bool alike() const { return count >= 2 && 2 * max_area <= 3 * min_area; }
};

// The whole elements of an exemplar (not periodic).
[[nodiscard]] ElementSizes element_sizes(const Plane& exemplar);

struct ElementChanges {
    int erased = 0;  // fragments made paper
    int split = 0;   // elements cut into blobs
    int trimmed = 0; // elements that lost attached thin pieces
};

// Erases and splits as above, on a plane whose columns wrap; `paper` is the ink they get
// (the exemplar's least), `reach` bounds an erased fragment's catchment (texels).
ElementChanges impose_element_sizes(Plane& ink, const ElementSizes& sizes, float paper, int reach);

}  // namespace lw::synth
