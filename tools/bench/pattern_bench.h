// tools/bench/pattern_bench.h — `linework-bench pattern` and `linework-bench hatch`: wall time of
// the 2D stroke synthesizers on the CPU, median over repeats, with their fidelity numbers.
//
// pattern: Barla et al. 2006 report about 1 s for 1D patterns and 5–10 s for 2D ones; ours
//          are timed on a 1D path of --path-elements seeds and a 2D region of --elements seeds
//          (analysis of the reference included, as the command runs it).
// hatch:   Jodoin et al. 2002 report 2 s to synthesize 500 strokes from a training set of 50
//          (1.4 GHz Athlon); ours: --count strokes from a --training-size procedural training
//          sequence (or a file), KL2 watched per block of 50.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace lw::bench {

struct PatternBenchOptions {
    std::string reference_1d, reference_2d;  // stroke files; empty: procedural references
    int elements = 500;                      // 2D target seeds
    int path_elements = 100;                 // 1D target seeds
    int rings_1d = 5, rings_2d = 2;
    float scale_1d = 3.0f, scale_2d = 3.0f;  // ε
    int repeats = 20;
    uint64_t seed = 1;
};

struct HatchBenchOptions {
    std::string training;   // stroke file; empty: a procedural sequence
    int training_size = 50;
    int count = 500;
    int window = 6;
    int repeats = 20;
    uint64_t seed = 1;
};

CLI::App* add_pattern_bench(CLI::App& app, PatternBenchOptions& options);
int run_pattern_bench(const PatternBenchOptions& options);
CLI::App* add_hatch_bench(CLI::App& app, HatchBenchOptions& options);
int run_hatch_bench(const HatchBenchOptions& options);

}  // namespace lw::bench
