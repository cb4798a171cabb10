// `linework coherence-report DUMPS...` — sliding and stretch measured from path dumps.
//
// Reads every frame_NNNN.json of each dump folder (in frame order) and prints the two
// measures of engine/coherence/path_dump.h: sliding (median |Δt| of nearby samples in
// consecutive frames) and stretch (on-screen pixels per texture period, and the share of
// samples inside the best factor-of-2 band). With --against REF: per frame, how far the
// parameterization is from REF's dump of the same frame (a farm chunk against one render).
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

struct ReportOptions {
    std::vector<std::string> folders;
    std::string against;
    double max_p90 = -1.0;  // < 0: no threshold
};

std::vector<PathDump> read_dumps(const std::string& folder) {
    if (!std::filesystem::is_directory(folder)) throw Error(folder + ": no such dump folder");
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".json" && entry.path().filename().string().rfind("frame_", 0) == 0)
            files.push_back(entry.path());
    if (files.empty()) throw Error(folder + ": no frame_NNNN.json dumps");
    std::sort(files.begin(), files.end());
    std::vector<PathDump> frames;
    for (const auto& file : files) frames.push_back(read_path_dump(file));
    return frames;
}

// Per frame of `frames` that `reference` has: the phase error; 1 when a p90 passes the bound.
int report_against(const std::string& folder, const std::vector<PathDump>& frames, const ReportOptions& o) {
    const std::vector<PathDump> reference = read_dumps(o.against);
    std::printf("%s against %s: phase error |dt| per frame, periods\n", folder.c_str(), o.against.c_str());
    int over = 0;
    for (const PathDump& frame : frames) {
        const auto ref = std::find_if(reference.begin(), reference.end(),
                                      [&](const PathDump& r) { return r.frame == frame.frame; });
        if (ref == reference.end()) throw Error(o.against + ": no dump of frame " + std::to_string(frame.frame));
        const PhaseError e = measure_phase_error(frame, *ref);
        // No sample near the reference's paths is no measure, not a zero one.
        const bool bad = o.max_p90 >= 0.0 && (e.pairs == 0 || e.p90 > o.max_p90);
        over += bad;
        std::printf("  frame %d: median %.5f, p90 %.5f, max %.5f, %.2f %% over 0.25 (%zu samples)%s\n", frame.frame,
                    e.median, e.p90, e.max, 100.0 * e.over_quarter, e.pairs, !bad ? "" : e.pairs == 0 ? "  NO MATCHED SAMPLES" : "  OVER THE BOUND");
    }
    if (o.max_p90 >= 0.0) std::printf("%d frame(s) with p90 over %.4g periods\n", over, o.max_p90);
    return over > 0 ? 1 : 0;
}

int run_report(const ReportOptions& o) {
    int status = 0;
    for (const std::string& folder : o.folders) {
        const std::vector<PathDump> frames = read_dumps(folder);
        if (!o.against.empty()) {
            status = std::max(status, report_against(folder, frames, o));
            continue;
        }
        std::printf("%s: %zu frames\n", folder.c_str(), frames.size());
        print_measures("all paths", frames);
        // Per line set: each has its own texture and tracker, so its own period band.
        const std::vector<std::string> sets = line_sets_in(frames);
        if (sets.size() > 1)
            for (const std::string& set : sets)
                print_measures(set.empty() ? "layers" : "line set " + set, paths_of_line_set(frames, set));
    }
    return status;
}

}  // namespace

Runner add_coherence_report_command(CLI::App& app) {
    auto o = std::make_shared<ReportOptions>();
    CLI::App* cmd = app.add_subcommand("coherence-report",
                                       "Measure sliding and stretch of strokes from --dump-paths folders; with "
                                       "--against, the phase error of each frame against another render's dumps.");
    cmd->add_option("dumps", o->folders, "Dump folders written by `linework render --dump-paths`")->required();
    cmd->add_option("--against", o->against,
                    "Reference dump folder of the same frames (one render of the shot): print per frame how far "
                    "the parameterization is from it (|dt| in periods: median, 90th percentile, max)");
    cmd->add_option("--max-p90", o->max_p90, "With --against: exit 1 when a frame's 90th percentile passes this "
                                             "many periods");
    return [o] {
        if (o->max_p90 >= 0.0 && o->against.empty()) throw usage_error("--max-p90 needs --against REF");
        return run_report(*o);
    };
}

}  // namespace lw::cli
