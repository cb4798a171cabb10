// `linework slam-pattern dots|dashes|pencil -o FILE.exr` — procedural SLAMs.
//
// Exactly self-similar stroke textures (A_1.0 = [A_0.5 A_0.5] at every texel) for styles
// and tests, until `linework slam` synthesizes them from an exemplar.
#include <cstdio>
#include <memory>

#include "commands.h"
#include "cli_numbers.h"
#include "core/error.h"
#include "io/slam_io.h"
#include "stroke/slam.h"

namespace lw::cli {

namespace {

struct PatternOptions {
    std::string pattern;
    std::string output;
    int levels = 17;
    int length = 1024;
    int height = 32;
    unsigned seed = 1;
};

int run_pattern(const PatternOptions& o) {
    const SlamPattern pattern = o.pattern == "dots"     ? SlamPattern::Dots
                                : o.pattern == "dashes" ? SlamPattern::Dashes
                                                        : SlamPattern::Pencil;
    if (o.length % 2 != 0) throw usage_error("--length: must be even (level 0.5 is half of it)");
    const Slam slam = make_procedural_slam(pattern, o.levels, o.length, o.height, o.seed);
    write_slam(o.output, slam);
    std::printf("%s: %d levels of %dx%d, self-similarity error %.3g, mean step between levels %.3g (largest %.3g)\n",
                o.output.c_str(), slam.levels, slam.length, slam.height, double(slam_self_similarity_error(slam)),
                double(slam_mean_level_step(slam)), double(slam_max_level_step(slam)));
    return 0;
}

}  // namespace

Runner add_slam_pattern_command(CLI::App& app) {
    auto o = std::make_shared<PatternOptions>();
    CLI::App* cmd = app.add_subcommand("slam-pattern", "Write a procedural self-similar line artmap (SLAM) as .exr.");
    cmd->add_option("pattern", o->pattern, "dots, dashes or pencil")
        ->required()
        ->check(CLI::IsMember({"dots", "dashes", "pencil"}));
    cmd->add_option("-o,--output", o->output, "Output SLAM file (.exr)")->required()->check(output_file(".exr"));
    cmd->add_option("--levels", o->levels, "Levels from 0.5 to 1.0")->check(CLI::Range(2, 256))->capture_default_str();
    cmd->add_option("--length", o->length, "Texture length, texels")->check(CLI::Range(16, 16384))->capture_default_str();
    cmd->add_option("--height", o->height, "Texture height (across the stroke), texels")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the element jitter")->check(seed(UINT32_MAX))->capture_default_str();
    return [o] { return run_pattern(*o); };
}

}  // namespace lw::cli
