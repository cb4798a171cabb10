#include "ribbon/synthesize.h"

#include "core/error.h"
#include "core/timer.h"
#include "ribbon/dp_gpu.h"
#include "ribbon/dp_reference.h"
#include "ribbon/problem.h"
#include "ribbon/ribbon_draw.h"

namespace lw {

RibbonSynthesis synthesize_ribbon(const Context& ctx, const Exemplar& exemplar, const ArclengthCurve& curve,
                                  const RibbonSynthesisDesc& desc) {
    RibbonSynthesis out;
    out.ribbon = build_ribbon(curve, desc.params);
    const RibbonRenderer renderer(ctx);

    out.forbidden = desc.avoid_overlaps ? renderer.avoidance_map(out.ribbon, desc.width, desc.height)
                                        : ForbiddenMask{desc.width, desc.height,
                                                        std::vector<uint8_t>(size_t(desc.width) * size_t(desc.height))};
    if (desc.user_forbidden) merge_forbidden(out.forbidden, *desc.user_forbidden);
    const DpProblem problem = build_problem(exemplar, out.ribbon, &out.forbidden);

    Timer dp_timer;
    const bool host = desc.site.value_or(ctx.preferred_compute_site()) == ComputeSite::Host;
    std::optional<RibbonDpGpu> gpu;  // its pipelines only when it runs
    if (!host) gpu.emplace(ctx);
    const DpRunner runner = host ? DpRunner(run_dp_reference) : gpu->runner();
    DpRunOptions options;
    options.progress = desc.progress;
    // The valid lists for the baselines: the runner keeps them in its tables, so run through
    // a wrapper that remembers the first (unconstrained) run's.
    std::vector<std::vector<uint32_t>> valid;
    const DpRunner remembering = [&](const DpProblem& p, const DpRunOptions& o) {
        DpTables t = runner(p, o);
        if (valid.empty()) valid = t.valid;
        return t;
    };
    out.solution = solve_ribbon(problem, remembering, desc.seed, options);
    out.dp_ms = dp_timer.elapsed_ms();
    out.dp_on_host = host;

    out.greedy_cost = path_cost(problem, greedy_positions(problem, valid, out.solution.positions.front()));
    out.random_cost = path_cost(problem, random_positions(problem, valid, desc.seed));

    if (desc.stitch) {
        Timer stitch_timer;
        out.stitch = host ? stitch_reference(problem, out.solution.positions)
                                    : RibbonStitcherGpu(ctx).stitch(problem, out.solution.positions);
        out.stitch_ms = stitch_timer.elapsed_ms();
    }
    Timer draw_timer;
    out.image = renderer.draw(out.ribbon, exemplar, out.solution.positions, out.stitch ? &*out.stitch : nullptr,
                              &out.forbidden, desc.width, desc.height);
    out.draw_ms = draw_timer.elapsed_ms();
    return out;
}

}  // namespace lw
