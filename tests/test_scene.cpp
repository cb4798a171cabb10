// Scene loading on real files: every model under tests/data/models loads with the expected
// triangle count, every file under tests/data/invalid fails with a specific message, and
// welding, transforms and normals hold their properties on hand-built and real meshes.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "geometry/welded_mesh.h"
#include "scene/model.h"
#include "scene/triangle_mesh.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

fs::path data_dir() { return fs::path(LW_SOURCE_DIR) / "tests" / "data"; }

// Every .gltf/.glb under `folder`, relative to it, sorted.
std::vector<std::string> gltf_files_under(const fs::path& folder) {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
            files.push_back(fs::relative(entry.path(), folder).generic_string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TriangleMesh drawn(const Model& model) { return flatten(model, world_transforms(model)); }

size_t mesh_triangles(const Model& model) {
    size_t count = 0;
    for (const Mesh& mesh : model.meshes)
        for (const Primitive& primitive : mesh.primitives) count += primitive.indices.size() / 3;
    return count;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Test names from the file path: "Fox/Fox.glb" -> "Fox_Fox_glb".
template <class Case>
std::string file_test_name(const ::testing::TestParamInfo<Case>& param) {
    std::string name = param.param.file;
    std::replace_if(
        name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

// ---- Real models -------------------------------------------------------------------------

struct ModelCase {
    const char* file;        // relative to tests/data/models
    size_t drawn_triangles;  // after flatten (instances counted), from MANIFEST.md
};

// Triangle counts are the MANIFEST's; CesiumMilkTruck's 3,624 counts its wheel mesh twice.
const ModelCase kModels[] = {
    {"BoxTextured/BoxTextured.glb", 12},
    {"CesiumMan/CesiumMan.glb", 4672},
    {"CesiumMan/glTF/CesiumMan.gltf", 4672},
    {"CesiumMilkTruck/CesiumMilkTruck.glb", 3624},
    {"FlightHelmet/FlightHelmet.gltf", 94722},
    {"Fox/Fox.glb", 576},
    {"LeePerrySmith/LeePerrySmith.glb", 17684},
    {"RobotExpressive/RobotExpressive.glb", 3237},
    {"SimpleSkin/SimpleSkin.gltf", 8},
    {"Suzanne/Monkey.glb", 3936},
    {"Suzanne/glTF/Monkey.gltf", 3936},
    {"craft_speederD/craft_speederD.gltf", 322},
    {"spot/spot.glb", 5856},
};

void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.file; }

class ModelFile : public ::testing::TestWithParam<ModelCase> {};

TEST_P(ModelFile, LoadsWithExpectedTrianglesAndFiniteGeometry) {
    const Model model = load_gltf(data_dir() / "models" / GetParam().file);
    ASSERT_FALSE(model.roots.empty());
    const TriangleMesh mesh = drawn(model);
    EXPECT_EQ(mesh.triangle_count(), GetParam().drawn_triangles);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) ASSERT_TRUE(finite(p));
    for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    for (uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
    EXPECT_GT(compute_bounds(mesh.positions).radius(), 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Models, ModelFile, ::testing::ValuesIn(kModels), file_test_name<ModelCase>);

TEST(ModelFiles, EveryModelFileHasACase) {
    std::vector<std::string> listed;
    for (const ModelCase& c : kModels) listed.emplace_back(c.file);
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(gltf_files_under(data_dir() / "models"), listed);
}

TEST(ModelFiles, TexturesAreNotNeeded) {
    // The texture images were deliberately not copied: the loader must not look at them.
    for (const auto& entry : fs::recursive_directory_iterator(data_dir() / "models")) {
        const std::string ext = entry.path().extension().string();
        EXPECT_TRUE(ext != ".png" && ext != ".jpg" && ext != ".jpeg") << entry.path();
    }
    const Model helmet = load_gltf(data_dir() / "models/FlightHelmet/FlightHelmet.gltf");
    EXPECT_EQ(helmet.meshes.size(), 6u);
}

void expect_same_geometry(const Model& a, const Model& b) {
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t m = 0; m < a.meshes.size(); ++m) {
        ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size());
        for (size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
            const Primitive& pa = a.meshes[m].primitives[p];
            const Primitive& pb = b.meshes[m].primitives[p];
            EXPECT_EQ(pa.positions, pb.positions);
            EXPECT_EQ(pa.normals, pb.normals);
            EXPECT_EQ(pa.indices, pb.indices);
            EXPECT_EQ(pa.joints, pb.joints);
            EXPECT_EQ(pa.weights, pb.weights);
        }
    }
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(a.roots, b.roots);
    const TriangleMesh ma = drawn(a), mb = drawn(b);
    EXPECT_EQ(ma.positions, mb.positions);
    EXPECT_EQ(ma.indices, mb.indices);
}

TEST(ModelParity, SuzanneGlbAndGltfGiveIdenticalGeometry) {
    const Model glb = load_gltf(data_dir() / "models/Suzanne/Monkey.glb");
    const Model gltf = load_gltf(data_dir() / "models/Suzanne/glTF/Monkey.gltf");
    expect_same_geometry(glb, gltf);
}

TEST(ModelParity, CesiumManGlbAndGltfGiveIdenticalGeometryAndAnimation) {
    const Model glb = load_gltf(data_dir() / "models/CesiumMan/CesiumMan.glb");
    const Model gltf = load_gltf(data_dir() / "models/CesiumMan/glTF/CesiumMan.gltf");
    expect_same_geometry(glb, gltf);
    ASSERT_EQ(glb.animations.size(), gltf.animations.size());
    for (size_t a = 0; a < glb.animations.size(); ++a) {
        ASSERT_EQ(glb.animations[a].samplers.size(), gltf.animations[a].samplers.size());
        for (size_t s = 0; s < glb.animations[a].samplers.size(); ++s) {
            EXPECT_EQ(glb.animations[a].samplers[s].times, gltf.animations[a].samplers[s].times);
            EXPECT_EQ(glb.animations[a].samplers[s].values, gltf.animations[a].samplers[s].values);
        }
    }
    ASSERT_EQ(glb.skins.size(), 1u);
    ASSERT_EQ(gltf.skins.size(), 1u);
    EXPECT_EQ(glb.skins[0].joints, gltf.skins[0].joints);
    EXPECT_EQ(glb.skins[0].inverse_bind, gltf.skins[0].inverse_bind);
}

// Skinned primitives: joints index the node's skin, weights are non-negative and some joint
// has influence. CesiumMan (sums down to 0.18) and RobotExpressive (up to 1.76) store
// weights that do not sum to one, so only files known to be clean check the sum.
enum class WeightSums { One, Positive };

void expect_valid_skinning(const Model& model, WeightSums sums) {
    bool any_skinned = false;
    for (const Node& node : model.nodes) {
        if (node.mesh < 0 || node.skin < 0) continue;
        const size_t joint_count = model.skins[static_cast<size_t>(node.skin)].joints.size();
        for (const Primitive& p : model.meshes[static_cast<size_t>(node.mesh)].primitives) {
            ASSERT_EQ(p.joints.size(), p.positions.size());
            ASSERT_EQ(p.weights.size(), p.positions.size());
            any_skinned = true;
            for (size_t v = 0; v < p.positions.size(); ++v) {
                for (int c = 0; c < 4; ++c) {
                    ASSERT_LT(p.joints[v][c], joint_count);
                    ASSERT_GE(p.weights[v][c], 0.0f);
                }
                const float sum = p.weights[v].x + p.weights[v].y + p.weights[v].z + p.weights[v].w;
                if (sums == WeightSums::One) {
                    ASSERT_NEAR(sum, 1.0f, 1e-3f) << "vertex " << v;
                } else {
                    ASSERT_GT(sum, 0.1f) << "vertex " << v;
                    ASSERT_LT(sum, 2.0f) << "vertex " << v;
                }
            }
        }
    }
    EXPECT_TRUE(any_skinned);
}

TEST(ModelContent, FoxHasThreeNamedAnimationsAndASkin) {
    const Model fox = load_gltf(data_dir() / "models/Fox/Fox.glb");
    ASSERT_EQ(fox.animations.size(), 3u);
    EXPECT_EQ(fox.animations[0].name, "Survey");
    EXPECT_EQ(fox.animations[1].name, "Walk");
    EXPECT_EQ(fox.animations[2].name, "Run");
    for (const Animation& a : fox.animations) EXPECT_GT(a.duration, 0.0f);
    ASSERT_EQ(fox.skins.size(), 1u);
    EXPECT_EQ(fox.skins[0].joints.size(), 24u);
    expect_valid_skinning(fox, WeightSums::One);
}

TEST(ModelContent, CesiumManHasNineteenAnimationsOfOneJointEach) {
    const Model man = load_gltf(data_dir() / "models/CesiumMan/CesiumMan.glb");
    ASSERT_EQ(man.animations.size(), 19u);
    std::set<int> animated;
    for (const Animation& a : man.animations) {
        ASSERT_EQ(a.channels.size(), 3u);
        EXPECT_EQ(a.channels[0].node, a.channels[1].node);
        EXPECT_EQ(a.channels[0].node, a.channels[2].node);
        animated.insert(a.channels[0].node);
        for (const AnimationSampler& s : a.samplers) {
            ASSERT_FALSE(s.times.empty());
            EXPECT_EQ(s.values.size(), s.times.size() * static_cast<size_t>(s.components));
            EXPECT_TRUE(std::is_sorted(s.times.begin(), s.times.end()));
            EXPECT_GE(a.duration, s.times.back());
        }
    }
    // One animation per joint: together they drive all 19 joints.
    ASSERT_EQ(man.skins.size(), 1u);
    EXPECT_EQ(animated, std::set<int>(man.skins[0].joints.begin(), man.skins[0].joints.end()));
    expect_valid_skinning(man, WeightSums::Positive);
}

TEST(ModelContent, RobotExpressiveHasTwoSkinsFourteenAnimationsSeventyFourNodes) {
    const Model robot = load_gltf(data_dir() / "models/RobotExpressive/RobotExpressive.glb");
    EXPECT_EQ(robot.skins.size(), 2u);
    EXPECT_EQ(robot.animations.size(), 14u);
    EXPECT_EQ(robot.nodes.size(), 74u);
    expect_valid_skinning(robot, WeightSums::Positive);
}

TEST(ModelContent, SimpleSkinFromDataUrisHasSkinAndAnimation) {
    const Model model = load_gltf(data_dir() / "models/SimpleSkin/SimpleSkin.gltf");
    ASSERT_EQ(model.skins.size(), 1u);
    EXPECT_EQ(model.skins[0].joints, (std::vector<int>{1, 2}));
    ASSERT_EQ(model.skins[0].inverse_bind.size(), 2u);
    // Joint 1 sits at y = 1, so its inverse bind matrix moves y = 1 back to the origin.
    EXPECT_NEAR(model.skins[0].inverse_bind[1][3][1], -1.0f, 1e-6f);
    ASSERT_EQ(model.animations.size(), 1u);
    ASSERT_EQ(model.animations[0].channels.size(), 1u);
    EXPECT_EQ(model.animations[0].channels[0].node, 2);
    EXPECT_EQ(model.animations[0].channels[0].path, AnimationChannel::Path::Rotation);
    EXPECT_EQ(model.animations[0].samplers[0].components, 4);
    EXPECT_GT(model.animations[0].duration, 0.0f);
    expect_valid_skinning(model, WeightSums::One);
}

TEST(ModelContent, CesiumMilkTruckHasNodeAnimationAndAnInstancedMesh) {
    const Model truck = load_gltf(data_dir() / "models/CesiumMilkTruck/CesiumMilkTruck.glb");
    ASSERT_EQ(truck.animations.size(), 2u);
    for (const Animation& a : truck.animations)
        for (const AnimationChannel& c : a.channels) {
            EXPECT_EQ(c.path, AnimationChannel::Path::Rotation);
            EXPECT_GE(truck.nodes[static_cast<size_t>(c.node)].mesh, 0);  // the wheels turn
        }
    std::vector<int> users(truck.meshes.size(), 0);
    for (const Node& node : truck.nodes)
        if (node.mesh >= 0) ++users[static_cast<size_t>(node.mesh)];
    EXPECT_EQ(*std::max_element(users.begin(), users.end()), 2);
    EXPECT_EQ(mesh_triangles(truck), 2856u);  // stored once, drawn 3,624 times (see kModels)
}

TEST(ModelContent, BoxTexturedUsesANodeMatrix) {
    const Model box = load_gltf(data_dir() / "models/BoxTextured/BoxTextured.glb");
    ASSERT_EQ(box.nodes.size(), 2u);
    EXPECT_TRUE(box.nodes[0].has_matrix);
    // The matrix turns the file's Z-up box Y-up: drawn positions differ from stored ones.
    const TriangleMesh mesh = drawn(box);
    EXPECT_NE(mesh.positions, box.meshes[0].primitives[0].positions);
    EXPECT_EQ(mesh.positions.size(), box.meshes[0].primitives[0].positions.size());
}

// ---- Invalid files ----------------------------------------------------------------------

struct InvalidCase {
    const char* file;     // relative to tests/data/invalid
    const char* keyword;  // what the message must say about the problem
};

const InvalidCase kInvalid[] = {
    {"assimp/IndexOutOfRange/IndexOutOfRange.gltf", "index 255"},
    {"assimp/MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
    {"gltf-validator/buffer/not_found.gltf", "not_found.bin"},
    {"gltf-validator/buffer_view/invalid_length.gltf", "runs past the end of buffer 0"},
    {"gltf-validator/glb/invalid_json_chunk.glb", "parse error"},
    {"gltf-validator/glb/invalid_magic.glb", "magic"},
    {"gltf-validator/glb/length_mismatch.glb", "does not match the file size"},
    {"gltf-validator/glb/truncated_chunk_data.glb", "truncated"},
    {"gltf-validator/json/invalid_object.gltf", "JSON"},
    {"gltf-validator/json/invalid_syntax.gltf", "JSON"},
    {"gltf-validator/mesh/unresolved_indices.gltf", "indices accessor out of bounds"},
    {"gltf-validator/mesh_data/index_buffer_oob.gltf", "past the vertex count"},
    {"gltf-validator/node/node_loop.gltf", "cycle: 0 -> 1 -> 2 -> 0"},
    {"tinygltf/BoundsChecking/invalid-buffer-view-index.gltf", "invalid bufferView"},
    {"tinygltf/BoundsChecking/invalid-primitive-indices.gltf", "indices accessor out of bounds"},
};

void PrintTo(const InvalidCase& c, std::ostream* os) { *os << c.file; }

class InvalidFile : public ::testing::TestWithParam<InvalidCase> {};

TEST_P(InvalidFile, FailsWithOneLineNamingFileAndProblem) {
    const fs::path path = data_dir() / "invalid" / GetParam().file;
    ASSERT_TRUE(fs::exists(path));
    try {
        (void)load_gltf(path);
        FAIL() << "loaded " << path;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(GetParam().keyword), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_EQ(e.exit_code(), 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Invalid, InvalidFile, ::testing::ValuesIn(kInvalid), file_test_name<InvalidCase>);

TEST(InvalidFiles, EveryInvalidFileHasACase) {
    std::vector<std::string> listed;
    for (const InvalidCase& c : kInvalid) listed.emplace_back(c.file);
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(gltf_files_under(data_dir() / "invalid"), listed);
}

// ---- Transforms and normals --------------------------------------------------------------

TEST(WorldTransforms, ComposeParentTimesChild) {
    Model model;
    model.nodes.resize(3);
    model.nodes[0].translation = {1.0f, 0.0f, 0.0f};
    model.nodes[0].children = {1};
    model.nodes[1].parent = 0;
    model.nodes[1].scale = glm::vec3(2.0f);
    model.nodes[1].children = {2};
    model.nodes[2].parent = 1;
    model.nodes[2].has_matrix = true;
    model.nodes[2].matrix = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1));
    model.roots = {0};
    const std::vector<glm::mat4> world = world_transforms(model);
    ASSERT_EQ(world.size(), 3u);
    // Parent × child: scale then translate gives x = 1 + 2·1 = 3 (the other order gives 4).
    const glm::vec3 p1 = glm::vec3(world[1] * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(p1, glm::vec3(3, 0, 0)), 0.0f, 1e-6f);
    // Rotate (1,0,0) to (0,1,0), scale to (0,2,0), translate to (1,2,0).
    const glm::vec3 p2 = glm::vec3(world[2] * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(p2, glm::vec3(1, 2, 0)), 0.0f, 1e-6f);
}

TEST(WorldTransforms, TrsOrderIsTranslateRotateScale) {
    Node node;
    node.translation = {0.0f, 0.0f, 5.0f};
    node.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    node.scale = {2.0f, 1.0f, 1.0f};
    // Scale x first (2,0,0), rotate to (0,2,0), then translate.
    const glm::vec3 p = glm::vec3(node.local_transform() * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(p, glm::vec3(0, 2, 5)), 0.0f, 1e-6f);
}

TEST(VertexNormals, AreaWeightedIgnoringDegenerateAndIsolated) {
    // Vertex 0 is shared by a big face in z = 0 (area 2, normal +z) and a small one in
    // x = 0 (area 0.5, normal +x); vertex 5 belongs to a zero-area face only; 6 to none.
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0},
                                              {0, 0, 1}, {3, 3, 3}, {9, 9, 9}};
    const std::vector<uint32_t> indices = {0, 1, 2, 0, 3, 4, 5, 5, 5};
    const std::vector<glm::vec3> normals = vertex_normals(positions, indices);
    ASSERT_EQ(normals.size(), positions.size());
    const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0.0f, 2.0f));
    EXPECT_NEAR(glm::distance(normals[0], expected), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(normals[1], glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(normals[3], glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(normals[5], glm::vec3(0, 0, 1));  // only a zero-area face: fallback
    EXPECT_EQ(normals[6], glm::vec3(0, 0, 1));  // isolated: fallback
}

TEST(Bounds, MinMaxCenterRadius) {
    const Bounds b = compute_bounds({{1, 2, 3}, {-1, 0, 5}, {0, 4, 4}});
    EXPECT_EQ(b.min, glm::vec3(-1, 0, 3));
    EXPECT_EQ(b.max, glm::vec3(1, 4, 5));
    EXPECT_EQ(b.center(), glm::vec3(0, 2, 4));
    EXPECT_FLOAT_EQ(b.radius(), 0.5f * std::sqrt(4.0f + 16.0f + 4.0f));
}

// ---- Welding -----------------------------------------------------------------------------

// A unit cube as a file would store it: 4 vertices per face (split for normals), 12
// counter-clockwise triangles seen from outside.
TriangleMesh split_cube() {
    TriangleMesh mesh;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            const glm::vec3 n = side * axes[axis];
            const glm::vec3 u = axes[(axis + 1) % 3], v = side * axes[(axis + 2) % 3];
            const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
            for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                mesh.positions.push_back(0.5f * (n + c.x * u + c.y * v));
                mesh.normals.push_back(n);
            }
            mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    return mesh;
}

void expect_consistent_adjacency(const WeldedMesh& w) {
    ASSERT_EQ(w.face_edges.size(), w.faces.size());
    ASSERT_EQ(w.face_neighbors.size(), w.faces.size());
    for (size_t f = 0; f < w.faces.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            const MeshEdge& e = w.edges[static_cast<size_t>(w.face_edges[f][i])];
            const uint32_t a = w.faces[f][(i + 1) % 3], b = w.faces[f][(i + 2) % 3];
            EXPECT_EQ(e.v[0], std::min(a, b));
            EXPECT_EQ(e.v[1], std::max(a, b));
            const int g = w.face_neighbors[f][i];
            if (g < 0) continue;
            // The neighbour sees this face across the same edge.
            const glm::ivec3& back = w.face_neighbors[static_cast<size_t>(g)];
            EXPECT_TRUE(back[0] == static_cast<int>(f) || back[1] == static_cast<int>(f) ||
                        back[2] == static_cast<int>(f));
        }
}

TEST(Weld, SplitCubeBecomesClosedGenusZero) {
    const WeldedMesh w = weld(split_cube());
    EXPECT_EQ(w.positions.size(), 8u);
    EXPECT_EQ(w.faces.size(), 12u);
    EXPECT_EQ(w.edges.size(), 18u);
    EXPECT_EQ(w.border_edge_count(), 0u);
    for (const glm::ivec3& n : w.face_neighbors)
        for (int i = 0; i < 3; ++i) EXPECT_GE(n[i], 0);
    for (const MeshEdge& e : w.edges) EXPECT_EQ(e.face_count, 2u);
    EXPECT_EQ(
        static_cast<long>(w.positions.size()) - static_cast<long>(w.edges.size()) + static_cast<long>(w.faces.size()),
        2);
    ASSERT_EQ(w.welded_index.size(), 24u);
    for (size_t v = 0; v < 24; ++v) EXPECT_EQ(w.positions[w.welded_index[v]], split_cube().positions[v]);
    expect_consistent_adjacency(w);
}

TEST(Weld, QuadHasFiveEdgesFourOnTheBorderInFirstAppearanceOrder) {
    TriangleMesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    const WeldedMesh w = weld(quad);
    ASSERT_EQ(w.edges.size(), 5u);
    EXPECT_EQ(w.border_edge_count(), 4u);
    // Face 0's edges opposite corners 0, 1, 2: (1,2), (2,0), (0,1); then face 1's new ones.
    const uint32_t expected[5][2] = {{1, 2}, {0, 2}, {0, 1}, {2, 3}, {0, 3}};
    for (size_t e = 0; e < 5; ++e) {
        EXPECT_EQ(w.edges[e].v[0], expected[e][0]) << e;
        EXPECT_EQ(w.edges[e].v[1], expected[e][1]) << e;
    }
    EXPECT_EQ(w.edges[1].face_count, 2u);  // the diagonal
    EXPECT_EQ(w.face_neighbors[0], glm::ivec3(-1, 1, -1));
    EXPECT_EQ(w.face_neighbors[1], glm::ivec3(-1, -1, 0));
    expect_consistent_adjacency(w);
}

TEST(Weld, DropsFacesThatBecomeDegenerateAndMergesNegativeZero) {
    TriangleMesh mesh;
    // Vertices 3 and 4 repeat vertex 1's position (4 with -0.0): the second face collapses.
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, -0.0f, 0}, {2, 2, 0}};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    const WeldedMesh w = weld(mesh);
    EXPECT_EQ(w.positions.size(), 4u);
    EXPECT_EQ(w.welded_index[3], w.welded_index[1]);
    EXPECT_EQ(w.welded_index[4], w.welded_index[1]);
    ASSERT_EQ(w.faces.size(), 1u);
    EXPECT_EQ(w.faces[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(w.edges.size(), 3u);
}

// The welded numbering follows the faces, not the vertex buffer: the same triangles with
// their vertices stored in another order (as an OBJ reader numbers them) weld identically.
TEST(Weld, VertexBufferOrderDoesNotChangeTheWeldedMesh) {
    const TriangleMesh spot = drawn(load_gltf(data_dir() / "models/spot/spot.glb"));
    TriangleMesh reversed = spot;
    const size_t n = spot.positions.size();
    for (size_t v = 0; v < n; ++v) {
        reversed.positions[n - 1 - v] = spot.positions[v];
        reversed.normals[n - 1 - v] = spot.normals[v];
    }
    for (uint32_t& i : reversed.indices) i = uint32_t(n - 1 - i);
    const WeldedMesh a = weld(spot), b = weld(reversed);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.faces, b.faces);
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (size_t e = 0; e < a.edges.size(); ++e) {
        EXPECT_EQ(a.edges[e].v[0], b.edges[e].v[0]);
        EXPECT_EQ(a.edges[e].v[1], b.edges[e].v[1]);
    }
    for (size_t v = 0; v < n; ++v) EXPECT_EQ(a.welded_index[v], b.welded_index[n - 1 - v]);
}

// update_positions takes each welded vertex from the input vertex weld took it from (the
// first used by the faces): here the seam copy stored second but used first.
TEST(Weld, UpdatePositionsFollowsTheWeldOrder) {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}};  // 1 and 3 are seam copies
    mesh.normals.assign(4, glm::vec3(0, 0, 1));
    mesh.indices = {0, 3, 2, 0, 1, 2};
    WeldedMesh w = weld(mesh);
    ASSERT_EQ(w.welded_index[1], w.welded_index[3]);
    TriangleMesh deformed = mesh;
    deformed.positions[1] = {5, 0, 0};
    deformed.positions[3] = {7, 0, 0};
    update_positions(w, deformed);
    EXPECT_EQ(w.positions[w.welded_index[3]], glm::vec3(7, 0, 0));
}

TEST(Weld, NonManifoldEdgeHasNoNeighbours) {
    TriangleMesh fin;  // three triangles on the edge (0,1)
    fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    fin.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    const WeldedMesh w = weld(fin);
    ASSERT_EQ(w.edges[2].v[0], 0u);
    ASSERT_EQ(w.edges[2].v[1], 1u);
    EXPECT_EQ(w.edges[2].face_count, 3u);
    for (size_t f = 0; f < 3; ++f)
        for (int i = 0; i < 3; ++i) EXPECT_EQ(w.face_neighbors[f][i], -1);
    expect_consistent_adjacency(w);
}

TEST(Weld, SpotIsClosedAfterWelding) {
    const Model spot = load_gltf(data_dir() / "models/spot/spot.glb");
    const WeldedMesh w = weld(drawn(spot));
    EXPECT_EQ(w.faces.size(), 5856u);
    EXPECT_EQ(w.positions.size(), 2930u);  // spot_triangulated.obj's vertex count
    EXPECT_EQ(w.border_edge_count(), 0u);
    EXPECT_EQ(
        static_cast<long>(w.positions.size()) - static_cast<long>(w.edges.size()) + static_cast<long>(w.faces.size()),
        2);
    expect_consistent_adjacency(w);
}

TEST(Weld, SuzanneHasOpenBorders) {
    // Control for the test above: Suzanne's eyes are separate open shells.
    const WeldedMesh w = weld(drawn(load_gltf(data_dir() / "models/Suzanne/Monkey.glb")));
    EXPECT_GT(w.border_edge_count(), 0u);
}

}  // namespace
}  // namespace lw
