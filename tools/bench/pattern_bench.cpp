#include "pattern_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/random.h"
#include "core/timer.h"
#include "hatch/hatching.h"
#include "pattern/fidelity.h"
#include "pattern/synthesis.h"
#include "vector/stroke_io.h"
#include "stats.h"

namespace lw::bench {

namespace {

constexpr float kPi = 3.14159265f;

Stroke segment(glm::vec2 c, float angle, float length, float width, glm::vec3 color = glm::vec3(0.0f)) {
    const glm::vec2 d = 0.5f * length * glm::vec2(std::cos(angle), std::sin(angle));
    return make_stroke({c - d, c + d}, width, color);
}

// 30 strokes along x whose orientation turns from 20° to 160° (scenes/patterns/orientation_gradient.svg).
std::vector<Stroke> gradient_reference() {
    std::vector<Stroke> s;
    for (int i = 0; i < 30; ++i)
        s.push_back(segment({20.0f + 14.0f * float(i), 40.0f}, (20.0f + 140.0f * float(i) / 29.0f) * kPi / 180.0f, 34.0f, 1.5f));
    return s;
}

// About 100 bars in four directions on a jittered triangular grid (scenes/patterns/multi_bars.svg).
std::vector<Stroke> bars_reference(Rng& rng) {
    std::vector<Stroke> s;
    int row = 0;
    for (float y = 13.0f; y < 260.0f; y += 22.5f, ++row)
        for (float x = row % 2 ? 26.0f : 13.0f; x < 260.0f; x += 26.0f) {
            const float a = float(45 * int(rng.index(4))) * kPi / 180.0f + float(rng.uniform(-0.1, 0.1));
            s.push_back(segment({x + float(rng.uniform(-4, 4)), y + float(rng.uniform(-4, 4))}, a, 16.0f, 2.0f));
        }
    return s;
}

std::vector<Stroke> hatch_training(int n, Rng& rng) {
    std::vector<Stroke> s;
    float x = 14.0f;
    for (int i = 0; i < n; ++i) {
        const float length = 34.0f + 8.0f * std::sin(float(i) / 6.0f) + float(rng.uniform(-3, 3));
        const float slant = (70.0f + 10.0f * std::sin(float(i) / 9.0f) + float(rng.uniform(-4, 4))) * kPi / 180.0f;
        // As scenes/patterns/hatch_training.svg: slightly bent, of slightly varying width.
        Stroke stroke = segment({x, 40.0f + float(rng.uniform(-3, 3))}, slant, length, 1.1f + float(rng.uniform(-0.2, 0.2)));
        const glm::vec2 a = stroke.points[0], b = stroke.points[1], d = glm::normalize(b - a);
        const float bend = float(rng.uniform(-2, 2));
        stroke.points = {a, a + (b - a) / 3.0f + bend * glm::vec2(-d.y, d.x), a + 2.0f * (b - a) / 3.0f + bend * glm::vec2(-d.y, d.x), b};
        stroke.widths.assign(4, stroke.widths[0]);
        s.push_back(std::move(stroke));
        x += 7.5f + 2.0f * std::sin(float(i) / 4.0f) + float(rng.uniform(-1, 1));
    }
    return s;
}

void print(const char* what, const Stats& s, int repeats) {
    std::printf("  %-40s median %8.3f ms  (min %.3f, max %.3f; %d runs)\n", what, s.median, s.min, s.max, repeats);
}

void print_fidelity(const PatternFidelity& f) {
    std::printf("  fidelity: KS D orientation %.3f, length %.3f, thickness %.3f, colour %.3f (α = 0.05 bound %.3f); "
                "NN distance median %.2f (reference %.2f), KS %.3f\n",
                f.ks_orientation, f.ks_length, f.ks_thickness, f.ks_color, f.critical, f.median_nn_output,
                f.median_nn_reference, f.ks_nearest);
}

}  // namespace

CLI::App* add_pattern_bench(CLI::App& app, PatternBenchOptions& o) {
    CLI::App* cmd = app.add_subcommand("pattern", "Stroke patterns by example (Barla et al. 2006): 1D and 2D synthesis time.");
    cmd->add_option("--reference-1d", o.reference_1d, "1D reference stroke file (default: a procedural orientation gradient)");
    cmd->add_option("--reference-2d", o.reference_2d, "2D reference stroke file (default: procedural bars in four directions)");
    cmd->add_option("--elements", o.elements, "2D target seeds")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--path-elements", o.path_elements, "1D target seeds")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--rings-1d", o.rings_1d, "k along the path")->capture_default_str();
    cmd->add_option("--rings-2d", o.rings_2d, "k in the region")->capture_default_str();
    cmd->add_option("--scale-1d", o.scale_1d, "ε for the 1D reference")->capture_default_str();
    cmd->add_option("--scale-2d", o.scale_2d, "ε for the 2D reference")->capture_default_str();
    cmd->add_option("--repeats", o.repeats, "Timed runs")->check(CLI::Range(1, 10000))->capture_default_str();
    cmd->add_option("--seed", o.seed, "Seed")->capture_default_str();
    return cmd;
}

int run_pattern_bench(const PatternBenchOptions& o) {
    std::printf("device: CPU (one thread)\n");
    Rng rng(o.seed);
    for (int pass = 0; pass < 2; ++pass) {
        const bool along = pass == 0;
        const std::string& file = along ? o.reference_1d : o.reference_2d;
        const std::vector<Stroke> reference =
            file.empty() ? (along ? gradient_reference() : bars_reference(rng)) : load_strokes(file).strokes;
        PatternDesc desc{.epsilon = along ? o.scale_1d : o.scale_2d, .rings = along ? o.rings_1d : o.rings_2d, .seed = o.seed};
        const PatternFrame ref_frame = bounding_frame(reference, along);
        const PatternAnalysis probe = analyze_pattern(reference, ref_frame, desc);
        // A target holding the wanted number of elements: N_tar = N_ref·A_tar/A_ref.
        const double scale = double(along ? o.path_elements : o.elements) / double(probe.elements.size());
        PatternFrame target;
        target.along_path = along;
        if (along) {
            const float length = float(double(probe.measure) * scale);
            for (int i = 0; i <= 64; ++i) {  // a gentle wave
                const float x = length * float(i) / 64.0f;
                target.curve.points.push_back({x, 60.0f * std::sin(x / 150.0f)});
            }
            // The wave is longer than its chord: shorten until the arc length is right.
            const float arc = frame_measure(target);
            for (glm::vec2& p : target.curve.points) p.x *= length / arc;
        } else {
            const float side = float(std::sqrt(double(probe.measure) * scale));
            target.curve.points = {{0, 0}, {side, 0}, {side, side}, {0, side}};
            target.curve.closed = true;
        }
        std::vector<double> total, analysis, lloyd, match;
        PatternSynthesis last;
        for (int r = -1; r < o.repeats; ++r) {  // one warm-up
            Timer t;
            const PatternAnalysis ref = analyze_pattern(reference, ref_frame, desc);
            const double a_ms = t.elapsed_ms();
            PatternSynthesis s = synthesize_pattern(ref, target, desc);
            const double ms = t.elapsed_ms();
            if (r < 0) continue;
            total.push_back(ms);
            analysis.push_back(a_ms);
            lloyd.push_back(s.lloyd_ms);
            match.push_back(s.match_ms);
            last = std::move(s);
        }
        std::printf("%s pattern: %zu reference strokes -> %zu elements, %zu target elements, %d rings, %d matched / %d closest\n",
                    along ? "1D" : "2D", reference.size(), probe.elements.size(), last.source.size(), last.rings,
                    last.matched, last.fallback);
        print("analysis + synthesis (what the paper times)", stats(total), o.repeats);
        print("  analysis (clustering, distribution)", stats(analysis), o.repeats);
        print("  Lloyd seeds (30 iterations)", stats(lloyd), o.repeats);
        print("  neighbourhood matching", stats(match), o.repeats);
        print_fidelity(measure_fidelity(probe, last, target, desc.fit));
    }
    return 0;
}

CLI::App* add_hatch_bench(CLI::App& app, HatchBenchOptions& o) {
    CLI::App* cmd = app.add_subcommand("hatch", "Hatching by example (Jodoin et al. 2002): N strokes from a training set.");
    cmd->add_option("--training", o.training, "Training stroke file (default: a procedural sequence)");
    cmd->add_option("--training-size", o.training_size, "Procedural training strokes")->check(CLI::Range(3, 100000))->capture_default_str();
    cmd->add_option("--count", o.count, "Strokes generated")->check(CLI::Range(1, 10000000))->capture_default_str();
    cmd->add_option("--window", o.window, "N-gram window")->capture_default_str();
    cmd->add_option("--repeats", o.repeats, "Timed runs")->check(CLI::Range(1, 10000))->capture_default_str();
    cmd->add_option("--seed", o.seed, "Seed")->capture_default_str();
    return cmd;
}

int run_hatch_bench(const HatchBenchOptions& o) {
    std::printf("device: CPU (one thread)\n");
    Rng training_rng(o.seed);
    const HatchTraining t = make_training(o.training.empty() ? hatch_training(o.training_size, training_rng)
                                                            : load_strokes(o.training).strokes);
    const HatchDesc desc{.count = o.count, .window = o.window, .block = 50};
    std::vector<double> generate, place;
    HatchSequence last;
    for (int r = -1; r < o.repeats; ++r) {
        Rng rng(o.seed + uint64_t(r + 1));
        Timer timer;
        HatchSequence seq = generate_hatching(t, desc, rng);
        const double g = timer.elapsed_ms();
        const std::vector<Stroke> strokes = place_on_line(t, seq.ids);
        const double total = timer.elapsed_ms();
        if (r < 0) continue;
        generate.push_back(g);
        place.push_back(total);
        last = std::move(seq);
    }
    std::printf("hatching: %zu strokes from a training set of %zu (%d varying dimensions), window %d, blocks of 50:\n",
                last.ids.size(), t.strokes.size(), t.vectors.dim, o.window);
    print("N-gram + KL2 per block", stats(generate), o.repeats);
    print("  + laying the strokes out", stats(place), o.repeats);
    double sum = 0, worst = 0;
    int restarts = 0;
    for (const HatchBlock& b : last.blocks) {
        sum += b.kl2;
        worst = std::max(worst, b.kl2);
        restarts += b.attempts - 1;
    }
    std::printf("  KL2 per block: mean %.3f, largest %.3f over %zu blocks; %d restart(s) at the automatic threshold %.2f\n",
                sum / double(last.blocks.size()), worst, last.blocks.size(), restarts, last.threshold);
    return 0;
}

}  // namespace lw::bench
