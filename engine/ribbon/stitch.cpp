#include "ribbon/stitch.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/error.h"
#include "core/parallel.h"
#include "ribbon_stitch_comp.h"

namespace lw {

namespace {

float beta(uint32_t l, uint32_t r) { return (texel_opaque(l) || texel_opaque(r)) ? kStitchP : 0.0f; }

// One seam, exactly as shaders/ribbon_stitch.comp computes it.
void stitch_seam(const DpProblem& problem, size_t row, glm::ivec2 prev, glm::ivec2 cur, std::vector<int32_t>& remap,
                 float& before, float& after) {
    const Exemplar& e = *problem.exemplar;
    const int C = problem.samples;
    const std::vector<glm::ivec2>& right = problem.rows[row - 1].right;
    const std::vector<glm::ivec2>& left = problem.rows[row].left;
    std::vector<uint32_t> L(static_cast<size_t>(C)), R(static_cast<size_t>(C));
    for (int k = 0; k < C; ++k) {
        const glm::ivec2 l = cur + left[size_t(k)], r = prev + right[size_t(k)];
        L[size_t(k)] = e.at(l.x, l.y);
        R[size_t(k)] = e.at(r.x, r.y);
    }
    std::vector<float> rows(2 * size_t(C));
    std::vector<uint8_t> moves(size_t(C) * size_t(C));
    for (int s = 0; s < C; ++s) {
        float* here = &rows[size_t(s & 1) * size_t(C)];
        const float* above = &rows[size_t((s + 1) & 1) * size_t(C)];
        for (int t = 0; t < C; ++t) {
            const float c = xi(L[size_t(s)], R[size_t(t)]), b = beta(L[size_t(s)], R[size_t(t)]);
            float best;
            uint8_t move;
            if (s == 0 && t == 0) {
                best = 0.0f;
                move = RIBBON_MOVE_DIAGONAL;
            } else if (s == 0) {
                best = here[t - 1] + b;
                move = RIBBON_MOVE_T;
            } else if (t == 0) {
                best = above[t] + b;
                move = RIBBON_MOVE_S;
            } else {
                best = above[t - 1];
                move = RIBBON_MOVE_DIAGONAL;
                const float from_s = above[t] + b;
                const float from_t = here[t - 1] + b;
                if (from_s < best) {
                    best = from_s;
                    move = RIBBON_MOVE_S;
                }
                if (from_t < best) {
                    best = from_t;
                    move = RIBBON_MOVE_T;
                }
            }
            here[t] = best + c;
            moves[size_t(s) * size_t(C) + size_t(t)] = move;
        }
    }
    remap.assign(size_t(C), 0);
    int s = C - 1, t = C - 1;
    float best_c = std::numeric_limits<float>::infinity();
    int best_t = t;
    while (true) {
        const float c = xi(L[size_t(s)], R[size_t(t)]);
        if (c <= best_c) {
            best_c = c;
            best_t = t;
        }
        if (s == 0 && t == 0) break;
        const uint8_t move = moves[size_t(s) * size_t(C) + size_t(t)];
        if (move != RIBBON_MOVE_T) {
            remap[size_t(s)] = best_t;
            best_c = std::numeric_limits<float>::infinity();
        }
        if (move == RIBBON_MOVE_DIAGONAL) {
            --s;
            --t;
        } else if (move == RIBBON_MOVE_S) {
            --s;
        } else {
            --t;
        }
    }
    remap[0] = best_t;
    before = 0.0f;
    after = 0.0f;
    for (int k = 0; k < C; ++k) before += xi(L[size_t(k)], R[size_t(k)]);
    for (int k = 0; k < C; ++k) after += xi(L[size_t(k)], R[size_t(remap[size_t(k)])]);
}

struct StitchPush {
    int32_t width, height, samples, seam_count;
    int32_t pad, moves_per_seam, seam_begin, batch;
};

}  // namespace

float StitchResult::total_before() const {
    float total = 0.0f;
    for (float e : error_before) total += e;
    return total;
}

float StitchResult::total_after() const {
    float total = 0.0f;
    for (float e : error_after) total += e;
    return total;
}

StitchResult stitch_reference(const DpProblem& problem, const std::vector<glm::ivec2>& positions) {
    const size_t seams = positions.size() > 0 ? positions.size() - 1 : 0;
    StitchResult result;
    result.remap.resize(seams);
    result.error_before.resize(seams);
    result.error_after.resize(seams);
    parallel_for(seams, 4, [&](size_t begin, size_t end, size_t) {
        for (size_t i = begin; i < end; ++i)
            stitch_seam(problem, i + 1, positions[i], positions[i + 1], result.remap[i], result.error_before[i],
                        result.error_after[i]);
    });
    return result;
}

RibbonStitcherGpu::RibbonStitcherGpu(const Context& ctx)
    : ctx_(&ctx),
      pipeline_(ctx, {.spirv = LW_SPIRV(ribbon_stitch_comp_spv), .storage_buffers = 7,
                      .push_constant_size = sizeof(StitchPush), .name = "ribbon stitch"}) {}

StitchResult RibbonStitcherGpu::stitch(const DpProblem& problem, const std::vector<glm::ivec2>& positions,
                                       size_t max_scratch_bytes) const {
    const Context& ctx = *ctx_;
    const size_t seams = positions.size() > 0 ? positions.size() - 1 : 0;
    StitchResult result;
    if (seams == 0) return result;
    const int C = problem.samples;

    // Per seam: the right-edge offsets of the row before it, then the left-edge offsets of the
    // row after it.
    std::vector<glm::ivec2> probes;
    std::vector<glm::ivec4> seam_info;
    for (size_t i = 0; i < seams; ++i) {
        const auto right_offset = int32_t(probes.size());
        probes.insert(probes.end(), problem.rows[i].right.begin(), problem.rows[i].right.end());
        const auto left_offset = int32_t(probes.size());
        probes.insert(probes.end(), problem.rows[i + 1].left.begin(), problem.rows[i + 1].left.end());
        seam_info.push_back({positions[i], positions[i + 1]});
        seam_info.push_back({right_offset, left_offset, 0, 0});
    }

    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const auto out_usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    const Buffer exemplar = upload_buffer(ctx, problem.exemplar->texels, storage, "ribbon stitch exemplar");
    const Buffer probe_buffer = upload_buffer(ctx, probes, storage, "ribbon stitch probes");
    const Buffer seam_buffer = upload_buffer(ctx, seam_info, storage, "ribbon stitch seams");
    const auto moves_per_seam = int32_t((size_t(C) * size_t(C) + 15) / 16);
    // Scratch (two rows of M and the moves) for a batch of seams under max_scratch_bytes.
    const size_t scratch_per_seam = (2 * size_t(C) + size_t(moves_per_seam)) * 4;
    const size_t batch = std::clamp<size_t>(max_scratch_bytes / scratch_per_seam, 1, seams);
    const Buffer rows(ctx, {.size = VkDeviceSize(batch) * 2 * size_t(C) * 4, .usage = storage, .name = "ribbon stitch rows"});
    const Buffer moves(ctx, {.size = VkDeviceSize(batch) * size_t(moves_per_seam) * 4, .usage = storage,
                             .name = "ribbon stitch moves"});
    const Buffer remap(ctx, {.size = VkDeviceSize(seams) * size_t(C) * 4, .usage = out_usage, .name = "ribbon stitch remap"});
    const Buffer errors(ctx, {.size = VkDeviceSize(seams) * 8, .usage = out_usage, .name = "ribbon stitch errors"});

    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        for (size_t begin = 0; begin < seams; begin += batch) {
            const StitchPush push{problem.exemplar->width, problem.exemplar->height, C, int32_t(seams), 0,
                                  moves_per_seam, int32_t(begin), int32_t(batch)};
            pipeline_.dispatch(ctx, cmd, {&exemplar, &probe_buffer, &seam_buffer, &rows, &moves, &remap, &errors},
                               &push, uint32_t((batch + RIBBON_GROUP - 1) / RIBBON_GROUP));
            // The next batch reuses the scratch.
            record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
                                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                                  VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT |
                                      VK_ACCESS_2_TRANSFER_READ_BIT);
        }
    });
    const std::vector<int32_t> flat = read_buffer_as<int32_t>(ctx, remap);
    const std::vector<float> err = read_buffer_as<float>(ctx, errors);
    result.remap.resize(seams);
    result.error_before.resize(seams);
    result.error_after.resize(seams);
    for (size_t i = 0; i < seams; ++i) {
        result.remap[i].assign(flat.begin() + std::ptrdiff_t(i * size_t(C)), flat.begin() + std::ptrdiff_t((i + 1) * size_t(C)));
        result.error_before[i] = err[2 * i];
        result.error_after[i] = err[2 * i + 1];
    }
    return result;
}

}  // namespace lw
