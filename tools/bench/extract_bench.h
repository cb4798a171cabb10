// tools/bench/extract_bench.h — `linework-bench lines --extract-only`: the host line
// extraction alone (extract_lines_reference: per-vertex view quantities, then the per-face
// isolines and feature edges), timed per view, so that it can be set beside rtsc's
// per-view extraction on the same mesh and camera (docs/BENCHMARKS.md). Prints one line:
// `extract: median X ms (min A, max B)`. With intersection lines among the types, the
// per-view time includes appending them as a frame does (found once for a still pose), and
// a second line times finding them again, as each new pose of an animation does. Needs no
// Vulkan device.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/camera.h"

namespace lw::bench {

// The camera as `linework render` takes it: each part given replaces the framing camera's.
struct CameraFlags {
    std::string eye, target, up;
    std::optional<float> fov;
};

struct ExtractBenchOptions {
    std::string model;
    int subdivide = 0;
    CameraFlags camera;     // only the eye matters to the extraction
    std::string types;      // "silhouette,suggestive,crease,border"; empty: the defaults
    std::string contours = "smooth";  // smooth, mesh or auto (LineParams::contours)
    std::vector<int> threads{1};  // several: timed in turn, run by run (noisy machines)
    int repeat = 50;
    bool crossed_copy = false;  // add a turned and moved copy of the model that cuts through it
};

// The camera flags over `camera` (the one framing the model): usage errors name the flag.
void apply_camera_flags(ViewCamera& camera, const CameraFlags& flags);

int run_extract_bench(const ExtractBenchOptions& options);

}  // namespace lw::bench
