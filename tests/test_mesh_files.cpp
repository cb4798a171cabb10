// OBJ and PLY models (scene/mesh_file_loader.cpp): the same triangles as the glTF they were
// written from, the same render, and clear errors for malformed files.
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/error.h"
#include "geometry/test_meshes.h"
#include "io/image_io.h"
#include "scene/model.h"
#include "scene/triangle_mesh.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;
using test::quote;
using test::run_linework;

std::string number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(v));  // 9 digits: the float, to a correctly rounding reader
    return text;
}

// The mesh as OBJ: v and vn per vertex, faces "f a//a b//b c//c" (1-based).
void write_obj(const fs::path& path, const TriangleMesh& mesh) {
    std::ofstream out(path);
    out << "# written by test_mesh_files\no mesh\n";
    for (const auto& p : mesh.positions) out << "v " << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z) << '\n';
    for (const auto& n : mesh.normals) out << "vn " << number(n.x) << ' ' << number(n.y) << ' ' << number(n.z) << '\n';
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        out << 'f';
        for (int c = 0; c < 3; ++c) out << ' ' << mesh.indices[3 * t + c] + 1 << "//" << mesh.indices[3 * t + c] + 1;
        out << '\n';
    }
}

// The mesh as binary little-endian PLY with normals.
void write_ply(const fs::path& path, const TriangleMesh& mesh) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\ncomment written by test_mesh_files\n"
        << "element vertex " << mesh.positions.size() << "\n"
        << "property float x\nproperty float y\nproperty float z\n"
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << "element face " << mesh.triangle_count() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const float values[6] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z,
                                 mesh.normals[v].x,   mesh.normals[v].y,   mesh.normals[v].z};
        out.write(reinterpret_cast<const char*>(values), sizeof values);
    }
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const unsigned char three = 3;
        out.write(reinterpret_cast<const char*>(&three), 1);
        const int32_t corners[3] = {int32_t(mesh.indices[3 * t]), int32_t(mesh.indices[3 * t + 1]),
                                    int32_t(mesh.indices[3 * t + 2])};
        out.write(reinterpret_cast<const char*>(corners), sizeof corners);
    }
}

TriangleMesh world_mesh(const Model& model) { return flatten(model, world_transforms(model)); }

// Triangle by triangle, the same corners: positions to Assimp's OBJ number parser, whose
// fast_atof is not correctly rounded (on spot, 16 of 17568 corners with x ~ -4.3e-19 read
// 1 ulp off; PLY is binary and exact), normals to float rounding (they are renormalized).
void expect_same_triangles(const TriangleMesh& a, const TriangleMesh& b, const std::string& what) {
    ASSERT_EQ(a.triangle_count(), b.triangle_count()) << what;
    size_t position_mismatches = 0, normal_mismatches = 0;
    for (size_t i = 0; i < a.indices.size(); ++i) {
        const uint32_t va = a.indices[i], vb = b.indices[i];
        const glm::vec3 pa = a.positions[va], pb = b.positions[vb];
        position_mismatches += glm::length(pa - pb) > 2.4e-7f * std::max(glm::length(pa), 1e-30f);
        normal_mismatches += glm::length(a.normals[va] - b.normals[vb]) > 1e-6f;
    }
    EXPECT_EQ(position_mismatches, 0u) << what;
    EXPECT_EQ(normal_mismatches, 0u) << what;
}

class MeshFileFromGltf : public ::testing::TestWithParam<std::string> {};

// A multi-node, multi-material model and a single-mesh one, written out flattened.
TEST_P(MeshFileFromGltf, GivesTheSameTriangles) {
    const fs::path dir = test::temp_dir();
    const TriangleMesh glb = world_mesh(load_gltf(test::data_dir() / GetParam()));
    write_obj(dir / "m.obj", glb);
    write_ply(dir / "m.ply", glb);
    for (const char* name : {"m.obj", "m.ply"}) {
        const Model model = load_model(dir / name);
        EXPECT_TRUE(model.cameras.empty() && model.animations.empty() && model.skins.empty());
        expect_same_triangles(glb, world_mesh(model), name);
    }
}

INSTANTIATE_TEST_SUITE_P(Models, MeshFileFromGltf,
                         ::testing::Values("models/spot/spot.glb", "models/CesiumMilkTruck/CesiumMilkTruck.glb"),
                         [](const auto& param_info) { return fs::path(param_info.param).stem().string(); });

TEST(MeshFile, ObjPolygonsAreTriangulatedAndNormalsComputedWhenAbsent) {
    const fs::path path = test::temp_dir() / "quad.obj";
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nl 1 3\n";
    const TriangleMesh mesh = world_mesh(load_model(path));
    ASSERT_EQ(mesh.triangle_count(), 2u) << "a quad is two triangles; the line is dropped";
    for (const auto& n : mesh.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    ASSERT_EQ(mesh.face_material.size(), 2u);
    EXPECT_EQ(mesh.face_material[0], -1) << "Assimp's stand-in material is no material";
}

// A closed model wound inside out gets no smooth contours (rtsc's kr > 0 holds nowhere on it):
// the render says so and how to get an outline; the same model wound outward, or a hollow one
// whose cavity faces in, renders silently.
TEST(MeshFile, AnInsideOutModelIsNamedWithTheRemedy) {
    const fs::path dir = test::temp_dir();
    TriangleMesh sphere = make_icosphere(1.0f, 3);
    write_obj(dir / "outward.obj", sphere);
    for (size_t t = 0; t < sphere.indices.size(); t += 3) std::swap(sphere.indices[t + 1], sphere.indices[t + 2]);
    write_obj(dir / "inward.obj", sphere);
    const auto inward = run_linework("render " + quote(dir / "inward.obj") + " --device cpu --size 160x120 -o " +
                                     quote(dir / "in.png"));
    ASSERT_EQ(inward.exit_code, 0) << inward.output;
    EXPECT_NE(inward.output.find("warning: 1 closed part(s) of the mesh (1280 of 1280 triangles) wind inside out"),
              std::string::npos)
        << inward.output;
    EXPECT_NE(inward.output.find("--contours mesh"), std::string::npos) << inward.output;
    EXPECT_NE(inward.output.find("lines: 0 segments"), std::string::npos) << inward.output;
    const auto outward = run_linework("render " + quote(dir / "outward.obj") + " --device cpu --size 160x120 -o " +
                                      quote(dir / "out.png"));
    ASSERT_EQ(outward.exit_code, 0) << outward.output;
    EXPECT_EQ(outward.output.find("warning"), std::string::npos) << outward.output;
    EXPECT_EQ(outward.output.find("lines: 0 segments"), std::string::npos) << outward.output;
    // A hollow ball: the cavity's wall faces in by right, inside the outer shell: no warning.
    TriangleMesh hollow = make_icosphere(1.0f, 3);
    for (size_t t = 0; t < sphere.indices.size(); ++t) sphere.indices[t] += uint32_t(hollow.positions.size());
    for (glm::vec3& p : sphere.positions) p *= 0.5f;
    hollow.positions.insert(hollow.positions.end(), sphere.positions.begin(), sphere.positions.end());
    hollow.normals.insert(hollow.normals.end(), sphere.normals.begin(), sphere.normals.end());
    hollow.indices.insert(hollow.indices.end(), sphere.indices.begin(), sphere.indices.end());
    write_obj(dir / "hollow.obj", hollow);
    const auto cavity = run_linework("render " + quote(dir / "hollow.obj") + " --device cpu --size 160x120 -o " +
                                     quote(dir / "hollow.png"));
    ASSERT_EQ(cavity.exit_code, 0) << cavity.output;
    EXPECT_EQ(cavity.output.find("warning"), std::string::npos) << cavity.output;
}

TEST(MeshFile, AsciiPlyWithMaterialsOfTheObjGroups) {
    const fs::path dir = test::temp_dir();
    std::ofstream(dir / "two.mtl") << "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n";
    std::ofstream(dir / "two.obj") << "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                      "usemtl red\nf 1 2 3\nusemtl blue\nf 2 4 3\n";
    const Model obj = load_model(dir / "two.obj");
    const TriangleMesh mesh = world_mesh(obj);
    ASSERT_EQ(mesh.triangle_count(), 2u);
    ASSERT_EQ(mesh.face_material.size(), 2u);
    EXPECT_NE(mesh.face_material[0], mesh.face_material[1]);
    EXPECT_EQ(obj.materials.at(size_t(mesh.face_material[0])).name, "red");
    EXPECT_EQ(obj.materials.at(size_t(mesh.face_material[1])).name, "blue");

    std::ofstream(dir / "tri.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                      "end_header\n0 0 0\n2 0 0\n0 2 0\n3 0 1 2\n";
    const TriangleMesh tri = world_mesh(load_model(dir / "tri.ply"));
    ASSERT_EQ(tri.triangle_count(), 1u);
    EXPECT_EQ(tri.positions[tri.indices[1]], glm::vec3(2, 0, 0));
}

// Malformed files: lw::Error naming the file, never a crash (the CLI's messages are rows of
// docs/ERRORS.md; these are the loader's own).
TEST(MeshFile, MalformedFilesGiveAnErrorNamingTheFile) {
    const fs::path dir = test::temp_dir();
    std::string huge_polygon = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 1100; ++i) huge_polygon.append(" ").append(std::to_string(1 + i % 3));
    huge_polygon += "\n";
    const std::pair<const char*, std::string> files[] = {
        {"points.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                       "end_header\n0 0 0\n1 1 1\n"},
        {"noheader.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"},
        {"short.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\x01\x02"},
        {"past.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n"},
        {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"},
        {"words.obj", "hello world\n"},
        {"empty.obj", ""},
        {"huge.obj", huge_polygon},  // more corners than Assimp's ear cutting is given
    };
    for (const auto& [name, text] : files) {
        std::ofstream(dir / name, std::ios::binary) << text;
        try {
            (void)load_model(dir / name);
            ADD_FAILURE() << name << " loaded";
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind((dir / name).string() + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

// The acceptance point: a model given as .glb, .obj and .ply renders identically.
TEST(MeshFile, GlbObjAndPlyRenderIdentically) {
    const fs::path dir = test::temp_dir(), model = test::data_dir() / "models/spot/spot.glb";
    const TriangleMesh glb = world_mesh(load_gltf(model));
    write_obj(dir / "spot.obj", glb);
    write_ply(dir / "spot.ply", glb);
    const std::string common = " --device cpu --size 200x150 --validation";
    std::vector<ImageRGBA8> images;
    for (const fs::path& input : {model, dir / "spot.obj", dir / "spot.ply"}) {
        const fs::path out = dir / input.extension().string().substr(1);
        const auto r = run_linework("render " + quote(input) + " -o " + quote(out) + common);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        images.push_back(read_image_rgba8(out / "frame_0000.png"));
    }
    for (size_t i = 1; i < images.size(); ++i) {
        ASSERT_EQ(images[i].pixels.size(), images[0].pixels.size());
        size_t differing = 0;
        for (size_t p = 0; p < images[0].pixels.size(); ++p) differing += images[i].pixels[p] != images[0].pixels[p];
        EXPECT_EQ(differing, 0u) << (i == 1 ? "obj" : "ply") << " differs from the glb";
    }
}

// A grid of 4 × 4 vertices (x = column, y = row) as triangle strips, one strip per row of
// cells: the first two rows stitched into one strip by repeated vertices (degenerate
// triangles, which still count in the strip's parity: after the even run 7 7 4 4 the second
// row winds as the first), a last repeat making the run before the restart odd, then `-1`
// and the third row, led by a repeated vertex: parity starts again at the restart, and the
// leading repeat turns the third row the other way (the usual way to flip a strip).
// Written as ASCII, binary little- and big-endian.
void write_strip_ply(const fs::path& path, const std::string& format) {
    const std::vector<int32_t> strip = {0, 4, 1, 5, 2, 6, 3, 7, 7, 4, 4, 8, 5, 9, 6, 10, 7, 11, 11,
                                        -1, 8, 8, 12, 9, 13, 10, 14, 11, 15};
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat " << format << " 1.0\nelement vertex 16\nproperty float x\nproperty float y\nproperty float z\n"
        << "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    auto put = [&](auto value) {
        if (format == "ascii") {
            out << value << ' ';
            return;
        }
        char bytes[sizeof value];
        std::memcpy(bytes, &value, sizeof value);
        if (format == "binary_big_endian") std::reverse(bytes, bytes + sizeof value);
        out.write(bytes, sizeof value);
    };
    for (int v = 0; v < 16; ++v) {
        put(float(v % 4));
        put(float(v / 4));
        put(0.0f);
        if (format == "ascii") out << '\n';
    }
    put(int32_t(strip.size()));
    for (const int32_t i : strip) put(i);
}

// Assimp 5.2 read a whole strip element as its last triangle (a scan of 268,686 triangles as
// one); the strips are read as rtsc's trimesh2 reads them. A file that also has faces, or
// its vertices after the strips, is refused.
TEST(MeshFile, PlyTriangleStripsAreReadWhole) {
    const fs::path dir = test::temp_dir();
    std::vector<uint32_t> first;
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        const fs::path path = dir / (std::string(format) + ".ply");
        write_strip_ply(path, format);
        const TriangleMesh mesh = world_mesh(load_model(path));
        // Three rows of three cells, two triangles a cell; the degenerate ones skipped.
        ASSERT_EQ(mesh.triangle_count(), 18u) << format;
        ASSERT_EQ(mesh.positions.size(), 16u) << format;
        for (size_t t = 0; t < mesh.triangle_count(); ++t) {
            const glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
                            c = mesh.positions[mesh.indices[3 * t + 2]];
            const bool third_row = std::min({a.y, b.y, c.y}) == 2.0f;
            const float turn = glm::cross(b - a, c - a).z;
            EXPECT_TRUE(third_row ? turn > 0.0f : turn < 0.0f) << format << ": triangle " << t << " winds the other way";
        }
        // Every cell covered: the triangles' areas sum to the grid's, 3 × 3.
        float area = 0.0f;
        for (size_t t = 0; t < mesh.triangle_count(); ++t)
            area += 0.5f * glm::length(glm::cross(mesh.positions[mesh.indices[3 * t + 1]] - mesh.positions[mesh.indices[3 * t]],
                                                  mesh.positions[mesh.indices[3 * t + 2]] - mesh.positions[mesh.indices[3 * t]]));
        EXPECT_NEAR(area, 9.0f, 1e-5f) << format;
        if (first.empty()) first = mesh.indices;
        EXPECT_EQ(mesh.indices, first) << format << " reads other triangles than ascii";
    }
    // A strip naming a vertex the file does not have.
    std::ofstream(dir / "bad.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                                      "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 7\n";
    try {
        (void)load_model(dir / "bad.ply");
        ADD_FAILURE() << "a strip past the vertices was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.ply: PLY tristrips 0 refers to vertex 7 of 3"), std::string::npos) << e.what();
    }
    const std::string vertices = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string strips = "element tristrips 1\nproperty list int int vertex_indices\n";
    const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
    const struct {
        const char* name;
        std::string header, body, error;
    } refused[] = {{"both.ply", vertices + faces + strips, "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n",
                    "both.ply: PLY has both faces and triangle strips"},
                   {"after.ply", strips + vertices, "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n",
                    "after.ply: PLY element vertex comes after tristrips"},
                   {"restart.ply", vertices + strips, "0 0 0\n1 0 0\n0 1 0\n4 0 1 -2 2\n",
                    "restart.ply: PLY tristrips 0: -2.000000 is not a vertex index"}};
    for (const auto& r : refused) {
        std::ofstream(dir / r.name) << "ply\nformat ascii 1.0\n" << r.header << "end_header\n" << r.body;
        try {
            (void)load_model(dir / r.name);
            ADD_FAILURE() << r.name << " was read";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(r.error), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace lw
