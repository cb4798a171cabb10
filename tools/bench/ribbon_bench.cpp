#include "ribbon_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "cli_numbers.h"
#include "core/timer.h"
#include "gpu/context.h"
#include "ribbon/dp_gpu.h"
#include "ribbon/dp_reference.h"
#include "ribbon/exemplar_gen.h"
#include "ribbon/problem.h"
#include "stats.h"

namespace lw::bench {

CLI::App* add_ribbon_bench(CLI::App& app, RibbonBenchOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "ribbon", "Ribbon DP: wall time per row (extractColumns … updateTableRow, readback) on a gentle arc.");
    cmd->add_option("--pattern", o.pattern, "Generated exemplar: chain, lace, zigzag, beads, rope")
        ->check(CLI::IsMember(exemplar_names()))
        ->capture_default_str();
    cmd->add_option("--exemplar-size", o.exemplar_size, "Exemplar size WxH")->capture_default_str();
    cmd->add_option("--rows", o.rows, "DP rows timed, after one warm-up row")->check(CLI::Range(1, 1000))->capture_default_str();
    cmd->add_option("--piece", o.piece, "Piece length δ (default b / 2)")->check(lw::cli::positive("pixels"));
    cmd->add_option("--scale", o.scale, "s, exemplar pixels across the ribbon (default: the exemplar height)")
        ->check(lw::cli::positive("exemplar pixels"));
    cmd->add_flag("--reference", o.reference, "Also time the plain C++ reference on the same rows");
    cmd->add_option("--device", o.device, "auto, cpu, gpu or an index")->capture_default_str();
    return cmd;
}

int run_ribbon_bench(const RibbonBenchOptions& o) {
    int w = 0, h = 0;
    if (std::sscanf(o.exemplar_size.c_str(), "%dx%d", &w, &h) != 2)
        throw usage_error("--exemplar-size: expected WxH, got \"" + o.exemplar_size + "\"");
    const Exemplar exemplar = make_exemplar(generate_exemplar(o.pattern, w, h, 1), o.pattern);
    Context ctx({.device = parse_device_choice(o.device)});
    std::printf("device: %s\n", ctx.info().describe().c_str());

    const float s = o.scale > 0.0f ? o.scale : default_ribbon_scale(exemplar);
    const float b = s, delta = o.piece > 0.0f ? o.piece : std::max(1.0f, std::round(b / 2.0f));
    // A gentle arc (radius 6b) long enough for warm-up + timed rows.
    const float radius = 6.0f * b, length = delta * float(o.rows + 1) + 0.5f * delta;
    Curve2D arc;
    for (int i = 0; i <= 256; ++i) {
        const float a = length / radius * float(i) / 256.0f;
        arc.points.push_back({radius * std::sin(a), radius * (1.0f - std::cos(a))});
    }
    const Ribbon ribbon = build_ribbon(ArclengthCurve(arc), {.width = b, .piece = delta, .scale = s});
    const DpProblem problem = build_problem(exemplar, ribbon);
    std::printf("exemplar: %s %dx%d, s = b = %g, δ = %g, C = %d, U = %u positions, %zu rows\n", o.pattern.c_str(), w,
                h, double(s), double(delta), ribbon.samples, problem.position_count(), problem.rows.size());

    RibbonDpGpu gpu(ctx);
    Timer total;
    const DpTables t = gpu.run(problem);
    const double total_ms = total.elapsed_ms();
    std::vector<double> rows(t.row_ms.begin() + 1, t.row_ms.end());  // row 1 is the warm-up
    double valid = 0;
    for (const auto& v : t.valid) valid += double(v.size());
    valid /= double(t.valid.size());
    const Stats g = stats(rows);
    std::printf("valid positions: %.0f per row on average (%.1f %% of U)\n", valid,
                100.0 * valid / problem.position_count());
    std::printf("GPU DP row (wall, submit to readback): median %.2f ms (min %.2f, max %.2f) over %zu rows; whole run %.0f ms\n",
                g.median, g.min, g.max, rows.size(), total_ms);
    if (o.reference) {
        const DpTables r = run_dp_reference(problem);
        const Stats c = stats(std::vector<double>(r.row_ms.begin() + 1, r.row_ms.end()));
        std::printf("C++ reference row: median %.2f ms (min %.2f, max %.2f)\n", c.median, c.min, c.max);
        if (r.valid != t.valid || r.last_costs != t.last_costs) throw Error("the GPU and the C++ reference disagree");
    }
    return 0;
}

}  // namespace lw::bench
