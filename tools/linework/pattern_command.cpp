// `linework pattern` — a stroke pattern synthesized from a reference along a path or in a region
// (Barla et al. 2006; engine/pattern/synthesis.h).
#include <cstdio>
#include <memory>
#include <optional>

#include "commands.h"
#include "cli_numbers.h"
#include "core/error.h"
#include "core/log.h"
#include "core/timer.h"
#include "pattern/synthesis.h"
#include "vector/curve.h"
#include "vector/stroke_io.h"

namespace lw::cli {

namespace {

struct PatternOptions {
    std::string reference, output, path, region, ref_path, ref_region, fit = "contour";
    std::optional<float> scale;
    int rings = 0;
    float variation = 0.0f;
    int lloyd = 30;
    uint64_t seed = 1;
};

PatternFrame load_frame(const std::string& file, bool along_path) {
    PatternFrame f;
    f.along_path = along_path;
    f.curve = load_curve(file);
    if (!along_path) {
        if (f.curve.points.size() < 3) throw Error(file + ": a region needs at least three points");
        f.curve.closed = true;
    }
    // Checks the curve now, so that its problems name its file.
    if (naming(file, [&] { return frame_measure(f); }) <= 0.0f)
        throw Error(file + (along_path ? ": the path has no length" : ": the region has no area"));
    return f;
}

int run_pattern(const PatternOptions& o) {
    if (!is_stroke_file_path(o.output)) throw usage_error("-o: " + o.output + ": strokes are written as .svg or .json");
    refuse_writing_over_input(o.output, {o.reference, o.path, o.region, o.ref_path, o.ref_region});
    const bool along_path = !o.path.empty();
    if (along_path == !o.region.empty()) throw usage_error("give exactly one of --path and --region");
    if (!o.ref_path.empty() && !along_path) throw usage_error("--ref-path goes with --path (use --ref-region with --region)");
    if (!o.ref_region.empty() && along_path) throw usage_error("--ref-region goes with --region (use --ref-path with --path)");

    Timer total;
    StrokeSet reference = load_strokes(o.reference);
    const PatternFrame target = load_frame(along_path ? o.path : o.region, along_path);
    const std::string ref_frame_file = along_path ? o.ref_path : o.ref_region;
    const PatternFrame ref_frame = ref_frame_file.empty() ? bounding_frame(reference.strokes, along_path)
                                                          : load_frame(ref_frame_file, along_path);

    PatternDesc desc;
    desc.epsilon = o.scale.value_or(0.0f);
    desc.fit = o.fit == "skeleton" ? FitMode::Skeleton : FitMode::Contour;
    desc.rings = o.rings;
    desc.variation = o.variation;
    desc.seed = o.seed;
    desc.lloyd_iterations = o.lloyd;

    Timer analysis_timer;
    const PatternAnalysis ref = naming(o.reference, [&] { return analyze_pattern(reference.strokes, ref_frame, desc); });
    const double analysis_ms = analysis_timer.elapsed_ms();
    if (const std::string w = pattern_analysis_warning(ref); !w.empty()) log_warning(o.reference + ": " + w);
    size_t edges = 0;
    for (const auto& n : ref.distribution.neighbours) edges += n.size();
    // The reference's own frame: its bounding box's (default), or the file given for it.
    const std::string frame = ref_frame_file.empty() ? "its bounding box's" : ref_frame_file + "'s";
    std::printf("reference: %s, %zu strokes -> %zu elements at scale ε = %g (%s fit), %s %s %s %.1f, %zu neighbour pairs "
                "(%.1f ms)\n",
                o.reference.c_str(), ref.strokes.size(), ref.elements.size(), double(ref.epsilon), o.fit.c_str(),
                along_path ? "a chain along" : "an unskewed Delaunay graph in", frame.c_str(),
                along_path ? "midline, of length" : "region, of area", double(ref.measure), edges / 2, analysis_ms);
    std::fflush(stdout);

    const PatternSynthesis s = naming(along_path ? o.path : o.region, [&] { return synthesize_pattern(ref, target, desc); });
    std::printf("target: %s %.1f, %zu seeds (N_ref·A_tar/A_ref) after %d Lloyd iterations (%.1f ms)\n",
                along_path ? "path length" : "region area", double(frame_measure(target)), s.source.size(), o.lloyd,
                s.lloyd_ms);
    // The first element, at the centre, has no neighbours placed yet: it is neither.
    std::printf("synthesis: %d-ring neighbourhoods, the centre element and then %d elements that matched a reference "
                "neighbourhood, %d that took the closest (%.1f ms); variation %g\n",
                s.rings, s.matched, s.fallback, s.match_ms, double(o.variation));
    save_strokes(o.output, s.strokes);
    std::printf("wrote %s (%zu strokes, %.1f ms in all)\n", o.output.c_str(), s.strokes.strokes.size(), total.elapsed_ms());
    return 0;
}

}  // namespace

Runner add_pattern_command(CLI::App& app) {
    auto o = std::make_shared<PatternOptions>();
    CLI::App* cmd = app.add_subcommand(
        "pattern",
        "Synthesize a stroke pattern like a reference, along a path (1D) or in a region (2D)\n"
        "(Barla, Breslav, Thollot, Sillion & Markosian 2006). The reference's strokes are grouped\n"
        "into elements at scale ε (proximity and continuation of their PCA boxes); the elements'\n"
        "arrangement (a chain, or a Delaunay triangulation of unskewed triangles) is measured; the\n"
        "target is seeded by Lloyd's method and filled from its centre outward, each seed taking a\n"
        "reference element whose k-ring neighbourhood matches the elements already placed.\n"
        "Example: linework pattern scenes/patterns/flowers.svg --region scenes/curves/circle.json -o out.svg");
    cmd->add_option("reference", o->reference,
                    "Reference strokes: SVG (path M L H V C S Q T Z, polyline, polygon, line, rect, circle, ellipse,\n"
                    "use; stroke, stroke-width)\n"
                    "or JSON {\"strokes\": [{\"points\": [[x, y], ...], \"width\": w, \"color\": [r, g, b]}]}")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output strokes: .svg (one <polyline>/<path> per stroke) or .json")
        ->required()
        ->check(output_file());
    cmd->add_option("--path", o->path,
                    "Synthesize along this path (1D): JSON {\"points\": [[x, y], ...], \"closed\": bool} or an SVG\n"
                    "file of one curve: a <path> (commands M, L, H, V, C, S, Q, T, Z), polyline or basic shape, transforms\n"
                    "applied (as for `linework ribbon --curve`)");
    cmd->add_option("--region", o->region, "Synthesize inside this region (2D): a curve file as for --path, read as a polygon");
    cmd->add_option("--ref-path", o->ref_path,
                    "The reference's own path (default: the long midline of its bounding box)");
    cmd->add_option("--ref-region", o->ref_region, "The reference's own region (default: its bounding box)");
    cmd->add_option("--scale", o->scale,
                    "ε: the distance below which strokes are seen as one element (drawing units; default:\n"
                    "twice the median stroke width, so only touching strokes group). Crosses and flowers\n"
                    "need about half their size")
        ->check(positive("drawing units"));
    cmd->add_option("--rings", o->rings,
                    "k: neighbourhood size in graph steps (default 3 along a path, 2 in a region; 5 follows\n"
                    "smooth changes of orientation, length or thickness along a path)")
        ->check(CLI::Range(1, 12));
    cmd->add_option("--variation", o->variation,
                    "v in [0, 1]: swap each element's orientation, length and width for similar reference\n"
                    "values, and bring back the reference's irregular positions (§3.3; default 0: none)")
        ->check(within(0.0, 1.0));
    cmd->add_option("--fit", o->fit, "Fit element boxes to stroke skeletons or to their contours (width included)")
        ->check(CLI::IsMember({"skeleton", "contour"}))
        ->capture_default_str();
    cmd->add_option("--lloyd", o->lloyd, "Lloyd iterations for the seeds")->check(CLI::Range(0, 1000))->capture_default_str();
    cmd->add_option("--seed", o->seed, "Seed of the random choices (seeds, picks among matches, variation)")->check(seed())
        ->capture_default_str();
    return [o] { return run_pattern(*o); };
}

}  // namespace lw::cli
