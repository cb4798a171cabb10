// `linework slam EXEMPLAR.png -o OUT.exr` — a self-similar line artmap synthesized from one
// exemplar (Bénard et al. 2010 §3.2: Portilla–Simoncelli synthesis on a seed pyramid).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "commands.h"
#include "cli_numbers.h"
#include "core/error.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "progress.h"
#include "slam_synth/slam_builder.h"
#include "slam_synth/slam_conditions.h"
#include "slam_synth/slam_fidelity.h"

namespace lw::cli {

namespace {

struct SlamOptions {
    std::string exemplar, output, preview;
    int levels = 17, length = 1024, iterations = 15, threads = 0;
    unsigned seed = 1;
    bool global = false, report = false;
};

std::string decibels(double db) {
    char text[32];
    if (std::isinf(db)) return db > 0 ? "inf" : "-inf";
    std::snprintf(text, sizeof text, "%.1f", db);
    return text;
}

// "1.23x" of the exemplar's grain, or "-" for an exemplar without any.
std::string times(double value, double reference) {
    char text[32];
    if (reference > 0.0) std::snprintf(text, sizeof text, "%.2fx", value / reference);
    else std::snprintf(text, sizeof text, "-");
    return text;
}

void print_fidelity_row(const char* name, double grain, double exemplar_grain, const synth::ElementStatistics& e,
                        const char* stray) {
    std::printf("  %-14s %8.4f %7s %8.2f %8.1f %7.3f %5d %s\n", name, grain, times(grain, exemplar_grain).c_str(),
                e.per_100_texels, e.mean_area, e.area_cv, e.holes, stray);
}

// Fidelity to the exemplar (slam_fidelity.h): grain along the length, elements, stray ink.
void print_fidelity(const synth::SlamSynthesis& s, const synth::Plane& exemplar) {
    const double exemplar_grain = synth::grain(exemplar, false);
    std::printf("fidelity to the exemplar (each level at its synthesized length):\n");
    std::printf("  %-14s %8s %7s %8s %8s %7s %5s %s\n", "", "grain", "/ exem.", "elem/100", "area", "area cv", "holes",
                "stray ink in empty rows");
    print_fidelity_row("exemplar", exemplar_grain, exemplar_grain, synth::element_statistics(exemplar, false), "");
    double worst = 0.0;
    for (size_t i = 0; i < s.levels.size(); ++i) {
        const synth::LevelFidelity f = synth::level_fidelity(exemplar, s.levels[i]);
        worst = std::max(worst, f.grain);
        char name[32], stray[64];
        std::snprintf(name, sizeof name, "level %.3f", s.slam.level_value(int(i)));
        std::snprintf(stray, sizeof stray, "%.3f %% of %d rows", 100.0 * f.stray.share, f.stray.empty_rows);
        print_fidelity_row(name, f.grain, exemplar_grain, f.elements, stray);
    }
    std::printf("  largest grain over all levels: %.4f (%s the exemplar's)\n", worst, times(worst, exemplar_grain).c_str());
    // Whether the last iteration held elements to the exemplar's sizes (element_sizes.h).
    const synth::ElementSizes& sizes = s.target.elements;
    if (sizes.alike())
        std::printf("  element sizes imposed: the exemplar's %d elements are alike (%d-%d texels)\n", sizes.count,
                    sizes.min_area, sizes.max_area);
    else if (sizes.count >= 2)
        std::printf("  element sizes not imposed: the exemplar's %d elements are unlike (%d-%d texels, over 1.5x apart)\n",
                    sizes.count, sizes.min_area, sizes.max_area);
    else
        std::printf("  element sizes not imposed: the exemplar has %s whole element\n", sizes.count ? "one" : "no");
}

void print_report(const synth::SlamSynthesis& s, const synth::SlamSynthesisDesc& desc) {
    // textureSynth's per-group SNR, for the first and the last level against their seeds.
    const int first = 0, last = s.slam.levels - 1;
    const auto a = synth::level_statistics_report(s, desc, first), b = synth::level_statistics_report(s, desc, last);
    std::printf("statistics, SNR in dB against the exemplar (seed -> synthesized):\n");
    std::printf("  %-30s %-18s %s\n", "group", "level 0.5", "level 1.0");
    for (size_t g = 0; g < a.seed.size(); ++g)
        std::printf("  %-30s %6s -> %-8s %6s -> %s\n", a.seed[g].name.c_str(), decibels(a.seed[g].snr_db).c_str(),
                    decibels(a.synthesized[g].snr_db).c_str(), decibels(b.seed[g].snr_db).c_str(),
                    decibels(b.synthesized[g].snr_db).c_str());
}

int run_slam(const SlamOptions& o) {
    if (std::filesystem::path(o.output).extension() != ".exr")
        throw usage_error("-o: " + o.output + ": a SLAM file is OpenEXR (.exr)");
    refuse_writing_over_input(o.output, {o.exemplar});
    if (!o.preview.empty()) refuse_writing_over_input(o.preview, {o.exemplar}, "--preview");
    const synth::Plane ink = synth::exemplar_ink(read_image_rgba8(o.exemplar));
    synth::SlamSynthesisDesc desc{.levels = o.levels,
                                  .length = o.length,
                                  .iterations = o.iterations,
                                  .seed = o.seed,
                                  .scope = o.global ? synth::StatisticsScope::Global : synth::StatisticsScope::Rows,
                                  .threads = o.threads,
                                  .exemplar_name = o.exemplar};
    // The engine's parameter errors name these flags.
    const auto named = [](auto&& f) { return flags_named({{"SLAM length", "--length"}, {"SLAM levels", "--levels"}}, f); };
    // Every refusal before the header, so that a wrong --length is the only line printed.
    const synth::SlamModel m = named([&] { return synth::check_slam_synthesis(ink, desc); }).model;
    std::printf("exemplar: %s (%dx%d), padded to %d rows; %d scales, 4 orientations, Na = 9; %s statistics\n",
                o.exemplar.c_str(), ink.cols, ink.rows, m.padded_rows, m.scales,
                o.global ? "global (1D)" : "per-row mean/variance (1.5D)");
    std::printf("SLAM: %d levels, Lmax = %d, %d iterations per level, seed %u\n", o.levels, o.length, o.iterations, o.seed);
    std::fflush(stdout);

    Progress progress(o.levels, "level");
    int done = 0;
    desc.on_level = [&](const synth::SlamLevelReport& r) { progress.update(++done, r.index, r.ms); };
    const synth::SlamSynthesis s = named([&] { return synth::synthesize_slam(ink, desc); });
    if (s.exemplar_cols != ink.cols)
        std::printf("exemplar cropped to %d column%s (a multiple of %d)\n", s.exemplar_cols, s.exemplar_cols == 1 ? "" : "s",
                    m.unit);
    for (const synth::SlamLevelReport& r : s.reports)
        std::printf("  level %2d  l = %.4f  %5d texels  %7.1f ms%s\n", r.index, r.level, r.length, r.ms,
                    r.tiled ? "  (A_0.5 twice: what its synthesis computes, without the rounding)" : "");
    std::printf("analysis %.0f ms, synthesis %.0f ms\n", s.analysis_ms, s.synthesis_ms);

    const synth::SlamConditions c = synth::measure_slam_conditions(s);
    std::printf("top level periodic: left half vs right half differ by at most %.3g (A_1.0 is A_0.5 twice)\n",
                c.top_periodicity);
    std::printf("self-similarity error (A_1.0 vs [A_0.5 A_0.5], as stored): %.3g\n", c.self_similarity);
    std::printf("mean |A_l - A_l+| between adjacent levels: %.4f\n", c.mean_level_step);
    std::printf("RMS difference of adjacent levels %.4f, of A_0.5 and A_1.0 %.4f: ratio %.3f\n", c.rmse_adjacent,
                c.rmse_ends, c.rmse_ends > 0 ? c.rmse_adjacent / c.rmse_ends : 0.0);
    std::printf("tiling: wrap-around column step %.4f; interior mean %.4f, largest %.4f (the wrap ranks above %.0f %% of them)\n",
                c.wrap_difference, c.interior_difference, c.interior_max, 100.0 * c.wrap_rank);
    if (o.report) {
        print_report(s, desc);
        print_fidelity(s, ink);
    }

    write_slam(o.output, s.slam);
    std::printf("wrote %s\n", o.output.c_str());
    if (!o.preview.empty()) {
        write_png(o.preview, synth::contact_sheet(s, ink));
        std::printf("wrote %s\n", o.preview.c_str());
    }
    return 0;
}

}  // namespace

Runner add_slam_command(CLI::App& app) {
    auto o = std::make_shared<SlamOptions>();
    CLI::App* cmd = app.add_subcommand(
        "slam",
        "Synthesize a self-similar line artmap (SLAM) from one stroke exemplar (Bénard et al. 2010).\n"
        "Each level A_l, l = 0.5 … 1, is a Portilla–Simoncelli texture synthesized at length l·Lmax from\n"
        "a seed W_l of a seed pyramid built so that A_1.0 = [A_0.5 A_0.5] and adjacent levels differ\n"
        "little. Rows across the stroke keep the exemplar's mean and variance (1.5D).\n"
        "Example: linework slam scenes/exemplars/slam-dots.png -o dots.exr --preview dots.png");
    cmd->add_option("exemplar", o->exemplar,
                    "Exemplar image, 4–64 rows across the stroke: its alpha is the ink when it has any\n"
                    "translucent pixel, else 1 − luminance")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output SLAM file (.exr)")->required()->check(output_file(".exr"));
    cmd->add_option("--levels", o->levels,
                    "Levels from 0.5 to 1.0. Each is synthesized at l·Lmax rounded to the pyramid's unit "
                    "(2^(scales+1) texels: 32 for a 32-row exemplar), so past Lmax/(2·unit) + 1 levels (17 for "
                    "32 rows at 1024) adjacent levels share lengths; the authors step by at least the stroke's width")
        ->check(CLI::Range(2, 256))
        ->capture_default_str();
    cmd->add_option("--length", o->length,
                    "Lmax: texels of level 1.0 (and of every stored level); a multiple of twice the exemplar's pyramid\n"
                    "unit (64 for a 32-row exemplar, printed in the error otherwise)")
        ->check(CLI::Range(16, 16384))
        ->capture_default_str();
    cmd->add_option("--iterations", o->iterations, "Synthesis iterations per level (textureSynth uses 50)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the white noise W_source")->check(seed(UINT32_MAX))->capture_default_str();
    cmd->add_option("--preview", o->preview, "Write a contact sheet of the exemplar and every level (PNG)")
        ->check(output_file(".png"));
    cmd->add_option("--threads", o->threads, "Levels synthesized in parallel (default: one per core)")
        ->check(CLI::Range(0, 256));
    cmd->add_flag("--global", o->global, "Impose every statistic per texture (the 1D model), not mean/variance per row");
    cmd->add_flag("--report", o->report,
                  "Print the SNR of each statistic group (as textureSynth) of levels 0.5 and 1.0 and their seeds,\n"
                  "and the fidelity to the exemplar: grain along the length, elements (ink > 0.5: count per 100\n"
                  "texels, area, its coefficient of variation, enclosed paper), stray ink in empty rows, and whether\n"
                  "the exemplar's elements are alike enough (sizes within 1.5x) for the synthesis to hold them to its sizes");
    return [o] { return run_slam(*o); };
}

}  // namespace lw::cli
