// engine/render/frame_renderer.h — one stylized 3D frame, all stages in order.
//
// Input:  a world-space mesh (set once, or again after a deformation), camera matrices and
//         the eye, the surface style and the scene's `LinesDesc` with its line sets.
// Output: `Frame` — the final image (surface + lines) and depth read back, the visible and
//         hidden screen paths, per line set the paths it drew with their parameterization
//         (for SVG, dumps and ribbons), and timings per stage.
//
// Line sets (render/line_sets.h) are drawn in order; each selects its own copy of the runs
// and, when the frame is parameterized, fits it with its own tracker and coherence
// parameters (its SLAM's length, its κ) — one set's texture never sets another's period.
//
// A frame is two submissions: (1) surface pass + line extraction compute pass, depth and
// segments read back (on a CPU device the host runs the reference extraction while the
// device draws the surface); (2) after chaining and visibility on the CPU, the line pass
// over the colour target, colour read back. See README "Architecture".
//
// Frames may overlap (begin/finish): frame f's host stages after the depth — chaining,
// visibility, parameterization, stroke geometry — run while the device draws frame f + 1's
// surface into the other of two targets. On lavapipe the surface pass's vertex stage keeps
// one core of two busy and leaves the other to them.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "coherence/coherence.h"
#include "coherence/path_dump.h"
#include "gpu/context.h"
#include "gpu/timestamps.h"
#include "lines/extract_gpu.h"
#include "lines/extract_reference.h"
#include "lines/intersections.h"
#include "lines/line_mesh.h"
#include "lines/svg_export.h"
#include "lines/visibility.h"
#include "render/layer_pass.h"
#include "render/line_pass.h"
#include "render/line_sets.h"
#include "render/surface_pass.h"
#include "scene/style.h"
#include "stroke/slam.h"
#include "stroke/slam_texture.h"
#include "stroke/stroke_pass.h"

namespace lw {

struct FrameTimings {
    double total_ms = 0.0;       // wall, whole frame
    double extract_ms = 0.0;     // CPU: the host extraction (CPU devices) and intersection lines, else 0
    double chain_ms = 0.0;       // CPU
    double visibility_ms = 0.0;  // CPU
    double coherence_ms = 0.0;   // votes + RANSAC + splat, wall
    std::vector<PassTime> gpu;   // per GPU pass (surface, lines extract, lines draw)
};

struct FrameReadback {
    ImageRGBA8 color;
    std::vector<float> depth;  // window-space depth in [0, 1], row-major, 1 = background
    float znear = 0.0f, zfar = 0.0f;  // the planes `depth` was drawn with (eye depth from it)
};

// What to read back besides what the line stages need.
struct FrameOutputs {
    bool color = true;   // the final image (false: a viewer or a benchmark that shows nothing)
    bool depth = false;  // the depth buffer (EXR output)
    // false: only what the temporal state needs (depth, lines, visibility, each set's votes,
    // RANSAC and splat; layers' trackers): no shading, no strokes built or drawn, no colour.
    // A farm's first phase runs frames so (§4 of the SLAM paper: the state is the splat).
    bool draw = true;
};

// One line set's share of a frame.
struct LineSetFrame {
    std::string name;
    size_t set = 0;                 // index in effective_line_sets(lines)
    std::vector<ScreenPath> paths;  // what it draws: the runs it selected, after its chaining
                                    // options and, when its strokes read T (a SLAM, dashes,
                                    // displacement) and the frame is parameterized, its tracker
                                    // (fragments dropped, merged paths split) and resampled at
                                    // fixed texture phases
    std::vector<PathParam> params;  // per path of `paths` when it was parameterized so, else empty
    // A set whose strokes read no T, parameterized for the record (FrameInput::
    // parameterize_every_set: path dumps, a policy asked for): the tracker's pieces at fixed
    // phases and their parameters. It is drawn from `paths`, as when nothing is parameterized:
    // the pieces would draw caps and tapers at every cut, and a diagnostic must not change
    // the picture.
    std::vector<ScreenPath> recorded_paths;
    std::vector<PathParam> recorded_params;
    bool recorded = false;          // the set was fitted for the record (the two above are its fit)
    CoherenceParams coherence;      // what the set was parameterized with
};


struct Frame {
    FrameReadback image;
    std::vector<LineSegment> segments;
    std::vector<LinePath> paths;
    std::vector<ScreenPath> screen_paths;  // every visible and hidden run, scene spacing
    std::vector<LineSetFrame> sets;        // per enabled line set, in drawing order
    std::vector<LayerResult> layers;  // per vector layer, when the frame had layers
    FrameTimings timings;
};

// What a frame is drawn with: render()'s arguments, kept with a frame in flight.
struct FrameInput {
    CameraMatrices camera;
    glm::vec3 eye{0.0f};
    SurfaceStyle surface;
    LinesDesc lines;
    FrameOutputs outputs;
    std::optional<CoherenceParams> coherence;
    // With `coherence`: parameterize every set (path dumps, a policy asked for), or only the
    // sets whose strokes read T (a SLAM, dashes, displacement). A plain set fitted because
    // another set is dashed would be cut into the tracker's pieces, and drawn differently.
    bool parameterize_every_set = true;
    std::optional<std::vector<LayerFrame>> layers;
};

// The frame's lines as SVG groups: one per line set of `lines` (effective_line_sets), in
// drawing order, with its colour and width; sets that drew nothing are empty groups.
// `with_shapes` off: the paths alone (what tools reading the lines back need; building the
// strokes' shapes costs as much again as drawing them).
[[nodiscard]] std::vector<SvgGroup> line_set_svg_groups(const LinesDesc& lines, const Frame& frame, bool with_shapes = true);
// Each set's parameterized paths, as `--dump-paths` writes them (coherence/path_dump.h): the
// drawn ones, or those recorded for a set drawn without its parameter.
[[nodiscard]] std::vector<DumpGroup> line_set_dump_groups(const Frame& frame);

class FrameRenderer {
public:
    // `color_format`: the target's (RenderTarget); colour read back is RGBA whatever it is.
    FrameRenderer(const Context& ctx, uint32_t width, uint32_t height, VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM);

    // The materials of the meshes given next (render/surface_materials.h): what colours and
    // cuts the surface. Call it before set_mesh, which groups the triangles by material; again
    // with the same faces and their textures decoded (the textures are uploaded, the mesh
    // kept). Materials for different faces while a mesh is set are an error.
    void set_materials(const SurfaceMaterials& materials);

    // Uploads the mesh for shading and, when lines are wanted, builds and uploads its
    // line mesh (weld, curvature, feature edges) with `crease_angle_deg`, its curvature
    // fitted as `curvature` says (LineParams::curvature). A `still` mesh (one deform() will
    // not move) is searched for closed surfaces once, so that views skip the back faces no
    // pixel can see (geometry/closed_surfaces.h; 0.2–0.4 s for 70k–95k triangles here); a mesh
    // that will be deformed draws every face in every pose, so that a frame's pixels do not
    // depend on which pose a run started from.
    void set_mesh(const TriangleMesh& mesh, bool with_lines, float crease_angle_deg,
                  CurvatureFit curvature = CurvatureFit::Exact, bool still = true);

    // A new pose of the mesh given to set_mesh (same topology: an animation frame). The
    // line mesh keeps its welding and feature size; positions, curvature and its derivative
    // are recomputed (a deforming surface changes its curvature).
    void deform(const TriangleMesh& posed);

    const LineMesh* line_mesh() const { return line_mesh_ ? &*line_mesh_ : nullptr; }

    // Line set `set` (an index of effective_line_sets) is drawn as strokes textured with
    // `slam`; for the per-type shorthand the index is the line type's.
    void set_slam(size_t set, const Slam& slam);
    // The set is drawn without a texture again (the viewer's style switch).
    void clear_slam(size_t set);

    // What each welded face belongs to, for line sets that select models or materials.
    void set_face_groups(FaceGroups groups) { groups_ = std::move(groups); }

    // A new image size (a resized window): the target and the readback buffers are made
    // again; the coherence tracker starts afresh (its splat buffer has the old size).
    void resize(uint32_t width, uint32_t height);

    // The target the last finished frame was drawn into; after render() or finish() its
    // colour image holds the final frame in TRANSFER_SRC_OPTIMAL (a viewer copies it to the
    // screen).
    const RenderTarget& target() const { return slots_[finished_].target; }

    // Vector-art layers drawn over the 3D lines (render/layer_pass.h), in order.
    void set_layers(std::vector<LayerStyle> styles);

    // The coherent parameterization carried from frame to frame (3D lines and each SLAM
    // layer), to save beside an offline render and restore when it resumes. Restoring
    // takes the line mesh as it is now: pose it at the saved frame first.
    struct CoherenceSnapshot {
        std::vector<std::optional<CoherenceTracker::State>> sets;  // per line set
        std::vector<std::optional<CoherenceTracker::State>> layers;
    };
    [[nodiscard]] CoherenceSnapshot coherence_snapshot() const;
    void restore_coherence(const CoherenceSnapshot& snapshot);

    // One frame. With `coherence` (the base parameters: policy, splat radius, RANSAC), every
    // set's visible paths are parameterized (§4: votes from the previous frame, RANSAC,
    // splat for the next one; with `every_set` false only the sets that read T, as a scene
    // session draws them) — call it for consecutive frames in order; without, sets that
    // need a parameter (SLAM, dashes, displacement) tile at T = s·κ/Lmax. `layers`:
    // this frame of each layer given to set_layers. Without a mesh (a scene of layers
    // alone) the frame is the background and the layers.
    [[nodiscard]] Frame render(const CameraMatrices& camera, const glm::vec3& eye, const SurfaceStyle& surface,
                               const LinesDesc& lines, const FrameOutputs& outputs = {},
                               const CoherenceParams* coherence = nullptr, std::vector<LayerFrame>* layers = nullptr,
                               bool every_set = true);

    // render() in two halves, so that frames overlap: begin() submits the frame's surface
    // pass (and on a CPU device extracts its lines on the host meanwhile) and returns;
    // finish() completes the oldest frame begun and returns it. At most two frames are in
    // flight: a viewer begins frame f + 1, then finishes frame f. Frames finish in the order
    // they began (the parameterization carries from one to the next). resize() and
    // set_layers() need none in flight; a pose (deform) or another line mesh may come
    // between begin and finish.
    void begin(FrameInput input);
    [[nodiscard]] Frame finish();
    [[nodiscard]] size_t in_flight() const { return flight_.size(); }

private:
    // A target and what a frame in it needs until it finishes.
    struct Slot {
        Slot(const Context& ctx, uint32_t width, uint32_t height, VkFormat format, uint32_t samples);
        RenderTarget target;
        Buffer depth_readback, color_readback;
        GpuTimer timer;
        UploadArena vertices{VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "line and stroke triangles"};  // the lines draw's
        FrameInput input;
        std::vector<LineSetDesc> sets;
        bool draw_lines = false;
        Frame frame;  // its segments and the extraction's time, until finish() adds the rest
        double begin_ms = 0.0;
        std::optional<Context::Submission> surface_work;
        // The line mesh's positions in the frame's pose, kept when it is posed again before
        // the frame finishes (its votes carry samples from that pose).
        std::optional<std::vector<glm::vec3>> positions;
        // The ray-casting index of the frame's pose, when a line set selects occlusion
        // levels ("qi"): built in begin(), while the line mesh is in that pose.
        OcclusionCounter occlusion;
        bool levels = false;
    };
    void keep_positions_of_frames_in_flight();
    // The slot's target and the surface pass at `samples` per pixel (1, 4 or 8;
    // SurfaceStyle::samples sets it per frame), made again when it changes.
    void prepare_slot(Slot& slot, uint32_t samples);

    const Context* ctx_;
    std::vector<Slot> slots_;   // two
    std::vector<size_t> flight_;  // slots of frames begun and not finished, oldest first
    size_t finished_ = 0;         // the slot of the last frame finished
    SurfacePass surface_pass_;
    LinePass line_pass_;
    LineExtractor extractor_;
    bool extraction_on_host_;  // CPU devices: extract_lines_reference, beside the surface pass
    ExtractWorkspace extract_workspace_;  // its per-vertex scratch, kept from frame to frame
    IntersectionCache intersections_;     // per pose of the line mesh (either extraction)
    std::optional<GpuMesh> mesh_;
    // Its closed surfaces when it is still: the back faces a view may skip (surface_pass.h).
    ClosedSurfaces closed_;
    std::vector<DrawSurfaces> closed_draws_;  // of mesh_'s draws (draw_surfaces), found with closed_
    std::string inside_out_warned_;           // the last warning of parts wound inside out (said once)
    SurfaceMaterials materials_;  // without textures: what set_mesh groups by
    std::optional<GpuMaterials> gpu_materials_;
    std::optional<LineMesh> line_mesh_;
    struct SetState {
        std::unique_ptr<CoherenceTracker> tracker;  // made on first use: it holds a float target
        std::optional<Slam> slam;                   // its length and height set κ and Lmax
        std::unique_ptr<SlamTexture> texture;
    };
    SetState& set_state(size_t set);
    // Per set: select, parameterize (as `in` asks), and (with `strokes`) build stroke geometry
    // (StrokeVertex) for non-plain sets. `levels`: the frame's occlusion-level index, when a
    // set selects levels (a set with its own spacing tests visibility again and counts them too).
    void prepare_sets(Frame& frame, const std::vector<LineSetDesc>& sets, const FrameInput& in, const DepthImage& depth,
                      const OcclusionCounter* levels, const std::vector<glm::vec3>& positions,
                      std::vector<std::vector<StrokeVertex>>* strokes);
    void record_sets(VkCommandBuffer cmd, RenderTarget& target, const Frame& frame,
                     const std::vector<LineSetDesc>& sets, const LinesDesc& lines,
                     const std::vector<std::vector<StrokeVertex>>& strokes, UploadArena& arena);
    std::vector<SetState> sets_;
    FaceGroups groups_;
    std::unique_ptr<StrokePass> stroke_pass_;
    std::unique_ptr<SlamTexture> solid_;  // styled sets without a SLAM
    // Translucent sets (alpha < 1) are drawn into the layer and composited once (made at the
    // first; the draw submission waits, so frames share them).
    std::optional<CoverageLayer> set_layer_;
    std::unique_ptr<LayerComposite> composite_;
    std::unique_ptr<LayerPass> layers_;
    std::vector<LayerStyle> layer_styles_;  // to make layers_ again on resize
};

}  // namespace lw
