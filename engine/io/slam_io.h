// engine/io/slam_io.h — SLAM files: one multi-part OpenEXR, a part per level (through OpenEXR).
//
// Contract (DESIGN.md "SLAM file"): the levels as one multi-image file readable by
// OpenImageIO; each part is `length` × `height`, one float channel "Y" holding ink in
// [0, 1]; metadata "linework:levels", "linework:length", "linework:exemplar",
// "linework:seed" on every part. Parts are ordered from level 0.5 to level 1.0.
#pragma once

#include <filesystem>

#include "stroke/slam.h"

namespace lw {

void write_slam(const std::filesystem::path& path, const Slam& slam);

// Throws lw::Error naming the file for a missing file, an unreadable one, or one whose
// parts disagree in size or count with its metadata.
[[nodiscard]] Slam read_slam(const std::filesystem::path& path);

}  // namespace lw
