// `linework hatch` — hatching sequences by N-grams with a KL2 watch (Jodoin et al. 2002;
// engine/hatch/hatching.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "commands.h"
#include "cli_numbers.h"
#include "core/error.h"
#include "core/timer.h"
#include "hatch/hatching.h"
#include "vector/stroke_io.h"

namespace lw::cli {

namespace {

struct HatchOptions {
    std::string training, output, along;
    int count = 0, window = 6, block = 50;
    double threshold = -1.0;
    float plausible = 0.5f;
    uint64_t seed = 1;
    bool kl2 = false;
    bool window_given = false;
};

int run_hatch(const HatchOptions& o) {
    Timer total;
    if (!is_stroke_file_path(o.output)) throw usage_error("-o: " + o.output + ": strokes are written as .svg or .json");
    refuse_writing_over_input(o.output, {o.training, o.along});
    StrokeSet train = load_strokes(o.training);
    const HatchTraining t = naming(o.training, [&] { return make_training(std::move(train.strokes)); });
    if (o.window >= int(t.strokes.size()))
        throw usage_error("--window: " + std::to_string(o.window) + (o.window_given ? "" : " (the default)") +
                          " must be smaller than the training size (" + std::to_string(t.strokes.size()) + " strokes in " +
                          o.training + "): give --window " + std::to_string(int(t.strokes.size()) - 1) + " or less");
    // With --kl2 stdout holds the block lines only; the rest goes to stderr.
    FILE* info = o.kl2 ? stderr : stdout;

    std::vector<ArclengthCurve> paths;
    if (!o.along.empty()) {
        const StrokeSet along = load_strokes(o.along);
        paths = naming(o.along, [&] { return hatch_paths(along.strokes); });
    }

    std::fprintf(info, "training: %s, %zu strokes, %d-dimensional vectors (%d varying)\n", o.training.c_str(),
                 t.strokes.size(), t.raw_dim, t.vectors.dim);

    HatchDesc desc;
    desc.count = o.count;
    desc.window = o.window;
    desc.block = o.block;
    desc.threshold = o.threshold;
    desc.plausible = o.plausible;
    Rng rng(o.seed);
    size_t restarts = 0, over = 0;
    int last_window = o.window;
    auto report = [&](const HatchBlock& b, bool kept) {
        if (!kept) {
            ++restarts;
            if (b.next_window > 0)
                std::fprintf(stderr, "hatch: block %d (window %d) KL2 %.3f over the threshold %.3g: generated again with window %d\n",
                             b.index, b.window, b.kl2, b.threshold, b.next_window);
            else
                std::fprintf(stderr, "hatch: block %d (window %d) KL2 %.3f over the threshold %.3g: the best attempt is kept\n",
                             b.index, b.window, b.kl2, b.threshold);
            return;
        }
        // A block kept above the threshold does not keep its window (generate_hatching).
        if (!b.over_threshold) last_window = b.window;
        if (b.over_threshold) ++over;
        if (o.kl2)
            std::printf("block %d strokes %zu-%zu KL2 %.4f\n", b.index, b.first, b.last, b.kl2);
    };

    StrokeSet out;
    Timer generation;
    Hatching h = hatch(t, desc, paths, rng, report);  // Fig. 8 along paths: one sequence each
    out.strokes = std::move(h.strokes);
    const double threshold = h.threshold;
    const double generation_ms = generation.elapsed_ms();
    // Along paths each path is a sequence of its own, in blocks of up to --block strokes, and
    // the strokes generated past a path's end are dropped: say both, as the block lines
    // number the generated strokes.
    const std::string along =
        paths.empty() ? ""
                      : " along " + std::to_string(paths.size()) + " path(s), one sequence each, " +
                            std::to_string(out.strokes.size()) + " placed (" +
                            std::to_string(h.generated - out.strokes.size()) + " ran past a path's end),";
    const std::string windows =
        last_window == o.window ? std::to_string(o.window) : std::to_string(o.window) + " (" + std::to_string(last_window) + " at the end)";
    // The automatic threshold is 3 times the KL2 of random blocks, which a training of a few
    // strokes can put at or below 0 (the estimator's bias): then no block is checked.
    char checked[160];
    if (threshold > 0.0)
        std::snprintf(checked, sizeof checked, "%zu block(s) generated again, %zu kept above the KL2 threshold %.3g", restarts,
                      over, threshold);
    else
        std::snprintf(checked, sizeof checked, "no block checked (%s)",
                      o.threshold == 0.0 ? "--threshold 0"
                                         : "random blocks of this training score KL2 at or below 0: too few strokes to judge");
    std::fprintf(info, "generated %zu strokes%s with window %s in blocks of %s%d (%.1f ms); %s\n", h.generated, along.c_str(),
                 windows.c_str(), paths.empty() ? "" : "up to ", o.block, generation_ms, checked);
    save_strokes(o.output, out);
    std::fprintf(info, "wrote %s (%.1f ms in all)\n", o.output.c_str(), total.elapsed_ms());
    return 0;
}

}  // namespace

Runner add_hatch_command(CLI::App& app) {
    auto o = std::make_shared<HatchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "hatch",
        "Continue a hand-drawn hatching sequence by example (Jodoin, Epstein, Granger-Piché &\n"
        "Ostromoukhov 2002). Each next stroke is copied from the training strokes whose N − 1\n"
        "predecessors resemble the last N − 1 strokes drawn (an N-gram with a Gibbs probability and\n"
        "a random pick among the plausible ones). The sequence is made in blocks; a block whose KL2\n"
        "divergence from the training passes the threshold is made again with a larger window.\n"
        "Example: linework hatch scenes/patterns/hatch_training.svg -o out.svg --count 200 --kl2");
    cmd->add_option("training", o->training,
                    "Training strokes in drawing order (SVG or JSON stroke file, as for `linework pattern`)")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output strokes: .svg (one <polyline>/<path> per stroke) or .json")
        ->required()
        ->check(output_file());
    cmd->add_option("--count", o->count, "Strokes to generate (with --along: at most this many per path)")
        ->required()
        ->check(CLI::Range(1, 1000000));
    CLI::Option* window = cmd->add_option("--window", o->window,
                    "N, the N-gram window: each stroke follows the last N − 1 (larger follows the training\n"
                    "more closely; a window too small for the training may loop, and KL2 shows it)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--block", o->block, "Strokes per block whose KL2 is checked")->check(CLI::Range(2, 100000))->capture_default_str();
    cmd->add_option("--threshold", o->threshold,
                    "KL2 above which a block is made again with a window larger by 2 (0: never; default:\n"
                    "3 times the median KL2 of blocks drawn from the training at random, since KL2's scale\n"
                    "depends on the training; a block looping on a few strokes scores tens)")
        ->check(within(0.0, 1e9));
    cmd->add_option("--plausible", o->plausible,
                    "c in (0, 1]: strokes whose Gibbs probability is at least c times the best are plausible")
        ->check(within(1e-6, 1.0))
        ->capture_default_str();
    cmd->add_option("--along", o->along,
                    "Lay sequences along these paths (a stroke file: each stroke is a path), strokes turned\n"
                    "with the path and offset across it as in the training (the paper's Fig. 8)");
    cmd->add_option("--seed", o->seed, "Seed of the random picks")->check(seed())->capture_default_str();
    cmd->add_flag("--kl2", o->kl2,
                  "Print one line per block on stdout: `block B strokes A-B KL2 V` (the rest goes to stderr)");
    return [o, window] {
        o->window_given = window->count() > 0;
        return run_hatch(*o);
    };
}

}  // namespace lw::cli
