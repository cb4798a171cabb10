// glTF loading on small files written by the tests: primitive modes, accessor layouts
// (stride, normalized, sparse, no bufferView) and the checks tinygltf does not make.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scene/model.h"
#include "scene/triangle_mesh.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

constexpr int kFloat = 5126, kUByte = 5121, kUShort = 5123, kUInt = 5125;

std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t chunk = 0;
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        for (size_t k = 0; k < 3; ++k) chunk = chunk << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) out += k <= n ? alphabet[(chunk >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// A fresh folder per test, removed afterwards.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("linework-gltf-" + std::string(info->name()) + "-" + std::to_string(std::random_device{}()));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

// Builds one buffer, its views and accessors; the test supplies meshes, nodes and the rest.
class GltfWriter {
public:
    template <class T>
    int view(const std::vector<T>& data, size_t stride = 0) {
        while (bytes_.size() % 4 != 0) bytes_ += '\0';
        const size_t offset = bytes_.size();
        bytes_.append(reinterpret_cast<const char*>(data.data()), data.size() * sizeof(T));
        views_.push_back(R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" +
                         std::to_string(data.size() * sizeof(T)) +
                         (stride ? R"(,"byteStride":)" + std::to_string(stride) : std::string()) + "}");
        return static_cast<int>(views_.size() - 1);
    }
    // `view` -1 leaves bufferView out; `extra` adds members such as "normalized" or "sparse".
    int accessor(int view, int component_type, size_t count, const char* type, const std::string& extra = "",
                 size_t byte_offset = 0) {
        std::string json = R"({"componentType":)" + std::to_string(component_type) + R"(,"count":)" +
                           std::to_string(count) + R"(,"type":")" + type + "\"";
        if (view >= 0) json += R"(,"bufferView":)" + std::to_string(view);
        if (byte_offset) json += R"(,"byteOffset":)" + std::to_string(byte_offset);
        if (!extra.empty()) json += "," + extra;
        accessors_.push_back(json + "}");
        return static_cast<int>(accessors_.size() - 1);
    }
    int positions(const std::vector<float>& xyz) { return accessor(view(xyz), kFloat, xyz.size() / 3, "VEC3"); }

    // Writes dir/name. With `bin_name`, the buffer goes to that file (cut to `bin_bytes`
    // when given) instead of a data URI.
    fs::path write(const fs::path& dir, const std::string& name, const std::string& body,
                   const std::string& bin_name = "", size_t bin_bytes = std::string::npos) const {
        std::string buffer_uri = "data:application/octet-stream;base64," + base64(bytes_);
        if (!bin_name.empty()) {
            std::ofstream(dir / bin_name, std::ios::binary) << bytes_.substr(0, bin_bytes);
            buffer_uri = bin_name;
        }
        std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" + std::to_string(bytes_.size()) +
                           R"(,"uri":")" + buffer_uri + R"("}],"bufferViews":[)" + join(views_) + R"(],"accessors":[)" +
                           join(accessors_) + "]";
        if (!body.empty()) json += "," + body;
        const fs::path path = dir / name;
        std::ofstream(path) << json << "}";
        return path;
    }

private:
    static std::string join(const std::vector<std::string>& parts) {
        std::string out;
        for (const std::string& p : parts) out += (out.empty() ? "" : ",") + p;
        return out;
    }
    std::string bytes_;
    std::vector<std::string> views_, accessors_;
};

// A one-node scene drawing mesh 0, whose single primitive is given as JSON.
std::string one_primitive(const std::string& primitive, const std::string& node_extra = "") {
    return R"("meshes":[{"primitives":[)" + primitive + R"(]}],"nodes":[{"mesh":0)" +
           (node_extra.empty() ? "" : "," + node_extra) + "}]";
}

std::string load_error(const fs::path& path) {
    try {
        (void)load_gltf(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "(loaded without error)";
}

void expect_load_error(const fs::path& path, const std::string& keyword) {
    const std::string message = load_error(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(keyword), std::string::npos) << message;
}

glm::vec3 face_normal(const TriangleMesh& mesh, size_t t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                    c = mesh.positions[mesh.indices[3 * t + 2]];
    return glm::cross(b - a, c - a);
}

TriangleMesh load_and_flatten(const fs::path& path) {
    const Model model = load_gltf(path);
    return flatten(model, world_transforms(model));
}

// A zig-zag strip in z = 0 whose first triangle is counter-clockwise seen from +z.
std::vector<float> zigzag(int vertices) {
    std::vector<float> xyz;
    for (int i = 0; i < vertices; ++i)
        xyz.insert(xyz.end(), {static_cast<float>(i / 2), static_cast<float>(1 - i % 2), 0.0f});
    return xyz;
}

TEST(GltfModes, TriangleStripKeepsEveryTriangleCounterClockwise) {
    TempDir dir;
    for (const bool indexed : {true, false}) {
        GltfWriter w;
        const int pos = w.positions(zigzag(6));
        std::string primitive = R"({"mode":5,"attributes":{"POSITION":)" + std::to_string(pos) + "}";
        if (indexed)
            primitive += R"(,"indices":)" + std::to_string(w.accessor(w.view(std::vector<uint16_t>{0, 1, 2, 3, 4, 5}),
                                                                      kUShort, 6, "SCALAR"));
        const TriangleMesh mesh = load_and_flatten(w.write(dir.path(), "strip.gltf", one_primitive(primitive + "}")));
        ASSERT_EQ(mesh.triangle_count(), 4u) << indexed;
        for (size_t t = 0; t < 4; ++t) EXPECT_GT(face_normal(mesh, t).z, 0.0f) << "triangle " << t;
        for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    }
}

TEST(GltfModes, FourVertexStripGivesTwoTriangles) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    const TriangleMesh mesh = load_and_flatten(w.write(
        dir.path(), "quad.gltf", one_primitive(R"({"mode":5,"attributes":{"POSITION":)" + std::to_string(pos) + "}}")));
    ASSERT_EQ(mesh.triangle_count(), 2u);
    EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
    EXPECT_GT(face_normal(mesh, 0).z, 0.0f);
    EXPECT_GT(face_normal(mesh, 1).z, 0.0f);
}

TEST(GltfModes, TriangleFanSharesTheFirstVertex) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0});  // centre, then counter-clockwise
    const int idx = w.accessor(w.view(std::vector<uint8_t>{0, 1, 2, 3, 4}), kUByte, 5, "SCALAR");
    const TriangleMesh mesh =
        load_and_flatten(w.write(dir.path(), "fan.gltf",
                                 one_primitive(R"({"mode":6,"attributes":{"POSITION":)" + std::to_string(pos) +
                                               R"(},"indices":)" + std::to_string(idx) + "}")));
    ASSERT_EQ(mesh.triangle_count(), 3u);
    for (size_t t = 0; t < 3; ++t) {
        EXPECT_GT(face_normal(mesh, t).z, 0.0f) << t;
        EXPECT_NE(std::find(mesh.indices.begin() + 3 * t, mesh.indices.begin() + 3 * t + 3, 0u),
                  mesh.indices.begin() + 3 * t + 3);
    }
}

TEST(GltfModes, NonIndexedTrianglesNumberTheirVertices) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1});
    const Model model = load_gltf(
        w.write(dir.path(), "list.gltf", one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + "}}")));
    EXPECT_EQ(model.meshes[0].primitives[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(GltfModes, PointsOnlyIsNoTriangles) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    expect_load_error(w.write(dir.path(), "points.gltf",
                              one_primitive(R"({"mode":0,"attributes":{"POSITION":)" + std::to_string(pos) + "}}")),
                      "no triangle primitives");
}

TEST(GltfModes, LinesAreSkippedBesideTriangles) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const std::string p = std::to_string(pos);
    const Model model = load_gltf(w.write(
        dir.path(), "mixed.gltf",
        one_primitive(R"({"mode":1,"attributes":{"POSITION":)" + p + R"(}},{"attributes":{"POSITION":)" + p + "}}")));
    ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
    EXPECT_EQ(model.meshes[0].primitives[0].indices.size(), 3u);
}

TEST(GltfErrors, NanPositionIsNotFinite) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0});
    expect_load_error(
        w.write(dir.path(), "nan.gltf", one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + "}}")),
        "finite");
}

TEST(GltfErrors, UnknownExtensionAndMissingFileNameThePath) {
    TempDir dir;
    const fs::path obj = dir.path() / "model.obj";
    std::ofstream(obj) << "v 0 0 0\n";
    expect_load_error(obj, "extension");
    expect_load_error(dir.path() / "missing.gltf", "no such file");
    expect_load_error(dir.path() / "missing.glb", "no such file");
}

TEST(GltfErrors, ShortBinIsAnError) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const fs::path path =
        w.write(dir.path(), "short.gltf", one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + "}}"),
                "short.bin", 20);
    const std::string message = load_error(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("short.bin"), std::string::npos) << message;
}

TEST(GltfErrors, AccessorPastItsBufferViewEnd) {
    TempDir dir;
    GltfWriter w;
    const int view = w.view(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int pos = w.accessor(view, kFloat, 4, "VEC3");  // one element more than stored
    expect_load_error(
        w.write(dir.path(), "long.gltf", one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + "}}")),
        "past the end of bufferView 0");
}

TEST(GltfErrors, WrongComponentTypeForIndices) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int idx = w.accessor(w.view(std::vector<float>{0, 1, 2}), kFloat, 3, "SCALAR");
    expect_load_error(w.write(dir.path(), "floatidx.gltf",
                              one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + R"(},"indices":)" +
                                            std::to_string(idx) + "}")),
                      "has component type FLOAT, expected UNSIGNED_BYTE or UNSIGNED_SHORT or UNSIGNED_INT");
}

TEST(GltfErrors, NodeWithTwoParentsAndChildOutOfRange) {
    TempDir dir;
    GltfWriter w;
    const std::string mesh = R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" +
                             std::to_string(w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})) + "}}]}]";
    expect_load_error(
        w.write(dir.path(), "two.gltf", mesh + R"(,"nodes":[{"children":[2]},{"children":[2]},{"mesh":0}])"),
        "node 2 has two parents");
    expect_load_error(w.write(dir.path(), "range.gltf", mesh + R"(,"nodes":[{"mesh":0,"children":[7]}])"),
                      "node 0 child refers to node 7, which does not exist");
    expect_load_error(w.write(dir.path(), "nomesh.gltf", mesh + R"(,"nodes":[{"mesh":3}])"), "refers to mesh 3");
}

TEST(GltfErrors, AnimationTimesMustIncrease) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int times = w.accessor(w.view(std::vector<float>{0.0f, 1.0f, 1.0f}), kFloat, 3, "SCALAR");
    const int values = w.accessor(w.view(std::vector<float>(9, 0.0f)), kFloat, 3, "VEC3");
    const std::string animation = R"("animations":[{"samplers":[{"input":)" + std::to_string(times) + R"(,"output":)" +
                                  std::to_string(values) +
                                  R"(}],"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}]}])";
    expect_load_error(
        w.write(dir.path(), "anim.gltf",
                one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + "}}") + "," + animation),
        "not strictly increasing");
}

TEST(GltfAccessors, InterleavedStrideAndNormalizedWeights) {
    TempDir dir;
    GltfWriter w;
    // Position and normal interleaved: 24-byte stride.
    const int view = w.view(std::vector<float>{0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1}, 24);
    const int pos = w.accessor(view, kFloat, 3, "VEC3");
    const int nrm = w.accessor(view, kFloat, 3, "VEC3", "", 12);
    const int joints =
        w.accessor(w.view(std::vector<uint16_t>{0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0}), kUShort, 3, "VEC4");
    const int weights = w.accessor(w.view(std::vector<uint8_t>{255, 0, 0, 0, 128, 127, 0, 0, 0, 255, 0, 0}), kUByte, 3,
                                   "VEC4", R"("normalized":true)");
    const int ibm = w.accessor(w.view(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                                         1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1}),
                               kFloat, 2, "MAT4");
    const std::string primitive = R"({"attributes":{"POSITION":)" + std::to_string(pos) + R"(,"NORMAL":)" +
                                  std::to_string(nrm) + R"(,"JOINTS_0":)" + std::to_string(joints) +
                                  R"(,"WEIGHTS_0":)" + std::to_string(weights) + "}}";
    const std::string body = R"("meshes":[{"primitives":[)" + primitive +
                             R"(]}],"nodes":[{"mesh":0,"skin":0},{"children":[2]},{}],)" +
                             R"("skins":[{"joints":[1,2],"inverseBindMatrices":)" + std::to_string(ibm) + "}]";
    const Model model = load_gltf(w.write(dir.path(), "skin.gltf", body));
    const Primitive& p = model.meshes[0].primitives[0];
    EXPECT_EQ(p.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(p.normals, (std::vector<glm::vec3>(3, glm::vec3(0, 0, 1))));
    EXPECT_EQ(p.joints[1], glm::u16vec4(1, 0, 0, 0));
    EXPECT_FLOAT_EQ(p.weights[0].x, 1.0f);
    EXPECT_FLOAT_EQ(p.weights[1].x, 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(p.weights[1].y, 127.0f / 255.0f);
    ASSERT_EQ(model.skins.size(), 1u);
    EXPECT_EQ(model.skins[0].inverse_bind[1][3][1], -1.0f);  // column-major: translation in column 3
}

TEST(GltfAccessors, SparseValuesReplaceZerosOfAnAccessorWithoutBufferView) {
    TempDir dir;
    GltfWriter w;
    const int indices_view = w.view(std::vector<uint8_t>{1, 2});
    const int values_view = w.view(std::vector<float>{1, 0, 0, 0, 1, 0});
    const std::string sparse = R"("sparse":{"count":2,"indices":{"bufferView":)" + std::to_string(indices_view) +
                               R"(,"componentType":5121},"values":{"bufferView":)" + std::to_string(values_view) + "}}";
    const int pos = w.accessor(-1, kFloat, 3, "VEC3", sparse);
    const Model model = load_gltf(w.write(dir.path(), "sparse.gltf",
                                          one_primitive(R"({"attributes":{"POSITION":)" + std::to_string(pos) + "}}")));
    EXPECT_EQ(model.meshes[0].primitives[0].positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST(GltfFlatten, MirroringNodeFlipsWindingAndKeepsNormalsOutward) {
    TempDir dir;
    GltfWriter w;
    const int pos = w.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int nrm = w.accessor(w.view(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}), kFloat, 3, "VEC3");
    const std::string primitive =
        R"({"attributes":{"POSITION":)" + std::to_string(pos) + R"(,"NORMAL":)" + std::to_string(nrm) + "}}";
    const TriangleMesh mesh =
        load_and_flatten(w.write(dir.path(), "mirror.gltf", one_primitive(primitive, R"("scale":[-1,1,1])")));
    ASSERT_EQ(mesh.triangle_count(), 1u);
    EXPECT_GT(glm::dot(face_normal(mesh, 0), mesh.normals[0]), 0.0f);
    EXPECT_NEAR(mesh.normals[0].z, 1.0f, 1e-6f);
}

TEST(GltfFlatten, NonUniformScaleKeepsNormalsPerpendicular) {
    TempDir dir;
    GltfWriter w;
    // A triangle in the plane x + y = 0 with its normal (1,1,0)/√2, scaled by 2 along x.
    const int pos = w.positions({0, 0, 0, -1, 1, 0, 0, 0, 1});
    const float s = 1.0f / std::sqrt(2.0f);
    const int nrm = w.accessor(w.view(std::vector<float>{s, s, 0, s, s, 0, s, s, 0}), kFloat, 3, "VEC3");
    const std::string primitive =
        R"({"attributes":{"POSITION":)" + std::to_string(pos) + R"(,"NORMAL":)" + std::to_string(nrm) + "}}";
    const TriangleMesh mesh =
        load_and_flatten(w.write(dir.path(), "scaled.gltf", one_primitive(primitive, R"("scale":[2,1,1])")));
    const glm::vec3 geometric = glm::normalize(face_normal(mesh, 0));
    EXPECT_NEAR(glm::dot(geometric, mesh.normals[0]), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(mesh.normals[0], glm::normalize(glm::vec3(0.5f, 1.0f, 0.0f))), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace lw
