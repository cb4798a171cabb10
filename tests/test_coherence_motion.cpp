// Coherence per kind of motion (issue 19): an orbit of a static model, a skinned clip under
// a still camera and under an orbit, and a dolly. Each renders a short, small shot twice —
// coherent and the tiling (arclength) policy — and compares the sliding measures of the path
// dumps (coherence/path_dump.h), as `linework coherence-report --baseline` does for the
// 120-frame table of docs/BENCHMARKS.md ("Coherence on every model"). The bounds are that
// table's goals where these short shots reach them, and otherwise the figures measured here
// with a margin (each test says which), so that a regression of the cause fixed for issue 19
// (a per-path scale wandering from frame to frame) fails them.
#include <string>

#include "coherence/path_dump.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

class CoherenceMotion : public test::GpuTest {
protected:
    // `frames` frames of the scene (JSON, paths relative to tests/data/models), its camera
    // path's progress over them, 24 frames a second; every line set's dumps.
    std::vector<PathDump> shot(const std::string& json, ParamPolicy policy, int frames) {
        const SceneDesc desc = parse_scene_json(json, test::data_dir() / "models/shot.json");
        SessionOptions options = default_session_options(desc);
        options.coherent = true;
        options.coherence.policy = policy;
        SceneSession session(ctx(), desc, options);
        std::vector<PathDump> dumps;
        for (int f = 0; f < frames; ++f) {
            const FrameRequest request{.when = {.progress = float(f) / float(frames - 1), .seconds = float(f) / 24.0f},
                                       .outputs = {.color = false}};
            const Frame frame = session.frame(request);
            const std::vector<DumpGroup> groups = line_set_dump_groups(frame);
            dumps.push_back(parse_path_dump(path_dump_json(f, desc.width, desc.height, groups), "frame"));
        }
        return dumps;
    }
    struct Ratios {
        double median = 0.0, p90 = 0.0, pops = 0.0;  // in periods of each policy's T, as the issue's goals
        double p90_px = 0.0;                          // in pixels along the path
    };
    // Each textured line set (silhouettes, suggestive contours) against the same set drawn
    // with the tiling policy; the stretch condition (one factor-of-2 band) on each.
    struct Bounds {
        double median, p90, pops;
    };
    // `sets`: the line sets the shot has enough of (the low-poly Fox shows few suggestive
    // contours); each is held to `bounds`.
    std::vector<Ratios> compare(const std::string& json, int frames, std::initializer_list<const char*> sets,
                                Bounds bounds) {
        const std::vector<PathDump> coherent = shot(json, ParamPolicy::Coherent, frames);
        const std::vector<PathDump> tiling = shot(json, ParamPolicy::Arclength, frames);
        // As `coherence-report --baseline`: below 1e-4 periods nothing slides measurably (ratio
        // 0); a share of pops counts from the first pop.
        auto ratio = [](double a, double b, double nothing = 1e-4) { return a <= nothing ? 0.0 : b > nothing ? a / b : 1e9; };
        std::vector<Ratios> out;
        for (const char* set : sets) {
            const SlidingMeasure c = measure_sliding(paths_of_line_set(coherent, set));
            const SlidingMeasure t = measure_sliding(paths_of_line_set(tiling, set));
            const StretchMeasure band = measure_stretch(paths_of_line_set(coherent, set));
            const Ratios r{ratio(c.median_dt, t.median_dt), ratio(c.p90_dt, t.p90_dt), ratio(c.pops, t.pops, 0.0),
                           ratio(c.p90_px, t.p90_px)};
            std::printf("%s: coherent median %.5f p90 %.5f (%.2f px) pops %.4f (%zu pairs), in band %.4f; arclength "
                        "median %.5f p90 %.5f (%.2f px) pops %.4f; ratios %.3f %.3f %.3f, p90 in pixels %.3f\n",
                        set, c.median_dt, c.p90_dt, c.p90_px, c.pops, c.pairs, band.share_in_band, t.median_dt, t.p90_dt,
                        t.p90_px, t.pops, r.median, r.p90, r.pops, r.p90_px);
            RecordProperty(std::string(set) + "_ratios",
                           std::to_string(r.median) + " " + std::to_string(r.p90) + " " + std::to_string(r.pops));
            EXPECT_GT(c.pairs, 300u) << set;
            EXPECT_GE(band.share_in_band, 0.99) << set;
            EXPECT_LE(r.median, bounds.median) << set;
            EXPECT_LE(r.p90, bounds.p90) << set;
            EXPECT_LE(r.pops, bounds.pops) << set;
            out.push_back(r);
        }
        return out;
    }
};

const char* const kStrokes = R"("lines": {"silhouette": {"slam": "../../../scenes/slams/dots.exr"},
                                          "suggestive": {"slam": "../../../scenes/slams/dots.exr"}})";

std::string scene(const std::string& model, const std::string& extra) {
    return R"({"model": ")" + model + R"(", "size": [320, 240], "samples": 1, )" + kStrokes +
           (extra.empty() ? "" : ", " + extra) + "}";
}

// A static model, the camera turning 3° a frame (the table's orbit, shorter and smaller).
// Measured: silhouettes 0.000 / 0.150 / 0.35 (median / p90 / pops against the tiling policy;
// 0.69 pops before merged paths were split again at the middle of each seam, 0.48 before
// four rejected votes at a path's end made a piece), suggestive contours 0.000 / 0.112 / 0.00; with each path's own fitted scale (before issue 19) the
// median ratio was about 2/3. The pops left at this size are T-junctions, where the measure
// matches a line ending behind another with that other line (0.04 on the 640×480 table).
TEST_F(CoherenceMotion, StaticModelUnderAnOrbit) {
    compare(scene("LeePerrySmith/LeePerrySmith.glb", R"("camera": {"orbit": 69})"), 24, {"silhouette", "suggestive"},
            {.median = 0.2, .p90 = 0.35, .pops = 0.5});
}

// A skinned clip under a still camera: the lines move with the pose alone. Measured: 0.000 /
// 0.245 / 0.208 (0.166 / 0.230 before the perspective-correct samples and the pieces at a
// path's end; 0.274 / 0.276 before seams stayed put): the goals.
TEST_F(CoherenceMotion, SkinnedClipUnderAStillCamera) {
    // The Fox three-quarters from the side, so that its legs swing across the view.
    compare(scene("Fox/Fox.glb", R"("camera": {"eye": [191.7, 106.5, 142.7], "target": [0, 39.4, -10.7]},
                                   "animation": {"clip": "Walk"})"),
            24, {"silhouette"}, {.median = 0.2, .p90 = 0.35, .pops = 0.25});
}

// The same clip while the camera turns 3° a frame. Measured: 0.000 / 0.236 / 0.163 (0.191
// pops before the pieces at a path's end; 0.330 / 0.285 before merged paths were split again
// at the middle of each seam): the goals.
TEST_F(CoherenceMotion, SkinnedClipUnderAnOrbit) {
    compare(scene("Fox/Fox.glb", R"("camera": {"eye": [191.7, 106.5, 142.7], "target": [0, 39.4, -10.7], "orbit": 69},
                                   "animation": {"clip": "Walk"})"),
            24, {"silhouette"}, {.median = 0.2, .p90 = 0.35, .pops = 0.25});
}

// A low-poly model under a still camera: nothing moves, so no texture may slide. A box's
// edge is one segment running away from the eye; its samples' surface points were mixed at
// screen fractions, pixels off their samples (up to 49 px on test_visibility's line), so the
// tracker read its votes elsewhere and the creases slid 4–8 px a frame. Measured since the
// fix: 0 px at every pair (the tiling policy: 0 as well).
TEST_F(CoherenceMotion, LowPolyEdgesUnderAStillCamera) {
    const std::vector<PathDump> dumps = shot(
        scene("BoxTextured/BoxTextured.glb", R"("camera": {"eye": [1.3, 0.9, 1.7], "target": [0, 0, 0]})"),
        ParamPolicy::Coherent, 8);
    const SlidingMeasure creases = measure_sliding(paths_of_line_set(dumps, "crease"));
    std::printf("creases: median %.4f px, p90 %.4f px, pops %.4f of %zu pairs\n", creases.median_px, creases.p90_px,
                creases.pops, creases.pairs);
    EXPECT_GT(creases.pairs, 300u);
    EXPECT_LT(creases.p90_px, 0.05);
    EXPECT_EQ(creases.pops, 0.0);
    // Nor on the surface (the dump's surface points read back).
    const SlidingStats on_surface = measure_sliding_on_surface(paths_of_line_set(dumps, "crease"));
    EXPECT_GT(on_surface.pairs, 300u);
    EXPECT_LT(on_surface.p90_px, 0.05);
    // From the third frame on the paths are kept as they were (coherence/still_paths.h); the
    // second is the one fitted to the first's splat, where misplaced votes showed.
    const SlidingMeasure refit =
        measure_sliding(paths_of_line_set(std::vector<PathDump>(dumps.begin(), dumps.begin() + 2), "crease"));
    EXPECT_GT(refit.pairs, 50u);
    EXPECT_LT(refit.p90_px, 0.05);
}

// The box's creases under an orbit, measured on the surface (path_dump.h): the screen
// measure counts a crease carried across the screen by its surface as sliding under either
// policy (median ratios 0.4–1 on the 640×480 orbits, BENCHMARKS "Creases on the surface"); on the surface the tiling
// policy's texture slides as the crease foreshortens about the path's start, and ours about
// the phase its votes agree on, half as far. Measured: median 0.36 against 0.91 px, p90 2.1
// against 3.7 px (ratios 0.40, 0.57); anchored at the path's start as tiling is, ratios of 1.
TEST_F(CoherenceMotion, CreasesOnTheSurfaceUnderAnOrbit) {
    const std::string json = scene("BoxTextured/BoxTextured.glb", R"("camera": {"eye": [1.3, 0.9, 1.7], "target": [0, 0, 0], "orbit": 69})");
    const SlidingStats coherent = measure_sliding_on_surface(paths_of_line_set(shot(json, ParamPolicy::Coherent, 24), "crease"));
    const SlidingStats tiling = measure_sliding_on_surface(paths_of_line_set(shot(json, ParamPolicy::Arclength, 24), "crease"));
    std::printf("creases on the surface: coherent median %.3f px, p90 %.3f px, pops %.4f (%zu pairs); arclength median "
                "%.3f px, p90 %.3f px, pops %.4f (%zu pairs)\n",
                coherent.median_px, coherent.p90_px, coherent.pops, coherent.pairs, tiling.median_px, tiling.p90_px,
                tiling.pops, tiling.pairs);
    EXPECT_GT(coherent.pairs, 300u);
    EXPECT_GT(tiling.pairs, 300u);
    EXPECT_LE(coherent.median_px, 0.55 * tiling.median_px);
    EXPECT_LE(coherent.p90_px, 0.75 * tiling.p90_px);
}

// A dolly toward the model: the texture's scale follows the view's zoom (the SLAM level
// changes) and its phase stays on the lines. Measured: silhouettes 0.503 / 0.196 / 0.26,
// suggestive contours 0.334 / 0.460 / 0.62. (Against the nearest sample a frame earlier,
// before the measure interpolated between samples: 0.307 / 0.208 / 0.33 and 0.343 / 0.587 /
// 0.65. The tiling policy's silhouette median was one sample spacing, 2 px, and is 1.2 px
// between samples; ours stayed at 0.8 px. The median was 0.147 until shared ends compared
// with their own path.) Not the orbit's goals: a perspective dolly
// zooms near parts more than far ones, and a contour's votes carry only the zoom at the
// subject's median depth along the line (coherence.cpp, gather_votes).
TEST_F(CoherenceMotion, Dolly) {
    compare(scene("spot/spot.glb", R"("camera_path": {"keyframes": [
        {"time": 0, "eye": [0.3, 0.4, 3.2], "target": [0, 0.1, 0]},
        {"time": 1, "eye": [0.2, 0.3, 2.0], "target": [0, 0.1, 0]}]})"),
            24, {"silhouette", "suggestive"}, {.median = 0.6, .p90 = 0.75, .pops = 0.9});
}

}  // namespace
}  // namespace lw
