#include "render/frame_renderer.h"


#include "core/error.h"
#include "core/timer.h"
#include "geometry/welded_mesh.h"
#include "lines/chaining.h"
#include "lines/extract_reference.h"

namespace lw {

FrameRenderer::FrameRenderer(const Context& ctx, uint32_t width, uint32_t height, VkFormat color_format)
    : ctx_(&ctx),
      target_(ctx, width, height, color_format),
      surface_pass_(ctx, color_format),
      line_pass_(ctx, color_format),
      extractor_(ctx),
      extraction_on_host_(ctx.preferred_compute_site() == ComputeSite::Host),
      timer_(ctx),
      depth_readback_(ctx, {.size = VkDeviceSize(width) * height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            .purpose = MemoryPurpose::Readback, .name = "depth readback"}),
      color_readback_(ctx, {.size = VkDeviceSize(width) * height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            .purpose = MemoryPurpose::Readback, .name = "color readback"}) {}

void FrameRenderer::set_mesh(const TriangleMesh& mesh, bool with_lines, float crease_angle_deg) {
    mesh_ = upload_mesh(*ctx_, mesh);
    line_mesh_.reset();
    if (with_lines) {
        line_mesh_ = build_line_mesh(mesh, crease_angle_deg);
        if (!extraction_on_host_) extractor_.set_mesh(*line_mesh_);
    }
}

void FrameRenderer::deform(const TriangleMesh& posed) {
    mesh_ = upload_mesh(*ctx_, posed);
    if (!line_mesh_) return;
    update_positions(line_mesh_->mesh, posed);
    line_mesh_->curvature = compute_curvature(line_mesh_->mesh);
    if (!extraction_on_host_) extractor_.set_mesh(*line_mesh_);
}

void FrameRenderer::set_slam(LineType type, const Slam& slam) {
    slams_[size_t(type)] = std::make_unique<SlamTexture>(*ctx_, slam);
    if (!stroke_pass_) stroke_pass_ = std::make_unique<StrokePass>(*ctx_, target_.color.format());
}

void FrameRenderer::resize(uint32_t width, uint32_t height) {
    if (width == target_.width && height == target_.height) return;
    vkDeviceWaitIdle(ctx_->device());  // nothing in flight may still use the old target
    target_ = RenderTarget(*ctx_, width, height, target_.color.format());
    depth_readback_ = Buffer(*ctx_, {.size = VkDeviceSize(width) * height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                     .purpose = MemoryPurpose::Readback, .name = "depth readback"});
    color_readback_ = Buffer(*ctx_, {.size = VkDeviceSize(width) * height * 4, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                     .purpose = MemoryPurpose::Readback, .name = "color readback"});
    tracker_.reset();
    if (layers_) layers_ = std::make_unique<LayerPass>(*ctx_, width, height, layer_styles_);
}

void FrameRenderer::set_layers(std::vector<LayerStyle> styles) {
    layer_styles_ = styles;
    layers_ = std::make_unique<LayerPass>(*ctx_, target_.width, target_.height, std::move(styles));
    if (!stroke_pass_) stroke_pass_ = std::make_unique<StrokePass>(*ctx_, target_.color.format());
}

FrameRenderer::CoherenceSnapshot FrameRenderer::coherence_snapshot() const {
    CoherenceSnapshot snapshot;
    if (tracker_) snapshot.lines = tracker_->state();
    if (layers_) snapshot.layers = layers_->states();
    return snapshot;
}

void FrameRenderer::restore_coherence(const CoherenceSnapshot& snapshot) {
    if (snapshot.lines) {
        if (!tracker_) tracker_ = std::make_unique<CoherenceTracker>(*ctx_, target_.width, target_.height);
        tracker_->restore(*snapshot.lines, line_mesh_ ? SurfaceFrame{&line_mesh_->mesh.positions, &line_mesh_->mesh.faces}
                                                      : SurfaceFrame{});
    }
    if (layers_) layers_->restore(snapshot.layers);
}

Frame FrameRenderer::render(const CameraMatrices& camera, const glm::vec3& eye, const SurfaceStyle& surface,
                            const LinesDesc& lines, const FrameOutputs& outputs, const CoherenceParams* coherence,
                            std::vector<LayerFrame>* layers) {
    if (!mesh_ && !layers_) throw Error("FrameRenderer: no mesh and no layers set");
    const bool draw_lines = lines.enabled && line_mesh_.has_value();
    Timer total;
    Frame frame;
    const VkDeviceSize pixels = VkDeviceSize(target_.width) * target_.height;
    Buffer& depth_readback = depth_readback_;
    Buffer& color_readback = color_readback_;

    // (1) Surface and depth; line extraction in the same submission, or (on a CPU device, see
    // ComputeSite) by the host while the device draws the surface: lavapipe's vertex stage
    // runs on one thread and leaves the other core to the host extraction.
    const bool host_extraction = draw_lines && extraction_on_host_;
    for (int attempt = 0;; ++attempt) {
        Context::Submission surface_work = ctx_->submit([&](VkCommandBuffer cmd) {
            timer_.reset(cmd);
            timer_.begin(cmd, "surface");
            if (mesh_)
                surface_pass_.record(cmd, target_, *mesh_, camera, eye, surface);
            else
                surface_pass_.record_clear(cmd, target_, surface);
            timer_.end(cmd);
            if (draw_lines && !host_extraction) extractor_.record(cmd, eye, lines.params, &timer_);
            if (draw_lines || outputs.depth) record_image_to_buffer(cmd, target_.depth, depth_readback);
            record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        if (host_extraction) {
            Timer extract;
            frame.segments = extract_lines_reference(*line_mesh_, eye, lines.params);
            frame.timings.extract_ms = extract.elapsed_ms();
        }
        surface_work.wait();
        if (!draw_lines || host_extraction || extractor_.read_segments(frame.segments)) break;
        if (attempt == 2) throw Error("line extraction: the segment count kept growing past the buffer");
    }
    frame.timings.gpu = timer_.results();
    depth_readback.invalidate(*ctx_);
    const std::span<const float> depth_pixels(static_cast<const float*>(depth_readback.mapped()), pixels);
    if (outputs.depth) frame.image.depth.assign(depth_pixels.begin(), depth_pixels.end());

    // Chaining and visibility on the CPU.
    if (draw_lines) {
        Timer chain;
        frame.paths = chain_segments(frame.segments);
        frame.timings.chain_ms = chain.elapsed_ms();
        Timer visibility;
        const DepthImage depth{int(target_.width), int(target_.height), depth_pixels, camera.znear, camera.zfar};
        frame.screen_paths = compute_visibility(frame.paths, camera, depth, {.sample_spacing_px = lines.sample_spacing_px});
        frame.timings.visibility_ms = visibility.elapsed_ms();
    }

    // Coherent parameterization of the visible paths (§4), for strokes and dumps.
    if (draw_lines && coherence) {
        if (!tracker_) tracker_ = std::make_unique<CoherenceTracker>(*ctx_, target_.width, target_.height);
        Timer param_timer;
        frame.params = tracker_->update(frame.screen_paths, camera,
                                        {&line_mesh_->mesh.positions, &line_mesh_->mesh.faces}, *coherence);
        // Strokes and dumps use samples at fixed texture phases (see resample_at_phase).
        for (size_t p = 0; p < frame.screen_paths.size(); ++p)
            if (frame.screen_paths[p].visible)
                frame.screen_paths[p] = resample_at_phase(frame.screen_paths[p], frame.params[p], lines.sample_spacing_px);
        frame.timings.coherence_ms = param_timer.elapsed_ms();
    }

    // Vector layers: their own trackers and stroke geometry.
    if (layers_ && layers) {
        Timer layer_timer;
        frame.layers = layers_->prepare(*layers, coherence != nullptr, lines.sample_spacing_px);
        frame.timings.coherence_ms += layer_timer.elapsed_ms();
    }

    // Stroke geometry per SLAM-styled type; the other types stay plain lines.
    LinesDesc plain = lines;
    std::array<std::vector<StrokeVertex>, kLineTypeCount> strokes;
    if (draw_lines && !frame.params.empty())
        for (size_t p = 0; p < frame.screen_paths.size(); ++p) {
            const ScreenPath& path = frame.screen_paths[p];
            const auto t = size_t(path.type);
            if (!slams_[t] || !path.visible || !line_type_enabled(lines.params, path.type)) continue;
            const LineStyle& style = lines.styles[t];
            append_stroke(path,
                          StrokeParams{.rho = frame.params[p].rho, .phi = frame.params[p].phi,
                                       .fold = frame.params[p].fold, .width = style.width, .color = style.color,
                                       .taper_px = style.taper_px},
                          strokes[t]);
        }
    for (int t = 0; t < kLineTypeCount; ++t) {
        if (slams_[size_t(t)] && !frame.params.empty()) disable_line_type(plain.params, LineType(t));
        // Ribbon styles are synthesized over the finished frame (ribbon/ribbon_strokes.h).
        if (!lines.styles[size_t(t)].ribbon.empty()) disable_line_type(plain.params, LineType(t));
    }

    // (2) Lines and strokes over the surface, colour read back. Vertex buffers must outlive
    // the submission.
    Buffer quads;
    std::array<Buffer, kLineTypeCount> stroke_buffers;
    std::vector<Buffer> layer_buffers;
    ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
        timer_.reset(cmd);
        timer_.begin(cmd, "lines draw");
        if (draw_lines) quads = line_pass_.record(*ctx_, cmd, target_, frame.screen_paths, plain);
        for (size_t t = 0; t < strokes.size(); ++t)
            if (!strokes[t].empty()) stroke_buffers[t] = stroke_pass_->record(*ctx_, cmd, target_, strokes[t], *slams_[t]);
        if (layers_ && layers) layer_buffers = layers_->record(*ctx_, cmd, target_, *stroke_pass_);
        timer_.end(cmd);
        if (outputs.color) record_image_to_buffer(cmd, target_.color, color_readback);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    for (const PassTime& t : timer_.results()) frame.timings.gpu.push_back(t);
    if (outputs.color) {
        frame.image.color = read_rgba8(*ctx_, color_readback, target_.width, target_.height, target_.color.format());
    }
    frame.timings.total_ms = total.elapsed_ms();
    return frame;
}

}  // namespace lw
