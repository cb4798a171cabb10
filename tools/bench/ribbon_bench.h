// tools/bench/ribbon_bench.h — `linework-bench ribbon`: time per DP row of the ribbon
// synthesizer (Zhou et al. 2013, §4 reports 30 ms and 650 ms per row on a GTX 580 for
// exemplars of 199×82 and 325×64).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace lw::bench {

struct RibbonBenchOptions {
    std::string pattern = "chain";       // a generated exemplar (the bench links no image reader)
    std::string exemplar_size = "199x82";
    int rows = 4;                        // DP rows timed (after one warm-up row)
    float piece = 0.0f;                  // δ; default b / 2
    float scale = 0.0f;                  // s; default default_ribbon_scale()
    bool reference = false;              // also time the C++ reference
    std::string device = "auto";
};

CLI::App* add_ribbon_bench(CLI::App& app, RibbonBenchOptions& options);
int run_ribbon_bench(const RibbonBenchOptions& options);

}  // namespace lw::bench
