// `linework coherence-report DUMPS...` — sliding and stretch measured from path dumps.
//
// Reads every frame_NNNN.json of each dump folder (in frame order) and prints the two
// measures of engine/coherence/path_dump.h: sliding (median |Δt| of nearby samples in
// consecutive frames) and stretch (on-screen pixels per texture period, and the share of
// samples inside the best factor-of-2 band).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "coherence/path_dump.h"
#include "commands.h"
#include "core/error.h"

namespace lw::cli {

namespace {

void print_measures(const std::string& what, const std::vector<PathDump>& frames) {
    const SlidingMeasure sliding = measure_sliding(frames);
    const StretchMeasure stretch = measure_stretch(frames);
    std::printf("  %s:\n", what.c_str());
    std::printf("    sliding: median |dt| %.5f periods over %zu matched sample pairs\n", sliding.median_dt, sliding.pairs);
    std::printf("    stretch: %.2f %% of %zu samples within [%.1f, %.1f) px per period; median %.1f px\n",
                100.0 * stretch.share_in_band, stretch.samples, stretch.band_low, 2.0 * stretch.band_low,
                stretch.median_ds_du);
}

int run_report(const std::vector<std::string>& folders) {
    for (const std::string& folder : folders) {
        if (!std::filesystem::is_directory(folder)) throw Error(folder + ": no such dump folder");
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            if (entry.path().extension() == ".json" && entry.path().filename().string().rfind("frame_", 0) == 0)
                files.push_back(entry.path());
        if (files.empty()) throw Error(folder + ": no frame_NNNN.json dumps");
        std::sort(files.begin(), files.end());
        std::vector<PathDump> frames;
        for (const auto& file : files) frames.push_back(read_path_dump(file));
        std::printf("%s: %zu frames\n", folder.c_str(), frames.size());
        print_measures("all paths", frames);
        // Per line set: each has its own texture and tracker, so its own period band.
        const std::vector<std::string> sets = line_sets_in(frames);
        if (sets.size() > 1)
            for (const std::string& set : sets)
                print_measures(set.empty() ? "layers" : "line set " + set, paths_of_line_set(frames, set));
    }
    return 0;
}

}  // namespace

Runner add_coherence_report_command(CLI::App& app) {
    auto folders = std::make_shared<std::vector<std::string>>();
    CLI::App* cmd = app.add_subcommand("coherence-report",
                                       "Measure sliding and stretch of strokes from --dump-paths folders.");
    cmd->add_option("dumps", *folders, "Dump folders written by `linework render --dump-paths`")->required();
    return [folders] { return run_report(*folders); };
}

}  // namespace lw::cli
