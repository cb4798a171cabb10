// engine/stroke/outline.h — the outer outline of what a set's runs bound, as one closed path.
//
// Input:  a line set's selected runs (ScreenPath, pixels), usually visible silhouettes,
//         borders and creases; a joining tolerance in pixels.
// Output: one closed ScreenPath per connected drawing: its outer boundary, walked once; and
//         the runs that bound nothing, unchanged. Drawings over ~6000 × 6000 px (whose grid
//         cells would be wider than half the tolerance) are returned as they are.
//
// The outline you see is pieces of several contours: where a contour passes behind another
// surface its visible run ends on the occluding contour, which goes on (a T-junction on
// screen: Freestyle's T-vertex), and each run is its own stroke. Line Art and Pencil+ also
// offer the outline as one stroke. Here the runs are drawn `tolerance_px` wide into a grid of
// half-pixel cells (closing gaps up to that width, such as a run that ends a sample short of
// the contour that hides it); the outside is what a fill from the grid's border reaches; each
// region it does not reach (8-connected) that encloses cells off the lines (at least a
// tolerance-wide square) is one drawing, and the boundary of that region, walked once round
// by radial sweep, is its outline. Runs in a region that encloses nothing (a loose line)
// stay as they are, and each occlusion level (ScreenPath::qi) is traced on its own. Each
// boundary cell is snapped to the nearest point of the runs, so the outline lies on them.
// (A walk over a planar graph of the runs split at their junctions was tried first: nearly
// parallel runs a pixel apart make thin faces there in which the walk lost its way.) Only the
// outer boundary is kept, so interior lines in the selection do no harm: select every type
// that can bound the drawing (silhouettes, borders, and creases on hard-edged models).
//
// Samples keep their surface point, face and fade; s is the outline's own pixel arc length.
#pragma once

#include <vector>

#include "types/screen_path.h"

namespace lw {

[[nodiscard]] std::vector<ScreenPath> trace_outlines(const std::vector<ScreenPath>& runs, float tolerance_px = 3.0f);

}  // namespace lw
