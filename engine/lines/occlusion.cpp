// Occlusion levels by ray casting with Embree (Intel's ray-tracing kernels, Debian's
// libembree-dev): its BVH and traversal are an order of magnitude faster than a general
// AABB tree for rays (docs/BENCHMARKS.md, "Occlusion levels").
#include "lines/occlusion.h"

#include <algorithm>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "core/error.h"

namespace lw {

namespace {

constexpr float kAtThePoint = 1e-3f;     // of the way: the point's own surface
constexpr float kSameCrossing = 1e-6f;   // of the way: one crossing hit on several triangles

void check(RTCDevice device, const char* call) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) throw Error(std::string("occlusion levels: ") + call + " failed (Embree error " +
                                             std::to_string(int(error)) + ")");
}

// What one ray collects: the filter sees every hit along the ray, records where it is and
// rejects it, so that the traversal goes on to the next (Embree's "all hits" pattern). The
// Embree context comes first so that the filter can find the rest from it.
struct HitContext {
    RTCIntersectContext context;
    const std::vector<glm::uvec3>* faces;
    glm::uvec3 own;  // corners of the contour's face whose neighbours are left out; ~0u: none
    std::vector<float>* along;
};

void record_hit(const RTCFilterFunctionNArguments* args) {
    const auto* hits = reinterpret_cast<const HitContext*>(args->context);
    args->valid[0] = 0;  // never accept: find them all
    const glm::uvec3 f = (*hits->faces)[RTCHitN_primID(args->hit, args->N, 0)];
    for (int i = 0; i < 3; ++i)
        if (f[i] == hits->own.x || f[i] == hits->own.y || f[i] == hits->own.z) return;
    hits->along->push_back(RTCRayN_tfar(args->ray, args->N, 0));
}

}  // namespace

struct OcclusionCounter::Index {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<glm::uvec3> faces;
    Index() {
        // One build thread: frames extract on one core while lavapipe uses the other.
        device = rtcNewDevice("threads=1");
        if (!device) throw Error("occlusion levels: rtcNewDevice failed (Embree could not start)");
        // Counting needs every hit: filter functions on, and back faces not culled.
        if (!rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) ||
            rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED)) {
            rtcReleaseDevice(device);
            throw Error("occlusion levels: this Embree library was built without filter functions or with back-face "
                        "culling, so it cannot count the surfaces a ray crosses");
        }
    }
    ~Index() {
        if (scene) rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    Index(const Index&) = delete;
    Index& operator=(const Index&) = delete;
};

OcclusionCounter::OcclusionCounter() = default;
OcclusionCounter::~OcclusionCounter() = default;
OcclusionCounter::OcclusionCounter(OcclusionCounter&&) noexcept = default;
OcclusionCounter& OcclusionCounter::operator=(OcclusionCounter&&) noexcept = default;

bool OcclusionCounter::empty() const { return !index_ || !index_->scene; }

void OcclusionCounter::set_mesh(const LineMesh& mesh) {
    if (!empty() && holds_pose(generation_, mesh)) return;
    // The device is started once and kept; each new pose gets a new scene (an animation
    // asks for one a frame).
    if (!index_) index_ = std::make_unique<Index>();
    Index& index = *index_;
    if (index.scene) rtcReleaseScene(index.scene);
    index.scene = nullptr;
    generation_ = 0;
    const WeldedMesh& m = mesh.mesh;
    index.faces = m.faces;
    std::unique_ptr<RTCSceneTy, void (*)(RTCScene)> scene(rtcNewScene(index.device), rtcReleaseScene);
    check(index.device, "rtcNewScene");
    // Robust: watertight triangle tests, so that a ray through an edge is not let through
    // between its two triangles.
    rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene.get(), RTC_BUILD_QUALITY_MEDIUM);
    // Released when this function leaves (the scene keeps its own reference once attached).
    const std::unique_ptr<RTCGeometryTy, void (*)(RTCGeometry)> owned(
        rtcNewGeometry(index.device, RTC_GEOMETRY_TYPE_TRIANGLE), rtcReleaseGeometry);
    check(index.device, "rtcNewGeometry");
    RTCGeometry geometry = owned.get();
    // Buffers Embree allocates (padded as its SIMD loads need) and we fill.
    auto* positions = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                  3 * sizeof(float), m.positions.size()));
    auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                     3 * sizeof(uint32_t), m.faces.size()));
    check(index.device, "rtcSetNewGeometryBuffer");
    for (size_t v = 0; v < m.positions.size(); ++v)
        for (int c = 0; c < 3; ++c) positions[3 * v + size_t(c)] = m.positions[v][c];
    for (size_t f = 0; f < m.faces.size(); ++f)
        for (int c = 0; c < 3; ++c) triangles[3 * f + size_t(c)] = m.faces[f][c];
    rtcSetGeometryIntersectFilterFunction(geometry, record_hit);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene.get(), geometry);
    rtcCommitScene(scene.get());
    check(index.device, "rtcCommitScene");
    index.scene = scene.release();
    generation_ = mesh.generation;
}

uint32_t OcclusionCounter::surfaces_in_front(const glm::vec3& eye, const glm::vec3& point, uint32_t face,
                                             bool contour) const {
    if (empty()) return 0;
    const glm::vec3 d = point - eye;
    if (d == glm::vec3(0.0f)) return 0;
    // Hit distances as fractions of the way (the ray's direction is the whole way); kept per
    // thread, as tens of thousands of rays a frame would each allocate it otherwise.
    thread_local std::vector<float> along;
    along.clear();
    HitContext hits{.context = {},
                    .faces = &index_->faces,
                    .own = contour && face < index_->faces.size() ? index_->faces[face] : glm::uvec3(~0u),
                    .along = &along};
    rtcInitIntersectContext(&hits.context);
    RTCRayHit ray{};
    ray.ray.org_x = eye.x, ray.ray.org_y = eye.y, ray.ray.org_z = eye.z;
    ray.ray.dir_x = d.x, ray.ray.dir_y = d.y, ray.ray.dir_z = d.z;
    ray.ray.tnear = 0.0f;
    ray.ray.tfar = 1.0f - kAtThePoint;
    ray.ray.mask = ~0u;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(index_->scene, &hits.context, &ray);
    std::sort(along.begin(), along.end());
    uint32_t crossings = 0;
    for (size_t i = 0; i < along.size(); ++i)
        if (i == 0 || along[i] - along[i - 1] > kSameCrossing) ++crossings;
    return crossings;
}

}  // namespace lw
