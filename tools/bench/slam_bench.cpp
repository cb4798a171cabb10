#include "slam_bench.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "slam_synth/slam_builder.h"
#include "slam_synth/slam_conditions.h"
#include "stroke/slam.h"

namespace lw::bench {

CLI::App* add_slam_bench(CLI::App& app, SlamBenchOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "slam", "SLAM synthesis (Portilla–Simoncelli per level on the seed pyramid): wall time of whole runs.");
    cmd->add_option("--pattern", o.pattern, "Procedural exemplar: dots, dashes or pencil")
        ->check(CLI::IsMember({"dots", "dashes", "pencil"}))
        ->capture_default_str();
    cmd->add_option("--exemplar-length", o.exemplar_length, "Exemplar texels along the stroke")
        ->check(CLI::Range(64, 16384))
        ->capture_default_str();
    cmd->add_option("--exemplar-rows", o.exemplar_rows, "Exemplar rows (across the stroke)")
        ->check(CLI::Range(4, 64))
        ->capture_default_str();
    cmd->add_option("--levels", o.levels, "SLAM levels")->check(CLI::Range(2, 256))->capture_default_str();
    cmd->add_option("--length", o.length, "Lmax")->check(CLI::Range(64, 16384))->capture_default_str();
    cmd->add_option("--iterations", o.iterations, "Iterations per level")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--threads", o.threads, "Levels in parallel (0: one per core)")->check(CLI::Range(0, 256));
    cmd->add_option("--repeat", o.repeat, "Timed runs (after none: the first run is timed too)")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    cmd->add_flag("--global", o.global, "Global statistics (1D) instead of per-row (1.5D)");
    return cmd;
}

int run_slam_bench(const SlamBenchOptions& o) {
    const SlamPattern pattern = o.pattern == "dots"     ? SlamPattern::Dots
                                : o.pattern == "dashes" ? SlamPattern::Dashes
                                                        : SlamPattern::Pencil;
    const Slam procedural = make_procedural_slam(pattern, 2, o.exemplar_length, o.exemplar_rows, 1);
    synth::Plane exemplar(o.exemplar_rows, o.exemplar_length);
    for (int r = 0; r < exemplar.rows; ++r)
        for (int x = 0; x < exemplar.cols; ++x) exemplar.at(r, x) = procedural.at(0, r, x);
    const synth::SlamModel m = synth::slam_model(o.exemplar_rows, "procedural:" + o.pattern);
    const int threads = o.threads > 0 ? o.threads : int(worker_count());
    std::printf("device: CPU, %d thread(s) (%zu cores)\n", threads, worker_count());
    std::printf("exemplar: procedural %s %dx%d, padded to %d rows, %d scales, 4 orientations, Na = 9\n",
                o.pattern.c_str(), o.exemplar_length, o.exemplar_rows, m.padded_rows, m.scales);
    std::printf("SLAM: %d levels, Lmax = %d, %d iterations per level, %s statistics\n", o.levels, o.length, o.iterations,
                o.global ? "global" : "per-row");
    std::vector<double> totals;
    synth::SlamSynthesis last;
    for (int run = 0; run < o.repeat; ++run) {
        Timer timer;
        last = synth::synthesize_slam(exemplar, {.levels = o.levels,
                                                 .length = o.length,
                                                 .iterations = o.iterations,
                                                 .scope = o.global ? synth::StatisticsScope::Global
                                                                   : synth::StatisticsScope::Rows,
                                                 .threads = threads,
                                                 .exemplar_name = "procedural:" + o.pattern});
        totals.push_back(timer.elapsed_ms());
        std::printf("  run %d: %.0f ms (analysis %.0f ms, synthesis %.0f ms)\n", run + 1, totals.back(),
                    last.analysis_ms, last.synthesis_ms);
    }
    std::vector<double> sorted = totals;
    std::sort(sorted.begin(), sorted.end());
    double level_sum = 0;  // over the synthesized levels (level 1.0 is level 0.5 tiled)
    int synthesized = 0;
    for (const auto& r : last.reports)
        if (!r.tiled) {
            level_sum += r.ms;
            ++synthesized;
        }
    std::printf("whole SLAM: min %.0f ms, median %.0f ms over %d run(s); per synthesized level %.1f ms on average "
                "(%.2f ms per iteration)\n",
                sorted.front(), sorted[sorted.size() / 2], o.repeat, level_sum / double(std::max(synthesized, 1)),
                level_sum / double(std::max(synthesized, 1)) / o.iterations);
    const synth::SlamConditions c = synth::measure_slam_conditions(last);
    std::printf("conditions: top periodicity %.3g, self-similarity %.3g, mean level step %.4f, wrap %.4f vs interior "
                "mean %.4f, largest %.4f\n",
                c.top_periodicity, c.self_similarity, c.mean_level_step, c.wrap_difference, c.interior_difference,
                c.interior_max);
    return 0;
}

}  // namespace lw::bench
