// tests/test_materials.cpp — glTF materials on the surface (issue 17 item 3): base colour
// factors and textures against known texels and the CPU reference (render/surface_reference.h),
// the switch that ignores them, and alpha-masked holes that lines show through.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/color.h"
#include "core/error.h"
#include "core/random.h"
#include "io/image_io.h"
#include "render/surface_reference.h"
#include "scene/scene.h"
#include "session/scene_session.h"
#include "test_support.h"

namespace lw {
namespace {

using test::GpuTest;
using json = nlohmann::json;

// An axis-aligned quad in the plane z, its corners' uv (0,0) at the upper left.
struct Quad {
    glm::vec2 min, max;
    float z = 0.0f;
    int material = 0;
};

// Writes NAME.gltf (+ .bin) holding one mesh with a primitive per quad; `materials`,
// `textures`, `images` and `samplers` are the glTF arrays as given.
std::filesystem::path write_quads(const std::filesystem::path& dir, const std::string& name,
                                  const std::vector<Quad>& quads, json document) {
    std::vector<float> floats;       // per quad: 4 positions, 4 normals, 4 uvs
    std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};
    json accessors = json::array(), views = json::array(), primitives = json::array();
    size_t offset = 0;
    const auto add_view = [&](size_t bytes, int target) {
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
        offset += bytes;
        return int(views.size()) - 1;
    };
    // Indices first (shared by every quad), then each quad's attributes.
    accessors.push_back({{"bufferView", add_view(indices.size() * 2, 34963)}, {"componentType", 5123},
                         {"count", indices.size()}, {"type", "SCALAR"}});
    for (const Quad& q : quads) {
        const std::array<glm::vec3, 4> p{glm::vec3(q.min.x, q.max.y, q.z), glm::vec3(q.min.x, q.min.y, q.z),
                                         glm::vec3(q.max.x, q.min.y, q.z), glm::vec3(q.max.x, q.max.y, q.z)};
        const std::array<glm::vec2, 4> uv{glm::vec2(0, 0), glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0)};
        for (const glm::vec3& v : p) floats.insert(floats.end(), {v.x, v.y, v.z});
        for (int i = 0; i < 4; ++i) floats.insert(floats.end(), {0.0f, 0.0f, 1.0f});
        for (const glm::vec2& t : uv) floats.insert(floats.end(), {t.x, t.y});
        const int first = int(accessors.size());
        accessors.push_back({{"bufferView", add_view(48, 34962)}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
                             {"min", {q.min.x, q.min.y, q.z}}, {"max", {q.max.x, q.max.y, q.z}}});
        accessors.push_back({{"bufferView", add_view(48, 34962)}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
        accessors.push_back({{"bufferView", add_view(32, 34962)}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
        primitives.push_back({{"attributes", {{"POSITION", first}, {"NORMAL", first + 1}, {"TEXCOORD_0", first + 2}}},
                              {"indices", 0}, {"material", q.material}});
    }
    std::ofstream bin(dir / (name + ".bin"), std::ios::binary);
    bin.write(reinterpret_cast<const char*>(indices.data()), std::streamsize(indices.size() * 2));
    bin.write(reinterpret_cast<const char*>(floats.data()), std::streamsize(floats.size() * 4));
    bin.close();
    document["asset"] = {{"version", "2.0"}};
    document["buffers"] = {{{"uri", name + ".bin"}, {"byteLength", offset}}};
    document["bufferViews"] = views;
    document["accessors"] = accessors;
    document["meshes"] = {{{"primitives", primitives}}};
    document["nodes"] = {{{"mesh", 0}}};
    document["scenes"] = {{{"nodes", {0}}}};
    document["scene"] = 0;
    const auto path = dir / (name + ".gltf");
    std::ofstream(path) << document.dump(1);
    return path;
}

// A 4 × 4 texture whose sixteen texels all differ.
ImageRGBA8 distinct_texels() {
    ImageRGBA8 image{4, 4, std::vector<uint8_t>(64)};
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            uint8_t* p = image.at(x, y);
            p[0] = uint8_t(20 + 60 * x), p[1] = uint8_t(230 - 50 * y), p[2] = uint8_t((37 * (x + 4 * y)) % 256), p[3] = 255;
        }
    return image;
}

// The pixel a world point lands in.
glm::ivec2 pixel_of(const CameraMatrices& camera, glm::vec3 world, int width, int height) {
    const glm::vec3 p = project_to_pixel(camera, world, float(width), float(height));
    return {int(std::floor(p.x)), int(std::floor(p.y))};
}

struct Rendered {
    ImageRGBA8 image;
    ImageRGBA8 reference;
    CameraMatrices camera;
};

// Renders `scene` and its CPU reference (unlit scenes only for the reference to mean anything).
Rendered render(const Context& ctx, const SceneDesc& desc) {
    SceneSession session(ctx, desc);
    const LoadedScene& scene = session.scene();
    Rendered r;
    r.image = session.frame({.camera = scene.camera}).image.color;
    r.camera = camera_matrices(scene.camera, float(desc.width) / float(desc.height), scene.bounds);
    r.reference = surface_reference(scene.mesh, scene_materials(scene, scene.mesh, 0, true), r.camera, desc.width,
                                    desc.height, desc.style.color, desc.style.background);
    return r;
}

double mean_abs_difference(const ImageRGBA8& a, const ImageRGBA8& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    return sum / double(a.pixels.size());
}

TEST_F(GpuTest, MaterialsShowTheirTexelsAndFactors) {
    const auto dir = test::temp_dir();
    write_png(dir / "texels.png", distinct_texels());
    const json doc = {
        {"images", {{{"uri", "texels.png"}}}},
        {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}},  // NEAREST: each texel a flat square
        {"textures", {{{"source", 0}, {"sampler", 0}}}},
        {"materials",
         {{{"name", "textured"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
          {{"name", "plain"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.5, 0.8, 1.0}}}}}}}};
    const auto model = write_quads(dir, "quads", {{{-1.1f, -0.5f}, {-0.1f, 0.5f}, 0.0f, 0}, {{0.1f, -0.5f}, {1.1f, 0.5f}, 0.0f, 1}},
                                   doc);
    SceneDesc desc = parse_scene_json(R"({"model": "quads.gltf", "size": [240, 120], "shading": "unlit",
        "lines": false, "samples": 1, "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov": 30}})",
                                      dir / "scene.json");
    const Rendered r = render(ctx(), desc);
    // Known texels: the centre of each texel's square shows the texel as stored (unlit).
    const ImageRGBA8 texels = distinct_texels();
    for (int ty = 0; ty < 4; ++ty)
        for (int tx = 0; tx < 4; ++tx) {
            const glm::vec3 centre(-1.1f + (float(tx) + 0.5f) / 4.0f, 0.5f - (float(ty) + 0.5f) / 4.0f, 0.0f);
            const glm::ivec2 p = pixel_of(r.camera, centre, 240, 120);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(r.image.at(p.x, p.y)[c]), int(texels.at(tx, ty)[c]), 1)
                    << "texel " << tx << "," << ty << " channel " << c;
        }
    // The factor is linear: it shows sRGB-encoded.
    const glm::ivec2 plain = pixel_of(r.camera, {0.6f, 0.0f, 0.0f}, 240, 120);
    const std::array<float, 3> factor{0.2f, 0.5f, 0.8f};
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(int(r.image.at(plain.x, plain.y)[c]), int(std::lround(linear_to_srgb(factor[size_t(c)]) * 255.0f)), 1);
    // The CPU reference agrees everywhere but on a few edge pixels.
    const ImageDiff d = compare_images(r.image, r.reference, 2);
    EXPECT_LT(d.differing_fraction, 0.005) << "max error " << d.max_abs_error;

    // Materials off: both quads take the scene colour.
    desc.style.materials = false;
    const Rendered off = render(ctx(), desc);
    for (const glm::vec3 at : {glm::vec3(-0.6f, 0.0f, 0.0f), glm::vec3(0.6f, 0.0f, 0.0f)}) {
        const glm::ivec2 p = pixel_of(off.camera, at, 240, 120);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(int(off.image.at(p.x, p.y)[c]), int(std::lround(desc.style.color[c] * 255.0f)), 1);
    }
}

// A 64 × 64 texture of black and white texels drawn 2–3× smaller than it is, with each
// minification filter glTF names. NEAREST without mipmaps shows stored texels only (Vulkan
// takes minFilter only where λ > 0, which a one-level sampler with maxLod 0 never reaches);
// *_MIPMAP_NEAREST reads one level, not a blend of two. The CPU reference filters as glTF says.
TEST_F(GpuTest, MinificationFollowsTheSampler) {
    const auto dir = test::temp_dir();
    ImageRGBA8 noise{64, 64, std::vector<uint8_t>(64 * 64 * 4, 255)};
    Rng rng(17);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const uint8_t v = rng.uniform() < 0.5f ? 0 : 255;
            uint8_t* p = noise.at(x, y);
            p[0] = p[1] = p[2] = v;
        }
    write_png(dir / "noise.png", noise);
    const auto draw = [&](int min_filter, int size) {
        const json doc = {{"images", {{{"uri", "noise.png"}}}},
                          {"samplers", {{{"magFilter", 9729}, {"minFilter", min_filter}}}},
                          {"textures", {{{"source", 0}, {"sampler", 0}}}},
                          {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}}};
        write_quads(dir, "noise", {{{-1.0f, -1.0f}, {1.0f, 1.0f}, 0.0f, 0}}, doc);
        SceneDesc desc = parse_scene_json(R"({"model": "noise.gltf", "shading": "unlit", "lines": false, "samples": 1,
            "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov": 30}})",
                                          dir / "scene.json");
        desc.width = desc.height = size;
        return render(ctx(), desc);
    };
    // Pixels well inside the quad (it covers 93 % of the frame).
    const auto inside = [](const ImageRGBA8& image, auto&& each) {
        const int m = image.width / 8;
        for (int y = m; y < image.height - m; ++y)
            for (int x = m; x < image.width - m; ++x) each(image.at(x, y));
    };

    const Rendered nearest = draw(9728, 32);  // NEAREST, no mip chain: 2.1 texels a pixel
    int grey = 0, pixels = 0;
    inside(nearest.image, [&](const uint8_t* p) {
        ++pixels;
        if (p[0] > 1 && p[0] < 254) ++grey;
    });
    EXPECT_EQ(grey, 0) << "of " << pixels << " pixels: NEAREST minification blended texels";
    // Where a pixel centre falls within rounding of a texel edge the two may pick neighbours.
    EXPECT_LT(compare_images(nearest.image, nearest.reference, 1).differing_fraction, 0.01) << "GPU against the CPU reference";

    // 2.9 texels a pixel (λ ≈ 1.5): one level, or a blend of levels 1 and 2.
    const Rendered one_level = draw(9985, 24);   // LINEAR_MIPMAP_NEAREST
    const Rendered two_levels = draw(9987, 24);  // LINEAR_MIPMAP_LINEAR
    const double own = mean_abs_difference(one_level.image, one_level.reference);
    const double other = mean_abs_difference(one_level.image, two_levels.image);
    EXPECT_LT(own, 1.0) << "MIPMAP_NEAREST against its CPU reference";
    EXPECT_GT(other, 4.0 * own + 1.0) << "MIPMAP_NEAREST is not drawn as MIPMAP_LINEAR";
    EXPECT_LT(mean_abs_difference(two_levels.image, two_levels.reference), 1.0);
}

// The milk truck: four materials, two of them textured (one atlas, mipmapped). Its unlit
// render agrees with the CPU reference's filtering of the same texels and mip chain.
TEST_F(GpuTest, MilkTruckMaterialsMatchTheCpuReference) {
    const SceneDesc desc = parse_scene_json(R"({"model": "CesiumMilkTruck/CesiumMilkTruck.glb", "shading": "unlit",
        "lines": false, "samples": 1, "size": [320, 240]})",
                                            test::data_dir() / "models/truck.json");
    const Rendered r = render(ctx(), desc);
    const ImageDiff d = compare_images(r.image, r.reference, 8);
    EXPECT_LT(d.differing_fraction, 0.02) << "max error " << d.max_abs_error;
    EXPECT_LT(mean_abs_difference(r.image, r.reference), 1.0);
    // Not one grey: the truck's texture shows many colours.
    std::vector<uint32_t> colours;
    for (size_t i = 0; i < r.image.pixels.size(); i += 4)
        colours.push_back(uint32_t(r.image.pixels[i]) << 16 | uint32_t(r.image.pixels[i + 1]) << 8 | r.image.pixels[i + 2]);
    std::sort(colours.begin(), colours.end());
    EXPECT_GT(std::unique(colours.begin(), colours.end()) - colours.begin(), 500);
}

// A skinned, textured model subdivided (the viewer's --subdivide) keeps its texture in every
// pose: the posed mesh is subdivided like the rest mesh, so its triangles are the materials'.
TEST_F(GpuTest, SubdividedAnimationKeepsItsMaterials) {
    const SceneDesc desc = parse_scene_json(R"({"model": "CesiumMan/CesiumMan.glb", "shading": "unlit",
        "lines": false, "samples": 1, "size": [160, 160], "animation": {"clip": 0}})",
                                            test::data_dir() / "models/man.json");
    const auto draw = [&](int subdivide) {
        SessionOptions options = default_session_options(desc);
        options.subdivide = subdivide;
        SceneSession session(ctx(), desc, options);
        std::vector<ImageRGBA8> frames;
        for (float t : {0.0f, 0.5f}) frames.push_back(session.frame({.when = {.seconds = t}}).image.color);
        return frames;
    };
    const std::vector<ImageRGBA8> plain = draw(0), fine = draw(1);
    for (size_t i = 0; i < plain.size(); ++i) {
        std::vector<uint32_t> colours;
        for (size_t p = 0; p < fine[i].pixels.size(); p += 4)
            colours.push_back(uint32_t(fine[i].pixels[p]) << 16 | uint32_t(fine[i].pixels[p + 1]) << 8 | fine[i].pixels[p + 2]);
        std::sort(colours.begin(), colours.end());
        EXPECT_GT(std::unique(colours.begin(), colours.end()) - colours.begin(), 200) << "frame " << i << ": textured";
        // Midpoint subdivision moves no texel and no silhouette: the two agree (before: 2.07).
        EXPECT_LT(mean_abs_difference(plain[i], fine[i]), 0.05) << "frame " << i;
    }
}

// Ink (dark line pixels) inside each cell of a 4 × 4 grid over the quad [-1, 1]² at z,
// cells shrunk by `margin` pixels so that the quad's own border lines stay out.
std::array<int, 16> ink_per_cell(const ImageRGBA8& image, const CameraMatrices& camera, float z, int margin) {
    std::array<int, 16> ink{};
    for (int cy = 0; cy < 4; ++cy)
        for (int cx = 0; cx < 4; ++cx) {
            const glm::ivec2 a = pixel_of(camera, {-1.0f + 0.5f * float(cx), 1.0f - 0.5f * float(cy), z}, image.width, image.height);
            const glm::ivec2 b = pixel_of(camera, {-0.5f + 0.5f * float(cx), 0.5f - 0.5f * float(cy), z}, image.width, image.height);
            for (int y = a.y + margin; y < b.y - margin; ++y)
                for (int x = a.x + margin; x < b.x - margin; ++x) {
                    const uint8_t* p = image.at(x, y);
                    if (p[0] + p[1] + p[2] < 3 * 80) ++ink[size_t(4 * cy + cx)];
                }
        }
    return ink;
}

// A fence in front of the cow: a quad whose texture is a checker of opaque and fully
// transparent texels, alpha mode MASK. The cow's lines show through the holes and only there;
// with materials off the quad is solid and hides them all. Lines-only frames (depth only)
// cut the same holes.
TEST_F(GpuTest, MaskedQuadShowsTheLinesBehindItsHoles) {
    const auto dir = test::temp_dir();
    ImageRGBA8 checker{4, 4, std::vector<uint8_t>(64)};
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            uint8_t* p = checker.at(x, y);
            p[0] = p[1] = p[2] = 230;
            p[3] = (x + y) % 2 ? 0 : 255;
        }
    write_png(dir / "checker.png", checker);
    const float z = 1.2f;
    const json doc = {{"images", {{{"uri", "checker.png"}}}},
                      {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}},
                      {"textures", {{{"source", 0}, {"sampler", 0}}}},
                      {"materials", {{{"name", "fence"}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.5},
                                      {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}}};
    write_quads(dir, "fence", {{{-1.0f, -1.0f}, {1.0f, 1.0f}, z, 0}}, doc);
    std::filesystem::copy_file(test::data_dir() / "models/spot/spot.glb", dir / "spot.glb");
    SceneDesc desc = parse_scene_json(R"({"model": ["fence.gltf", "spot.glb"], "size": [320, 320],
        "camera": {"eye": [0, 0.1, 6], "target": [0, 0.1, 0], "fov": 30}})",
                                      dir / "scene.json");
    const auto ink = [&](const SceneDesc& d) {
        SceneSession session(ctx(), d);
        const ImageRGBA8 image = session.frame({}).image.color;
        return ink_per_cell(image, camera_matrices(session.scene().camera, 1.0f, session.scene().bounds), z, 5);
    };
    const auto check_holes = [](const std::array<int, 16>& cells, const char* what) {
        int through = 0;
        for (int c = 0; c < 16; ++c) {
            const bool hole = ((c % 4) + (c / 4)) % 2 == 1;
            if (hole) through += cells[size_t(c)];
            else EXPECT_EQ(cells[size_t(c)], 0) << what << ": ink on opaque cell " << c;
        }
        EXPECT_GT(through, 100) << what << ": the cow's lines through the holes";
    };
    check_holes(ink(desc), "shaded");
    SceneDesc lines_only = desc;
    lines_only.style.draw_surface = false;
    check_holes(ink(lines_only), "lines only");
    SceneDesc solid = desc;
    solid.style.materials = false;
    for (int cell : ink(solid)) EXPECT_EQ(cell, 0) << "materials off: the quad hides the cow";
}

// Glass in front of the cow: a BLEND quad of half-transparent red. It tints what is behind it
// (over the white background: half red, half white) and hides no line.
TEST_F(GpuTest, BlendedQuadTintsAndHidesNoLines) {
    const auto dir = test::temp_dir();
    const float z = 1.2f;
    const json doc = {{"materials", {{{"name", "glass"}, {"alphaMode", "BLEND"},
                                      {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.0, 0.0, 0.5}}}}}}}};
    write_quads(dir, "glass", {{{-1.0f, -1.0f}, {1.0f, 1.0f}, z, 0}}, doc);
    std::filesystem::copy_file(test::data_dir() / "models/spot/spot.glb", dir / "spot.glb");
    const SceneDesc desc = parse_scene_json(R"({"model": ["glass.gltf", "spot.glb"], "size": [320, 320], "shading": "unlit",
        "camera": {"eye": [0, 0.1, 6], "target": [0, 0.1, 0], "fov": 30}})",
                                            dir / "scene.json");
    SceneSession session(ctx(), desc);
    const ImageRGBA8 image = session.frame({}).image.color;
    const CameraMatrices camera = camera_matrices(session.scene().camera, 1.0f, session.scene().bounds);
    const glm::ivec2 corner = pixel_of(camera, {-0.9f, 0.9f, z}, 320, 320);  // glass over the background
    const uint8_t* p = image.at(corner.x, corner.y);
    EXPECT_NEAR(int(p[0]), 255, 1);
    EXPECT_NEAR(int(p[1]), 128, 1);
    EXPECT_NEAR(int(p[2]), 128, 1);
    int ink = 0;
    for (int cell : ink_per_cell(image, camera, z, 5)) ink += cell;
    EXPECT_GT(ink, 300) << "the cow's lines show through the glass";
}

// Model problems name the file and the material.
TEST(Materials, BadMaterialsNameTheFileAndTheMaterial) {
    const auto dir = test::temp_dir();
    const auto error_of = [&](const json& doc) {
        const auto path = write_quads(dir, "bad", {{{-1.0f, -1.0f}, {1.0f, 1.0f}, 0.0f, 0}}, doc);
        try {
            (void)load_model(path);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error_of({{"materials", {{{"alphaMode", "CUTOUT"}}}}}).find("unknown alphaMode \"CUTOUT\""), std::string::npos);
    EXPECT_NE(error_of({{"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 2, 0, 1}}}}}}}})
                  .find("baseColorFactor value 2"),
              std::string::npos);
    EXPECT_NE(error_of({{"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}}}}})
                  .find("names texture 3"),
              std::string::npos);
    EXPECT_NE(error_of(json::object()).find("names material 0 but the file has 0"), std::string::npos);
    // KHR_texture_transform values are checked before they become floats and ints.
    const auto transformed = [](const json& transform) {
        return json{{"images", {{{"uri", "gone.png"}}}},
                    {"textures", {{{"source", 0}}}},
                    {"materials", {{{"pbrMetallicRoughness",
                                     {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}}}};
    };
    EXPECT_NE(error_of(transformed({{"offset", {1e300, 0}}})).find("KHR_texture_transform has a value that is not finite or too large"),
              std::string::npos);
    EXPECT_NE(error_of(transformed({{"texCoord", 1e20}})).find("KHR_texture_transform has texCoord"), std::string::npos);
    EXPECT_EQ(error_of(transformed({{"offset", {0.5, 0.25}}, {"rotation", 1.0}, {"texCoord", 0}})), "no error");
    const std::string missing = error_of({{"images", {{{"uri", "gone.png"}}}},
                                          {"textures", {{{"source", 0}}}},
                                          {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}}});
    EXPECT_EQ(missing, "no error") << "a missing image does not stop the model loading";
    const Model model = load_model(dir / "bad.gltf");
    try {
        (void)decode_model_image(model, 0);
        ADD_FAILURE() << "decoding a missing image succeeded";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.gltf: image 0 (gone.png): cannot read gone.png"), std::string::npos)
            << e.what();
    }
}

// A texture whose image is only in an extension's format (no "source") colours its material
// by the factor, and says so when drawn.
TEST(Materials, TextureWithoutAnImageSaysSo) {
    const auto dir = test::temp_dir();
    write_quads(dir, "ktx", {{{-1.0f, -1.0f}, {1.0f, 1.0f}, 0.0f, 0}},
                {{"textures", {json::object()}},
                 {"materials", {{{"name", "basis"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}}});
    const Model model = load_model(dir / "ktx.gltf");
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].base_color_texture.image, -1);
    EXPECT_NE(model.materials[0].base_color_texture.problem.find("ktx.gltf: texture 0 has no image Linework reads"),
              std::string::npos);
}

// A .glb stores its images in buffer views (copied once the views are checked); images no
// base colour uses are not kept.
TEST(Materials, BufferViewImagesDecode) {
    const Model box = load_model(test::data_dir() / "models/BoxTextured/BoxTextured.glb");
    ASSERT_EQ(box.materials.size(), 1u);
    const ImageRGBA8 texels = decode_model_image(box, box.materials[0].base_color_texture.image);
    EXPECT_GT(texels.width, 0);
    EXPECT_EQ(texels.pixels.size(), size_t(texels.width) * size_t(texels.height) * 4);
}

TEST(Materials, MipChainAveragesInLinearLightWeightedByAlpha) {
    // 2 × 2: black and white (opaque) average to sRGB 188, not 128; a transparent red texel
    // adds no red.
    ImageRGBA8 image{2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255, 255, 0, 0, 0}};
    image.pixels[8] = 255, image.pixels[9] = 255, image.pixels[10] = 255;  // texel (0,1) white
    const std::vector<ImageRGBA8> chain = srgb_mip_chain(image);
    ASSERT_EQ(chain.size(), 2u);
    EXPECT_EQ(chain[1].width, 1);
    const uint8_t* p = chain[1].at(0, 0);
    // Opaque: black, white, white (mean linear 2/3), the transparent red texel weightless.
    const int expected = int(std::lround(linear_to_srgb(2.0f / 3.0f) * 255.0f));
    EXPECT_EQ(int(p[0]), expected);
    EXPECT_EQ(int(p[1]), expected);
    EXPECT_EQ(int(p[3]), int(std::lround(0.75f * 255.0f)));
    // Odd sizes round down, 5 × 3 → 2 × 1 → 1 × 1.
    const std::vector<ImageRGBA8> odd = srgb_mip_chain(ImageRGBA8{5, 3, std::vector<uint8_t>(60, 255)});
    ASSERT_EQ(odd.size(), 3u);
    EXPECT_EQ(odd[1].width, 2);
    EXPECT_EQ(odd[1].height, 1);
    EXPECT_EQ(int(odd[2].at(0, 0)[0]), 255);
    // A block of transparent texels keeps their colour (mean in linear light), so that
    // filtering at a cut-out's edge does not darken towards black.
    const std::vector<ImageRGBA8> clear = srgb_mip_chain(ImageRGBA8{2, 2, {200, 0, 0, 0, 200, 0, 0, 0, 100, 0, 0, 0, 100, 0, 0, 0}});
    const float mean = 0.5f * (srgb_to_linear(200.0f / 255.0f) + srgb_to_linear(100.0f / 255.0f));
    EXPECT_EQ(int(clear[1].at(0, 0)[0]), int(std::lround(linear_to_srgb(mean) * 255.0f)));
    EXPECT_EQ(int(clear[1].at(0, 0)[3]), 0);
}

// A texture wider than the device allows (lavapipe: 16384) is drawn from its first mip level
// that fits, with a warning, instead of failing the frame.
TEST_F(GpuTest, OversizedTextureIsDrawnFromAMipLevel) {
    const auto dir = test::temp_dir();
    const int width = int(ctx().properties().limits.maxImageDimension2D) + 16;
    ImageRGBA8 ramp{width, 2, std::vector<uint8_t>(size_t(width) * 8, 255)};
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < width; ++x) ramp.at(x, y)[1] = uint8_t(255 * x / (width - 1));
    write_png(dir / "ramp.png", ramp);
    const json doc = {{"images", {{{"uri", "ramp.png"}}}},
                      {"textures", {{{"source", 0}}}},
                      {"materials", {{{"name", "wide"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}}};
    write_quads(dir, "wide", {{{-1.0f, -1.0f}, {1.0f, 1.0f}, 0.0f, 0}}, doc);
    const SceneDesc desc = parse_scene_json(R"({"model": "wide.gltf", "shading": "unlit", "lines": false, "samples": 1,
        "size": [64, 64], "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov": 30}})",
                                            dir / "scene.json");
    const Rendered r = render(ctx(), desc);
    // Hundreds of texels a pixel: the mip chain (from the level that fits) gives the same means.
    EXPECT_LT(mean_abs_difference(r.image, r.reference), 1.0);
    EXPECT_GT(int(r.image.at(56, 32)[1]) - int(r.image.at(8, 32)[1]), 150) << "the ramp shows";
}

}  // namespace
}  // namespace lw
