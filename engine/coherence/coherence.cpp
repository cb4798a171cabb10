#include "coherence/coherence.h"

#include <span>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>

#include "coherence_splat_frag.h"
#include "coherence_splat_vert.h"
#include "coherence/path_split.h"
#include "core/error.h"
#include "gpu/render_target.h"

namespace lw {

namespace {

struct SplatPush {  // mirrors shaders/coherence_splat.*
    glm::vec2 viewport;
    float radius;
    float pad;
};

struct Sprite {
    glm::vec2 center;
    float t;
};

// Unit direction of increasing arclength at sample k (central difference).
glm::vec2 path_tangent(const ScreenPath& path, size_t k) {
    const size_t a = k > 0 ? k - 1 : k, b = std::min(k + 1, path.samples.size() - 1);
    const glm::vec2 d = path.samples[b].pixel - path.samples[a].pixel;
    const float length = glm::length(d);
    return length > 0.0f ? d / length : glm::vec2(0.0f);
}

float path_length(const ScreenPath& path) {
    return path.samples.size() < 2 ? 0.0f : path.samples.back().s - path.samples.front().s;
}

// Pixels a unit of length at `world` covers on screen: the projection's Jacobian J (2×3) at
// the point, sqrt(|a × b|) for its rows a, b (det(J·Jᵀ)^¼: the scale of a perspective or
// orthographic camera, and of a vector layer's zoom).
float pixels_per_unit(const CameraMatrices& camera, glm::vec3 world, float width, float height) {
    const glm::mat4& m = camera.view_proj;
    const glm::vec4 clip = m * glm::vec4(world, 1.0f);
    auto row = [&](int i) { return glm::vec3(m[0][i], m[1][i], m[2][i]); };
    const glm::vec3 a = 0.5f * width * (row(0) * clip.w - clip.x * row(3)) / (clip.w * clip.w);
    const glm::vec3 b = 0.5f * height * (row(1) * clip.w - clip.y * row(3)) / (clip.w * clip.w);
    return std::sqrt(glm::length(glm::cross(a, b)));
}

}  // namespace

ScreenPath resample_at_phase(const ScreenPath& path, const PathParam& param, float spacing) {
    ScreenPath out = path;
    const auto& in = path.samples;
    if (in.size() < 2 || param.rho == 0.0f || !(spacing > 0.0f)) return out;
    out.samples.clear();
    const double step = std::abs(double(param.rho)) * spacing;  // T between samples
    const double s0 = path_arclength(path, 0), s1 = path_arclength(path, in.size() - 1);
    const double t0 = double(param.rho) * s0 + param.phi, t1 = double(param.rho) * s1 + param.phi;
    // Phases k·step inside [t0, t1] (or [t1, t0]), walked in the direction of increasing s.
    const double lo = std::min(t0, t1), hi = std::max(t0, t1);
    std::vector<double> arclengths{s0};
    for (double k = std::ceil(lo / step); k * step <= hi; k += 1.0) {
        const double s = (k * step - param.phi) / double(param.rho);
        if (s > s0 + 1e-3 && s < s1 - 1e-3) arclengths.push_back(s);
    }
    std::sort(arclengths.begin() + 1, arclengths.end());
    arclengths.push_back(s1);
    size_t segment = 0;
    for (double s : arclengths) {
        while (segment + 2 < in.size() && path_arclength(path, segment + 1) < s) ++segment;
        const ScreenSample& a = in[segment];
        const ScreenSample& b = in[segment + 1];
        const double sa = path_arclength(path, segment), sb = path_arclength(path, segment + 1);
        const float u = sb > sa ? float(std::clamp((s - sa) / (sb - sa), 0.0, 1.0)) : 0.0f;
        out.samples.push_back(ScreenSample{.pixel = glm::mix(a.pixel, b.pixel, u),
                                           .depth = glm::mix(a.depth, b.depth, u),
                                           .s = in.front().s + float(s),
                                           .position = glm::mix(a.position, b.position, u),
                                           .face = u < 0.5f ? a.face : b.face,
                                           .bary = u < 0.5f ? a.bary : b.bary,
                                           .alpha = glm::mix(a.alpha, b.alpha, u),
                                           .width = glm::mix(a.width, b.width, u),
                                           .other_face = u < 0.5f ? a.other_face : b.other_face});
    }
    return out;
}

namespace {

// A closed loop's parameterization has a seam where T jumps back by ρ·L. Votes inherit the
// previous frame's seam; start the loop there (at the largest jump between consecutive
// votes) so that its votes lie on one line and the seam stays where it was on the surface,
// instead of moving with wherever chaining happened to start the loop this frame.
uint32_t start_loop_at_seam(ScreenPath& path, VoteSet& votes, size_t p) {
    const uint32_t first = votes.offsets[p], last = votes.offsets[p + 1];
    if (!path.closed || last - first < 3 || path.samples.size() < 3) return 0;
    uint32_t seam = 0;
    float jump = 0.0f;
    for (uint32_t v = first; v + 1 < last; ++v) {
        const float d = std::abs(votes.votes[v + 1].t - votes.votes[v].t);
        if (d > jump) {
            jump = d;
            seam = v + 1;
        }
    }
    // Consecutive votes of a smooth parameterization differ by ρ·δ ≪ 0.25 of a period.
    if (jump < 0.25f) return 0;
    const size_t n = path.samples.size(), start = votes.sample[seam];
    rotate_loop(path, start);
    for (uint32_t v = first; v < last; ++v) {
        const uint32_t k = votes.sample[v];
        const uint32_t rotated_index = uint32_t((k + n - start) % n);
        votes.sample[v] = rotated_index;
        votes.votes[v].s = path_arclength(path, rotated_index);
    }
    // Keep the votes in sample order.
    std::vector<std::pair<uint32_t, Vote>> order;
    for (uint32_t v = first; v < last; ++v) order.push_back({votes.sample[v], votes.votes[v]});
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (uint32_t v = first; v < last; ++v) {
        votes.sample[v] = order[v - first].first;
        votes.votes[v] = order[v - first].second;
    }
    return uint32_t(start);
}

// A path's T(s) = ρs + φ: |ρ| the tracker's scale (update_view_scale), in the direction
// RANSAC found (without a fit, the one more votes agree with; RANSAC's slope sign was measured
// the better judge of a path's direction than counting votes both ways), and φ the phase
// most votes agree on (fit_phase). Without votes the path starts at phase 0, at the scale
// every other path has (§4.2's T = s/L would start it in another octave and texture size).
void param_from_scale(PathParam& param, const PathFit& fit, const VoteSet& votes, size_t p, float view_rho,
                      float inlier_px) {
    const std::span<const Vote> own(votes.votes.data() + votes.offsets[p], votes.offsets[p + 1] - votes.offsets[p]);
    param.rho = view_rho;
    param.phi = 0.0f;
    param.fitted = false;
    if (own.empty()) return;
    PhaseFit phase = fit_phase(own, fit.fitted && fit.rho < 0.0f ? -view_rho : view_rho, inlier_px);
    if (fit.fitted) {
        param.rho = fit.rho < 0.0f ? -view_rho : view_rho;
    } else if (const PhaseFit reversed = fit_phase(own, -view_rho, inlier_px); reversed.inliers > phase.inliers) {
        param.rho = -view_rho;
        phase = reversed;
    }
    param.phi = phase.phi;
    param.fitted = true;
}

}  // namespace

namespace {

std::vector<glm::vec3> sprites_of(const std::vector<ScreenPath>& paths, const std::vector<PathParam>& params) {
    std::vector<glm::vec3> sprites;
    for (size_t p = 0; p < paths.size(); ++p) {
        if (!paths[p].visible) continue;
        for (size_t k = 0; k < paths[p].samples.size(); ++k)
            sprites.push_back(glm::vec3(paths[p].samples[k].pixel,
                                        params[p].rho * path_arclength(paths[p], k) + params[p].phi));
    }
    return sprites;
}

}  // namespace

std::vector<glm::vec4> splat_reference(const std::vector<ScreenPath>& paths, const std::vector<PathParam>& params,
                                       int width, int height, float radius) {
    std::vector<glm::vec4> buffer(size_t(width) * height, glm::vec4(0.0f));
    add_sprites(sprites_of(paths, params), radius, width, height, buffer);
    return buffer;
}

CoherenceTracker::CoherenceTracker(const Context& ctx, uint32_t width, uint32_t height, ComputeSite site)
    : ctx_(&ctx), site_(site), width_(width), height_(height), fitter_(ctx, site) {
    if (site == ComputeSite::Host) return;  // the splat is a host loop (splat_sprites)
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(ctx.physical_device(), VK_FORMAT_R32G32B32A32_SFLOAT, &props);
    if (!(props.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT))
        throw Error(ctx.info().name + " cannot blend into RGBA32F attachments, which the parameterization splat needs "
                                      "(the host compute site splats on the host)");
    splat_image_ = Image(ctx, {.width = width, .height = height, .format = VK_FORMAT_R32G32B32A32_SFLOAT,
                               .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               .name = "parameterization splat"});
    splat_pipeline_ = GraphicsPipeline(ctx, {.vertex_spirv = LW_SPIRV(coherence_splat_vert_spv),
                                             .fragment_spirv = LW_SPIRV(coherence_splat_frag_spv),
                                             .vertex_stride = sizeof(Sprite),
                                             .attributes = {{.location = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
                                                            {.location = 1, .format = VK_FORMAT_R32_SFLOAT,
                                                             .offset = offsetof(Sprite, t)}},
                                             .color_format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                             .depth_format = VK_FORMAT_UNDEFINED,
                                             .depth_test = false,
                                             .depth_write = false,
                                             .blend = BlendMode::Additive,
                                             .push_constant_size = sizeof(SplatPush),
                                             .name = "coherence splat",
                                             .per_instance = true});
    splat_readback_ = Buffer(ctx, {.size = VkDeviceSize(width) * height * sizeof(glm::vec4),
                                   .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   .purpose = MemoryPurpose::Readback,
                                   .name = "splat readback"});
}

std::vector<CoherenceTracker::Carried> CoherenceTracker::carry_back(const std::vector<ScreenPath>& paths,
                                                                    const SurfaceFrame& surface) const {
    std::vector<Carried> out;
    if (!has_previous_) return out;
    const bool track_surface = surface.positions && surface.faces &&
                               previous_positions_.size() == surface.positions->size();
    for (uint32_t p = 0; p < paths.size(); ++p) {
        if (!paths[p].visible) continue;
        for (uint32_t k = 0; k < paths[p].samples.size(); ++k) {
            const ScreenSample& sample = paths[p].samples[k];
            // The sample's surface point one frame earlier: moved with its face.
            glm::vec3 previous = sample.position;
            if (track_surface && sample.face < surface.faces->size()) {
                const glm::uvec3 c = (*surface.faces)[sample.face];
                for (int i = 0; i < 3; ++i)
                    previous += sample.bary[i] * (previous_positions_[c[i]] - (*surface.positions)[c[i]]);
            }
            const glm::vec4 clip = previous_camera_.view_proj * glm::vec4(previous, 1.0f);
            out.push_back({p, k, project_to_pixel(previous_camera_, previous, float(width_), float(height_)), clip.z / clip.w});
        }
    }
    return out;
}

CoherenceTracker::ViewZoom CoherenceTracker::view_zoom(const std::vector<Carried>& carried,
                                                       const CameraMatrices& camera) const {
    // The view's zoom at the point on the previous view's axis (the image centre) at the
    // samples' median depth: a camera's dolly or focal change, a vector layer's scale, exactly
    // 1 for a still camera, and for an orbit about the subject 1 to second order in the angle
    // (when the samples' median depth is not the orbit's radius: ρ drifts by about 1e-4 a frame
    // at 3° a frame, 0.2 % over the 120-frame orbits measured).
    std::vector<float> depths;
    for (const Carried& c : carried)
        if (c.pixel.z > 0.0f && std::isfinite(c.ndc_depth)) depths.push_back(c.ndc_depth);
    const ViewZoom none{1.0f, glm::vec2(0.5f * float(width_), 0.5f * float(height_))};
    if (depths.empty()) return none;
    std::nth_element(depths.begin(), depths.begin() + std::ptrdiff_t(depths.size() / 2), depths.end());
    const glm::vec4 h = glm::inverse(previous_camera_.view_proj) * glm::vec4(0.0f, 0.0f, depths[depths.size() / 2], 1.0f);
    const glm::vec3 centre = glm::vec3(h) / h.w;
    const float change = pixels_per_unit(camera, centre, float(width_), float(height_)) /
                         pixels_per_unit(previous_camera_, centre, float(width_), float(height_));
    const glm::vec3 at = project_to_pixel(camera, centre, float(width_), float(height_));
    if (!std::isfinite(change) || !(change > 0.0f) || !(at.z > 0.0f)) return none;
    return {change, glm::vec2(at)};
}

VoteSet CoherenceTracker::gather_votes(const std::vector<ScreenPath>& paths, const std::vector<Carried>& carried,
                                       const ViewZoom& view) const {
    VoteSet set;
    // Where each sample was a frame earlier; the splat is then read at all those pixels at
    // once (on the host: at them alone, splat_grid.h).
    struct Query {
        uint32_t path, sample;
        glm::vec2 pixel;
    };
    std::vector<Query> queries;
    std::vector<glm::ivec2> pixels;
    for (const Carried& c : carried) {
        const ScreenPath& path = paths[c.path];
        const ScreenSample& sample = path.samples[c.sample];
        glm::vec3 pixel = c.pixel;
        // Where the view's zoom about its centre moves the sample (nothing on an orbit).
        const glm::vec2 zoomed = (sample.pixel - view.centre) * (1.0f / view.zoom - 1.0f);
        if (path.type == LineType::Silhouette) {
            // A contour is not attached to the surface: it slides over it as the view turns,
            // but its motion across itself is its surface point's (the normal image velocity of
            // an occluding contour is that of the surface point on it); its motion along the
            // line is the surface sliding under the contour and would drag the texture along
            // a contour that stays put on screen. Along the line it moves as the view's zoom
            // scales the image about the zoom's centre (a dolly; nothing on an orbit; the
            // centre's own motion is left out: on an orbit it is parallax, not the line's
            // motion, and measured worse).
            const glm::vec2 tangent = path_tangent(path, c.sample);
            const glm::vec2 moved = glm::vec2(pixel) - sample.pixel;
            pixel = glm::vec3(sample.pixel + moved + glm::dot(zoomed - moved, tangent) * tangent, pixel.z);
        } else if (!attached_to_surface(path.type)) {
            // A suggestive contour (the zero set of κr) moves over the surface at a speed of
            // its own, across itself too, so its surface point's motion is not the line's:
            // it looks up its closest correspondent where it is now (§4.1), moved only by the
            // view's zoom. So do rtsc's other view-dependent lines (suggestive highlights are
            // the other half of the same zero set; apparent ridges and principal highlights
            // slide as the view turns). Measured against the across motion (120-frame orbits, 640×480, p90
            // |Δt| against the tiling policy's): a statue scan 0.93 → 0.36, LeePerrySmith
            // 0.22 → 0.14, Suzanne 0.15 → 0.12, FlightHelmet 0.34 → 0.27.
            pixel = glm::vec3(sample.pixel + zoomed, pixel.z);
        }
        if (pixel.z <= 0.0f || pixel.x < 0.0f || pixel.y < 0.0f || pixel.x >= float(width_) || pixel.y >= float(height_))
            continue;
        queries.push_back({c.path, c.sample, glm::vec2(pixel)});
        pixels.emplace_back(int(pixel.x), int(pixel.y));
    }
    std::vector<glm::vec4> sums;
    if (site_ == ComputeSite::Host) {
        host_splat_.read(pixels, sums);
    } else {  // the device's splat, read back
        sums.resize(pixels.size());
        for (size_t q = 0; q < pixels.size(); ++q) sums[q] = splat_at(uint32_t(pixels[q].x), uint32_t(pixels[q].y));
    }
    size_t q = 0;
    for (uint32_t p = 0; p < paths.size(); ++p) {
        for (; q < queries.size() && queries[q].path == p; ++q) {
            const glm::vec4 sum = sums[q];
            if (sum.y <= 1e-6f) continue;
            // Σwt/Σw is the parameterization at the weighted centre of the sprites that
            // reached this pixel, not at the sample: near a path's ends (where all sprites lie
            // on one side) and at the pixel's own offset that would pull every vote along the
            // path and shrink ρ frame after frame. Vote at the arclength of that centre
            // instead: the sample's, moved by the centre's offset along the path.
            const uint32_t k = queries[q].sample;
            const glm::vec2 at = queries[q].pixel;
            const glm::vec2 centre = glm::vec2(std::floor(at.x) + 0.5f, std::floor(at.y) + 0.5f) + glm::vec2(sum.z, sum.w) / sum.y;
            const float along = glm::dot(centre - at, path_tangent(paths[p], k));
            set.votes.push_back({sum.x / sum.y, path_arclength(paths[p], k) + along});
            set.sample.push_back(k);
        }
        set.offsets.push_back(uint32_t(set.votes.size()));
    }
    return set;
}

// Why one scale for the set, carried through the view's zoom, and not each path's fitted
// slope (§4.2 fits both ρ and φ per path): fitted per path, ρ carried each frame's few-percent
// slope error into the next frame with nothing pulling it back. On a 360° orbit it wandered
// over the whole octave the SLAM fold allows (median |log2 ρ/ρ0| 0.3 on FlightHelmet's
// silhouettes, a third of the paths in the octave above the others), and every change of
// scale slid the texture along the path (BENCHMARKS "Coherence on every model"). A
// silhouette or suggestive contour slides over the surface and has no length of its own to
// follow; a crease has, but its foreshortening from frame to frame is smaller than the fit's
// noise. So ρ follows only the view's zoom (1 on an orbit, the ratio on a dolly or a vector
// layer's zoom; gather_votes), the same for every path of the set, and paths
// that meet or overlap in the splat agree on it; RANSAC's fit still gives each path's
// direction and its disagreeing runs, and the phase is fitted alone.
void CoherenceTracker::update_view_scale(VoteSet& votes, float zoom, const CoherenceParams& params) {
    // The tiling scale ρ0 is where fold_slam_level changes level (λ = 1: level 1 and 0.5 at
    // twice the coordinate scale). A scale held there by an orbit switched between the two
    // with every rounding of the zoom (identical strokes, as A1.0 = [A0.5 A0.5], but another
    // texture period): start √2 from either level change instead.
    const float rho0 = params.length_scale / params.slam_length_px;
    if (!(view_rho_ > 0.0f) || !has_previous_) view_rho_ = params.slam_levels ? rho0 * (1.0f / std::numbers::sqrt2_v<float>) : rho0;
    if (std::isfinite(zoom) && zoom > 0.0f) view_rho_ /= zoom;  // the texture keeps its size on the surface
    // Kept in T's home octave [ρ0/2, 2ρ0] (the SLAM fold draws T and 2^k·T alike, and T's
    // values stay in periods of the texture as drawn); the votes carry the previous frame's T,
    // so they are scaled with it.
    const float ratio = view_rho_ / rho0;
    if (!(ratio >= 0.5f && ratio <= 2.0f) && std::isfinite(ratio) && ratio > 0.0f) {
        const float scale = std::exp2(-std::round(std::log2(ratio)));
        view_rho_ *= scale;
        for (Vote& vote : votes.votes) vote.t *= scale;
    }
}

void CoherenceTracker::splat(const std::vector<ScreenPath>& paths, const std::vector<PathParam>& params, float radius,
                             GpuTimer* timer) {
    splat_sprites(sprites_of(paths, params), radius, timer);
}

void CoherenceTracker::restore(const State& state, const SurfaceFrame& surface) {
    has_previous_ = state.has_previous;
    previous_camera_ = state.camera;
    view_rho_ = state.view_rho;
    still_ = state.still;
    if (surface.positions) previous_positions_ = *surface.positions;
    if (state.has_previous) splat_sprites(state.sprites, state.radius, nullptr);
}

void CoherenceTracker::splat_sprites(const std::vector<glm::vec3>& sprites_in, float radius, GpuTimer* timer) {
    // A sample projected from a degenerate camera or face can be NaN or infinite: it reaches
    // no pixel (the GPU would clip it), and must not reach the integer arithmetic below.
    std::vector<glm::vec3> sprite_list;
    sprite_list.reserve(sprites_in.size());
    for (const glm::vec3& s : sprites_in)
        if (std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z)) sprite_list.push_back(s);
    last_sprites_ = sprite_list;
    last_radius_ = radius;
    if (site_ == ComputeSite::Host) {
        // Not drawn: read at the next frame's samples alone (splat_grid.h).
        host_splat_.splat(sprite_list, radius, int(width_), int(height_));
        return;
    }
    // Only the band of rows the sprites reach is cleared, drawn and read back: the copy of a
    // whole RGBA32F frame (15 MB at 1280×720) was most of this stage's time on lavapipe.
    splat_first_row_ = splat_rows_ = 0;
    if (sprite_list.empty()) return;
    float top = sprite_list.front().y, bottom = top;
    for (const glm::vec3& s : sprite_list) {
        top = std::min(top, s.y);
        bottom = std::max(bottom, s.y);
    }
    const float margin = radius + 2.0f;  // the sprite quads reach radius + 1 (coherence_splat.vert)
    const auto first = uint32_t(std::clamp(std::floor(top - margin), 0.0f, float(height_)));
    const auto end = uint32_t(std::clamp(std::ceil(bottom + margin) + 1.0f, 0.0f, float(height_)));
    if (end <= first) return;
    splat_first_row_ = first;
    splat_rows_ = end - first;

    ensure_buffer(*ctx_, sprite_buffer_, {.size = sprite_list.size() * sizeof(Sprite),
                                          .usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                          .purpose = MemoryPurpose::Upload,
                                          .name = "splat sprites"});
    auto* sprites = static_cast<Sprite*>(sprite_buffer_.mapped());
    for (size_t i = 0; i < sprite_list.size(); ++i) sprites[i] = {glm::vec2(sprite_list[i]), sprite_list[i].z};
    ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
        if (timer) {
            timer->reset(cmd);
            timer->begin(cmd, "splat");
        }
        record_image_barrier(cmd, splat_image_,
                             {.old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
                              .new_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                              .src_stage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                              .src_access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                              .dst_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                              .dst_access = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT |
                                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
        const VkRect2D band{{0, int32_t(splat_first_row_)}, {width_, splat_rows_}};
        begin_color_rendering(cmd, splat_image_, VK_ATTACHMENT_LOAD_OP_CLEAR, band, width_, height_);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, splat_pipeline_.get());
        const SplatPush push{{float(width_), float(height_)}, radius, 0.0f};
        splat_pipeline_.draw(cmd, sprite_buffer_, 6, &push, sizeof(push), uint32_t(sprite_list.size()));
        vkCmdEndRendering(cmd);
        record_image_barrier(cmd, splat_image_,
                             {.old_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                              .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              .src_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                              .src_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                              .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                              .dst_access = VK_ACCESS_2_TRANSFER_READ_BIT});
        if (timer) timer->end(cmd);
        record_image_rows_to_buffer(cmd, splat_image_, splat_readback_, splat_first_row_, splat_rows_);
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    // The next update() reads the band in place (splat_at), before anything splats again.
    splat_readback_.invalidate(*ctx_);
}

glm::vec4 CoherenceTracker::splat_at(uint32_t x, uint32_t y) const {
    if (y < splat_first_row_ || y >= splat_first_row_ + splat_rows_) return glm::vec4(0.0f);
    return static_cast<const glm::vec4*>(splat_readback_.mapped())[size_t(y) * width_ + x];
}

std::vector<glm::vec4> CoherenceTracker::splat_buffer() const {
    std::vector<glm::vec4> out(size_t(width_) * height_);
    if (site_ == ComputeSite::Host) {
        std::vector<glm::ivec2> pixels;
        for (uint32_t y = 0; y < height_; ++y)
            for (uint32_t x = 0; x < width_; ++x) pixels.emplace_back(x, y);
        host_splat_.read(pixels, out);
        return out;
    }
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x) out[size_t(y) * width_ + x] = splat_at(x, y);
    return out;
}

namespace {

// The tiling and stretching policies: ρ from the texture length or the path length, φ = 0.
std::vector<PathParam> fixed_params(const std::vector<ScreenPath>& paths, const CoherenceParams& params) {
    std::vector<PathParam> out(paths.size());
    for (size_t p = 0; p < paths.size(); ++p) {
        PathParam& param = out[p];
        param.length_px = path_length(paths[p]);
        if (params.policy == ParamPolicy::Stretch)  // the whole texture stretched over the path
            param.rho = param.length_px > 0.0f ? 1.0f / param.length_px : 1.0f;
        else  // tiling: one period per texture length on screen
            param.rho = params.length_scale / params.slam_length_px;
    }
    return out;
}

// What a kept path's pieces and parameters were made with besides its samples: the set's
// settings and scale (the view's ρ).
uint64_t settings_key(const CoherenceParams& p, float view_rho) {
    uint64_t h = 0;
    for (const float v : {p.splat_radius_px, p.length_scale, p.slam_length_px, p.min_stroke_length_px,
                          p.ransac.outlier_ratio, p.ransac.target_probability, p.ransac.inlier_px, view_rho})
        h = still_key_step(h, std::bit_cast<uint32_t>(v));
    for (const uint32_t v : {uint32_t(p.policy), uint32_t(p.slam_levels), p.ransac.max_iterations, p.ransac.seed})
        h = still_key_step(h, v);
    return h;
}

bool same_camera(const CameraMatrices& a, const CameraMatrices& b) {
    return a.view == b.view && a.proj == b.proj && a.view_proj == b.view_proj && a.znear == b.znear && a.zfar == b.zfar;
}

}  // namespace

bool too_short_for_texture(const ScreenPath& path, const CoherenceParams& params) {
    return path.visible && path_length(path) < params.min_stroke_length_px;
}

std::vector<PathParam> CoherenceTracker::update(std::vector<ScreenPath>& paths, const CameraMatrices& camera,
                                                const SurfaceFrame& surface, const CoherenceParams& params,
                                                GpuTimer* timer) {
    // Fragments too short to carry a stroke texture are not drawn, splatted or dumped.
    std::erase_if(paths, [&](const ScreenPath& path) { return too_short_for_texture(path, params); });
    std::vector<PathParam> out;
    if (params.policy != ParamPolicy::Coherent) {
        view_rho_ = 0.0f;  // back to the coherent policy, the scale starts afresh with the splat's T
        still_ = {};
        out = fixed_params(paths, params);
    } else {
        // A moving view (or the first) keeps no path: none is where it was. Its paths are
        // recorded all the same, so that a still view after it keeps them: unrecorded, the
        // first frame of a still shot was refitted by the second, which cut pieces at junctions
        // where neighbours' splats blend (spot_line_sets.json: 1.45 % of the pixels changed
        // from frame 0 to 1, none after).
        if (!has_previous_ || !same_camera(camera, previous_camera_)) still_ = {};
        out = update_keeping_still_paths(paths, camera, surface, params);
    }
    splat(paths, out, params.splat_radius_px, timer);
    has_previous_ = true;
    previous_camera_ = camera;
    if (surface.positions) previous_positions_ = *surface.positions;
    return out;
}

std::vector<PathParam> CoherenceTracker::parameterize(std::vector<ScreenPath>& paths, const CameraMatrices& camera,
                                                      const SurfaceFrame& surface, const CoherenceParams& params,
                                                      std::vector<PieceOrigin>* origins,
                                                      std::vector<uint32_t>* rotations) {
    const std::vector<Carried> carried = carry_back(paths, surface);
    const ViewZoom view = view_zoom(carried, camera);
    VoteSet votes = gather_votes(paths, carried, view);
    update_view_scale(votes, view.zoom, params);
    if (rotations) rotations->assign(paths.size(), 0);
    for (size_t p = 0; p < paths.size(); ++p) {
        const uint32_t start = start_loop_at_seam(paths[p], votes, p);
        if (rotations) (*rotations)[p] = start;
    }
    // RANSAC's fit finds each path's direction along the previous parameterization and the
    // runs of votes that disagree with it (pieces of paths that were apart a frame earlier).
    std::vector<PathFit> fits;
    if (!paths.empty()) fits = fitter_.fit(votes, params.ransac);
    split_merged_paths(paths, votes, fits, params.ransac, params.splat_radius_px, fitter_, origins);
    std::vector<PathParam> out(paths.size());
    for (size_t p = 0; p < paths.size(); ++p) {
        PathParam& param = out[p];
        param.length_px = path_length(paths[p]);
        param.votes = fits[p].votes;
        param_from_scale(param, fits[p], votes, p, view_rho_, params.ransac.inlier_px);
        // Only a SLAM has levels to fold into; a set without one (plain lines, dashes,
        // displacement: modifiers read ρ and φ) samples no texture along u, and folding it
        // would only flip u's scale between 1 and 2 as ρ, held at the tiling scale ρ0 where
        // the level changes, rounds either way.
        param.fold = params.slam_levels ? fold_slam_level(param.rho, params.length_scale, params.slam_length_px)
                                        : SlamFold{};
    }
    return out;
}

std::vector<PathParam> CoherenceTracker::update_keeping_still_paths(std::vector<ScreenPath>& paths,
                                                                    const CameraMatrices& camera,
                                                                    const SurfaceFrame& surface,
                                                                    const CoherenceParams& params) {
    // The pieces and parameters were made with the set's settings and scale: a set edited
    // under a still camera (the viewer's panel, a Python script) keeps none.
    if (still_.settings != settings_key(params, view_rho_)) still_ = {};
    std::vector<uint64_t> keys(paths.size());
    std::vector<const StillPath*> kept(paths.size());
    MovedPaths moved;
    for (size_t p = 0; p < paths.size(); ++p) {
        keys[p] = still_path_key(paths[p]);
        kept[p] = find_still_path(still_, keys[p]);
        if (!kept[p]) moved.pieces.push_back(std::move(paths[p]));
    }
    moved.params = parameterize(moved.pieces, camera, surface, params, &moved.origins, &moved.rotations);
    std::vector<PathParam> out;
    StillRecord record = assemble_still_frame(paths, keys, kept, still_, moved, out);
    record.settings = settings_key(params, view_rho_);
    still_ = std::move(record);
    return out;
}

}  // namespace lw
