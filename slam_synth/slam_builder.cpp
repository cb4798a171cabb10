#include "slam_builder.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "seed_pyramid.h"

namespace lw::synth {

namespace {

constexpr int kOrientations = 4, kNeighborhood = 9;

int level_length(double level, int length, int unit) {
    return std::max(unit, int(std::lround(level * length / unit)) * unit);
}

}  // namespace

SlamModel slam_model(int exemplar_rows, const std::string& name) {
    if (exemplar_rows < 4 || exemplar_rows > 64)
        throw Error(name + ": " + std::to_string(exemplar_rows) +
                    " rows; a SLAM exemplar is a stroke 4 to 64 texels wide (rows across the stroke)");
    SlamModel m;
    m.exemplar_rows = exemplar_rows;
    const int doubled = 2 * exemplar_rows;
    m.scales = int(std::floor(std::log2(double(doubled)))) - 2;
    m.unit = 1 << (m.scales + 1);
    m.padded_rows = (doubled + m.unit - 1) / m.unit * m.unit;
    m.pad_top = (m.padded_rows - exemplar_rows) / 2;
    return m;
}

Plane exemplar_ink(const ImageRGBA8& image) {
    Plane ink(image.height, image.width);
    bool translucent = false;
    for (size_t i = 3; i < image.pixels.size(); i += 4) translucent = translucent || image.pixels[i] < 255;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = image.at(x, y);
            ink.at(y, x) = translucent ? float(p[3]) / 255.0f
                                       : 1.0f - (0.2126f * float(p[0]) + 0.7152f * float(p[1]) + 0.0722f * float(p[2])) / 255.0f;
        }
    return ink;
}

Plane pad_exemplar(const Plane& exemplar, const SlamModel& model, int cols) {
    Plane padded(model.padded_rows, cols);
    for (int r = 0; r < exemplar.rows; ++r)
        for (int x = 0; x < cols; ++x) padded.at(r + model.pad_top, x) = exemplar.at(r, x);
    return padded;
}

SlamPlan check_slam_synthesis(const Plane& exemplar, const SlamSynthesisDesc& desc) {
    const std::string& name = desc.exemplar_name;
    SlamPlan plan;
    plan.model = slam_model(exemplar.rows, name);
    const SlamModel& m = plan.model;
    plan.exemplar_cols = exemplar.cols / m.unit * m.unit;
    if (plan.exemplar_cols < m.padded_rows)
        throw Error(name + ": " + std::to_string(exemplar.cols) + " columns; a " + std::to_string(exemplar.rows) +
                    "-row exemplar needs at least " + std::to_string(m.padded_rows) + " along the stroke");
    if (desc.length % (2 * m.unit) != 0 || desc.length < 2 * m.unit)
        throw ParameterError("SLAM length", ": " + std::to_string(desc.length) + " is not a multiple of " +
                                                std::to_string(2 * m.unit) + " (twice the pyramid unit of a " +
                                                std::to_string(exemplar.rows) + "-row exemplar)");
    if (desc.levels < 2) throw ParameterError("SLAM levels", ": at least 2");
    return plan;
}

SlamSynthesis synthesize_slam(const Plane& exemplar, const SlamSynthesisDesc& desc) {
    const std::string& name = desc.exemplar_name;
    SlamSynthesis out;
    const SlamPlan plan = check_slam_synthesis(exemplar, desc);
    out.model = plan.model;
    out.exemplar_cols = plan.exemplar_cols;
    const SlamModel& m = out.model;

    Timer analysis;
    const Plane padded = pad_exemplar(exemplar, m, out.exemplar_cols);
    // Paper alone in the columns synthesized (a blank image, or a transparent PNG whose ink
    // is in its colour while its alpha is 0 everywhere) gives a SLAM that draws nothing:
    // surely not what was meant.
    if (std::all_of(padded.v.begin(), padded.v.end(), [](float ink) { return !(ink > 0.5f / 255.0f); }))
        throw Error(name + ": holds no ink in its first " + std::to_string(out.exemplar_cols) +
                    " columns (every texel is paper; in a PNG with transparency the alpha is the ink), so its SLAM "
                    "would draw nothing");
    out.target = analyze_texture(padded, make_pyramid_geometry(m.padded_rows, out.exemplar_cols, m.scales, kOrientations),
                                 kNeighborhood);
    out.analysis_ms = analysis.elapsed_ms();

    Timer synthesis;
    const Plane half = half_seed(m.padded_rows, desc.length, desc.seed);
    Slam& slam = out.slam;
    slam.levels = desc.levels;
    slam.length = desc.length;
    slam.height = exemplar.rows;
    slam.exemplar = name;
    slam.seed = desc.seed;
    slam.ink.assign(size_t(slam.levels) * size_t(slam.height) * size_t(slam.length), 0.0f);
    out.levels.resize(size_t(desc.levels));
    out.reports.resize(size_t(desc.levels));

    // Stores level i (cropped to the exemplar's rows) and reports it.
    std::mutex report_mutex;
    auto store = [&](int i, Plane cropped, const Timer& timer) {
        const Plane stored = resample_length(cropped, desc.length);
        std::copy(stored.v.begin(), stored.v.end(), slam.ink.begin() + std::ptrdiff_t(size_t(i) * stored.size()));
        const SlamLevelReport report{.index = i, .level = slam.level_value(i), .length = cropped.cols, .ms = timer.elapsed_ms(),
                                     .tiled = i == desc.levels - 1};
        out.levels[size_t(i)] = std::move(cropped);
        std::lock_guard<std::mutex> lock(report_mutex);
        out.reports[size_t(i)] = report;
        if (desc.on_level) desc.on_level(report);
    };

    // Levels 0.5 … below 1.0 are independent: workers take them longest first; each writes
    // only its own slots.
    const int synthesized = desc.levels - 1;
    std::atomic<int> next{0};
    auto work = [&] {
        for (int k = next++; k < synthesized; k = next++) {
            const int i = synthesized - 1 - k;
            Timer timer;
            const int cols = level_length(slam.level_value(i), desc.length, m.unit);
            const PyramidGeometry g = make_pyramid_geometry(m.padded_rows, cols, m.scales, kOrientations);
            const Plane result = synthesize_texture(out.target, seed_level(half, slam.level_value(i), cols), g,
                                                    {.iterations = desc.iterations, .scope = desc.scope});
            Plane cropped(exemplar.rows, cols);
            for (int r = 0; r < exemplar.rows; ++r)
                for (int x = 0; x < cols; ++x) cropped.at(r, x) = std::clamp(result.at(r + m.pad_top, x), 0.0f, 1.0f);
            store(i, std::move(cropped), timer);
        }
    };
    const int threads = std::clamp(desc.threads > 0 ? desc.threads : int(worker_count()), 1, synthesized);
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();

    // Level 1.0: its seed is [W_0.5 W_0.5] exactly, and every step of the synthesis commutes
    // with the half-length shift (circular pyramid, statistics gathered over the whole image),
    // so in exact arithmetic A_1.0 = [A_0.5 A_0.5] (§3.2.1: self-similarity by construction).
    // Synthesized in float at twice the length it differs by rounding that the projections
    // amplify (about 1e-5 on the test's small SLAM, SlamSynthSlam.FullTopLevelIsTheTiledHalfUpToRounding;
    // 1e-4 … 1e-3 on 1024-texel exemplars); built by tiling it is exact, and the longest
    // level costs nothing.
    {
        Timer timer;
        store(desc.levels - 1, tile_twice(out.levels.front()), timer);
    }
    out.synthesis_ms = synthesis.elapsed_ms();
    return out;
}

ImageRGBA8 contact_sheet(const SlamSynthesis& s, const Plane& exemplar) {
    constexpr int gap = 4;
    int width = exemplar.cols, height = exemplar.rows + gap;
    for (const Plane& level : s.levels) {
        width = std::max(width, level.cols);
        height += level.rows + gap;
    }
    ImageRGBA8 sheet{.width = width, .height = height, .pixels = std::vector<uint8_t>(size_t(width) * size_t(height) * 4, 255)};
    auto draw = [&](const Plane& p, int top) {
        for (int r = 0; r < p.rows; ++r)
            for (int x = 0; x < p.cols; ++x) {
                const uint8_t v = uint8_t(std::lround(255.0 * (1.0 - std::clamp(double(p.at(r, x)), 0.0, 1.0))));
                uint8_t* px = sheet.at(x, top + r);
                px[0] = px[1] = px[2] = v;
            }
    };
    int top = 0;
    draw(exemplar, top);
    top += exemplar.rows + gap;
    for (const Plane& level : s.levels) {
        draw(level, top);
        top += level.rows + gap;
    }
    return sheet;
}

}  // namespace lw::synth
