// engine/scene/gltf_detail.h — internals shared by the glTF loader's translation units.
//
// Not part of the engine's interface: only gltf_loader.cpp, gltf_accessor.cpp,
// gltf_validate.cpp, gltf_objects.cpp and gltf_materials.cpp include it. tinygltf parses the file; everything here re-checks what it
// parsed, because tinygltf 2.7 accepts files whose indices, ranges or hierarchy are invalid.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/model.h"

namespace lw::gltf_detail {

// The parsed document plus the file name every message starts with.
struct Source {
    const tinygltf::Model& doc;
    std::string file;
};

// Throws lw::Error("<file>: <problem>").
[[noreturn]] void fail(const Source& source, const std::string& problem);

// Component types by their glTF names, for accessor rules.
inline constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
inline constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
inline constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
inline constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
inline constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
inline constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// What a use of an accessor requires. `role` names the use in messages, e.g.
// "indices of mesh 0 primitive 0".
struct AccessorRule {
    std::string role;
    std::vector<int> types;            // TINYGLTF_TYPE_*, any of
    std::vector<int> component_types;  // TINYGLTF_COMPONENT_TYPE_*, any of
    // Whether integer component types must be normalized (weights, quantized rotations) or
    // must not be (indices, joints). Float components ignore it.
    enum class Normalized { Required, Forbidden } normalized = Normalized::Forbidden;
};

// A decoded accessor: count elements of `components` values each, element after element,
// components in file order (a MAT4's 16 values column by column, as glTF stores them).
// Doubles hold every glTF component type exactly, including 32-bit unsigned indices.
struct AccessorData {
    size_t count = 0;
    int components = 0;
    std::vector<double> values;  // count * components

    double at(size_t element, int component) const {
        return values[element * static_cast<size_t>(components) + static_cast<size_t>(component)];
    }
};

// Checks the accessor against the rule and the buffers (index, bufferView, ranges, sparse
// substitution) and decodes it, honouring byteStride and normalized integers. An accessor
// without a bufferView reads as zeros, as glTF 2.0 specifies, then sparse values apply.
[[nodiscard]] AccessorData read_accessor(const Source& source, int accessor_index, const AccessorRule& rule);

// "accessor 3 (indices of mesh 0 primitive 0)": how messages name an accessor.
[[nodiscard]] std::string accessor_label(int accessor_index, const std::string& role);

// Fails when any decoded value is NaN or infinite.
void require_finite(const Source& source, const std::string& what, const AccessorData& data);

// Element count of an accessor after checking that the index exists (cheap: no decoding).
[[nodiscard]] size_t accessor_count(const Source& source, int accessor_index, const std::string& role);

// Whole-document structure checks that need no accessor data: buffer views inside their
// buffers, required extensions, node references, single parents, no cycles, scene node indices.
void validate_buffer_views(const Source& source);
void validate_required_extensions(const Source& source);
void validate_nodes(const Source& source);

// Roots to draw from: the default scene's nodes (scene, else scenes[0]) without those whose
// ancestor is listed too, else every parentless node. Assumes validate_nodes passed (the
// hierarchy is a tree, so walking up parents ends).
[[nodiscard]] std::vector<int> scene_roots(const Source& source);

// Conversions of the non-mesh objects (gltf_objects.cpp); each checks its references and
// reads its accessors through read_accessor.
[[nodiscard]] Skin convert_skin(const Source& source, size_t skin_index);
[[nodiscard]] Animation convert_animation(const Source& source, size_t animation_index);
[[nodiscard]] Camera convert_camera(const Source& source, size_t camera_index);
// A material (gltf_materials.cpp): base colour factor and texture, alpha mode and cutoff.
[[nodiscard]] Material convert_material(const Source& source, size_t material_index);

}  // namespace lw::gltf_detail
