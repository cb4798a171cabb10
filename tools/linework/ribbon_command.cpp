// `linework ribbon` — a structured pattern synthesized along a curve (Zhou et al. 2013), and
// `linework ribbon-exemplar` — the procedural exemplars it is shown with.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "cli_numbers.h"
#include "core/error.h"
#include "core/text.h"
#include "core/timer.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "ribbon/avoidance.h"
#include "ribbon/dp.h"
#include "vector/curve.h"
#include "ribbon/exemplar_gen.h"
#include "ribbon/problem.h"
#include "ribbon/synthesize.h"

namespace lw::cli {

namespace {

struct RibbonOptions {
    std::string exemplar, curve, output, dump, avoid, size;
    std::string device = "auto", compute = "auto";
    bool closed = false, stitch = false, transparent = false, reference = false, validation = false;
    std::optional<float> piece, width, scale;
    uint64_t seed = 1;
};

void write_dump(const std::string& path, const RibbonSynthesis& s) {
    using json = nlohmann::json;
    json positions = json::array();
    for (const glm::ivec2& u : s.solution.positions) positions.push_back({u.x, u.y});
    const json dump = {{"pieces", s.solution.positions.size()},
                       {"positions", positions},
                       {"seam_costs", s.solution.seam_costs},
                       {"total_cost", s.solution.total_cost},
                       {"greedy_cost", s.greedy_cost},
                       {"random_cost", s.random_cost},
                       {"valid_counts", s.solution.valid_counts},
                       {"row_ms", s.solution.row_ms}};
    std::ofstream out(path);
    out << dump.dump(1) << "\n";
    if (!out) throw Error(path + ": cannot write the DP dump");
}

// Over white unless the background should stay transparent.
ImageRGBA8 composite(const ImageRGBA8& image, bool transparent) {
    ImageRGBA8 out = image;
    if (!transparent) composite_over_white(out);
    return out;
}

int run_ribbon(const RibbonOptions& o) {
    // Flags first (exit code 2), then files (exit code 1 naming the file).
    refuse_writing_over_input(o.output, {o.exemplar, o.avoid});
    std::optional<glm::ivec2> size;
    if (!o.size.empty()) size = parse_size(o.size, "--size");
    const DeviceChoice device = parse_device_choice(o.device);
    // --reference is --compute host; auto: the context's choice (the host on CPU devices).
    if (o.reference && o.compute == "device") throw usage_error("--reference and --compute device contradict");
    const std::optional<ComputeSite> site = o.reference ? ComputeSite::Host : parse_compute_site(o.compute);

    const ImageRGBA8 image = read_image_rgba8(o.exemplar);
    const Exemplar exemplar = make_exemplar(image, o.exemplar);
    Curve2D curve_points = load_curve(o.curve);
    curve_points.closed = curve_points.closed || o.closed;
    const ArclengthCurve curve = naming(o.curve, [&] { return ArclengthCurve(curve_points); });

    RibbonSynthesisDesc desc;
    desc.params.scale = o.scale.value_or(default_ribbon_scale(exemplar));
    desc.params.width = o.width.value_or(desc.params.scale);
    desc.params.piece = o.piece.value_or(std::max(1.0f, std::round(desc.params.width / 2.0f)));
    desc.seed = o.seed;
    desc.stitch = o.stitch;
    desc.site = site;
    // A width too large for any image is named by the flag it came from: without --width, --scale.
    const Ribbon ribbon = flags_named({{"ribbon width", o.width ? "--width" : "--scale"}},
                                      [&] { return build_ribbon(curve, desc.params); });
    if (!size) size = default_ribbon_size(ribbon, curve_points.page, o.curve);
    desc.width = size->x;
    desc.height = size->y;
    // The curve is in output pixels: a --size that misses the ribbon would give a blank image,
    // one that cuts it a part.
    if (!o.size.empty()) flags_named({{"ribbon size", "--size"}}, [&] { check_ribbon_in_image(ribbon, size->x, size->y); });
    const glm::vec2 lo = ribbon.min_corner(), hi = ribbon.max_corner();
    if (lo.x < 0.0f || lo.y < 0.0f || hi.x > float(size->x) || hi.y > float(size->y))
        std::fprintf(stderr, "ribbon: warning: the ribbon (x %d to %d, y %d to %d) reaches past the %dx%d image and is cut there\n",
                     int(std::floor(lo.x)), int(std::ceil(hi.x)), int(std::floor(lo.y)), int(std::ceil(hi.y)), size->x,
                     size->y);
    ForbiddenMask user;
    if (!o.avoid.empty()) {
        user = forbidden_from_image(read_image_rgba8(o.avoid));
        if (user.width != size->x || user.height != size->y)
            throw Error(o.avoid + ": the avoidance map is " + std::to_string(user.width) + "x" +
                        std::to_string(user.height) + " but the output is " + std::to_string(size->x) + "x" +
                        std::to_string(size->y));
        desc.user_forbidden = &user;
    }

    const bool validation = o.validation || validation_from_environment();
    Context ctx({.device = device, .validation = validation, .compute_site = site});
    std::printf("device: %s\n", ctx.info().describe().c_str());
    std::printf("exemplar: %s (%dx%d), curve: %s (%.1f px, %s)\n", o.exemplar.c_str(), exemplar.width,
                exemplar.height, o.curve.c_str(), double(curve.length()), curve.closed() ? "closed" : "open");
    std::printf("ribbon: width b = %g px, piece δ = %g px, s = %g exemplar px across (C = %d), %zu pieces%s, size %dx%d\n",
                double(desc.params.width), double(desc.params.piece), double(desc.params.scale), ribbon.samples,
                ribbon.pieces.size(), curve.closed() ? " + terminal" : "", size->x, size->y);
    std::fflush(stdout);

    Timer progress_timer, total_timer;
    desc.progress = [&](size_t row, size_t rows, uint32_t valid) {
        if (row + 1 == rows || progress_timer.elapsed_ms() > 2000.0) {
            std::fprintf(stderr, "ribbon: row %zu/%zu, %u valid positions, %.1f s\n", row + 1, rows, valid,
                         total_timer.elapsed_ms() / 1000.0);
            progress_timer.reset();
        }
    };
    // (An exemplar the pieces cannot use is named: δ is --piece, s is --scale.)
    const RibbonSynthesis s = naming(o.exemplar, [&] { return synthesize_ribbon(ctx, exemplar, curve, desc); });

    double mean_row = 0.0;
    for (double ms : s.solution.row_ms) mean_row += ms;
    if (!s.solution.row_ms.empty()) mean_row /= double(s.solution.row_ms.size());
    std::printf("avoidance: %zu forbidden pixels\n", s.forbidden.count());
    std::printf("dp (%s): %.0f ms, %.2f ms per row; seam cost %.1f (greedy %.1f, random %.1f)%s\n",
                s.dp_on_host ? "C++, on the host" : "Vulkan compute", s.dp_ms, mean_row, double(s.solution.total_cost),
                double(s.greedy_cost), double(s.random_cost),
                curve.closed() ? (s.solution.closed_by_first_dp ? "; cycle from one DP" : "; cycle from a fixed-start DP")
                               : "");
    // Rows that needed a looser validity rule (engine/ribbon/problem.h), the first 8 named.
    const LooserRows looser = looser_rows(s.solution);
    const auto first_rows = [](const std::vector<size_t>& rows) {
        std::string text;
        for (size_t i = 0; i < std::min<size_t>(rows.size(), 8); ++i) text += (i ? ", " : "") + std::to_string(rows[i]);
        return text;
    };
    const std::string cut = first_rows(looser.cut), empty = first_rows(looser.empty);
    const size_t cut_count = looser.cut.size(), empty_count = looser.empty.size();
    if (empty_count > 0)
        std::printf("avoidance: %zu pieces (%s%s) lie where no ink can avoid the overlap and are left empty\n",
                    empty_count, empty.c_str(), empty_count > 8 ? ", …" : "");
    std::fflush(stdout);
    if (const std::optional<std::string> blank = blank_ribbon_reason(s.solution, o.avoid))
        throw Error(o.curve + ": " + *blank + "; nothing was written");
    const std::optional<ScaleShortfall> shortfall = cut_count > 0 ? scale_shortfall(exemplar, s.ribbon.scale) : std::nullopt;
    if (shortfall)
        std::fprintf(stderr,
                     "ribbon: warning: %zu of %zu pieces (%s%s) cannot hold the whole pattern and may cut it: --scale "
                     "%s is too small for the pattern's %d rows and one above and below (--scale %d holds them); "
                     "leave --scale out for the default, %s\n",
                     cut_count, s.solution.rules.size(), cut.c_str(), cut_count > 8 ? ", …" : "",
                     number_text(s.ribbon.scale).c_str(), shortfall->band_rows, shortfall->least_scale,
                     number_text(shortfall->default_scale).c_str());
    else if (cut_count > 0)
        std::fprintf(stderr,
                     "ribbon: warning: %zu of %zu pieces (%s%s) cannot hold the whole pattern where the curve bends "
                     "this tightly and may cut it; a shorter --piece or a wider --scale helps\n",
                     cut_count, s.solution.rules.size(), cut.c_str(), cut_count > 8 ? ", …" : "");
    if (s.stitch)
        std::printf("stitch: seam error %.1f -> %.1f (%.0f ms)\n", double(s.stitch->total_before()),
                    double(s.stitch->total_after()), s.stitch_ms);
    write_png(o.output, composite(s.image, o.transparent));
    std::printf("wrote %s\n", o.output.c_str());
    if (!o.dump.empty()) {
        write_dump(o.dump, s);
        std::printf("wrote %s\n", o.dump.c_str());
    }
    return exit_code_after_validation(ctx, validation);
}

struct ExemplarOptions {
    std::string name, output, size = "192x64";
    uint64_t seed = 1;
};

int run_exemplar(const ExemplarOptions& o) {
    const glm::ivec2 size = parse_size(o.size, "--size", {16, 16}, {4096, 4096});  // generate_exemplar's bounds
    const ImageRGBA8 image =
        flags_named({{"exemplar size", "--size"}}, [&] { return generate_exemplar(o.name, size.x, size.y, o.seed); });
    write_png(o.output, image);
    std::printf("wrote %s (%s, %dx%d, seed %llu)\n", o.output.c_str(), o.name.c_str(), size.x, size.y,
                static_cast<unsigned long long>(o.seed));
    return 0;
}

}  // namespace

Runner add_ribbon_command(CLI::App& app) {
    auto o = std::make_shared<RibbonOptions>();
    CLI::App* cmd = app.add_subcommand(
        "ribbon",
        "Synthesize a structured pattern along a curve (Zhou, Lasram & Lefebvre 2013).\n"
        "The ribbon of width b around the curve is cut into pieces of length δ; each piece\n"
        "copies a part of the exemplar (rotated to follow the curve, never stretched), chosen\n"
        "by dynamic programming (a Vulkan compute pass on a GPU, its C++ reference on a CPU\n"
        "device; --compute) so that neighbouring pieces match along their\n"
        "shared edge. Where the ribbon folds over or overlaps itself the pattern is kept out.\n"
        "Example: linework ribbon scenes/exemplars/chain.png --curve scenes/curves/wave.json -o chain.png");
    cmd->add_option("exemplar", o->exemplar, "Exemplar image: RGBA, alpha outlines the pattern (alpha >= 128 is ink)")
        ->required();
    cmd->add_option("--curve", o->curve,
                    "Curve in output pixels: JSON {\"points\": [[x, y], ...], \"closed\": bool} or an SVG\n"
                    "file of one curve: a <path> (commands M, L, H, V, C, S, Q, T, Z), polyline or basic shape, transforms\n"
                    "applied")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output PNG")->required()->check(output_file(".png"));
    cmd->add_flag("--closed", o->closed, "Close the curve: the last piece connects back to the first (§1.5)");
    cmd->add_flag("--stitch", o->stitch, "Deform pieces so that their edges align better (§3.2, P = 32)");
    cmd->add_option("--piece", o->piece, "Piece length δ along the curve, output pixels (default: b / 2; much shorter pieces\n"
                    "let the DP repeat near-uniform stretches of the exemplar)")
        ->check(positive("pixels"));
    cmd->add_option("--width", o->width, "Ribbon width b, output pixels (default: s, one exemplar pixel per pixel)")
        ->check(positive("pixels"));
    cmd->add_option("--scale", o->scale,
                    "s: exemplar pixels across the ribbon; the pattern is drawn at b / s output pixels per\n"
                    "exemplar pixel (default: the height of the exemplar's band of opaque rows + 2 + 30 %:\n"
                    "the slack is how far the pattern may wander from the curve)")
        ->check(positive("exemplar pixels"));
    cmd->add_option("--seed", o->seed,
                    "Breaks ties among equally cheap results (common with periodic exemplars along straight stretches, "
                    "rare elsewhere: most curves give the same image for every seed), and draws the random baseline")->check(seed())
        ->capture_default_str();
    cmd->add_option("--size", o->size, "Output size WxH (default: the ribbon's extent from the origin, and at least an SVG curve's\n"
                                         "page: its width and height)");
    cmd->add_option("--dump-dp", o->dump,
                    "Write the DP result as JSON: pieces, positions [[u, v], ...], seam_costs, total_cost,\n"
                    "greedy_cost, random_cost, valid_counts, row_ms")
        ->check(output_file(".json"));
    cmd->add_option("--avoid", o->avoid, "Avoidance map (PNG of the output size): alpha >= 128 is forbidden (§3.1)");
    cmd->add_flag("--transparent", o->transparent, "Keep the transparent background (default: over white)");
    cmd->add_option("--compute", o->compute,
                    "Where the DP and stitching run: auto (the host on CPU devices such as lavapipe, where the "
                    "threaded C++ DP is faster; the device on GPUs), device (Vulkan compute), or host (C++)")
        ->capture_default_str();
    cmd->add_flag("--reference", o->reference, "The same as --compute host: the plain C++ DP and stitching");
    cmd->add_option("--device", o->device, "auto, cpu (lavapipe), gpu, or an index from `linework devices`")
        ->capture_default_str();
    cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also LINEWORK_VALIDATION=1)");
    return [o] {
        return flags_named({{"ribbon width", "--width"}, {"ribbon piece", "--piece"}, {"ribbon scale", "--scale"}},
                           [&] { return run_ribbon(*o); });
    };
}

Runner add_ribbon_exemplar_command(CLI::App& app) {
    auto o = std::make_shared<ExemplarOptions>();
    CLI::App* cmd = app.add_subcommand(
        "ribbon-exemplar",
        "Generate a structured-pattern exemplar for `linework ribbon` from signed distances:\n"
        "chain, lace, zigzag, beads or rope (sizes and spacings vary with the seed).");
    cmd->add_option("name", o->name, "Pattern")->required()->check(CLI::IsMember(exemplar_names()));
    cmd->add_option("-o,--output", o->output, "Output PNG")->required()->check(output_file(".png"));
    cmd->add_option("--size", o->size, "Size WxH, 16x16 to 4096x4096")->capture_default_str();
    cmd->add_option("--seed", o->seed, "Variation seed")->check(seed())->capture_default_str();
    return [o] { return run_exemplar(*o); };
}

}  // namespace lw::cli
