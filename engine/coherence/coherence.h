// engine/coherence/coherence.h — coherent stroke parameterization across frames.
//
// Bénard et al. 2010, §4. Each visible path has T(s) = ρ·s + φ over its screen arclength s
// (pixels from the path's first sample). Per frame f:
//   1. votes: every sample of the new paths is carried to frame f − 1 and reads the splat
//      buffer (Σ w·t, Σ w) there; where Σ w > 0 it votes (Σwt/Σw, s) — §4.2. Creases,
//      borders and layers go where their surface point was (moved with the mesh, projected
//      with frame f − 1's camera); a silhouette takes that point's motion across itself and
//      the view's zoom along itself; a suggestive contour stays where it is, moved by the
//      zoom alone (gather_votes says why);
//   2. fit: RANSAC per path (ransac_gpu.h) finds each path's direction and the runs of votes
//      that disagree (merged paths, split there at the middle of each seam, and the pieces
//      fitted and split again, so that a path joining three earlier ones keeps all three
//      phases: §4.2's merge popping; path_split.h); ρ is not the path's own, as in §4.2, but
//      one scale for the set carried through the view's zoom, and each path fits its phase φ
//      to its votes (fit_phase; no votes: φ = 0). Why: update_view_scale in coherence.cpp;
//   3. splat: every sample writes t = T(s) as a sprite of radius δ,
//      w = clamp(1 − d/δ, 0, 1), additive, into a float buffer kept for frame f + 1 — §4.1
//      (the extra channels, Σ w·(c − pixel), place each vote where its average was taken).
// RANSAC and the splat run on the device (a compute dispatch; an RGBA32F render target read
// back) or, on CPU devices, on the host (fit_paths_reference; the splat read at the votes'
// pixels alone, splat_grid.h): ComputeSite. The scale and the phase fit are host code on
// both.
// The two comparison policies of the issue: arclength (tiling, T = s·κ / Lmax) and stretch
// (T = s/L, one texture stretched over the path, no level folding).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "coherence/path_param.h"
#include "coherence/path_split.h"
#include "coherence/ransac.h"
#include "coherence/ransac_gpu.h"
#include "coherence/splat_grid.h"
#include "coherence/still_paths.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "gpu/timestamps.h"
#include "lines/visibility.h"
#include "scene/camera.h"
#include "types/slam_level.h"
#include "types/line_set.h"  // ParamPolicy

namespace lw {

struct CoherenceParams {
    ParamPolicy policy = ParamPolicy::Coherent;
    float splat_radius_px = 4.0f;   // δ of the splat sprites
    float length_scale = 1.0f;      // κ: 1 draws the texture at its native pixel scale
    float slam_length_px = 1024.0f; // Lmax: the SLAM's texture length
    // Visible paths shorter than this are dropped (not drawn as strokes, splatted or dumped):
    // fragments of a few pixels show a sliver of the texture and are re-extracted differently
    // every frame (on the orbit of BENCHMARKS.md they hold half the samples).
    float min_stroke_length_px = 8.0f;
    // The texture is a SLAM whose level follows ρ: T's scale starts at ρ0/√2, in the middle
    // of the level range, not at ρ0 = κ/Lmax, where the level changes between 1 and 0.5 (see
    // update_view_scale). Without levels (dashes, displacement) it starts at ρ0, so that
    // their lengths on screen are as given.
    bool slam_levels = true;
    RansacParams ransac;
};

// Paths with their parameterization (a vector layer's frame, for dumps).
struct ParameterizedPaths {
    std::vector<ScreenPath> paths;
    std::vector<PathParam> params;  // per path
};

// A visible path shorter than params.min_stroke_length_px: a fragment the tracker drops (it
// shows only a sliver of the texture; a vector layer draws such strokes solid instead).
[[nodiscard]] bool too_short_for_texture(const ScreenPath& path, const CoherenceParams& params);

// Arclength of a sample along its path (the path's own origin).
inline float path_arclength(const ScreenPath& path, size_t sample) { return path.samples[sample].s - path.samples.front().s; }

// The surface the paths' samples lie on at this frame (welded positions and faces; the
// topology must stay the same from frame to frame). The tracker keeps a copy of the
// positions to carry the next frame's samples back.
struct SurfaceFrame {
    const std::vector<glm::vec3>* positions = nullptr;
    const std::vector<glm::uvec3>* faces = nullptr;
};

// The path resampled where its parameterization crosses multiples of ρ·spacing: samples
// about `spacing` pixels apart that sit at the same texture phases from frame to frame (so
// stroke vertices and dumped samples stay put on a path that does not slide). Attributes
// are interpolated linearly between the original samples; `s` keeps the path's arclength.
[[nodiscard]] ScreenPath resample_at_phase(const ScreenPath& path, const PathParam& param, float spacing);

// CPU reference of the splat: (Σ w·t, Σ w, Σ w·(c − pixel centre)) per pixel for sprites of
// radius δ centred at c.
[[nodiscard]] std::vector<glm::vec4> splat_reference(const std::vector<ScreenPath>& paths,
                                                     const std::vector<PathParam>& params, int width, int height,
                                                     float radius);

class CoherenceTracker {
public:
    // `site` Host (the default on CPU devices, see ComputeSite): the splat is splat_reference's
    // sums, read where the votes need them (splat_grid.h), and RANSAC is fit_paths_reference;
    // Device: the GPU splat and fit.
    CoherenceTracker(const Context& ctx, uint32_t width, uint32_t height, ComputeSite site);
    CoherenceTracker(const Context& ctx, uint32_t width, uint32_t height)
        : CoherenceTracker(ctx, width, height, ctx.preferred_compute_site()) {}

    // Parameterizes this frame's paths (hidden ones get the set's scale and phase 0) and
    // splats them for the next frame. Visible paths shorter than min_stroke_length_px are
    // removed, closed loops may be rotated to start at the seam they inherited, and paths that
    // merged pieces of different earlier paths split (see path_split.h), so `paths` may
    // change; the result has one entry per path after. Under the previous frame's camera and
    // with the same `params` (and scale), a path equal to one of that frame keeps its pieces
    // and parameters (still_paths.h). `timer` (optional) gets "ransac" and "splat" on the
    // device site; on the host site, and for an empty splat, it is not used.
    [[nodiscard]] std::vector<PathParam> update(std::vector<ScreenPath>& paths, const CameraMatrices& camera,
                                                const SurfaceFrame& surface, const CoherenceParams& params,
                                                GpuTimer* timer = nullptr);

    // Forgets the previous frame (a cut).
    void reset() {
        has_previous_ = false;
        view_rho_ = 0.0f;
        still_ = {};
    }

    // What the next update() needs of the frames before it, small enough to keep beside an
    // offline render (`linework render --resume`): the last splat's sprites (centre, T) and
    // radius, and the camera they were drawn with. The surface positions are the caller's to
    // restore (the mesh posed at that frame).
    struct State {
        bool has_previous = false;
        CameraMatrices camera;
        float radius = 0.0f;
        std::vector<glm::vec3> sprites;  // x, y in pixels; T
        float view_rho = 0.0f;  // the scale of every path, carried through the view's zoom (0: not set)
        StillRecord still;      // the last frame's paths, under a still camera (still_paths.h)
    };
    [[nodiscard]] State state() const {
        return {has_previous_, previous_camera_, last_radius_, last_sprites_, view_rho_, still_};
    }
    // Splats the state's sprites again (the same buffer, bit for bit, on the same device and
    // compute site).
    void restore(const State& state, const SurfaceFrame& surface);

    // The last splat, whole frame (rows it did not reach are zero); for tests.
    [[nodiscard]] std::vector<glm::vec4> splat_buffer() const;

private:
    // Each visible sample's surface point a frame earlier (moved with its face), projected
    // with the previous camera: its pixel and clip w, and its NDC depth.
    struct Carried {
        uint32_t path, sample;
        glm::vec3 pixel;
        float ndc_depth;
    };
    [[nodiscard]] std::vector<Carried> carry_back(const std::vector<ScreenPath>& paths, const SurfaceFrame& surface) const;
    // The view's zoom since the previous frame (how many more pixels a unit of length covers
    // now at the samples' median depth on the previous view's axis) and that point's pixel now.
    struct ViewZoom {
        float zoom = 1.0f;
        glm::vec2 centre;
    };
    [[nodiscard]] ViewZoom view_zoom(const std::vector<Carried>& carried, const CameraMatrices& camera) const;
    // The votes of the carried samples, each line type moved as the comments there say.
    [[nodiscard]] VoteSet gather_votes(const std::vector<ScreenPath>& paths, const std::vector<Carried>& carried,
                                       const ViewZoom& view) const;
    // The coherent policy's votes, fit and splits for `paths` (in place: loops rotated, merged
    // paths split); per path after, its parameters. `origins` (optional): where each piece
    // came from; `rotations` (optional, per path before): where its loop was made to start.
    [[nodiscard]] std::vector<PathParam> parameterize(std::vector<ScreenPath>& paths, const CameraMatrices& camera,
                                                      const SurfaceFrame& surface, const CoherenceParams& params,
                                                      std::vector<PieceOrigin>* origins,
                                                      std::vector<uint32_t>* rotations);
    // The paths found in the record (`still_`, emptied for a moving view) keep their pieces
    // and parameters, the others are parameterized; the record for the next frame is kept.
    [[nodiscard]] std::vector<PathParam> update_keeping_still_paths(std::vector<ScreenPath>& paths,
                                                                    const CameraMatrices& camera,
                                                                    const SurfaceFrame& surface,
                                                                    const CoherenceParams& params);
    // The set's scale (every path's |ρ|), carried through the view's zoom.
    void update_view_scale(VoteSet& votes, float zoom, const CoherenceParams& params);
    void splat(const std::vector<ScreenPath>& paths, const std::vector<PathParam>& params, float radius,
               GpuTimer* timer);
    void splat_sprites(const std::vector<glm::vec3>& sprites, float radius, GpuTimer* timer);
    // The device's last splat's (Σ w·t, Σ w, Σ w·(c − pixel)) at a pixel, read in place from
    // the readback.
    [[nodiscard]] glm::vec4 splat_at(uint32_t x, uint32_t y) const;

    const Context* ctx_;
    ComputeSite site_;
    uint32_t width_, height_;
    Image splat_image_;
    GraphicsPipeline splat_pipeline_;
    Buffer splat_readback_;  // the last splat, rows [splat_first_row_, + splat_rows_) valid
    uint32_t splat_first_row_ = 0, splat_rows_ = 0;
    Buffer sprite_buffer_;   // host-visible, kept from frame to frame
    SplatSums host_splat_;                 // ComputeSite::Host: the last splat, read where needed
    RansacFitter fitter_;
    bool has_previous_ = false;
    CameraMatrices previous_camera_;
    std::vector<glm::vec3> previous_positions_;
    std::vector<glm::vec3> last_sprites_;  // what made it (state())
    float last_radius_ = 0.0f;
    float view_rho_ = 0.0f;  // ρ of every path (0: not set yet)
    StillRecord still_;      // the last frame's paths, when its camera was the one before it
};

}  // namespace lw
