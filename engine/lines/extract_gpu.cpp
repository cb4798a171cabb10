#include "lines/extract_gpu.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "lines/extract_reference.h"
#include "lines/ridge_lines.h"
#include "lines_apparent_comp.h"
#include "lines_extract_comp.h"
#include "lines_vertex_comp.h"

namespace lw {

namespace {

// Mirrors CurvVertex and LinesPush in shaders/lines_shared.glsl / lines_extract.comp.
struct CurvVertex {
    glm::vec4 position, normal, pdir1_k1, pdir2_k2, dcurv;
};
struct LinesPush {  // LINES_PUSH_CONSTANTS
    glm::vec4 eye;         // w: sug_thresh / fs²
    glm::vec4 thresholds;  // rv_thresh / fs, ar_thresh / fs², sh_thresh / fs², ph_thresh / fs²
    float fade;
    uint32_t flags;
    uint32_t count;  // vertices (lines_vertex.comp, lines_apparent.comp) or faces (lines_extract.comp)
    uint32_t pad;  // lines_extract.comp: the mesh's edge count (mesh contours key vertices past it)
};
struct VertexView {  // mirrors VertexView in shaders/lines_shared.glsl
    float ndotv, kr, test_num;
    uint32_t signs;
};
static_assert(sizeof(LinesPush) == 48);
constexpr uint32_t kFlagFade = 1024u;  // FLAG_FADE
constexpr uint32_t kFlagMeshContours = 2048u, kFlagAutoContours = 4096u, kFaceCoarse = 512u;
constexpr VkDeviceSize kHeaderBytes = 16;  // count, capacity, 2 × pad

}  // namespace

LineExtractor::LineExtractor(const Context& ctx)
    : ctx_(&ctx),
      vertex_pipeline_(ctx, {.spirv = LW_SPIRV(lines_vertex_comp_spv),
                             .storage_buffers = 4,
                             .push_constant_size = sizeof(LinesPush),
                             .name = "lines extract, per vertex"}),
      apparent_pipeline_(ctx, {.spirv = LW_SPIRV(lines_apparent_comp_spv),
                               .storage_buffers = 6,
                               .push_constant_size = sizeof(LinesPush),
                               .name = "lines extract, apparent ridges per vertex"}),
      pipeline_(ctx, {.spirv = LW_SPIRV(lines_extract_comp_spv),
                      .storage_buffers = 8,
                      .push_constant_size = sizeof(LinesPush),
                      .name = "lines extract"}) {}

void LineExtractor::allocate_output(uint32_t capacity) {
    capacity_ = capacity;
    const VkDeviceSize bytes = kHeaderBytes + VkDeviceSize(capacity) * sizeof(LineSegment);
    output_ = Buffer(*ctx_, {.size = bytes,
                             .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             .name = "line segments"});
    readback_ = Buffer(*ctx_, {.size = bytes, .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               .purpose = MemoryPurpose::Readback, .name = "line segments readback"});
}

void LineExtractor::upload_vertices(const LineMesh& lm) {
    const auto& c = lm.curvature;
    std::vector<CurvVertex> vertices(lm.mesh.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {glm::vec4(lm.mesh.positions[i], 1.0f), glm::vec4(c.normals[i], 0.0f),
                       glm::vec4(c.pdir1[i], c.k1[i]), glm::vec4(c.pdir2[i], c.k2[i]), c.dcurv[i]};
    vertices_ = upload_buffer(*ctx_, vertices, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "line mesh vertices");
}

void LineExtractor::set_pose(const LineMesh& lm) {
    if (lm.mesh.positions.size() != vertex_count_ || lm.mesh.faces.size() != face_count_)
        throw Error("line extraction: a pose with other vertex or face counts than the mesh set");
    upload_vertices(lm);
}

void LineExtractor::set_mesh(const LineMesh& lm) {
    upload_vertices(lm);
    std::vector<glm::uvec4> faces(lm.mesh.faces.size()), face_edges(lm.mesh.faces.size());
    for (size_t f = 0; f < faces.size(); ++f) {
        faces[f] = glm::uvec4(lm.mesh.faces[f], lm.feature_edges[f] | (lm.face_coarse[f] ? kFaceCoarse : 0u));
        face_edges[f] = glm::uvec4(glm::uvec3(lm.mesh.face_edges[f]), lm.strip_corners[f]);
    }
    if (faces.empty()) throw Error("line extraction: the mesh has no faces");
    const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    faces_ = upload_buffer(*ctx_, faces, usage, "line mesh faces");
    face_edges_ = upload_buffer(*ctx_, face_edges, usage, "line mesh face edges");
    const VkDeviceSize nv = std::max<VkDeviceSize>(1, lm.mesh.positions.size());
    views_ = Buffer(*ctx_, {.size = nv * sizeof(VertexView), .usage = usage, .name = "line mesh view quantities"});
    highlight_num_ = Buffer(*ctx_, {.size = nv * sizeof(float), .usage = usage, .name = "suggestive highlight test"});
    apparent_ = Buffer(*ctx_, {.size = nv * sizeof(ApparentVertex), .usage = usage, .name = "apparent ridge curvature"});
    vertex_face_offsets_ = upload_buffer(*ctx_, lm.vertex_face_offsets, usage, "line mesh vertex face offsets");
    vertex_faces_ = upload_buffer(*ctx_, lm.vertex_faces, usage, "line mesh vertex faces");
    std::vector<glm::ivec4> neighbors(lm.mesh.faces.size());
    for (size_t f = 0; f < neighbors.size(); ++f) neighbors[f] = glm::ivec4(lm.mesh.face_neighbors[f], 0);
    face_neighbors_ = upload_buffer(*ctx_, neighbors, usage, "line mesh face neighbours");
    edge_count_ = uint32_t(lm.mesh.edges.size());
    vertex_count_ = static_cast<uint32_t>(lm.mesh.positions.size());
    face_count_ = static_cast<uint32_t>(faces.size());
    feature_size_ = lm.feature_size;
    if (capacity_ == 0) allocate_output(std::max<uint32_t>(4096, face_count_ / 32));
}

void LineExtractor::record(VkCommandBuffer cmd, const glm::vec3& eye, const LineParams& params, GpuTimer* timer) const {
    if (face_count_ == 0) throw Error("line extraction: no mesh set");
    const ScaledThresholds t = scaled_thresholds(params, feature_size_);
    uint32_t flags = params.fade ? kFlagFade : 0u;  // FLAG_* of shaders/lines_shared.glsl: bit t for LineType t
    if (params.contours == ContourMode::Mesh) flags |= kFlagMeshContours;
    if (params.contours == ContourMode::Auto) flags |= kFlagAutoContours;
    for (int type = 0; type < kFaceLineTypeCount; ++type)
        if (line_type_enabled(params, LineType(type))) flags |= 1u << type;
    const glm::vec4 thresholds(t.rv_thresh, t.ar_thresh, t.sh_thresh, t.ph_thresh);
    const LinesPush vertex_push{glm::vec4(eye, t.sug_thresh), thresholds, t.fade, flags, vertex_count_, 0u};
    const LinesPush face_push{glm::vec4(eye, t.sug_thresh), thresholds, t.fade, flags, face_count_, edge_count_};
    const uint32_t header[4] = {0u, capacity_, 0u, 0u};
    vkCmdUpdateBuffer(cmd, output_.get(), 0, sizeof(header), header);
    record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    if (timer) timer->begin(cmd, "lines extract");
    // Each vertex's quantities once (a vertex has about six faces), then the faces.
    const auto compute_to_compute = [&] {
        record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    };
    vertex_pipeline_.dispatch(*ctx_, cmd, {&vertices_, &views_, &highlight_num_, &apparent_}, &vertex_push,
                              (vertex_count_ + 63) / 64);
    compute_to_compute();
    if (params.apparent_ridges) {  // D_t1 q1 reads the neighbours' q1: a pass of its own
        apparent_pipeline_.dispatch(*ctx_, cmd, {&vertices_, &views_, &apparent_, &vertex_face_offsets_, &vertex_faces_, &faces_},
                                    &vertex_push, (vertex_count_ + 63) / 64);
        compute_to_compute();
    }
    pipeline_.dispatch(*ctx_, cmd,
                       {&vertices_, &faces_, &face_edges_, &output_, &views_, &highlight_num_, &apparent_, &face_neighbors_},
                       &face_push, (face_count_ + 63) / 64);
    if (timer) timer->end(cmd);
    record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferCopy region{.size = output_.size()};
    vkCmdCopyBuffer(cmd, output_.get(), readback_.get(), 1, &region);
    record_memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

bool LineExtractor::read_segments(std::vector<LineSegment>& segments) {
    readback_.invalidate(*ctx_);
    uint32_t count = 0;
    std::memcpy(&count, readback_.mapped(), sizeof(count));
    if (count > capacity_) {
        allocate_output(count + count / 4);
        return false;
    }
    segments.resize(count);
    if (count > 0)  // an empty vector's data() may be null, which memcpy must not get
        std::memcpy(segments.data(), static_cast<const std::byte*>(readback_.mapped()) + kHeaderBytes,
                    count * sizeof(LineSegment));
    return true;
}

std::vector<LineSegment> LineExtractor::extract(const glm::vec3& eye, const LineParams& params, GpuTimer* timer) {
    std::vector<LineSegment> segments;
    for (int attempt = 0; attempt < 3; ++attempt) {
        ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
            if (timer) timer->reset(cmd);
            record(cmd, eye, params, timer);
        });
        if (read_segments(segments)) return segments;
    }
    throw Error("line extraction: the segment count kept growing past the buffer");
}

}  // namespace lw
