// engine/coherence/path_param.h — a path's stroke parameterization, as the tracker gives it.
#pragma once

#include <cstdint>

#include "types/slam_level.h"

namespace lw {

// T(s) = ρ·s + φ over the path's screen arclength s (pixels from its first sample).
struct PathParam {
    float rho = 0.0f;
    float phi = 0.0f;
    uint32_t votes = 0;
    bool fitted = false;  // from votes (coherent policy); false: a fallback or another policy
    SlamFold fold;        // level and the coordinate scale actually sampled
    float length_px = 0.0f;
};

}  // namespace lw
