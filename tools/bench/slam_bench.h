// tools/bench/slam_bench.h — `linework-bench slam`: wall time of a whole SLAM synthesis
// (Bénard et al. 2010 §3.2; the target: 17 levels of a 1024 × 32 exemplar, padded to
// 64 rows, 15 iterations per level, ≤ 2 s on the 2-core development machine). The bench
// links no image reader: the exemplar is the procedural dots pattern of engine/stroke/slam.h
// unless a raw float file is given.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace lw::bench {

struct SlamBenchOptions {
    std::string pattern = "dots";  // dots, dashes or pencil (make_procedural_slam, level 0.5)
    int exemplar_length = 1024, exemplar_rows = 32;
    int levels = 17, length = 1024, iterations = 15, threads = 0, repeat = 3;
    bool global = false;
};

CLI::App* add_slam_bench(CLI::App& app, SlamBenchOptions& options);
int run_slam_bench(const SlamBenchOptions& options);

}  // namespace lw::bench
