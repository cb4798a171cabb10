// engine/ribbon/exemplar_gen.h — procedural structured-pattern exemplars for ribbons.
//
// No permissively licensed structured exemplars exist publicly, so these are generated from
// signed distances (which also gives exact ground truth): `chain` (flat links alternating
// with links seen edge-on), `lace` (a scalloped border with eyelets and picots), `zigzag`
// (a thick zigzag with dots in alternate bays), `beads` (beads of varied size and colour on
// a string), `rope` (slanted twisted strands). Element sizes and spacings vary with the seed
// so that the exemplar is structured but not periodic — the synthesizer has choices to make.
//
// Output: RGBA8, the pattern in a band around mid-height with transparent margins above and
// below (so that pieces can slice it, Zhou et al. 2013 §1.3); alpha antialiased from the
// distance (alpha = clamp(0.5 − d, 0, 1)); straight colour; fully transparent pixels are
// black (0, 0, 0, 0), so that ξ compares transparent pixels equally everywhere.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace lw {

[[nodiscard]] const std::vector<std::string>& exemplar_names();

// Throws a usage error for an unknown name or a size outside 16..4096 × 16..4096.
[[nodiscard]] ImageRGBA8 generate_exemplar(const std::string& name, int width, int height, uint64_t seed = 1);

}  // namespace lw
