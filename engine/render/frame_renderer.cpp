#include "render/frame_renderer.h"

#include <algorithm>


#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "geometry/welded_mesh.h"
#include "lines/chaining.h"
#include "lines/extract_reference.h"
#include "stroke/modifiers.h"

namespace lw {

namespace {

// The line pass's style of a plain set: the shorthand keeps the scene's look of hidden runs;
// sets that select hidden lines style them themselves.
LineDrawStyle plain_draw_style(const LinesDesc& lines, const LineSetDesc& set) {
    return {.color = set.style.color, .alpha = set.style.alpha, .width = set.style.width, .fade = set.style.fade,
            .hidden = lines.sets.empty() ? lines.hidden : HiddenLines::None};
}

// A styled set's strokes, `margin_px` past their outlines, visible paths into `visible` and
// hidden ones into `hidden`. Hidden runs have no fit: they tile.
void append_set_strokes(const LineSetFrame& out, const LineSetDesc& set, float margin_px,
                        std::vector<StrokeVertex>& visible, std::vector<StrokeVertex>& hidden) {
    const std::vector<PathParam> tiled = tiling_params(out.paths, out.coherence);
    for (size_t p = 0; p < out.paths.size(); ++p) {
        const PathParam& param = !out.params.empty() && out.paths[p].visible ? out.params[p] : tiled[p];
        const StrokeParams stroke{.rho = param.rho, .phi = param.phi, .fold = param.fold, .coverage_margin_px = margin_px};
        append_styled_stroke(out.paths[p], stroke, set.style, period_px(out.coherence),
                             out.paths[p].visible ? visible : hidden);
    }
}

// A set's strokes as record_sets draws them, without the coverage margin: the line pass's
// look for plain sets (dashes cut as geometry), the styled builder's for the others (a SLAM
// set in its solid ink). Ribbons are synthesized as images and have none.
// A set drawn once (draws_once) is a group of the opacity of its most opaque shape, which
// the renderer composites once as the PNG does; the shapes' opacities are relative to it.
void add_svg_shapes(const LinesDesc& lines, const LineSetDesc& set, const LineSetFrame& out, SvgGroup& group) {
    if (!set.style.ribbon.empty()) return;
    if (is_plain_line_set(set.style)) {
        const LineDrawStyle style = plain_draw_style(lines, set);
        for (const ScreenPath& path : out.paths)
            for (const StrokeVertex& v : line_triangles({path}, style, 0.0f, true))
                (path.visible ? group.shapes : group.hidden_shapes).push_back(v);
    } else {
        append_set_strokes(out, set, 0.0f, group.shapes, group.hidden_shapes);
    }
    if (!draws_once(set.style)) return;
    float most = 0.0f;
    for (const auto* shapes : {&group.shapes, &group.hidden_shapes})
        for (const StrokeVertex& v : *shapes) most = std::max(most, std::clamp(v.color.a, 0.0f, 1.0f));
    group.opacity = most;
}

// Smooth contours and suggestive contours are drawn as rtsc defines them: contours only where
// the radial curvature kr > 0, and kr's sign follows the faces' winding. On a closed part
// wound inside out (find_closed_surfaces: cavity walls left out) the contours seen from
// outside are then not drawn. Said once per mesh (a viewer rebuilding its lines keeps it).
std::string inside_out_warning(const ClosedSurfaces& closed) {
    size_t parts = 0, faces = 0;
    for (const ClosedSurfaces::Component& c : closed.components) parts += c.inward;
    if (parts == 0) return {};
    for (const int32_t c : closed.face_component) faces += c >= 0 && closed.components[size_t(c)].inward;
    return std::to_string(parts) + " closed part(s) of the mesh (" + std::to_string(faces) + " of " +
           std::to_string(closed.face_component.size()) +
           " triangles) wind inside out (negative volume): smooth silhouettes and suggestive contours follow the "
           "faces' winding (rtsc's kr > 0) and are not drawn on them as seen from outside. Unless they are "
           "interiors seen from within, reverse their winding in the model, or draw their outline with --contours "
           "mesh (scene key lines.contours: \"mesh\")";
}

}  // namespace

std::vector<DumpGroup> line_set_dump_groups(const Frame& frame) {
    std::vector<DumpGroup> groups;
    for (const LineSetFrame& set : frame.sets) {
        groups.push_back({set.name, set.recorded ? &set.recorded_paths : &set.paths,
                          set.recorded ? &set.recorded_params : &set.params});
    }
    return groups;
}

std::vector<SvgGroup> line_set_svg_groups(const LinesDesc& lines, const Frame& frame, bool with_shapes) {
    std::vector<SvgGroup> groups;
    const std::vector<LineSetDesc> sets = effective_line_sets(lines);
    for (const LineSetDesc& set : sets)
        groups.push_back({.id = set.name, .color = set.style.color, .width = set.style.width,
                          .cap = set.style.cap, .join = set.style.join, .hidden = set.select.selects_hidden()});
    for (const LineSetFrame& out : frame.sets) {
        groups[out.set].paths = &out.paths;
        if (with_shapes) add_svg_shapes(lines, sets[out.set], out, groups[out.set]);
    }
    // The shorthand has a set per type (its index); the default four always have a group,
    // the types off by default only when they are drawn.
    if (lines.sets.empty())
        for (size_t t = groups.size(); t-- > 0;)
            if (!sets[t].enabled && !(kDefaultLineTypes & (1u << t))) groups.erase(groups.begin() + std::ptrdiff_t(t));
    return groups;
}

FrameRenderer::Slot::Slot(const Context& ctx, uint32_t width, uint32_t height, VkFormat format, uint32_t samples)
    : target(ctx, width, height, format, samples),
      depth_readback(ctx, {.size = VkDeviceSize(width) * height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           .purpose = MemoryPurpose::Readback, .name = "depth readback"}),
      color_readback(ctx, {.size = VkDeviceSize(width) * height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           .purpose = MemoryPurpose::Readback, .name = "color readback"}),
      timer(ctx) {}

FrameRenderer::FrameRenderer(const Context& ctx, uint32_t width, uint32_t height, VkFormat color_format)
    : ctx_(&ctx),
      surface_pass_(ctx, color_format),
      line_pass_(ctx, color_format),
      extractor_(ctx),
      extraction_on_host_(ctx.preferred_compute_site() == ComputeSite::Host) {
    for (int i = 0; i < 2; ++i) slots_.emplace_back(ctx, width, height, color_format, 1);
}

void FrameRenderer::set_materials(const SurfaceMaterials& materials) {
    if (mesh_ && materials.face_material != materials_.face_material)
        throw Error("FrameRenderer: materials for other faces than the mesh's (set them before the mesh)");
    if (gpu_materials_) vkDeviceWaitIdle(ctx_->device());  // a viewer's frame may still read the old ones
    gpu_materials_.emplace(*ctx_, materials);
    materials_ = SurfaceMaterials{.materials = materials.materials, .face_material = materials.face_material};
}

void FrameRenderer::keep_positions_of_frames_in_flight() {
    for (size_t index : flight_) {
        Slot& slot = slots_[index];
        if (slot.surface_work) slot.surface_work->wait();  // its surface pass reads the mesh about to go
        if (line_mesh_ && !slot.positions) slot.positions = line_mesh_->mesh.positions;
    }
}

void FrameRenderer::set_mesh(const TriangleMesh& mesh, bool with_lines, float crease_angle_deg, CurvatureFit curvature,
                             bool still) {
    keep_positions_of_frames_in_flight();
    closed_ = still ? find_closed_surfaces(mesh) : ClosedSurfaces{};
    mesh_ = upload_mesh(*ctx_, mesh, &materials_, &closed_.face_both_ways);
    closed_draws_ = still ? draw_surfaces(mesh_->draws, mesh_->face_order, closed_) : std::vector<DrawSurfaces>{};
    line_mesh_.reset();
    if (with_lines) {
        if (std::string warning = inside_out_warning(closed_); warning != inside_out_warned_) {
            if (!warning.empty()) log_warning(warning);
            inside_out_warned_ = std::move(warning);
        }
        line_mesh_ = build_line_mesh(mesh, crease_angle_deg, curvature_options(curvature));
        if (!extraction_on_host_) extractor_.set_mesh(*line_mesh_);
    }
}

void FrameRenderer::deform(const TriangleMesh& posed) {
    keep_positions_of_frames_in_flight();
    mesh_ = upload_mesh(*ctx_, posed, &materials_);
    // A pose of a mesh given as still: from now on every face is drawn (a search a pose
    // would cost as much as intersection lines, geometry/closed_surfaces.h).
    closed_ = ClosedSurfaces{};
    closed_draws_.clear();
    if (!line_mesh_) return;
    pose_line_mesh(*line_mesh_, posed);
    if (!extraction_on_host_) extractor_.set_pose(*line_mesh_);
}

FrameRenderer::SetState& FrameRenderer::set_state(size_t set) {
    if (sets_.size() <= set) sets_.resize(set + 1);
    return sets_[set];
}

void FrameRenderer::set_slam(size_t set, const Slam& slam) {
    SetState& state = set_state(set);
    state.slam = slam;
    state.texture = std::make_unique<SlamTexture>(*ctx_, slam);
}

void FrameRenderer::clear_slam(size_t set) {
    if (set >= sets_.size()) return;
    sets_[set].slam.reset();
    sets_[set].texture.reset();
}

void FrameRenderer::resize(uint32_t width, uint32_t height) {
    const RenderTarget& current = slots_[finished_].target;
    if (width == current.width && height == current.height) return;
    if (!flight_.empty()) throw Error("FrameRenderer: resize with a frame in flight (finish it first)");
    vkDeviceWaitIdle(ctx_->device());  // nothing in flight may still use the old targets
    const VkFormat format = current.color.format();
    const uint32_t samples = current.samples;
    slots_.clear();
    for (int i = 0; i < 2; ++i) slots_.emplace_back(*ctx_, width, height, format, samples);
    finished_ = 0;
    for (SetState& state : sets_) state.tracker.reset();
    if (layers_) layers_ = std::make_unique<LayerPass>(*ctx_, width, height, layer_styles_);
}

void FrameRenderer::prepare_slot(Slot& slot, uint32_t samples) {
    if (samples == slot.target.samples && samples == surface_pass_.samples()) return;
    static_cast<void>(sample_count_bit(*ctx_, samples));  // the error, before anything changes
    vkDeviceWaitIdle(ctx_->device());  // a present may still read the slot's colour
    if (samples != slot.target.samples)
        slot.target = RenderTarget(*ctx_, slot.target.width, slot.target.height, slot.target.color.format(), samples);
    if (samples != surface_pass_.samples()) surface_pass_ = SurfacePass(*ctx_, slot.target.color.format(), samples);
}

void FrameRenderer::set_layers(std::vector<LayerStyle> styles) {
    if (!flight_.empty()) throw Error("FrameRenderer: layers set with a frame in flight (finish it first)");
    layer_styles_ = styles;
    layers_ = std::make_unique<LayerPass>(*ctx_, target().width, target().height, std::move(styles));
}

FrameRenderer::CoherenceSnapshot FrameRenderer::coherence_snapshot() const {
    CoherenceSnapshot snapshot;
    for (const SetState& state : sets_)
        snapshot.sets.push_back(state.tracker ? std::optional(state.tracker->state()) : std::nullopt);
    if (layers_) snapshot.layers = layers_->states();
    return snapshot;
}

void FrameRenderer::restore_coherence(const CoherenceSnapshot& snapshot) {
    const SurfaceFrame surface =
        line_mesh_ ? SurfaceFrame{&line_mesh_->mesh.positions, &line_mesh_->mesh.faces} : SurfaceFrame{};
    for (size_t i = 0; i < snapshot.sets.size(); ++i) {
        SetState& state = set_state(i);
        if (!snapshot.sets[i]) {
            state.tracker.reset();
            continue;
        }
        if (!state.tracker) state.tracker = std::make_unique<CoherenceTracker>(*ctx_, target().width, target().height);
        state.tracker->restore(*snapshot.sets[i], surface);
    }
    if (layers_) layers_->restore(snapshot.layers);
}

Frame FrameRenderer::render(const CameraMatrices& camera, const glm::vec3& eye, const SurfaceStyle& surface,
                            const LinesDesc& lines, const FrameOutputs& outputs, const CoherenceParams* coherence,
                            std::vector<LayerFrame>* layers, bool every_set) {
    begin({.camera = camera,
           .eye = eye,
           .surface = surface,
           .lines = lines,
           .outputs = outputs,
           .coherence = coherence ? std::optional(*coherence) : std::nullopt,
           .parameterize_every_set = every_set,
           .layers = layers ? std::optional(*layers) : std::nullopt});
    return finish();
}

void FrameRenderer::begin(FrameInput input) {
    if (!mesh_ && !layers_) throw Error("FrameRenderer: no mesh and no layers set");
    if (flight_.size() >= slots_.size()) throw Error("FrameRenderer: two frames in flight already (finish one first)");
    Timer begin_timer;
    const size_t index = ((flight_.empty() ? finished_ : flight_.back()) + 1) % slots_.size();
    Slot& slot = slots_[index];
    // Multisampling applies to a shaded surface; a scene without one (lines over the
    // background) takes one sample. Frames only tracked (outputs.draw off) take the scene's
    // count all the same: their depth, and so their lines, must be the drawn frames'.
    prepare_slot(slot, input.surface.draw_surface && mesh_ ? surface_samples(input.surface) : 1);
    slot.sets = effective_line_sets(input.lines);
    slot.draw_lines = input.lines.enabled && line_mesh_.has_value();
    slot.frame = Frame{};
    slot.positions.reset();
    const LineParams extraction = extraction_params(input.lines, slot.sets);
    slot.levels = slot.draw_lines && std::any_of(slot.sets.begin(), slot.sets.end(), [](const LineSetDesc& set) {
        return set.enabled && set.select.qi.has_value();
    });
    if (slot.levels) slot.occlusion.set_mesh(*line_mesh_);  // again only for a new pose

    // (1) Surface and depth; line extraction in the same submission, or (on a CPU device, see
    // ComputeSite) by the host while the device draws the surface: lavapipe's vertex stage
    // runs on one thread and leaves the other core to the host extraction.
    const bool host_extraction = slot.draw_lines && extraction_on_host_;
    // Without drawing, the surface is depth-only: the same vertex stage, so the same depth.
    SurfaceStyle surface_style = input.surface;
    if (!input.outputs.draw) surface_style.draw_surface = false;
    const BackFaceCulling culling{
        .surfaces = &closed_, .hidden = back_faces_hidden(closed_, input.camera), .draws = &closed_draws_};
    for (int attempt = 0;; ++attempt) {
        slot.surface_work.emplace(ctx_->submit([&](VkCommandBuffer cmd) {
            slot.timer.reset(cmd);
            slot.timer.begin(cmd, "surface");
            if (mesh_)
                surface_pass_.record(cmd, slot.target, *mesh_, input.camera, input.eye, surface_style,
                                     gpu_materials_ ? &*gpu_materials_ : nullptr, &culling);
            else
                surface_pass_.record_clear(cmd, slot.target, surface_style);
            slot.timer.end(cmd);
            if (slot.draw_lines && !host_extraction) extractor_.record(cmd, input.eye, extraction, &slot.timer);
            if (slot.draw_lines || input.outputs.depth) record_image_to_buffer(cmd, slot.target.depth, slot.depth_readback);
            record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        }));
        if (host_extraction) {
            Timer extract;
            extract_lines_reference(*line_mesh_, input.eye, extraction, slot.frame.segments, extract_workspace_);
            slot.frame.timings.extract_ms = extract.elapsed_ms();
        }
        if (!slot.draw_lines || host_extraction) break;
        // The device's segments are read now: the next frame's pass writes the same buffer.
        slot.surface_work->wait();
        if (extractor_.read_segments(slot.frame.segments)) break;
        if (attempt == 2) throw Error("line extraction: the segment count kept growing past the buffer");
    }
    if (slot.draw_lines && extraction.intersections) {  // found per pose, on the host (lines/intersections.h)
        Timer intersect;
        const std::vector<LineSegment>& crossing = intersection_lines(*line_mesh_, intersections_);
        slot.frame.segments.insert(slot.frame.segments.end(), crossing.begin(), crossing.end());
        slot.frame.timings.extract_ms += intersect.elapsed_ms();
    }
    slot.input = std::move(input);
    slot.begin_ms = begin_timer.elapsed_ms();
    flight_.push_back(index);
}

Frame FrameRenderer::finish() {
    if (flight_.empty()) throw Error("FrameRenderer: no frame in flight to finish");
    const size_t index = flight_.front();
    flight_.erase(flight_.begin());
    Slot& slot = slots_[index];
    finished_ = index;
    Timer total;
    slot.surface_work->wait();
    slot.surface_work.reset();
    Frame frame = std::move(slot.frame);
    FrameInput& in = slot.input;
    const CoherenceParams* coherence = in.coherence ? &*in.coherence : nullptr;
    RenderTarget& target = slot.target;
    frame.timings.gpu = slot.timer.results();
    slot.depth_readback.invalidate(*ctx_);
    const std::span<const float> depth_pixels(static_cast<const float*>(slot.depth_readback.mapped()),
                                              size_t(target.width) * target.height);
    if (in.outputs.depth) {
        frame.image.depth.assign(depth_pixels.begin(), depth_pixels.end());
        frame.image.znear = in.camera.znear;
        frame.image.zfar = in.camera.zfar;
    }

    // Chaining and visibility on the CPU; then each line set's selection and parameterization.
    std::vector<std::vector<StrokeVertex>> strokes(slot.sets.size());
    if (slot.draw_lines) {
        Timer chain;
        frame.paths = chain_segments(frame.segments);
        frame.timings.chain_ms = chain.elapsed_ms();
        Timer visibility;
        const DepthImage depth{int(target.width), int(target.height), depth_pixels, in.camera.znear, in.camera.zfar};
        const OcclusionCounter* levels = slot.levels ? &slot.occlusion : nullptr;
        frame.screen_paths =
            compute_visibility(frame.paths, in.camera, depth, {.sample_spacing_px = in.lines.sample_spacing_px}, levels);
        frame.timings.visibility_ms = visibility.elapsed_ms();
        prepare_sets(frame, slot.sets, in, depth, levels, slot.positions ? *slot.positions : line_mesh_->mesh.positions, in.outputs.draw ? &strokes : nullptr);
    }

    // Vector layers: their own trackers and stroke geometry.
    if (layers_ && in.layers) {
        Timer layer_timer;
        frame.layers = layers_->prepare(*in.layers, coherence != nullptr, in.lines.sample_spacing_px);
        frame.timings.coherence_ms += layer_timer.elapsed_ms();
    }
    if (!in.outputs.draw) {
        frame.timings.total_ms = slot.begin_ms + total.elapsed_ms();
        return frame;
    }
    const bool any_strokes = std::any_of(strokes.begin(), strokes.end(), [](const auto& s) { return !s.empty(); });
    if (!stroke_pass_ && (layers_ || any_strokes)) stroke_pass_ = std::make_unique<StrokePass>(*ctx_, target.color.format());

    // (2) Line sets in order, then layers, over the surface; colour read back. Their
    // triangles go into the slot's arena (its last frame's submission completed).
    slot.vertices.reset();
    ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
        slot.timer.reset(cmd);
        slot.timer.begin(cmd, "lines draw");
        if (slot.draw_lines) record_sets(cmd, target, frame, slot.sets, in.lines, strokes, slot.vertices);
        if (layers_ && in.layers) layers_->record(*ctx_, cmd, target, *stroke_pass_, slot.vertices);
        slot.timer.end(cmd);
        if (in.outputs.color) record_image_to_buffer(cmd, target.color, slot.color_readback);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    for (const PassTime& t : slot.timer.results()) frame.timings.gpu.push_back(t);
    if (in.outputs.color)
        frame.image.color = read_rgba8(*ctx_, slot.color_readback, target.width, target.height, target.color.format());
    frame.timings.total_ms = slot.begin_ms + total.elapsed_ms();
    return frame;
}

void FrameRenderer::prepare_sets(Frame& frame, const std::vector<LineSetDesc>& sets, const FrameInput& in,
                                 const DepthImage& depth, const OcclusionCounter* levels,
                                 const std::vector<glm::vec3>& positions, std::vector<std::vector<StrokeVertex>>* strokes) {
    Timer param_timer;
    const LinesDesc& lines = in.lines;
    const CameraMatrices& camera = in.camera;
    const CoherenceParams* coherence = in.coherence ? &*in.coherence : nullptr;
    // Whether set i's strokes read T (a SLAM drawn, dashes, displacement), and whether it is
    // fitted this frame (its tracker carries its parameterization on): those sets, or all.
    const auto reads_t = [&](size_t i) { return needs_parameterization(sets[i].style) || sets_[i].texture; };
    const auto fitted = [&](size_t i) { return coherence && (in.parameterize_every_set || reads_t(i)); };
    const SurfaceFrame surface{&positions, &line_mesh_->mesh.faces};
    const FaceGroups* groups = groups_.face_group.empty() ? nullptr : &groups_;
    std::vector<size_t> enabled;
    for (size_t i = 0; i < sets.size(); ++i) {
        if (!sets[i].enabled) continue;
        enabled.push_back(i);
        SetState& state = set_state(i);
        // A set not fitted this frame drops its tracker: fitted again later (a viewer's toggle),
        // it starts afresh rather than from a splat of frames ago.
        if (!fitted(i)) state.tracker.reset();
        else if (!state.tracker)
            state.tracker = std::make_unique<CoherenceTracker>(*ctx_, target().width, target().height);
    }
    // One set: its selection, parameterization (its own tracker) and strokes.
    std::vector<LineSetFrame> outs(enabled.size());
    const auto prepare = [&](size_t k) {
        const size_t i = enabled[k];
        const LineSetDesc& set = sets[i];
        SetState& state = sets_[i];
        LineSetFrame& out = outs[k];
        out.name = set.name;
        out.set = i;
        out.coherence = line_set_coherence(coherence ? *coherence : CoherenceParams{}, set,
                                           state.slam ? &*state.slam : nullptr, lines.sample_spacing_px);
        // A set with its own spacing samples the paths at that spacing.
        const float spacing = set.coherence.sample_spacing_px > 0.0f ? set.coherence.sample_spacing_px
                                                                     : lines.sample_spacing_px;
        out.paths = spacing == lines.sample_spacing_px
                        ? select_line_set(frame.screen_paths, set, groups)
                        : select_line_set(compute_visibility(frame.paths, camera, depth, {.sample_spacing_px = spacing},
                                                             levels),
                                          set, groups);
        if (fitted(i)) {
            const bool for_the_record = !reads_t(i);
            out.recorded = for_the_record;
            if (for_the_record) out.recorded_paths = out.paths;
            std::vector<ScreenPath>& paths = for_the_record ? out.recorded_paths : out.paths;
            std::vector<PathParam>& params = for_the_record ? out.recorded_params : out.params;
            params = state.tracker->update(paths, camera, surface, out.coherence);
            // Strokes and dumps use samples at fixed texture phases (see resample_at_phase).
            for (size_t p = 0; p < paths.size(); ++p)
                if (paths[p].visible) paths[p] = resample_at_phase(paths[p], params[p], spacing);
        }
        // Ribbons are synthesized over the read-back frame; plain sets are drawn by the line pass.
        if (strokes && set.style.ribbon.empty() && !(is_plain_line_set(set.style) && !state.texture))
            append_set_strokes(out, set, kCoverageMarginPx, (*strokes)[i], (*strokes)[i]);
    };
    // Sets share nothing but the frame's paths, which they read: on the host (CPU devices,
    // where the device is idle by now) they run side by side, each set a chunk taken as
    // threads finish. A device tracker submits work, which one thread must do.
    if (ctx_->preferred_compute_site() == ComputeSite::Host) {
        parallel_for(
            enabled.size(), 1, [&](size_t first, size_t last, size_t) {
                for (size_t k = first; k < last; ++k) prepare(k);
            },
            enabled.size());
    } else {
        for (size_t k = 0; k < enabled.size(); ++k) prepare(k);
    }
    for (LineSetFrame& out : outs) frame.sets.push_back(std::move(out));
    frame.timings.coherence_ms = param_timer.elapsed_ms();
}

void FrameRenderer::record_sets(VkCommandBuffer cmd, RenderTarget& target, const Frame& frame,
                                const std::vector<LineSetDesc>& sets, const LinesDesc& lines,
                                const std::vector<std::vector<StrokeVertex>>& strokes, UploadArena& arena) {
    for (const LineSetFrame& out : frame.sets) {
        const LineSetDesc& set = sets[out.set];
        const SetState& state = sets_[out.set];
        if (!set.style.ribbon.empty()) continue;
        const bool styled = !strokes[out.set].empty(), plain = is_plain_line_set(set.style) && !state.texture;
        if (!styled && !plain) continue;
        if (set.style.alpha <= 0.0f && set.style.alpha_modifiers.empty()) continue;  // invisible
        // A translucent set covers each pixel once, however its strokes overlap (the union
        // its SVG draws): into the layer, then the layer over the frame.
        CoverageLayer* layer = nullptr;
        if (draws_once(set.style)) {
            if (!set_layer_ || set_layer_->width != target.width || set_layer_->height != target.height)
                set_layer_.emplace(*ctx_, target.width, target.height);
            if (!composite_) composite_ = std::make_unique<LayerComposite>(*ctx_, target.color.format());
            layer = &*set_layer_;
        }
        bool drawn = false;
        if (styled) {
            if (!solid_) solid_ = std::make_unique<SlamTexture>(*ctx_, solid_slam());
            drawn = stroke_pass_->record(*ctx_, cmd, target, strokes[out.set], state.texture ? *state.texture : *solid_,
                                         arena, layer);
        } else {
            drawn = line_pass_.record(*ctx_, cmd, target, out.paths, plain_draw_style(lines, set), arena, layer);
        }
        if (drawn && layer) composite_->record(*ctx_, cmd, target, *layer);
    }
}

}  // namespace lw
