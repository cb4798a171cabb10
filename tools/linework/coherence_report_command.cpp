// `linework coherence-report DUMPS...` — sliding and stretch measured from path dumps.
//
// Reads every frame_NNNN.json of each dump folder (in frame order) and prints the two
// measures of engine/coherence/path_dump.h for all paths, per line set and per line type:
// sliding (median and 90th percentile of |Δt| of nearby samples in consecutive frames, and
// the share of pops over a quarter period; with --baseline, as ratios to another render; the
// same again over the pairs where one path lies alone, where paths of a set run closer than the
// match radius; for lines attached to the surface, also matched by surface point) and stretch (on-screen pixels per texture period, and the share of samples
// inside the best factor-of-2 band). With --against REF: per frame, how far the
// parameterization is from REF's dump of the same frame (a farm chunk against one render).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "coherence/path_dump.h"
#include "commands.h"
#include "core/error.h"

namespace lw::cli {

namespace {

struct Measures {
    SlidingMeasure sliding;
    SlidingStats on_surface;  // over the group's lines attached to the surface
    StretchMeasure stretch;
};

Measures measure(const std::vector<PathDump>& frames) {
    return {measure_sliding(frames), measure_sliding_on_surface(frames), measure_stretch(frames)};
}

// Below `nothing` (1e-4 periods, 0.01 px) nothing slides measurably: such a ratio is 0, not
// a quotient of rounding errors (a still camera's lines give 0 under both policies).
double ratio(double a, double b, double nothing = 1e-4) {
    if (a <= nothing) return 0.0;
    return b > nothing ? a / b : INFINITY;
}
// A share of pairs (pops) is a count over a count, with no rounding to allow for: any pop
// counts (until 2026-12-06 a share under 1e-4 read as none, and a render against itself
// could print 0 for the pops ratio).
double share_ratio(double a, double b) { return ratio(a, b, 0.0); }

// One group's measures; against a baseline's same group (another policy's render of the same
// shot), their ratios as well.
void print_measures(const std::string& what, const Measures& m, const Measures* baseline) {
    // Fewer pairs than this and a median or a share of pops is a handful of samples (the
    // tables of docs/BENCHMARKS.md leave such groups out).
    constexpr size_t kFewPairs = 300;
    std::printf("  %s:\n", what.c_str());
    std::printf("    sliding: median |dt| %.5f, p90 %.5f periods (%.2f, %.2f px), pops (|dt| > 0.25) %.3f %% of %zu matched "
                "sample pairs\n",
                m.sliding.median_dt, m.sliding.p90_dt, m.sliding.median_px, m.sliding.p90_px, 100.0 * m.sliding.pops,
                m.sliding.pairs);
    std::printf("    stretch: %.2f %% of %zu samples within [%.1f, %.1f) px per period; median %.1f px\n",
                100.0 * m.stretch.share_in_band, m.stretch.samples, m.stretch.band_low, 2.0 * m.stretch.band_low,
                m.stretch.median_ds_du);
    if (m.sliding.pairs < kFewPairs)
        std::printf("    (only %zu matched pairs: too few for the sliding figures to mean much)\n", m.sliding.pairs);
    if (baseline && baseline->sliding.pairs > 0)
        std::printf("    ratios to the baseline (this / baseline): median %.3f, p90 %.3f, pops %.3f; in pixels: median %.3f, p90 %.3f\n",
                    ratio(m.sliding.median_dt, baseline->sliding.median_dt),
                    ratio(m.sliding.p90_dt, baseline->sliding.p90_dt), share_ratio(m.sliding.pops, baseline->sliding.pops),
                    ratio(m.sliding.median_px, baseline->sliding.median_px, 0.01),
                    ratio(m.sliding.p90_px, baseline->sliding.p90_px, 0.01));
    // Lines attached to the surface, matched by their surface points (path_dump.h): what
    // moves along the surface, not the surface's own motion on the screen.
    const SlidingStats& o = m.on_surface;
    if (o.pairs > 0) {
        std::printf("    on the surface (lines attached to it, matched by surface point; static models): median |dt| "
                    "%.5f, p90 %.5f periods (%.2f, %.2f px), pops %.3f %% of %zu pairs\n",
                    o.median_dt, o.p90_dt, o.median_px, o.p90_px, 100.0 * o.pops, o.pairs);
        if (o.pairs < kFewPairs) std::printf("      (only %zu pairs on the surface: too few to mean much)\n", o.pairs);
        if (baseline && baseline->on_surface.pairs > 0) {
            const SlidingStats& b = baseline->on_surface;
            std::printf("      ratios to the baseline on the surface: median %.3f, p90 %.3f, pops %.3f; in pixels: median "
                        "%.3f, p90 %.3f\n",
                        ratio(o.median_dt, b.median_dt), ratio(o.p90_dt, b.p90_dt), share_ratio(o.pops, b.pops),
                        ratio(o.median_px, b.median_px, 0.01), ratio(o.p90_px, b.p90_px, 0.01));
        }
    }
    // The pairs where one path of the group lies alone within the match radius (see
    // SlidingMeasure::alone): where paths crowd, the measure compares neighbouring textures.
    const SlidingStats& a = m.sliding.alone;
    if (m.sliding.pairs > 0 && a.pairs < m.sliding.pairs) {
        std::printf("    where one path lies alone (%.1f %% of the pairs): median |dt| %.5f, p90 %.5f periods (%.2f, %.2f px), "
                    "pops %.3f %%\n",
                    100.0 * double(a.pairs) / double(m.sliding.pairs), a.median_dt, a.p90_dt, a.median_px, a.p90_px,
                    100.0 * a.pops);
        if (baseline && baseline->sliding.alone.pairs > 0) {
            const SlidingStats& b = baseline->sliding.alone;
            std::printf("      ratios to the baseline's such pairs: median %.3f, p90 %.3f, pops %.3f; in pixels: median %.3f, "
                        "p90 %.3f\n",
                        ratio(a.median_dt, b.median_dt), ratio(a.p90_dt, b.p90_dt), share_ratio(a.pops, b.pops),
                        ratio(a.median_px, b.median_px, 0.01), ratio(a.p90_px, b.p90_px, 0.01));
        }
    }
}

std::string image_size(const PathDump& dump) { return std::to_string(dump.width) + "x" + std::to_string(dump.height); }

struct ReportOptions {
    std::vector<std::string> folders;
    std::string against;
    std::string baseline;
    std::optional<double> max_p90;
};

std::vector<PathDump> read_dumps(const std::string& folder) {
    if (!std::filesystem::exists(folder)) throw Error(folder + ": no such dump folder");
    if (!std::filesystem::is_directory(folder))
        throw Error(folder + ": not a folder (give the folder of frame_NNNN.json dumps that --dump-paths wrote)");
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".json" && entry.path().filename().string().rfind("frame_", 0) == 0)
            files.push_back(entry.path());
    if (files.empty()) throw Error(folder + ": no frame_NNNN.json dumps");
    std::vector<std::pair<PathDump, std::filesystem::path>> read;
    for (const auto& file : files) {
        PathDump dump = read_path_dump(file);
        if (file.filename() != frame_name(dump.frame, "json"))
            throw Error(file.string() + ": holds frame " + std::to_string(dump.frame) + ", not the frame its name says");
        read.emplace_back(std::move(dump), file);
    }
    // In frame order (by name, frame_10000 would sort before frame_1001).
    std::ranges::sort(read, {}, [](const auto& r) { return r.first.frame; });
    std::vector<PathDump> frames;
    for (auto& [dump, file] : read) {
        // Sliding compares each frame with the one before: a frame missing or a dump of another
        // image size would compare what are not neighbouring frames.
        if (!frames.empty() && dump.frame != frames.back().frame + 1)
            throw Error(folder + ": frame " + std::to_string(dump.frame) + " follows frame " +
                        std::to_string(frames.back().frame) +
                        ": the frames between are missing (sliding compares each frame with the one before)");
        if (!frames.empty() && (dump.width != frames.front().width || dump.height != frames.front().height))
            throw Error(file.string() + ": " + image_size(dump) + ", but frame " + std::to_string(frames.front().frame) +
                        " is " + image_size(frames.front()) + ": the dumps of one render have one size");
        frames.push_back(std::move(dump));
    }
    return frames;
}

// Two renders measured against each other: the same image size, or pixels do not compare.
void require_same_size(const std::string& folder, const std::vector<PathDump>& frames, const std::string& other,
                       const std::vector<PathDump>& other_frames, const char* what) {
    if (frames.front().width != other_frames.front().width || frames.front().height != other_frames.front().height)
        throw Error(folder + " (" + image_size(frames.front()) + ") and " + what + " " + other + " (" +
                    image_size(other_frames.front()) + ") are dumps of different image sizes: render both at one --size");
}

// "24 frames, 0-23": a dump folder's frames, for messages.
std::string frame_span(const std::vector<PathDump>& frames) {
    return std::to_string(frames.size()) + " frames, " + std::to_string(frames.front().frame) + "-" +
           std::to_string(frames.back().frame);
}

// Per frame of `frames` (each must be in `reference`): the phase error; 1 when a p90 passes the bound.
int report_against(const std::string& folder, const std::vector<PathDump>& frames, const ReportOptions& o) {
    const std::vector<PathDump> reference = read_dumps(o.against);
    require_same_size(folder, frames, o.against, reference, "the reference");
    for (const PathDump& frame : frames)  // up front, not after the frames before it are printed
        if (std::none_of(reference.begin(), reference.end(), [&](const PathDump& r) { return r.frame == frame.frame; }))
            throw Error(o.against + ": no dump of frame " + std::to_string(frame.frame) + " (" + folder + " has " +
                        frame_span(frames) + ", the reference " + frame_span(reference) + ")");
    std::printf("%s against %s: phase error |dt| per frame, periods\n", folder.c_str(), o.against.c_str());
    int over = 0;
    for (const PathDump& frame : frames) {
        const auto ref = std::find_if(reference.begin(), reference.end(),
                                      [&](const PathDump& r) { return r.frame == frame.frame; });
        const PhaseError e = measure_phase_error(frame, *ref);
        // No sample near the reference's paths is no measure, not a zero one.
        const bool bad = o.max_p90 && (e.pairs == 0 || e.p90 > *o.max_p90);
        over += bad;
        std::printf("  frame %d: median %.5f, p90 %.5f, max %.5f, %.2f %% over 0.25 (%zu samples)%s\n", frame.frame,
                    e.median, e.p90, e.max, 100.0 * e.over_quarter, e.pairs, !bad ? "" : e.pairs == 0 ? "  NO MATCHED SAMPLES" : "  OVER THE BOUND");
    }
    if (o.max_p90) std::printf("%d frame(s) with p90 over %.4g periods\n", over, *o.max_p90);
    return over > 0 ? 1 : 0;
}

// A baseline is another render of the same shot: the same frames, or the ratios compare
// different motions.
void require_same_frames(const std::string& folder, const std::vector<PathDump>& frames, const std::string& baseline,
                         const std::vector<PathDump>& baseline_frames) {
    bool same = frames.size() == baseline_frames.size();
    for (size_t i = 0; same && i < frames.size(); ++i) same = frames[i].frame == baseline_frames[i].frame;
    if (!same)
        throw Error(folder + " (" + frame_span(frames) + ") and the baseline " + baseline + " (" +
                    frame_span(baseline_frames) + ") are not dumps of the same frames: render the baseline over the "
                    "same --frames");
}

// The groups a report shows: all paths, each line set (each has its own texture and
// tracker, so its own period band) and each line type.
struct Group {
    std::string name;
    std::vector<PathDump> frames;
};
std::vector<Group> groups_of(const std::vector<PathDump>& frames) {
    std::vector<Group> groups{{"all paths", frames}};
    const std::vector<std::string> sets = line_sets_in(frames);
    if (sets.size() > 1)
        for (const std::string& set : sets)
            groups.push_back({set.empty()                ? "layers"
                              : set.starts_with("layers[") ? set
                                                           : "line set " + set,
                              paths_of_line_set(frames, set)});
    const std::vector<std::string> types = types_in(frames);
    if (types.size() > 1)
        for (const std::string& type : types) groups.push_back({"type " + type, paths_of_type(frames, type)});
    return groups;
}

int run_report(const ReportOptions& o) {
    int status = 0;
    std::vector<std::pair<std::string, Measures>> baseline;
    std::vector<PathDump> baseline_frames;
    if (!o.baseline.empty()) {
        baseline_frames = read_dumps(o.baseline);
        for (const Group& g : groups_of(baseline_frames)) baseline.emplace_back(g.name, measure(g.frames));
    }
    for (const std::string& folder : o.folders) {
        const std::vector<PathDump> frames = read_dumps(folder);
        if (!o.baseline.empty()) {
            require_same_frames(folder, frames, o.baseline, baseline_frames);
            require_same_size(folder, frames, o.baseline, baseline_frames, "the baseline");
        }
        if (!o.against.empty()) {
            status = std::max(status, report_against(folder, frames, o));
            continue;
        }
        std::printf("%s: %zu frames%s\n", folder.c_str(), frames.size(),
                    o.baseline.empty() ? "" : (", baseline " + o.baseline).c_str());
        for (const Group& g : groups_of(frames)) {
            const auto base = std::find_if(baseline.begin(), baseline.end(), [&](const auto& b) { return b.first == g.name; });
            print_measures(g.name, measure(g.frames), base == baseline.end() ? nullptr : &base->second);
        }
    }
    return status;
}

}  // namespace

Runner add_coherence_report_command(CLI::App& app) {
    auto o = std::make_shared<ReportOptions>();
    CLI::App* cmd = app.add_subcommand("coherence-report",
                                       "Measure sliding and stretch of strokes from --dump-paths folders; with "
                                       "--against, the phase error of each frame against another render's dumps. "
                                       "Sliding: each sample's phase change |dt| against T on the previous frame's "
                                       "nearest path of the same line set (within 1.5 px), interpolated between that "
                                       "path's samples; its median, 90th percentile and the share over a quarter "
                                       "period (pops), also over the pairs where one path lies alone, and for "
                                       "lines attached to the surface (creases, borders, ridges, ...) with each "
                                       "sample matched by its surface point instead (static models).");
    cmd->add_option("dumps", o->folders, "Dump folders written by `linework render --dump-paths`")->required();
    cmd->add_option("--against", o->against,
                    "Reference dump folder of the same frames (one render of the shot): print per frame how far "
                    "the parameterization is from it (|dt| in periods: median, 90th percentile, max)");
    cmd->add_option("--baseline", o->baseline,
                    "Dump folder of the same shot under another policy (e.g. --param arclength): print each "
                    "measure's ratio to it as well (the coherence goal is median <= 0.2, p90 <= 0.35, pops <= 0.25)");
    cmd->add_option("--max-p90", o->max_p90, "With --against: exit 1 when a frame's 90th percentile passes this "
                                             "many periods (0 or more)")
        ->check(CLI::Validator(
            [](std::string& text) {
                const double v = std::strtod(text.c_str(), nullptr);
                return std::isfinite(v) && v >= 0.0 ? std::string() : "must be a number of periods, 0 or more";
            },
            "PERIODS >= 0"));
    return [o] {
        if (o->max_p90 && o->against.empty()) throw usage_error("--max-p90 needs --against REF");
        if (!o->baseline.empty() && !o->against.empty()) throw usage_error("--baseline and --against are two reports: give one");
        return run_report(*o);
    };
}

}  // namespace lw::cli
