// engine/scene/gltf_loader.cpp — load_gltf: tinygltf parses, we check and convert.
//
// Order of work: file-level checks (extension, existence, GLB framing), tinygltf, then the
// structure checks of gltf_validate.cpp (buffer views, hierarchy), then meshes, skins,
// animations and cameras, each read through the checked accessor reader. Nothing is trusted
// because tinygltf 2.7 accepts out-of-range indices, buffer views past their buffer and node
// cycles.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>

#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "scene/gltf_detail.h"
#include "scene/model.h"

#include <functional>

namespace lw {

namespace gltf_detail {

void fail(const Source& source, const std::string& problem) { throw Error(source.file + ": " + problem); }

}  // namespace gltf_detail

namespace {

using gltf_detail::accessor_label;
using gltf_detail::AccessorData;
using gltf_detail::AccessorRule;
using gltf_detail::fail;
using gltf_detail::kFloat;
using gltf_detail::kUByte;
using gltf_detail::kUInt;
using gltf_detail::kUShort;
using gltf_detail::read_accessor;
using gltf_detail::require_finite;
using gltf_detail::Source;
using Normalized = AccessorRule::Normalized;

// Images are kept as the file holds them (scene/material.h): decoding every texture of a
// model costs seconds and most renders of it draw lines, not textures. tinygltf hands over
// data-URI and external images here; a missing external image never reaches here (tinygltf
// warns and goes on) and is named when a texture needs it. Buffer-view images are skipped:
// tinygltf 2.7 passes their bytes before any check that the view lies inside its buffer
// (a crafted .glb would make the copy read past it); convert_images copies them, checked.
bool keep_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                const unsigned char* bytes, int size, void* user) {
    auto& images = *static_cast<std::vector<ModelImage>*>(user);
    if (index < 0 || image->bufferView >= 0) return true;
    if (images.size() <= size_t(index)) images.resize(size_t(index) + 1);
    if (bytes && size > 0) images[size_t(index)].bytes.assign(bytes, bytes + size);
    return true;
}

uint32_t read_u32(const unsigned char* bytes) {
    uint32_t v;
    std::memcpy(&v, bytes, sizeof v);
    return v;
}

// GLB framing (the binary container of glTF 2.0), checked before tinygltf so that a bad magic, a truncated
// chunk and a wrong total length each get their own message rather than tinygltf's
// "Invalid glTF binary.".
void check_glb_framing(const std::filesystem::path& path, const std::string& file) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(file + ": cannot open the file");
    in.seekg(0, std::ios::end);
    const size_t size = static_cast<size_t>(in.tellg());
    // Reads `count` header bytes at `offset` (only headers: chunk data is tinygltf's job).
    const auto read_header = [&](size_t offset, unsigned char* bytes, size_t count) {
        in.seekg(static_cast<std::streamoff>(offset));
        in.read(reinterpret_cast<char*>(bytes), static_cast<std::streamsize>(count));
        if (!in) throw Error(file + ": cannot read the file");
    };
    if (size < 12)
        throw Error(file + ": GLB file of " + std::to_string(size) + " bytes is shorter than its 12-byte header");
    unsigned char header[12];
    read_header(0, header, sizeof header);
    const uint32_t magic = read_u32(header);
    if (magic != 0x46546C67u) {  // "glTF"
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08X", magic);
        throw Error(file + ": bad GLB magic " + hex + " (expected \"glTF\")");
    }
    const uint32_t version = read_u32(header + 4);
    if (version != 2) throw Error(file + ": GLB version " + std::to_string(version) + " is not supported (expected 2)");
    // Chunks before the total length: a file cut short is better described by the chunk
    // it cuts than by the length mismatch that follows from it.
    size_t offset = 12;
    for (int chunk = 0; offset < size; ++chunk) {
        if (size - offset < 8)
            throw Error(file + ": GLB chunk " + std::to_string(chunk) + " header is truncated at the end of the file");
        unsigned char chunk_header[8];
        read_header(offset, chunk_header, sizeof chunk_header);
        const size_t length = read_u32(chunk_header);
        if (chunk == 0 && read_u32(chunk_header + 4) != 0x4E4F534Au)  // "JSON"
            throw Error(file + ": the first GLB chunk is not a JSON chunk");
        if (length > size - offset - 8)
            throw Error(file + ": GLB chunk " + std::to_string(chunk) + " (" + std::to_string(length) +
                        " bytes) is truncated: the file ends after " + std::to_string(size - offset - 8) + " of them");
        offset += 8 + length;
    }
    const uint32_t declared = read_u32(header + 8);
    if (declared != size)
        throw Error(file + ": GLB header length " + std::to_string(declared) + " does not match the file size " +
                    std::to_string(size));
}

tinygltf::Model parse_file(const std::filesystem::path& path, const std::string& file, std::vector<ModelImage>& images) {
    const std::string extension = lower(path.extension().string());
    if (extension != ".gltf" && extension != ".glb")
        throw Error(file + ": unsupported file extension '" + path.extension().string() + "' (expected .gltf or .glb)");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(file + ": no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw Error(file + ": not a regular file");

    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(keep_image, &images);
    tinygltf::Model doc;
    std::string err, warn;
    bool ok = false;
    if (extension == ".glb") {
        check_glb_framing(path, file);
        ok = parser.LoadBinaryFromFile(&doc, &err, &warn, path.string());
    } else {
        ok = parser.LoadASCIIFromFile(&doc, &err, &warn, path.string());
    }
    if (!ok) {
        const std::string reason = one_line(err.empty() ? warn : err);
        throw Error(file + ": cannot load glTF: " + (reason.empty() ? "tinygltf gave no reason" : reason));
    }
    // Warnings are about things we do not use (most often a missing texture image).
    if (!warn.empty()) log_debug(file + ": " + one_line(warn));
    return doc;
}

std::vector<glm::vec3> to_vec3(const AccessorData& data) {
    std::vector<glm::vec3> out(data.count);
    for (size_t e = 0; e < data.count; ++e)
        out[e] = glm::vec3(static_cast<float>(data.at(e, 0)), static_cast<float>(data.at(e, 1)),
                           static_cast<float>(data.at(e, 2)));
    return out;
}

// Index list of one primitive as triangles. Strips and fans follow the glTF 2.0 topology rules, which
// keeps every triangle's winding the same as the first one's.
std::vector<uint32_t> triangle_list(const Source& source, const std::string& what, int mode,
                                    const std::vector<uint32_t>& vertices) {
    const size_t n = vertices.size();
    std::vector<uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            fail(source, what + " has " + std::to_string(n) + " vertices in its triangle list, not a multiple of 3");
        return vertices;
    }
    if (n < 3) return out;
    out.reserve(3 * (n - 2));
    for (size_t i = 0; i + 2 < n; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Odd triangles swap their last two corners so that all face the same way.
            const bool odd = i % 2 == 1;
            out.insert(out.end(), {vertices[i], vertices[odd ? i + 2 : i + 1], vertices[odd ? i + 1 : i + 2]});
        } else {  // TRIANGLE_FAN
            out.insert(out.end(), {vertices[i + 1], vertices[i + 2], vertices[0]});
        }
    }
    return out;
}

// The images a material's base colour names, with names for messages and why one has no
// bytes; buffer-view images copied here, after validate_buffer_views. Other images (normal,
// metal-roughness maps) are dropped: nothing draws them.
std::vector<ModelImage> convert_images(const Source& source, const std::vector<Material>& materials,
                                       std::vector<ModelImage> images) {
    const tinygltf::Model& doc = source.doc;
    images.resize(doc.images.size());
    std::vector<char> used(doc.images.size(), 0);
    for (const Material& material : materials)
        if (material.base_color_texture.image >= 0) used[size_t(material.base_color_texture.image)] = 1;
    for (size_t i = 0; i < doc.images.size(); ++i) {
        const tinygltf::Image& in = doc.images[i];
        ModelImage& out = images[i];
        out.name = !in.name.empty() ? in.name : in.uri.rfind("data:", 0) == 0 ? std::string() : in.uri;
        if (!used[i]) {
            out.bytes.clear();
            out.problem = "no material's base colour uses it";
            continue;
        }
        if (in.bufferView >= 0) {
            if (size_t(in.bufferView) >= doc.bufferViews.size())
                fail(source, "image " + std::to_string(i) + " names bufferView " + std::to_string(in.bufferView) +
                                 " but the file has " + std::to_string(doc.bufferViews.size()));
            const tinygltf::BufferView& view = doc.bufferViews[size_t(in.bufferView)];
            const auto& data = doc.buffers[size_t(view.buffer)].data;  // in range: validate_buffer_views
            out.bytes.assign(data.begin() + std::ptrdiff_t(view.byteOffset),
                             data.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength));
        }
        if (out.bytes.empty())
            out.problem = in.uri.empty() || in.uri.rfind("data:", 0) == 0 ? "the image has no data"
                                                                           : "cannot read " + in.uri;
    }
    return images;
}

std::optional<Primitive> convert_primitive(const Source& source, const std::vector<Material>& materials,
                                          size_t mesh_index, size_t primitive_index) {
    const tinygltf::Primitive& in = source.doc.meshes[mesh_index].primitives[primitive_index];
    const std::string what = "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index);

    // Every reference must resolve, even in primitives we skip or attributes we ignore.
    for (const auto& [name, index] : in.attributes)
        (void)gltf_detail::accessor_count(source, index, name + " of " + what);
    if (in.indices != -1) (void)gltf_detail::accessor_count(source, in.indices, "indices of " + what);
    for (size_t t = 0; t < in.targets.size(); ++t)
        for (const auto& [name, index] : in.targets[t])
            (void)gltf_detail::accessor_count(source, index,
                                              name + " of morph target " + std::to_string(t) + " of " + what);

    if (in.mode < TINYGLTF_MODE_POINTS || in.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(source, what + " has unknown mode " + std::to_string(in.mode));
    if (in.mode < TINYGLTF_MODE_TRIANGLES) return std::nullopt;  // points and lines: nothing to shade

    const auto attribute = [&](const char* name) {
        const auto it = in.attributes.find(name);
        return it == in.attributes.end() ? -1 : it->second;
    };
    Primitive out;
    if (in.material < -1 || in.material >= int(materials.size()))
        fail(source, what + " names material " + std::to_string(in.material) + " but the file has " +
                         std::to_string(materials.size()));
    out.material = in.material;

    const int position_index = attribute("POSITION");
    if (position_index == -1) fail(source, what + " has no POSITION attribute");
    const std::string position_role = "POSITION of " + what;
    const AccessorData positions =
        read_accessor(source, position_index, {position_role, {TINYGLTF_TYPE_VEC3}, {kFloat}});
    for (size_t v = 0; v < positions.count; ++v)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(positions.at(v, c)))
                fail(source, accessor_label(position_index, position_role) + ": vertex " + std::to_string(v) +
                                 " has a coordinate that is not finite (" + std::to_string(positions.at(v, c)) + ")");
    out.positions = to_vec3(positions);
    const size_t vertex_count = out.positions.size();

    const auto check_count = [&](int index, const std::string& role, size_t count) {
        if (count != vertex_count)
            fail(source, accessor_label(index, role) + " has " + std::to_string(count) + " elements but POSITION has " +
                             std::to_string(vertex_count));
    };

    if (const int index = attribute("NORMAL"); index != -1) {
        const std::string role = "NORMAL of " + what;
        const AccessorData normals = read_accessor(source, index, {role, {TINYGLTF_TYPE_VEC3}, {kFloat}});
        check_count(index, role, normals.count);
        require_finite(source, accessor_label(index, role), normals);
        out.normals = to_vec3(normals);
    }

    if (out.material >= 0 && materials[size_t(out.material)].base_color_texture.image >= 0) {
        // The set its base colour texture reads; without it the texture cannot be placed.
        const std::string name = "TEXCOORD_" + std::to_string(materials[size_t(out.material)].base_color_texture.texcoord);
        const int index = attribute(name.c_str());
        if (index == -1)
            fail(source, what + " has no " + name + " attribute, which the base colour texture of material " +
                             std::to_string(out.material) + " reads");
        const std::string role = name + " of " + what;
        const AccessorData uv =
            read_accessor(source, index, {role, {TINYGLTF_TYPE_VEC2}, {kFloat, kUByte, kUShort}, Normalized::Required});
        check_count(index, role, uv.count);
        require_finite(source, accessor_label(index, role), uv);
        out.texcoords.resize(vertex_count);
        for (size_t v = 0; v < vertex_count; ++v) out.texcoords[v] = {float(uv.at(v, 0)), float(uv.at(v, 1))};
    }

    const int joints_index = attribute("JOINTS_0");
    const int weights_index = attribute("WEIGHTS_0");
    if ((joints_index == -1) != (weights_index == -1)) fail(source, what + " has only one of JOINTS_0 and WEIGHTS_0");
    if (joints_index != -1) {
        const std::string joints_role = "JOINTS_0 of " + what;
        const AccessorData joints =
            read_accessor(source, joints_index, {joints_role, {TINYGLTF_TYPE_VEC4}, {kUByte, kUShort}});
        check_count(joints_index, joints_role, joints.count);
        const std::string weights_role = "WEIGHTS_0 of " + what;
        const AccessorData weights =
            read_accessor(source, weights_index,
                          {weights_role, {TINYGLTF_TYPE_VEC4}, {kFloat, kUByte, kUShort}, Normalized::Required});
        check_count(weights_index, weights_role, weights.count);
        require_finite(source, accessor_label(weights_index, weights_role), weights);
        out.joints.resize(vertex_count);
        out.weights.resize(vertex_count);
        for (size_t v = 0; v < vertex_count; ++v)
            for (int c = 0; c < 4; ++c) {
                out.joints[v][c] = static_cast<uint16_t>(joints.at(v, c));
                out.weights[v][c] = static_cast<float>(weights.at(v, c));
            }
    }

    std::vector<uint32_t> vertices;  // the primitive's vertex sequence, before strip/fan expansion
    if (in.indices != -1) {
        const std::string role = "indices of " + what;
        const AccessorData indices =
            read_accessor(source, in.indices, {role, {TINYGLTF_TYPE_SCALAR}, {kUByte, kUShort, kUInt}});
        vertices.resize(indices.count);
        size_t worst = indices.count;  // position of the largest out-of-range value, if any
        for (size_t i = 0; i < indices.count; ++i) {
            const double value = indices.values[i];
            if (value >= static_cast<double>(vertex_count) && (worst == indices.count || value > indices.values[worst]))
                worst = i;
            vertices[i] = static_cast<uint32_t>(value);
        }
        if (worst != indices.count)
            fail(source, accessor_label(in.indices, role) + ": index " + std::to_string(vertices[worst]) +
                             " (at position " + std::to_string(worst) + ") is past the vertex count " +
                             std::to_string(vertex_count));
    } else {
        vertices.resize(vertex_count);
        for (size_t v = 0; v < vertex_count; ++v) vertices[v] = static_cast<uint32_t>(v);
    }
    out.indices = triangle_list(source, what, in.mode, vertices);
    return out;
}

Node convert_node(const tinygltf::Node& in) {
    Node out;
    out.name = in.name;
    out.children = in.children;
    out.mesh = in.mesh;
    out.camera = in.camera;
    out.skin = in.skin;
    const auto to_float = [](double v) { return static_cast<float>(v); };
    if (in.matrix.size() == 16) {
        out.has_matrix = true;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) out.matrix[c][r] = to_float(in.matrix[static_cast<size_t>(4 * c + r)]);
    }
    if (in.translation.size() == 3)
        out.translation = {to_float(in.translation[0]), to_float(in.translation[1]), to_float(in.translation[2])};
    if (in.rotation.size() == 4)  // glTF stores x, y, z, w; validate_nodes rejected zero quaternions
        out.rotation = glm::normalize(glm::quat(to_float(in.rotation[3]), to_float(in.rotation[0]),
                                                to_float(in.rotation[1]), to_float(in.rotation[2])));
    if (in.scale.size() == 3) out.scale = {to_float(in.scale[0]), to_float(in.scale[1]), to_float(in.scale[2])};
    return out;
}

// A skinned mesh's joint indices select entries of its node's skin.
void check_joint_indices(const Source& source, const Model& model) {
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        const Node& node = model.nodes[n];
        if (node.mesh < 0 || node.skin < 0) continue;
        const size_t joint_count = model.skins[static_cast<size_t>(node.skin)].joints.size();
        const Mesh& mesh = model.meshes[static_cast<size_t>(node.mesh)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p)
            for (const glm::u16vec4& joints : mesh.primitives[p].joints)
                for (int c = 0; c < 4; ++c)
                    if (joints[c] >= joint_count)
                        fail(source, "JOINTS_0 of mesh " + std::to_string(node.mesh) + " has joint " +
                                         std::to_string(joints[c]) + " but skin " + std::to_string(node.skin) +
                                         " of node " + std::to_string(n) + " has " + std::to_string(joint_count) +
                                         " joints");
    }
}

// Whether any node reachable from the roots draws a mesh with triangles (the hierarchy is
// known to be a tree here, so the walk ends).
bool draws_triangles(const Model& model) {
    std::vector<int> stack = model.roots;
    while (!stack.empty()) {
        const Node& node = model.nodes[static_cast<size_t>(stack.back())];
        stack.pop_back();
        if (node.mesh >= 0 && !model.meshes[static_cast<size_t>(node.mesh)].primitives.empty()) return true;
        stack.insert(stack.end(), node.children.begin(), node.children.end());
    }
    return false;
}

}  // namespace

Model load_gltf(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::vector<ModelImage> images;
    const tinygltf::Model doc = parse_file(path, file, images);
    const Source source{doc, file};

    gltf_detail::validate_required_extensions(source);
    gltf_detail::validate_buffer_views(source);
    gltf_detail::validate_nodes(source);

    Model model;
    model.path = path;
    for (size_t m = 0; m < doc.materials.size(); ++m) model.materials.push_back(gltf_detail::convert_material(source, m));
    model.images = convert_images(source, model.materials, std::move(images));
    size_t triangle_count = 0;
    for (size_t m = 0; m < doc.meshes.size(); ++m) {
        Mesh mesh;
        mesh.name = doc.meshes[m].name;
        for (size_t p = 0; p < doc.meshes[m].primitives.size(); ++p) {
            std::optional<Primitive> primitive = convert_primitive(source, model.materials, m, p);
            if (!primitive) continue;
            triangle_count += primitive->indices.size() / 3;
            mesh.primitives.push_back(std::move(*primitive));
        }
        model.meshes.push_back(std::move(mesh));
    }
    if (triangle_count == 0) fail(source, "no triangle primitives");

    model.nodes.reserve(doc.nodes.size());
    for (const tinygltf::Node& node : doc.nodes) model.nodes.push_back(convert_node(node));
    for (size_t n = 0; n < model.nodes.size(); ++n)
        for (int child : model.nodes[n].children) model.nodes[static_cast<size_t>(child)].parent = static_cast<int>(n);
    model.roots = gltf_detail::scene_roots(source);

    for (size_t s = 0; s < doc.skins.size(); ++s) model.skins.push_back(gltf_detail::convert_skin(source, s));
    check_joint_indices(source, model);
    for (size_t a = 0; a < doc.animations.size(); ++a)
        model.animations.push_back(gltf_detail::convert_animation(source, a));
    for (size_t c = 0; c < doc.cameras.size(); ++c) model.cameras.push_back(gltf_detail::convert_camera(source, c));

    if (!draws_triangles(model)) fail(source, "no node of the scene draws a mesh with triangles");
    return model;
}

glm::mat4 trs_matrix(const glm::vec3& t, const glm::quat& r, const glm::vec3& s) {
    glm::mat4 m = glm::mat4_cast(r);
    m[0] *= s.x;
    m[1] *= s.y;
    m[2] *= s.z;
    m[3] = glm::vec4(t, 1.0f);
    return m;
}

glm::mat4 Node::local_transform() const { return has_matrix ? matrix : trs_matrix(translation, rotation, scale); }

std::vector<glm::mat4> compose_world(const Model& model, const std::function<glm::mat4(size_t node)>& local_of) {
    // Iterative and guarded: a hand-built Model need not have gone through validation, so a
    // bad parent index is treated as a root and a parent cycle cannot loop forever.
    const size_t count = model.nodes.size();
    std::vector<glm::mat4> world(count);
    std::vector<char> done(count, 0);
    std::vector<size_t> chain;
    for (size_t start = 0; start < count; ++start) {
        chain.clear();
        size_t n = start;
        while (!done[n] && chain.size() <= count) {
            chain.push_back(n);
            const int parent = model.nodes[n].parent;
            if (parent < 0 || static_cast<size_t>(parent) >= count) break;
            n = static_cast<size_t>(parent);
        }
        // chain runs child → ancestor; compose from the top down.
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            if (done[*it]) continue;
            const int parent = model.nodes[*it].parent;
            const bool has_parent =
                parent >= 0 && static_cast<size_t>(parent) < count && done[static_cast<size_t>(parent)];
            const glm::mat4 local = local_of(*it);
            world[*it] = has_parent ? world[static_cast<size_t>(parent)] * local : local;
            done[*it] = 1;
        }
    }
    return world;
}

std::vector<glm::mat4> world_transforms(const Model& model) {
    return compose_world(model, [&](size_t node) { return model.nodes[node].local_transform(); });
}

}  // namespace lw
