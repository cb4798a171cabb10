// engine/session/scene_session.h — a scene made live: what `linework render`, `linework view`
// (and a farm task, or a Python session) drive frame by frame.
//
// Input:  a `SceneDesc` (scene file or bare model, with the caller's overrides applied),
//         a Vulkan context and `SessionOptions` (target format, the base coherence
//         parameters, whether frames are parameterized without strokes).
// Output: per `frame(request)` the finished `Frame`: the scene posed at the request's time,
//         seen from its camera (the scene's, its camera path's, or the request's), every
//         line set drawn in order, ribbons synthesized over the read-back colour, layers
//         composited, with depth, paths per set and per-stage times. `snapshot()` and
//         `restore()` carry the whole temporal state (every line set's and layer's tracker)
//         so that a resumed or distributed render continues exactly.
//
// Everything is loaded once at construction (models, SLAMs, ribbon exemplars, layers), so a
// bad file fails before any frame is drawn; errors name the file or the scene key.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "coherence/coherence.h"
#include "gpu/context.h"
#include "lines/svg_export.h"
#include "coherence/path_dump.h"
#include "render/frame_renderer.h"
#include "ribbon/exemplar.h"
#include "ribbon/ribbon_strokes.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "session/scene_layers.h"
#include "stroke/slam.h"

namespace lw {

// A partial camera from the command line: each part given replaces the scene's (or the
// framing camera's), so that a user can move the eye alone.
struct CameraOverride {
    std::optional<glm::vec3> eye, target, up;
};

struct SessionOptions {
    VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM;  // B8G8R8A8 for a viewer's swapchain
    int subdivide = 0;          // midpoint subdivisions of the merged mesh (benchmarks)
    // Parameterize every line set even where no style needs it (path dumps, a policy the
    // user chose); sets with a SLAM, dashes or displacement are parameterized anyway.
    bool coherent = false;
    CoherenceParams coherence;  // base of every set's and layer's: policy, splat radius, RANSAC
    float length_scale = 0.0f;  // κ for every set and layer (0: each its own, square texels)
    CameraOverride camera;
};

// What `linework render` runs a scene with when no option changes it: the scene's
// "coherence" keys, and where it gives none δ twice the scene's sample spacing (§4.1) and
// the rest at their defaults.
[[nodiscard]] SessionOptions default_session_options(const SceneDesc& desc);

struct FrameRequest {
    PathTime when;                      // animation clock and progress over the range
    std::optional<ViewCamera> camera;   // a viewer's camera; absent: the scene's at `when`
    FrameOutputs outputs;               // colour and depth readback
    uint64_t seed = 1;                  // ribbon synthesis
    // A viewer presents the target: ribbons drawn on the host are written back into it.
    bool ribbons_to_target = false;
};

class SceneSession {
public:
    SceneSession(const Context& ctx, SceneDesc desc, const SessionOptions& options = {});
    // With the models in memory (meshes given as arrays) instead of `desc.models`' files;
    // the description then names each by its model's path.
    SceneSession(const Context& ctx, SceneDesc desc, const SessionOptions& options, std::vector<Model> models);

    const SceneDesc& desc() const { return desc_; }
    const LoadedScene& scene() const { return scene_; }
    bool has_model() const { return !desc_.models.empty(); }
    bool animated() const { return animated_; }
    float duration_s() const;
    // The frames a render draws without a --frames: the scene's, else the clips' length.
    FrameRange default_frames() const;
    const std::vector<LineSetDesc>& line_sets() const { return sets_; }
    bool has_ribbons() const;

    // The lines as edited live (the viewer's panel): thresholds, sets on and off (the
    // shorthand's type switches or a set's "enabled"), widths and colours. A set's SLAM or ribbon and a crease angle are fixed at construction (or
    // after rebuild_lines()).
    LinesDesc& lines() { return desc_.lines; }
    SurfaceStyle& surface() { return desc_.style; }
    CoherenceParams& coherence() { return options_.coherence; }  // the base (viewer: policy, radius)
    // Whether a frame carries a parameterization on to the next (a set or layer reads T, or
    // every set is parameterized).
    [[nodiscard]] bool parameterized() const;
    // Whether what a frame draws depends on the frames before it: a set or layer whose strokes
    // read T under the coherent policy (votes from the previous frame's splat).
    [[nodiscard]] bool strokes_carry_state() const;
    // The line mesh again (a new crease angle); temporal state starts afresh.
    void rebuild_lines();
    // New lines as a whole (a Python script's edit): SLAMs and ribbon exemplars the new sets
    // name are read (a bad file throws and leaves the session as it was), and the line mesh
    // is rebuilt when lines are switched on or off or the crease angle changed.
    void set_lines(const LinesDesc& lines);
    // Whether a set's SLAM is drawn (the viewer's style switch; the SLAM stays loaded).
    void set_line_set_textured(size_t set, bool on);
    bool line_set_textured(size_t set) const;
    bool line_set_has_slam(size_t set) const { return set < slams_.size() && slams_[set].has_value(); }

    // The camera a frame at `when` sees without a request's override.
    [[nodiscard]] ViewCamera camera_at(const PathTime& when) const;

    [[nodiscard]] Frame frame(const FrameRequest& request) {
        begin_frame(request);
        return finish_frame();
    }
    // frame() in two halves (FrameRenderer::begin and finish): a viewer begins frame f + 1,
    // then finishes frame f, so that f's host stages run while the device draws f + 1's
    // surface. Frames finish in the order they began; at most two are in flight.
    void begin_frame(const FrameRequest& request);
    [[nodiscard]] Frame finish_frame();
    [[nodiscard]] size_t frames_in_flight() const { return pending_.size(); }
    // The last frame's ribbon synthesis per line set that has one.
    struct RibbonReport {
        std::string line_set;
        RibbonStrokeStats stats;
    };
    const std::vector<RibbonReport>& ribbon_reports() const { return ribbon_reports_; }

    // Needs no frame in flight.
    void resize(uint32_t width, uint32_t height);
    const RenderTarget& target() const { return renderer_.target(); }
    const FrameRenderer& renderer() const { return renderer_; }

    // The temporal state after the last frame, and the frame it belongs to.
    struct Snapshot {
        float seconds = 0.0f;  // the pose it was taken in
        FrameRenderer::CoherenceSnapshot coherence;
        // What it was taken of (0: not recorded, as in a render's saved state, whose options
        // signature is checked instead): restoring into another image size or line mesh fails.
        uint32_t width = 0, height = 0;
        size_t welded_vertices = 0;
    };
    [[nodiscard]] Snapshot snapshot() const;
    // Checks the snapshot against this session (sets, layers, and the size and line mesh when
    // recorded) before changing anything; throws lw::Error("snapshot: ...") when it is another's.
    void restore(const Snapshot& snapshot);

    // The frame's lines as SVG groups (one per line set, in order) and dump groups.
    [[nodiscard]] std::vector<SvgGroup> svg_groups(const Frame& frame, bool with_shapes = true) const;
    [[nodiscard]] std::vector<DumpGroup> dump_groups(const Frame& frame) const;

private:
    void load_line_styles();
    void pose(float seconds);
    void build_meshes();
    // Whether line set `set` is drawn and its strokes read T (a SLAM drawn, dashes, displacement).
    [[nodiscard]] bool reads_parameter(size_t set) const;
    [[nodiscard]] TriangleMesh posed_mesh(float seconds) const;
    double draw_ribbons(Frame& frame, uint64_t seed);

    struct Pending {  // what finish_frame() needs of a frame's request
        float seconds = 0.0f;
        uint64_t seed = 1;
        bool ribbons = false, color = false, ribbons_to_target = false;
    };
    std::vector<Pending> pending_;  // oldest first
    const Context* ctx_;
    SceneDesc desc_;
    SessionOptions options_;
    LoadedScene scene_;
    std::vector<LineSetDesc> sets_;              // effective_line_sets of the scene
    std::vector<std::optional<Slam>> slams_;     // per set
    std::vector<bool> textured_;                 // per set: its SLAM is drawn
    std::vector<std::optional<Exemplar>> ribbons_;  // per set
    SceneLayers layers_;
    FrameRenderer renderer_;
    bool animated_ = false;
    std::optional<float> posed_at_;              // the pose the renderer has
    bool textures_loaded_ = false;               // the renderer has the materials' textures (decoded on first need)
    float last_seconds_ = 0.0f;
    std::vector<RibbonReport> ribbon_reports_;
};

}  // namespace lw
