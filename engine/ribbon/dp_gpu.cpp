#include "ribbon/dp_gpu.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/timer.h"
#include "ribbon/dp_reference.h"
#include "ribbon_compact_comp.h"
#include "ribbon_cost_table_comp.h"
#include "ribbon_extract_columns_comp.h"
#include "ribbon_find_valid_comp.h"
#include "ribbon_update_row_comp.h"

namespace lw {

namespace {

// Mirror the push-constant blocks of the kernels.
struct FindValidPush {
    int32_t width, height, samples, count;
    int32_t top_offset, top_count, interior_offset, interior_count;
    int32_t forbidden_offset, forbidden_count, min_dx, max_dx;
    int32_t touches_forbidden, bottom_offset, bottom_count, rule;
    int32_t band_top, band_bottom, pad1, pad2;
};
struct CompactPush {
    uint32_t phase, count, blocks, pad;
};
struct ExtractPush {
    int32_t width, height, samples, count;
    int32_t right_offset, pad0, pad1, pad2;
};
struct CostPush {
    int32_t width, height, samples, prev_count;
    int32_t u_begin, u_count, left_offset, pad;
};
struct UpdatePush {
    int32_t prev_count, u_begin, u_count, pad;
};
static_assert(sizeof(FindValidPush) == 80 && sizeof(CostPush) == 32 && sizeof(ExtractPush) == 32);

// Where each row's probe lists start in the one probe buffer.
struct RowOffsets {
    int32_t right, top, top_count, bottom, bottom_count, interior, interior_count, forbidden, forbidden_count;
};

constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

Buffer device_buffer(const Context& ctx, VkDeviceSize bytes, const char* name) {
    return Buffer(ctx, {.size = std::max<VkDeviceSize>(bytes, 16), .usage = kUsage, .name = name});
}
Buffer readback_buffer(const Context& ctx, VkDeviceSize bytes, const char* name) {
    return Buffer(ctx, {.size = std::max<VkDeviceSize>(bytes, 16), .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        .purpose = MemoryPurpose::Readback, .name = name});
}

// Compute and transfer writes visible to the following compute and transfer work.
void barrier(VkCommandBuffer cmd) {
    const VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_TRANSFER_BIT;
    record_memory_barrier(cmd, stages, VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT, stages,
                          VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_TRANSFER_READ_BIT |
                              VK_ACCESS_2_TRANSFER_WRITE_BIT);
}
void host_barrier(VkCommandBuffer cmd) {
    record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}
void copy(VkCommandBuffer cmd, const Buffer& from, const Buffer& to, VkDeviceSize bytes, VkDeviceSize dst_offset = 0) {
    if (bytes == 0) return;
    VkBufferCopy region{.srcOffset = 0, .dstOffset = dst_offset, .size = bytes};
    vkCmdCopyBuffer(cmd, from.get(), to.get(), 1, &region);
}
uint32_t groups(uint64_t n, uint32_t size) { return uint32_t((n + size - 1) / size); }

}  // namespace

RibbonDpGpu::RibbonDpGpu(const Context& ctx)
    : ctx_(&ctx),
      find_valid_(ctx, {.spirv = LW_SPIRV(ribbon_find_valid_comp_spv), .storage_buffers = 3,
                        .push_constant_size = sizeof(FindValidPush), .name = "ribbon findValidPositions"}),
      compact_(ctx, {.spirv = LW_SPIRV(ribbon_compact_comp_spv), .storage_buffers = 5,
                     .push_constant_size = sizeof(CompactPush), .name = "ribbon compactValidPositions"}),
      extract_(ctx, {.spirv = LW_SPIRV(ribbon_extract_columns_comp_spv), .storage_buffers = 4,
                     .push_constant_size = sizeof(ExtractPush), .name = "ribbon extractColumns"}),
      cost_(ctx, {.spirv = LW_SPIRV(ribbon_cost_table_comp_spv), .storage_buffers = 5,
                  .push_constant_size = sizeof(CostPush), .name = "ribbon computeCostTable"}),
      update_(ctx, {.spirv = LW_SPIRV(ribbon_update_row_comp_spv), .storage_buffers = 4,
                    .push_constant_size = sizeof(UpdatePush), .name = "ribbon updateTableRow"}) {}

DpTables RibbonDpGpu::run(const DpProblem& problem, const DpRunOptions& options) {
    const Context& ctx = *ctx_;
    const Exemplar& e = *problem.exemplar;
    const uint32_t U = problem.position_count();
    const int32_t C = problem.samples;
    const size_t rows = problem.rows.size();
    const uint32_t max_groups = ctx.properties().limits.maxComputeWorkGroupCount[0];
    if (groups(U, RIBBON_GROUP) > max_groups || groups(U, RIBBON_SCAN_BLOCK) > max_groups)
        throw Error("ribbon: " + std::to_string(U) + " exemplar positions exceed the device's dispatch limits");

    // Every row's probes in one buffer, the left-edge offsets after them.
    std::vector<glm::ivec2> probes;
    std::vector<RowOffsets> offsets;
    auto append = [&](const std::vector<glm::ivec2>& list) {
        const auto at = int32_t(probes.size());
        probes.insert(probes.end(), list.begin(), list.end());
        return at;
    };
    for (const PieceProbes& p : problem.rows) {
        RowOffsets o{};
        o.right = append(p.right);
        o.top = append(p.top);
        o.top_count = int32_t(p.top.size());
        o.bottom = append(p.bottom);
        o.bottom_count = int32_t(p.bottom.size());
        o.interior = append(p.interior);
        o.interior_count = int32_t(p.interior.size());
        o.forbidden = append(p.forbidden);
        o.forbidden_count = int32_t(p.forbidden.size());
        offsets.push_back(o);
    }
    const auto left_offset = int32_t(probes.size());
    for (int dy : problem.left_dy) probes.push_back({0, dy});

    const Buffer exemplar = upload_buffer(ctx, e.texels, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "ribbon exemplar");
    const Buffer probe_buffer = upload_buffer(ctx, probes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "ribbon probes");
    const uint32_t blocks = groups(U, RIBBON_SCAN_BLOCK);
    const VkDeviceSize row_bytes = VkDeviceSize(U) * 4;
    Buffer flags = device_buffer(ctx, row_bytes, "ribbon valid flags");
    Buffer prefix = device_buffer(ctx, row_bytes, "ribbon scan prefix");
    Buffer block_sums = device_buffer(ctx, VkDeviceSize(blocks) * 4, "ribbon scan block sums");
    Buffer header = device_buffer(ctx, 16, "ribbon valid count");
    Buffer valid[2] = {device_buffer(ctx, row_bytes, "ribbon valid positions A"),
                       device_buffer(ctx, row_bytes, "ribbon valid positions B")};
    Buffer costs[2] = {device_buffer(ctx, row_bytes, "ribbon DP row A"), device_buffer(ctx, row_bytes, "ribbon DP row B")};
    Buffer back = device_buffer(ctx, row_bytes, "ribbon back pointers");
    Buffer columns, table, table_readback;
    VkDeviceSize columns_bytes = 0, table_bytes = 0, table_readback_bytes = 0;
    Buffer count_readback = readback_buffer(ctx, 16, "ribbon valid count readback");
    Buffer row_readback = readback_buffer(ctx, 3 * row_bytes, "ribbon row readback");

    auto record_find_and_compact = [&](VkCommandBuffer cmd, size_t row, const Buffer& valid_out, ValidityRule rule) {
        const PieceProbes& p = problem.rows[row];
        const RowOffsets& o = offsets[row];
        const FindValidPush fv{e.width, e.height, C, int32_t(U), o.top, o.top_count, o.interior,
                               o.interior_count, o.forbidden, o.forbidden_count, p.min_dx, p.max_dx,
                               p.touches_forbidden ? 1 : 0, o.bottom, o.bottom_count, int32_t(rule),
                               problem.band.x, problem.band.y, 0, 0};
        find_valid_.dispatch(ctx, cmd, {&exemplar, &probe_buffer, &flags}, &fv, groups(U, RIBBON_GROUP));
        barrier(cmd);
        for (uint32_t phase = 0; phase < 3; ++phase) {
            const CompactPush cp{phase, U, blocks, 0};
            compact_.dispatch(ctx, cmd, {&flags, &prefix, &block_sums, &valid_out, &header}, &cp,
                              phase == 1 ? 1 : blocks);
            barrier(cmd);
        }
        copy(cmd, header, count_readback, 4);
        host_barrier(cmd);
    };
    auto read_count = [&] {
        count_readback.invalidate(ctx);
        uint32_t n = 0;
        std::memcpy(&n, count_readback.mapped(), 4);
        return n;
    };
    auto read_u32 = [&](VkDeviceSize offset, size_t n) {
        std::vector<uint32_t> out(n);
        if (n > 0) std::memcpy(out.data(), static_cast<const std::byte*>(row_readback.mapped()) + offset, n * 4);
        return out;
    };

    // Rows where no position passes are searched again under a looser slicing rule (problem.h).
    auto relax = [&](size_t row, const Buffer& valid_out, uint32_t& count, ValidityRule& rule) {
        while (count == 0 && rule != ValidityRule::Any) {  // Band → Empty → Edges → Any
            rule = ValidityRule(int(rule) + 1);
            ctx.submit_and_wait([&](VkCommandBuffer cmd) { record_find_and_compact(cmd, row, valid_out, rule); });
            count = read_count();
        }
        if (count == 0) throw Error(no_valid_position_message(problem, row));
    };

    DpTables t;
    t.valid.resize(rows);
    t.back.resize(rows);
    t.rules.assign(rows, ValidityRule::Band);
    if (options.keep_cost_tables) t.cost_tables.resize(rows);

    // Row 0: valid positions, P[0, ·] = 0.
    ctx.submit_and_wait([&](VkCommandBuffer cmd) { record_find_and_compact(cmd, 0, valid[0], ValidityRule::Band); });
    uint32_t count = read_count();
    relax(0, valid[0], count, t.rules[0]);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        copy(cmd, valid[0], row_readback, VkDeviceSize(count) * 4);
        vkCmdFillBuffer(cmd, costs[0].get(), 0, VkDeviceSize(count) * 4, 0u);  // 0.0f
        host_barrier(cmd);
        barrier(cmd);
    });
    row_readback.invalidate(ctx);
    t.valid[0] = read_u32(0, count);
    if (options.first_position) {
        const uint32_t first = *options.first_position;
        if (std::find(t.valid[0].begin(), t.valid[0].end(), first) == t.valid[0].end())
            throw Error("ribbon: the fixed first position is not valid for piece 0");
        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            vkCmdUpdateBuffer(cmd, valid[0].get(), 0, 4, &first);
            barrier(cmd);
        });
        t.valid[0] = {first};
    }
    if (options.progress) options.progress(0, rows, uint32_t(t.valid[0].size()));

    int cur = 0;
    for (size_t i = 1; i < rows; ++i) {
        Timer timer;
        const int prev = cur;
        cur = 1 - cur;
        const auto prev_count = uint32_t(t.valid[i - 1].size());
        if (groups(prev_count, RIBBON_TILE) > ctx.properties().limits.maxComputeWorkGroupCount[1])
            throw Error("ribbon: " + std::to_string(prev_count) + " valid positions exceed the device's dispatch limits");
        const VkDeviceSize need_columns = VkDeviceSize(prev_count) * VkDeviceSize(C) * 4;
        if (need_columns > columns_bytes) {
            columns_bytes = need_columns;
            columns = device_buffer(ctx, columns_bytes, "ribbon right edges");
        }

        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            const ExtractPush ep{e.width, e.height, C, int32_t(prev_count), offsets[i - 1].right, 0, 0, 0};
            extract_.dispatch(ctx, cmd, {&exemplar, &probe_buffer, &valid[prev], &columns}, &ep,
                              groups(prev_count, RIBBON_GROUP));
            record_find_and_compact(cmd, i, valid[cur], ValidityRule::Band);
        });
        count = read_count();
        relax(i, valid[cur], count, t.rules[i]);

        // The table in chunks of new-piece positions, each under max_table_bytes.
        const size_t per_chunk = std::max<size_t>(1, options.max_table_bytes / 4 / prev_count);
        const auto chunk = uint32_t(options.keep_cost_tables ? count : std::min<size_t>(count, per_chunk));
        const VkDeviceSize need_table = VkDeviceSize(prev_count) * chunk * 4;
        if (need_table > table_bytes) {
            table_bytes = need_table;
            table = device_buffer(ctx, table_bytes, "ribbon cost table");
        }
        if (options.keep_cost_tables && need_table > table_readback_bytes) {
            table_readback_bytes = need_table;
            table_readback = readback_buffer(ctx, table_readback_bytes, "ribbon cost table readback");
        }
        const bool last = i + 1 == rows;
        ctx.submit_and_wait([&](VkCommandBuffer cmd) {
            for (uint32_t begin = 0; begin < count; begin += chunk) {
                const uint32_t n = std::min(chunk, count - begin);
                const CostPush cp{e.width, e.height, C, int32_t(prev_count), int32_t(begin), int32_t(n), left_offset, 0};
                cost_.dispatch(ctx, cmd, {&exemplar, &columns, &valid[cur], &probe_buffer, &table}, &cp,
                               groups(n, RIBBON_TILE), groups(prev_count, RIBBON_TILE));
                barrier(cmd);
                const UpdatePush up{int32_t(prev_count), int32_t(begin), int32_t(n), 0};
                update_.dispatch(ctx, cmd, {&table, &costs[prev], &costs[cur], &back}, &up, groups(n, RIBBON_GROUP));
                barrier(cmd);
            }
            copy(cmd, valid[cur], row_readback, VkDeviceSize(count) * 4);
            copy(cmd, back, row_readback, VkDeviceSize(count) * 4, row_bytes);
            if (last) copy(cmd, costs[cur], row_readback, VkDeviceSize(count) * 4, 2 * row_bytes);
            if (options.keep_cost_tables) copy(cmd, table, table_readback, need_table);
            host_barrier(cmd);
        });
        row_readback.invalidate(ctx);
        t.valid[i] = read_u32(0, count);
        t.back[i] = read_u32(row_bytes, count);
        if (last) {
            t.last_costs.resize(count);
            std::memcpy(t.last_costs.data(), static_cast<const std::byte*>(row_readback.mapped()) + 2 * row_bytes,
                        size_t(count) * 4);
        }
        if (options.keep_cost_tables) {
            table_readback.invalidate(ctx);
            t.cost_tables[i].resize(size_t(prev_count) * count);
            std::memcpy(t.cost_tables[i].data(), table_readback.mapped(), t.cost_tables[i].size() * 4);
        }
        t.row_ms.push_back(timer.elapsed_ms());
        if (options.progress) options.progress(i, rows, count);
    }
    if (rows == 1) t.last_costs.assign(t.valid[0].size(), 0.0f);
    return t;
}

}  // namespace lw
