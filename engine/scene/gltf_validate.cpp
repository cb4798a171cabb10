// engine/scene/gltf_validate.cpp — structure checks on a parsed glTF document.
//
// tinygltf 2.7 accepts buffer views past their buffer's end, out-of-range node references
// and node cycles (gltf-validator's node_loop.gltf: 0→1→2→0). Everything after loading walks
// the hierarchy, so a cycle would hang it: these checks run before any of that, and the
// cycle search is iterative so that it terminates on any input.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "scene/gltf_detail.h"

namespace lw::gltf_detail {

namespace {

std::string index_problem(const std::string& what, int index, size_t available, const std::string& kind) {
    return what + " refers to " + kind + " " + std::to_string(index) + ", which does not exist (the file has " +
           std::to_string(available) + ")";
}

bool in_range(int index, size_t size) { return index >= 0 && static_cast<size_t>(index) < size; }

void check_numbers(const Source& source, const std::string& what, const std::vector<double>& values,
                   std::initializer_list<size_t> allowed_sizes) {
    if (values.empty()) return;  // absent: the default applies
    if (std::find(allowed_sizes.begin(), allowed_sizes.end(), values.size()) == allowed_sizes.end())
        fail(source, what + " has " + std::to_string(values.size()) + " numbers, expected " +
                         std::to_string(*allowed_sizes.begin()));
    for (double v : values)
        if (!std::isfinite(v)) fail(source, what + " has a value that is not finite");
}

// Parent of every node; fails on a bad child index or a node claimed by two parents.
std::vector<int> parents_of(const Source& source) {
    const auto& nodes = source.doc.nodes;
    std::vector<int> parent(nodes.size(), -1);
    for (size_t n = 0; n < nodes.size(); ++n) {
        const std::string what = "node " + std::to_string(n);
        for (int child : nodes[n].children) {
            if (!in_range(child, nodes.size()))
                fail(source, index_problem(what + " child", child, nodes.size(), "node"));
            if (static_cast<size_t>(child) == n) fail(source, what + " lists itself as a child (a cycle)");
            int& p = parent[static_cast<size_t>(child)];
            if (p == static_cast<int>(n)) fail(source, what + " lists child " + std::to_string(child) + " twice");
            if (p != -1)
                fail(source, "node " + std::to_string(child) + " has two parents (nodes " + std::to_string(p) +
                                 " and " + std::to_string(n) + "); glTF requires a tree");
            p = static_cast<int>(n);
        }
    }
    return parent;
}

// With at most one parent per node, a node is in (or below) a cycle exactly when it cannot
// be reached from a parentless node. Finds such a node and reports its cycle in parent→child
// order, starting at the cycle's smallest index.
void check_acyclic(const Source& source, const std::vector<int>& parent) {
    const auto& nodes = source.doc.nodes;
    std::vector<char> reached(nodes.size(), 0);
    std::vector<int> stack;
    for (size_t n = 0; n < nodes.size(); ++n)
        if (parent[n] == -1) stack.push_back(static_cast<int>(n));
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        reached[static_cast<size_t>(n)] = 1;
        for (int child : nodes[static_cast<size_t>(n)].children) stack.push_back(child);
    }
    const auto unreached = std::find(reached.begin(), reached.end(), 0);
    if (unreached == reached.end()) return;

    // Walk up from the unreached node until a node repeats: that node lies on the cycle.
    std::vector<char> seen(nodes.size(), 0);
    int x = static_cast<int>(unreached - reached.begin());
    while (!seen[static_cast<size_t>(x)]) {
        seen[static_cast<size_t>(x)] = 1;
        x = parent[static_cast<size_t>(x)];
    }
    std::vector<int> cycle;  // ancestor order: x, parent(x), ...
    int n = x;
    do {
        cycle.push_back(n);
        n = parent[static_cast<size_t>(n)];
    } while (n != x);
    std::reverse(cycle.begin(), cycle.end());  // now parent→child order
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    std::string text;
    for (int c : cycle) text += std::to_string(c) + " -> ";
    text += std::to_string(cycle.front());
    fail(source, "node hierarchy has a cycle: " + text);
}

}  // namespace

void validate_buffer_views(const Source& source) {
    const auto& doc = source.doc;
    for (size_t i = 0; i < doc.bufferViews.size(); ++i) {
        const tinygltf::BufferView& view = doc.bufferViews[i];
        const std::string what = "bufferView " + std::to_string(i);
        if (!in_range(view.buffer, doc.buffers.size()))
            fail(source, index_problem(what, view.buffer, doc.buffers.size(), "buffer"));
        const size_t size = doc.buffers[static_cast<size_t>(view.buffer)].data.size();
        if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
            fail(source, what + " (byteOffset " + std::to_string(view.byteOffset) + ", byteLength " +
                             std::to_string(view.byteLength) + ") runs past the end of buffer " +
                             std::to_string(view.buffer) + " (" + std::to_string(size) + " bytes)");
    }
}

void validate_required_extensions(const Source& source) {
    // Extensions that only change materials, textures or lights: geometry reads the same
    // without them. Anything else (Draco, meshopt, quantization) changes how vertices are
    // stored, and reading such a file as plain glTF would give garbage.
    static constexpr std::string_view kHarmlessPrefixes[] = {"KHR_materials_", "KHR_texture_", "EXT_texture_",
                                                             "KHR_lights_punctual"};
    for (const std::string& name : source.doc.extensionsRequired) {
        const bool harmless = std::any_of(std::begin(kHarmlessPrefixes), std::end(kHarmlessPrefixes),
                                          [&](std::string_view prefix) { return name.starts_with(prefix); });
        if (!harmless) fail(source, "requires extension " + name + ", which this loader does not support");
    }
}

void validate_nodes(const Source& source) {
    const auto& doc = source.doc;
    for (size_t n = 0; n < doc.nodes.size(); ++n) {
        const tinygltf::Node& node = doc.nodes[n];
        const std::string what = "node " + std::to_string(n);
        if (node.mesh != -1 && !in_range(node.mesh, doc.meshes.size()))
            fail(source, index_problem(what, node.mesh, doc.meshes.size(), "mesh"));
        if (node.camera != -1 && !in_range(node.camera, doc.cameras.size()))
            fail(source, index_problem(what, node.camera, doc.cameras.size(), "camera"));
        if (node.skin != -1 && !in_range(node.skin, doc.skins.size()))
            fail(source, index_problem(what, node.skin, doc.skins.size(), "skin"));
        check_numbers(source, what + " matrix", node.matrix, {16});
        check_numbers(source, what + " translation", node.translation, {3});
        check_numbers(source, what + " rotation", node.rotation, {4});
        check_numbers(source, what + " scale", node.scale, {3});
        if (!node.rotation.empty()) {
            double length2 = 0.0;
            for (double v : node.rotation) length2 += v * v;
            if (!(length2 > 1e-12)) fail(source, what + " rotation is a zero quaternion");
        }
    }
    const std::vector<int> parent = parents_of(source);
    check_acyclic(source, parent);

    if (doc.defaultScene != -1 && !in_range(doc.defaultScene, doc.scenes.size()))
        fail(source, index_problem("the default scene", doc.defaultScene, doc.scenes.size(), "scene"));
    for (size_t s = 0; s < doc.scenes.size(); ++s)
        for (int n : doc.scenes[s].nodes)
            if (!in_range(n, doc.nodes.size()))
                fail(source, index_problem("scene " + std::to_string(s), n, doc.nodes.size(), "node"));
}

std::vector<int> scene_roots(const Source& source) {
    const auto& doc = source.doc;
    std::vector<int> parent(doc.nodes.size(), -1);
    for (size_t n = 0; n < doc.nodes.size(); ++n)
        for (int child : doc.nodes[n].children) parent[static_cast<size_t>(child)] = static_cast<int>(n);

    const tinygltf::Scene* scene = nullptr;
    if (doc.defaultScene >= 0)
        scene = &doc.scenes[static_cast<size_t>(doc.defaultScene)];
    else if (!doc.scenes.empty())
        scene = &doc.scenes.front();
    std::vector<int> roots;
    if (scene == nullptr) {
        for (size_t n = 0; n < doc.nodes.size(); ++n)
            if (parent[n] == -1) roots.push_back(static_cast<int>(n));
        return roots;
    }
    // glTF requires scene nodes to be roots, but exporters list children too (Kenney's
    // craft_speederD lists a child of a "tmpParent" node). Such a node is still drawn, with
    // its full parent chain; it is dropped only when an ancestor is listed as well, since
    // that ancestor draws it already. Duplicates are dropped the same way.
    std::vector<char> listed(doc.nodes.size(), 0);
    for (int n : scene->nodes) listed[static_cast<size_t>(n)] = 1;
    std::vector<char> taken(doc.nodes.size(), 0);
    for (int n : scene->nodes) {
        bool ancestor_listed = false;
        for (int a = parent[static_cast<size_t>(n)]; a != -1 && !ancestor_listed; a = parent[static_cast<size_t>(a)])
            ancestor_listed = listed[static_cast<size_t>(a)] != 0;
        if (ancestor_listed || taken[static_cast<size_t>(n)]) continue;
        taken[static_cast<size_t>(n)] = 1;
        roots.push_back(n);
    }
    return roots;
}

}  // namespace lw::gltf_detail
