// engine/scene/gltf_accessor.cpp — the one place that reads accessor data.
//
// tinygltf stores buffers and the accessor/bufferView descriptions but does not check that
// an accessor's elements lie inside its bufferView, or that the bufferView exists. Every read
// goes through `read_accessor`, which checks all of that before touching a byte.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "scene/gltf_detail.h"

namespace lw::gltf_detail {

namespace {

// Accessors without a bufferView are zeros: cap them so that a bogus count cannot make us
// allocate gigabytes for data the file never stored.
constexpr size_t kMaxZeroAccessorCount = size_t{1} << 24;

std::string type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "unknown type " + std::to_string(type);
    }
}

std::string component_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT:
            return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE:
            return "DOUBLE";
        default:
            return "unknown component type " + std::to_string(component_type);
    }
}

template <class Names>
std::string join_names(const std::vector<int>& values, Names names) {
    std::string out;
    for (int v : values) {
        if (!out.empty()) out += " or ";
        out += names(v);
    }
    return out;
}

bool contains(const std::vector<int>& values, int v) {
    return std::find(values.begin(), values.end(), v) != values.end();
}

// An unaligned little-endian value of type T at `bytes` (glTF data need not be aligned).
template <typename T>
double load(const unsigned char* bytes) {
    T v;
    std::memcpy(&v, bytes, sizeof v);
    return static_cast<double>(v);
}

// One component at `bytes`, converted as the glTF 2.0 spec says (normalized integers map to [0, 1]
// or [-1, 1]; plain integers keep their value).
double decode_component(const unsigned char* bytes, int component_type, bool normalized) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return normalized ? std::max(load<int8_t>(bytes) / 127.0, -1.0) : load<int8_t>(bytes);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? load<uint8_t>(bytes) / 255.0 : load<uint8_t>(bytes);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return normalized ? std::max(load<int16_t>(bytes) / 32767.0, -1.0) : load<int16_t>(bytes);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return normalized ? load<uint16_t>(bytes) / 65535.0 : load<uint16_t>(bytes);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return load<uint32_t>(bytes);
        case TINYGLTF_COMPONENT_TYPE_INT:
            return load<int32_t>(bytes);
        default:  // FLOAT; other types were rejected by the rule check
            return load<float>(bytes);
    }
}

// Checks that `count` elements of `element_size` bytes, `stride` apart, starting `offset`
// bytes into buffer view `view_index`, lie inside it; returns a pointer to the first one.
// Divisions instead of products so that absurd JSON values cannot overflow.
const unsigned char* checked_range(const Source& source, const std::string& what, int view_index, size_t offset,
                                   size_t stride, size_t count, size_t element_size) {
    const auto& doc = source.doc;
    if (view_index < 0 || static_cast<size_t>(view_index) >= doc.bufferViews.size())
        fail(source, what + ": bufferView " + std::to_string(view_index) + " does not exist (the file has " +
                         std::to_string(doc.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = doc.bufferViews[static_cast<size_t>(view_index)];
    // validate_buffer_views has checked that the view lies inside its buffer.
    const size_t length = view.byteLength;
    bool fits = offset <= length && element_size <= length - offset;
    if (fits && count > 1) fits = stride <= (length - offset - element_size) / (count - 1);
    if (!fits)
        fail(source, what + ": " + std::to_string(count) + " elements of " + std::to_string(element_size) +
                         " bytes (stride " + std::to_string(stride) + ", byteOffset " + std::to_string(offset) +
                         ") run past the end of bufferView " + std::to_string(view_index) + " (byteLength " +
                         std::to_string(length) + ")");
    return doc.buffers[static_cast<size_t>(view.buffer)].data.data() + view.byteOffset + offset;
}

// Replaces elements of `data` by the accessor's sparse values (glTF 2.0 sparse accessors).
void apply_sparse(const Source& source, const std::string& what, const tinygltf::Accessor& accessor,
                  size_t element_size, size_t component_size, AccessorData& data) {
    const auto& sparse = accessor.sparse;
    if (sparse.count <= 0) fail(source, what + ": sparse count " + std::to_string(sparse.count) + " is not positive");
    const size_t count = static_cast<size_t>(sparse.count);
    if (count > data.count)
        fail(source, what + ": sparse count " + std::to_string(count) + " exceeds the accessor count " +
                         std::to_string(data.count));
    const int index_type = sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(source, what + ": sparse indices have component type " + component_name(index_type) +
                         ", expected an unsigned integer type");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        fail(source, what + ": sparse byteOffset is negative");
    const size_t index_size = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(index_type)));
    const unsigned char* indices =
        checked_range(source, what + " sparse indices", sparse.indices.bufferView,
                      static_cast<size_t>(sparse.indices.byteOffset), index_size, count, index_size);
    const unsigned char* values =
        checked_range(source, what + " sparse values", sparse.values.bufferView,
                      static_cast<size_t>(sparse.values.byteOffset), element_size, count, element_size);
    double previous = -1.0;
    for (size_t i = 0; i < count; ++i) {
        const double index = decode_component(indices + i * index_size, index_type, false);
        if (index <= previous || index >= static_cast<double>(data.count))
            fail(source, what + ": sparse index " + std::to_string(static_cast<uint64_t>(index)) + " at position " +
                             std::to_string(i) + " is out of order or not below the count " +
                             std::to_string(data.count));
        previous = index;
        const size_t element = static_cast<size_t>(index);
        for (int c = 0; c < data.components; ++c)
            data.values[element * static_cast<size_t>(data.components) + static_cast<size_t>(c)] =
                decode_component(values + i * element_size + static_cast<size_t>(c) * component_size,
                                 accessor.componentType, accessor.normalized);
    }
}

}  // namespace

std::string accessor_label(int accessor_index, const std::string& role) {
    return "accessor " + std::to_string(accessor_index) + " (" + role + ")";
}

void require_finite(const Source& source, const std::string& what, const AccessorData& data) {
    for (size_t e = 0; e < data.count; ++e)
        for (int c = 0; c < data.components; ++c)
            if (!std::isfinite(data.at(e, c)))
                fail(source, what + ": element " + std::to_string(e) + " has a value that is not finite");
}

size_t accessor_count(const Source& source, int accessor_index, const std::string& role) {
    if (accessor_index < 0 || static_cast<size_t>(accessor_index) >= source.doc.accessors.size())
        fail(source, accessor_label(accessor_index, role) + " does not exist (the file has " +
                         std::to_string(source.doc.accessors.size()) + " accessors)");
    return source.doc.accessors[static_cast<size_t>(accessor_index)].count;
}

AccessorData read_accessor(const Source& source, int accessor_index, const AccessorRule& rule) {
    const std::string what = accessor_label(accessor_index, rule.role);
    const size_t count = accessor_count(source, accessor_index, rule.role);
    const tinygltf::Accessor& accessor = source.doc.accessors[static_cast<size_t>(accessor_index)];

    if (!contains(rule.types, accessor.type))
        fail(source,
             what + " has type " + type_name(accessor.type) + ", expected " + join_names(rule.types, type_name));
    if (!contains(rule.component_types, accessor.componentType))
        fail(source, what + " has component type " + component_name(accessor.componentType) + ", expected " +
                         join_names(rule.component_types, component_name));
    const bool is_float = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (!is_float && rule.normalized == AccessorRule::Normalized::Required && !accessor.normalized)
        fail(source, what + " has integer components that are not normalized");
    if (!is_float && rule.normalized == AccessorRule::Normalized::Forbidden && accessor.normalized)
        fail(source, what + " is normalized, which this use does not allow");
    if (count == 0) fail(source, what + " has count 0");

    AccessorData data;
    data.count = count;
    data.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
    const size_t component_size =
        static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType)));
    const size_t element_size = component_size * static_cast<size_t>(data.components);

    const unsigned char* bytes = nullptr;
    size_t stride = element_size;
    if (accessor.bufferView >= 0) {
        // Look the view up before using its stride; checked_range repeats the index check.
        if (static_cast<size_t>(accessor.bufferView) < source.doc.bufferViews.size()) {
            const size_t view_stride = source.doc.bufferViews[static_cast<size_t>(accessor.bufferView)].byteStride;
            if (view_stride != 0) {
                if (view_stride < element_size || view_stride % component_size != 0)
                    fail(source, what + ": bufferView " + std::to_string(accessor.bufferView) + " has byteStride " +
                                     std::to_string(view_stride) + ", which does not fit elements of " +
                                     std::to_string(element_size) + " bytes");
                stride = view_stride;
            }
        }
        bytes = checked_range(source, what, accessor.bufferView, accessor.byteOffset, stride, count, element_size);
    } else if (count > kMaxZeroAccessorCount) {
        fail(source, what + " has no bufferView and an implausible count " + std::to_string(count));
    }

    data.values.assign(count * static_cast<size_t>(data.components), 0.0);
    if (bytes != nullptr) {
        double* out = data.values.data();
        for (size_t e = 0; e < count; ++e) {
            const unsigned char* element = bytes + e * stride;
            for (int c = 0; c < data.components; ++c)
                *out++ = decode_component(element + static_cast<size_t>(c) * component_size, accessor.componentType,
                                          accessor.normalized);
        }
    }
    if (accessor.sparse.isSparse) apply_sparse(source, what, accessor, element_size, component_size, data);
    return data;
}

}  // namespace lw::gltf_detail
