// engine/lines/extract_gpu.h — feature-line extraction as one Vulkan compute pass.
//
// Input:  a `LineMesh` (uploaded once with `set_mesh`; again after a deformation), the eye
//         and `LineParams` per frame.
// Output: the same `LineSegment`s as extract_lines_reference (in another order: the pass
//         appends with an atomic counter; `sort_segments` makes them comparable).
//
// Two dispatches, laid out as the host extraction: shaders/lines_vertex.comp computes each
// vertex's view quantities and sign byte once; shaders/lines_extract.comp runs one
// invocation per face that reads them. Apparent ridges add shaders/lines_apparent.comp
// between the two (each vertex's derivative reads its neighbours' curvature). The output buffer starts at a 32nd of the face count
// and grows (the pass is re-run) when a view needs more.
#pragma once

#include <vector>

#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "gpu/timestamps.h"
#include "lines/line_mesh.h"

namespace lw {

class LineExtractor {
public:
    explicit LineExtractor(const Context& ctx);

    void set_mesh(const LineMesh& mesh);
    // Another pose of the mesh last given to set_mesh (pose_line_mesh: same vertices and
    // faces): only the per-vertex positions and curvature are uploaded again.
    void set_pose(const LineMesh& mesh);

    // Records the pass into `cmd`: clears the counter, dispatches (timed as "lines extract"
    // when `timer` is given) and copies the result to host memory. Read it with
    // `read_segments` once the command buffer completed.
    void record(VkCommandBuffer cmd, const glm::vec3& eye, const LineParams& params, GpuTimer* timer = nullptr) const;

    // The segments of the last completed `record`; false when the buffer was too small
    // (it has been grown: record again).
    [[nodiscard]] bool read_segments(std::vector<LineSegment>& segments);

    // Convenience: record, submit, wait, retry on overflow; `timer` gets "lines extract".
    [[nodiscard]] std::vector<LineSegment> extract(const glm::vec3& eye, const LineParams& params,
                                                   GpuTimer* timer = nullptr);

private:
    void allocate_output(uint32_t capacity);
    void upload_vertices(const LineMesh& mesh);

    const Context* ctx_;
    ComputePipeline vertex_pipeline_, apparent_pipeline_, pipeline_;
    Buffer vertices_, faces_, face_edges_, views_;
    Buffer highlight_num_, apparent_;                 // per vertex, for rtsc's optional lines
    Buffer vertex_face_offsets_, vertex_faces_;      // LineMesh's, for apparent ridges
    Buffer face_neighbors_;                          // WeldedMesh's, for mesh contours
    uint32_t edge_count_ = 0;
    uint32_t vertex_count_ = 0;
    Buffer output_;           // header (count, capacity) + segments, Device memory
    Buffer readback_;         // same size, Readback memory
    uint32_t capacity_ = 0;
    uint32_t face_count_ = 0;
    float feature_size_ = 0.0f;
};

}  // namespace lw
