// engine/scene/line_set_file.h — reads the scene file's "line_sets" (README "Line sets").
//
// Input:  the scene's JSON object (its reader) and the file, for messages and relative paths.
// Output: the sets in drawing order; every key checked, errors name the key path
//         ("line_sets[1].style.dashes: ...").
#pragma once

#include <filesystem>
#include <vector>

#include "types/line_set.h"

namespace lw {

namespace scene_detail {
class ObjectReader;
}

[[nodiscard]] std::vector<LineSetDesc> read_line_sets(scene_detail::ObjectReader& scene,
                                                      const std::filesystem::path& file);

}  // namespace lw
