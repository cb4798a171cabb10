// engine/stroke/outline.h — the outer outline of what a set's runs bound, as one closed path.
//
// Input:  a line set's selected runs (ScreenPath, pixels), usually visible silhouettes and
//         borders; a joining tolerance in pixels.
// Output: one closed ScreenPath per connected drawing: its outer boundary, walked once.
//
// The outline you see is pieces of several contours: where a contour passes behind another
// surface its visible run ends on the occluding contour, which goes on (a T-junction on
// screen: Freestyle's T-vertex). Each run is one stroke; Line Art and Pencil+ also offer the
// outline as one stroke. Here: every open end of a run within `tolerance_px` of another run
// splits that run there (the T-junction) or meets its end (a corner); the pieces form a
// planar graph whose nodes are those meeting points; ends that meet nothing are pruned back
// to the first junction (spurs: an inner line that ends inside the drawing); and the outer
// face of each connected part is walked from its leftmost node, turning at every node onto
// the next piece round the node on the outside, until the walk comes back. Of the two
// turning senses the one enclosing the larger area is the outer boundary. A part whose walk
// does not come back within its pieces (a gap over the tolerance) gives no outline.
//
// Samples keep their surface point, face and fade; s is the outline's own pixel arc length.
#pragma once

#include <vector>

#include "types/screen_path.h"

namespace lw {

[[nodiscard]] std::vector<ScreenPath> trace_outlines(const std::vector<ScreenPath>& runs, float tolerance_px = 3.0f);

}  // namespace lw
