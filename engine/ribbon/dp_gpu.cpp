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
    int32_t left, right, top, top_count, bottom, bottom_count, interior, interior_count, forbidden, forbidden_count;
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

// Every row's probes in one buffer.
struct PackedProbes {
    std::vector<glm::ivec2> probes;
    std::vector<RowOffsets> offsets;  // per row
};
PackedProbes pack_probes(const DpProblem& problem) {
    PackedProbes packed;
    auto append = [&](const std::vector<glm::ivec2>& list) {
        const auto at = int32_t(packed.probes.size());
        packed.probes.insert(packed.probes.end(), list.begin(), list.end());
        return at;
    };
    for (const PieceProbes& p : problem.rows) {
        RowOffsets o{};
        o.left = append(p.left);
        o.right = append(p.right);
        o.top = append(p.top);
        o.top_count = int32_t(p.top.size());
        o.bottom = append(p.bottom);
        o.bottom_count = int32_t(p.bottom.size());
        o.interior = append(p.interior);
        o.interior_count = int32_t(p.interior.size());
        o.forbidden = append(p.forbidden);
        o.forbidden_count = int32_t(p.forbidden.size());
        packed.offsets.push_back(o);
    }
    return packed;
}

// The five kernels, as RibbonDpGpu keeps them.
struct DpKernels {
    const ComputePipeline &find_valid, &compact, &extract, &cost, &update;
};

// One run of the DP on the device: its buffers (kept from row to row, grown when a row needs
// more) and the steps that fill `tables` row by row.
class DpRun {
public:
    DpRun(const Context& ctx, const DpKernels& kernels, const DpProblem& problem, const DpRunOptions& options)
        : ctx_(ctx), k_(kernels), problem_(problem), options_(options), e_(*problem.exemplar),
          U_(problem.position_count()), C_(problem.samples), packed_(pack_probes(problem)),
          blocks_(groups(U_, RIBBON_SCAN_BLOCK)), row_bytes_(VkDeviceSize(U_) * 4),
          exemplar_(upload_buffer(ctx, e_.texels, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "ribbon exemplar")),
          probes_(upload_buffer(ctx, packed_.probes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "ribbon probes")),
          flags_(device_buffer(ctx, row_bytes_, "ribbon valid flags")),
          prefix_(device_buffer(ctx, row_bytes_, "ribbon scan prefix")),
          block_sums_(device_buffer(ctx, VkDeviceSize(blocks_) * 4, "ribbon scan block sums")),
          header_(device_buffer(ctx, 16, "ribbon valid count")),
          valid_{device_buffer(ctx, row_bytes_, "ribbon valid positions A"),
                 device_buffer(ctx, row_bytes_, "ribbon valid positions B")},
          costs_{device_buffer(ctx, row_bytes_, "ribbon DP row A"), device_buffer(ctx, row_bytes_, "ribbon DP row B")},
          back_(device_buffer(ctx, row_bytes_, "ribbon back pointers")),
          count_readback_(readback_buffer(ctx, 16, "ribbon valid count readback")),
          row_readback_(readback_buffer(ctx, 3 * row_bytes_, "ribbon row readback")) {}

    // Row 0: its valid positions (or the fixed first one), P[0, ·] = 0.
    void first_row(DpTables& t);
    // Row i ≥ 1: the right edges of row i − 1's positions, row i's valid positions, the cost
    // table against row i − 1 and the row update; valid list and back pointers read back.
    void next_row(size_t i, DpTables& t);

private:
    void record_find_and_compact(VkCommandBuffer cmd, size_t row, const Buffer& valid_out, ValidityRule rule) const;
    [[nodiscard]] uint32_t read_count() const;
    [[nodiscard]] std::vector<uint32_t> read_u32(VkDeviceSize offset, size_t n) const;
    void relax(size_t row, const Buffer& valid_out, uint32_t& count, ValidityRule& rule) const;
    void grow(Buffer& buffer, VkDeviceSize& bytes, VkDeviceSize need, const char* name, bool readback) const;

    const Context& ctx_;
    const DpKernels& k_;
    const DpProblem& problem_;
    const DpRunOptions& options_;
    const Exemplar& e_;
    const uint32_t U_;
    const int32_t C_;
    const PackedProbes packed_;
    const uint32_t blocks_;
    const VkDeviceSize row_bytes_;
    const Buffer exemplar_, probes_;
    Buffer flags_, prefix_, block_sums_, header_, valid_[2], costs_[2], back_;
    Buffer columns_, table_, table_readback_;  // grown as rows need
    VkDeviceSize columns_bytes_ = 0, table_bytes_ = 0, table_readback_bytes_ = 0;
    Buffer count_readback_, row_readback_;
    int cur_ = 0;  // which of valid_ and costs_ holds the last row
};

void DpRun::record_find_and_compact(VkCommandBuffer cmd, size_t row, const Buffer& valid_out, ValidityRule rule) const {
    const PieceProbes& p = problem_.rows[row];
    const RowOffsets& o = packed_.offsets[row];
    const FindValidPush fv{e_.width, e_.height, C_, int32_t(U_), o.top, o.top_count, o.interior,
                           o.interior_count, o.forbidden, o.forbidden_count, p.min_dx, p.max_dx,
                           p.touches_forbidden ? 1 : 0, o.bottom, o.bottom_count, int32_t(rule),
                           problem_.band.x, problem_.band.y, 0, 0};
    k_.find_valid.dispatch(ctx_, cmd, {&exemplar_, &probes_, &flags_}, &fv, groups(U_, RIBBON_GROUP));
    barrier(cmd);
    for (uint32_t phase = 0; phase < 3; ++phase) {
        const CompactPush cp{phase, U_, blocks_, 0};
        k_.compact.dispatch(ctx_, cmd, {&flags_, &prefix_, &block_sums_, &valid_out, &header_}, &cp,
                            phase == 1 ? 1 : blocks_);
        barrier(cmd);
    }
    copy(cmd, header_, count_readback_, 4);
    host_barrier(cmd);
}

uint32_t DpRun::read_count() const {
    count_readback_.invalidate(ctx_);
    uint32_t n = 0;
    std::memcpy(&n, count_readback_.mapped(), 4);
    return n;
}

std::vector<uint32_t> DpRun::read_u32(VkDeviceSize offset, size_t n) const {
    std::vector<uint32_t> out(n);
    if (n > 0) std::memcpy(out.data(), static_cast<const std::byte*>(row_readback_.mapped()) + offset, n * 4);
    return out;
}

// Rows where no position passes are searched again under a looser slicing rule (problem.h).
void DpRun::relax(size_t row, const Buffer& valid_out, uint32_t& count, ValidityRule& rule) const {
    while (count == 0 && rule != ValidityRule::Any) {  // Band → Empty → Edges → Any
        rule = ValidityRule(int(rule) + 1);
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) { record_find_and_compact(cmd, row, valid_out, rule); });
        count = read_count();
    }
    if (count == 0) throw Error(no_valid_position_message(problem_, row));
}

void DpRun::grow(Buffer& buffer, VkDeviceSize& bytes, VkDeviceSize need, const char* name, bool readback) const {
    if (need <= bytes) return;
    bytes = need;
    buffer = readback ? readback_buffer(ctx_, bytes, name) : device_buffer(ctx_, bytes, name);
}

void DpRun::first_row(DpTables& t) {
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) { record_find_and_compact(cmd, 0, valid_[0], ValidityRule::Band); });
    uint32_t count = read_count();
    relax(0, valid_[0], count, t.rules[0]);
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        copy(cmd, valid_[0], row_readback_, VkDeviceSize(count) * 4);
        vkCmdFillBuffer(cmd, costs_[0].get(), 0, VkDeviceSize(count) * 4, 0u);  // 0.0f
        host_barrier(cmd);
        barrier(cmd);
    });
    row_readback_.invalidate(ctx_);
    t.valid[0] = read_u32(0, count);
    if (options_.first_position) {
        const uint32_t first = *options_.first_position;
        if (std::find(t.valid[0].begin(), t.valid[0].end(), first) == t.valid[0].end())
            throw Error("ribbon: the fixed first position is not valid for piece 0");
        ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
            vkCmdUpdateBuffer(cmd, valid_[0].get(), 0, 4, &first);
            barrier(cmd);
        });
        t.valid[0] = {first};
    }
    cur_ = 0;
}

void DpRun::next_row(size_t i, DpTables& t) {
    const int prev = cur_;
    cur_ = 1 - cur_;
    const auto prev_count = uint32_t(t.valid[i - 1].size());
    if (groups(prev_count, RIBBON_TILE) > ctx_.properties().limits.maxComputeWorkGroupCount[1])
        throw Error("ribbon: " + std::to_string(prev_count) + " valid positions exceed the device's dispatch limits");
    grow(columns_, columns_bytes_, VkDeviceSize(prev_count) * VkDeviceSize(C_) * 4, "ribbon right edges", false);

    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        const ExtractPush ep{e_.width, e_.height, C_, int32_t(prev_count), packed_.offsets[i - 1].right, 0, 0, 0};
        k_.extract.dispatch(ctx_, cmd, {&exemplar_, &probes_, &valid_[prev], &columns_}, &ep,
                            groups(prev_count, RIBBON_GROUP));
        record_find_and_compact(cmd, i, valid_[cur_], ValidityRule::Band);
    });
    uint32_t count = read_count();
    relax(i, valid_[cur_], count, t.rules[i]);

    // The table in chunks of new-piece positions, each under max_table_bytes.
    const size_t per_chunk = std::max<size_t>(1, options_.max_table_bytes / 4 / prev_count);
    const auto chunk = uint32_t(options_.keep_cost_tables ? count : std::min<size_t>(count, per_chunk));
    const VkDeviceSize need_table = VkDeviceSize(prev_count) * chunk * 4;
    grow(table_, table_bytes_, need_table, "ribbon cost table", false);
    if (options_.keep_cost_tables)
        grow(table_readback_, table_readback_bytes_, need_table, "ribbon cost table readback", true);
    const bool last = i + 1 == problem_.rows.size();
    ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
        for (uint32_t begin = 0; begin < count; begin += chunk) {
            const uint32_t n = std::min(chunk, count - begin);
            const CostPush cp{e_.width, e_.height, C_, int32_t(prev_count), int32_t(begin), int32_t(n),
                                packed_.offsets[i].left, 0};
            k_.cost.dispatch(ctx_, cmd, {&exemplar_, &columns_, &valid_[cur_], &probes_, &table_}, &cp,
                             groups(n, RIBBON_TILE), groups(prev_count, RIBBON_TILE));
            barrier(cmd);
            const UpdatePush up{int32_t(prev_count), int32_t(begin), int32_t(n), 0};
            k_.update.dispatch(ctx_, cmd, {&table_, &costs_[prev], &costs_[cur_], &back_}, &up, groups(n, RIBBON_GROUP));
            barrier(cmd);
        }
        copy(cmd, valid_[cur_], row_readback_, VkDeviceSize(count) * 4);
        copy(cmd, back_, row_readback_, VkDeviceSize(count) * 4, row_bytes_);
        if (last) copy(cmd, costs_[cur_], row_readback_, VkDeviceSize(count) * 4, 2 * row_bytes_);
        if (options_.keep_cost_tables) copy(cmd, table_, table_readback_, need_table);
        host_barrier(cmd);
    });
    row_readback_.invalidate(ctx_);
    t.valid[i] = read_u32(0, count);
    t.back[i] = read_u32(row_bytes_, count);
    if (last) {
        t.last_costs.resize(count);
        std::memcpy(t.last_costs.data(), static_cast<const std::byte*>(row_readback_.mapped()) + 2 * row_bytes_,
                    size_t(count) * 4);
    }
    if (options_.keep_cost_tables) {
        table_readback_.invalidate(ctx_);
        t.cost_tables[i].resize(size_t(prev_count) * count);
        std::memcpy(t.cost_tables[i].data(), table_readback_.mapped(), t.cost_tables[i].size() * 4);
    }
}

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
    const uint32_t U = problem.position_count();
    const uint32_t max_groups = ctx_->properties().limits.maxComputeWorkGroupCount[0];
    if (groups(U, RIBBON_GROUP) > max_groups || groups(U, RIBBON_SCAN_BLOCK) > max_groups)
        throw Error("ribbon: " + std::to_string(U) + " exemplar positions exceed the device's dispatch limits");
    const size_t rows = problem.rows.size();
    DpTables t;
    t.valid.resize(rows);
    t.back.resize(rows);
    t.rules.assign(rows, ValidityRule::Band);
    if (options.keep_cost_tables) t.cost_tables.resize(rows);

    const DpKernels kernels{find_valid_, compact_, extract_, cost_, update_};
    DpRun run(*ctx_, kernels, problem, options);
    run.first_row(t);
    if (options.progress) options.progress(0, rows, uint32_t(t.valid[0].size()));
    for (size_t i = 1; i < rows; ++i) {
        Timer timer;
        run.next_row(i, t);
        t.row_ms.push_back(timer.elapsed_ms());
        if (options.progress) options.progress(i, rows, uint32_t(t.valid[i].size()));
    }
    if (rows == 1) t.last_costs.assign(t.valid[0].size(), 0.0f);
    return t;
}

}  // namespace lw
