// engine/scene/ply_check.cpp — check_ply_structure: what Assimp 5.2's PLY reader trusts.
//
// Assimp (Debian 12's 5.2.5) reads a PLY's element counts and list lengths and allocates and
// fills that many values before it looks at what the file holds: a header that never ends
// loops for ever, "element vertex 4000000000" reserves tens of GB, and in ASCII a list length
// of 10^70 fills memory until the process is killed (found by tests/fuzz/fuzz_mesh). This
// pass reads only the structure — the header, and for ASCII the list lengths — so that such
// a file is refused in one pass over its bytes; Assimp still reads the values.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/ply_check.h"

namespace lw {

namespace {

struct PlyProperty {
    bool list = false;
    unsigned size = 0;        // bytes of a scalar (binary)
    unsigned count_size = 0;  // bytes of a list's length (binary)
    std::string type;         // of a scalar or a list's items
    std::string count_type;   // of a list's length
    std::string name;
};

struct PlyElement {
    std::string name;
    unsigned long long count = 0;
    std::vector<PlyProperty> properties;
};

unsigned type_size(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

// The header of a PLY file read whole into `bytes`.
struct PlyLayout {
    std::string format;
    std::vector<PlyElement> elements;
    size_t header_end = 0;  // the body's first byte
};

template <class Fail>
PlyLayout read_layout(const std::string& bytes, Fail fail) {
    PlyLayout layout;
    if (bytes.rfind("ply\n", 0) != 0 && bytes.rfind("ply\r\n", 0) != 0) fail("not a PLY file (the first line is not \"ply\")");
    size_t header_end = std::string::npos;
    for (size_t at = bytes.find("end_header"); at != std::string::npos; at = bytes.find("end_header", at + 1))
        if (bytes[at - 1] == '\n' && (at + 10 == bytes.size() || bytes[at + 10] == '\n' || bytes[at + 10] == '\r')) {
            header_end = bytes.find('\n', at);
            header_end = header_end == std::string::npos ? bytes.size() : header_end + 1;
            break;
        }
    if (header_end == std::string::npos) fail("PLY header has no end_header line before the end of the file");
    layout.header_end = header_end;

    std::istringstream header(bytes.substr(0, header_end));
    std::string line;
    std::string& format = layout.format;
    std::vector<PlyElement>& elements = layout.elements;
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "format") {
            words >> format;
        } else if (word == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count)) fail("PLY header: bad element line \"" + line + "\"");
            elements.push_back(e);
        } else if (word == "property") {
            if (elements.empty()) fail("PLY header: a property before any element");
            std::string type;
            words >> type;
            PlyProperty p;
            if (type == "list") {
                std::string count_type, item_type;
                words >> count_type >> item_type;
                p.list = true;
                p.count_size = type_size(count_type);
                p.size = type_size(item_type);
                p.type = item_type;
                p.count_type = count_type;
                if (p.count_size == 0 || p.size == 0) fail("PLY header: bad list property \"" + line + "\"");
            } else {
                p.size = type_size(type);
                p.type = type;
                if (p.size == 0) fail("PLY header: unknown property type \"" + type + "\"");
            }
            words >> p.name;
            elements.back().properties.push_back(p);
        } else if (!word.empty() && word != "ply" && word != "comment" && word != "obj_info" && word != "end_header") {
            // Assimp reads such lines its own way, and then the body differently from us.
            std::string shown = line.substr(0, 40);
            for (char& c : shown)
                if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
            fail("PLY header: unknown line \"" + shown + "\"");
        }
    }
    if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        fail("PLY header: unknown format \"" + format + "\"");

    return layout;
}

std::vector<PlyElement>::const_iterator find_element(const std::vector<PlyElement>& elements, const char* name) {
    return std::find_if(elements.begin(), elements.end(), [&](const PlyElement& e) { return e.name == name; });
}

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

bool check_ply_structure(const std::filesystem::path& path, const std::string& file) {
    const std::string bytes = read_bytes(path);
    const auto fail = [&](const std::string& problem) { throw Error(file + ": " + problem); };
    const PlyLayout layout = read_layout(bytes, fail);
    const std::string& format = layout.format;
    const std::vector<PlyElement>& elements = layout.elements;
    const size_t header_end = layout.header_end;

    // Every element takes at least a byte per property (binary: its size; ASCII: a digit and
    // a separator), so the counts cannot outgrow the file.
    const unsigned long long body = bytes.size() - header_end;
    unsigned long long least = 0;
    for (const PlyElement& e : elements) {
        unsigned long long per = 0;
        for (const PlyProperty& p : e.properties) per += format == "ascii" ? 2 : (p.list ? p.count_size : p.size);
        if (per > 0 && e.count > body / per) fail("PLY element " + e.name + " declares " + std::to_string(e.count) +
                                                  " entries, more than the file's " + std::to_string(body) + " bytes hold");
        least += e.count * per;
    }
    if (least > body) fail("PLY body of " + std::to_string(body) + " bytes is shorter than its header declares");
    // Triangle strips are read by read_ply_strips, whole, up to the strips (so the vertices
    // come first), and instead of faces, not beside them.
    auto element = [&](const char* name) { return find_element(elements, name); };
    const bool strips = element("tristrips") != elements.end();
    if (strips && element("face") != elements.end())
        fail("PLY has both faces and triangle strips (elements face and tristrips): give one or the other");
    if (strips && element("vertex") == elements.end()) fail("PLY has triangle strips but no vertex element");
    if (strips && element("vertex") > element("tristrips"))
        fail("PLY element vertex comes after tristrips: give the vertices first");
    if (format != "ascii") return strips;

    // ASCII: walk the tokens as the header lays them out; a list's length must fit the tokens left.
    const char* p = bytes.c_str() + header_end;
    const char* const end = bytes.c_str() + bytes.size();
    const auto next = [&]() -> const char* {
        while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
        if (p >= end) return nullptr;
        const char* token = p;
        while (p < end && !std::isspace(static_cast<unsigned char>(*p))) ++p;
        return token;
    };
    for (const PlyElement& e : elements)
        for (unsigned long long i = 0; i < (e.properties.empty() ? 0 : e.count); ++i)
            for (const PlyProperty& prop : e.properties) {
                const char* token = next();
                if (!token) fail("PLY body ends inside element " + e.name + " " + std::to_string(i));
                if (!prop.list) continue;
                char* stop = nullptr;
                const unsigned long long n = std::strtoull(token, &stop, 10);
                if (stop == token || n > (unsigned long long)(end - p) / 2 + 1)
                    fail("PLY element " + e.name + " " + std::to_string(i) + ": list length \"" +
                         std::string(token, size_t(std::min<ptrdiff_t>(p - token, 24))) + "\" is past the file's end");
                for (unsigned long long k = 0; k < n; ++k)
                    if (!next()) fail("PLY body ends inside element " + e.name + " " + std::to_string(i));
            }
    return strips;
}

namespace {

// The values of a PLY body in the order the header lays them out, ASCII or binary.
class BodyReader {
public:
    BodyReader(const std::string& bytes, const PlyLayout& layout, std::string file)
        : bytes_(bytes), at_(layout.header_end), ascii_(layout.format == "ascii"),
          swap_((layout.format == "binary_big_endian") != (std::endian::native == std::endian::big)),
          file_(std::move(file)) {}

    // The next value of `type` (`size` bytes in binary), in entry `i` of `element`.
    double next(const std::string& type, unsigned size, const PlyElement& element, unsigned long long i) {
        if (ascii_) {
            while (at_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[at_]))) ++at_;
            const char* begin = bytes_.c_str() + at_;
            char* stop = nullptr;
            const double v = std::strtod(begin, &stop);
            if (stop == begin) throw Error(file_ + ": PLY body: no number in element " + element.name + " " + std::to_string(i));
            at_ += size_t(stop - begin);
            return v;
        }
        if (at_ + size > bytes_.size())
            throw Error(file_ + ": PLY body ends inside element " + element.name + " " + std::to_string(i));
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + at_, size);
        at_ += size;
        if (swap_) std::reverse(raw, raw + size);
        return decode(raw, type);
    }

private:
    static double decode(const unsigned char* raw, const std::string& type) {
        auto as = [&]<class T>(T) {
            T v;
            std::memcpy(&v, raw, sizeof(T));
            return double(v);
        };
        if (type == "char" || type == "int8") return as(int8_t{});
        if (type == "uchar" || type == "uint8") return as(uint8_t{});
        if (type == "short" || type == "int16") return as(int16_t{});
        if (type == "ushort" || type == "uint16") return as(uint16_t{});
        if (type == "int" || type == "int32") return as(int32_t{});
        if (type == "uint" || type == "uint32") return as(uint32_t{});
        if (type == "float" || type == "float32") return as(float{});
        return as(double{});
    }

    const std::string& bytes_;
    size_t at_;
    bool ascii_, swap_;
    std::string file_;
};

// Triangles of one strip's indices: triangle k is (v_k, v_k+1, v_k+2), its first two swapped
// when k is odd so that every triangle of the strip winds the same way; -1 restarts the strip;
// degenerate triangles (stitching strips together) are skipped.
void strip_triangles(const std::vector<int64_t>& strip, std::vector<uint32_t>& out) {
    int64_t a = -1, b = -1;
    bool odd = false;
    for (const int64_t v : strip) {
        if (v < 0) {
            a = b = -1;
            odd = false;
            continue;
        }
        if (a < 0) {
            a = v;
            continue;
        }
        if (b < 0) {
            b = v;
            continue;
        }
        if (a != b && b != v && a != v) {
            const int64_t first = odd ? b : a, second = odd ? a : b;
            out.insert(out.end(), {uint32_t(first), uint32_t(second), uint32_t(v)});
        }
        a = b;
        b = v;
        odd = !odd;
    }
}

// A strip's index as read: a vertex, or a restart (-1; the largest value of an unsigned type).
int64_t strip_index(double v, const PlyProperty& prop, const std::string& file, unsigned long long strip) {
    const bool is_unsigned = prop.type[0] == 'u';
    if (v == -1.0 || (is_unsigned && v == std::exp2(8.0 * prop.size) - 1.0)) return -1;
    if (!(v >= 0.0 && v < 4294967295.0) || v != std::floor(v))
        throw Error(file + ": PLY tristrips " + std::to_string(strip) + ": " + std::to_string(v) + " is not a vertex index");
    return int64_t(v);
}

}  // namespace

PlyStripMesh read_ply_strips(const std::filesystem::path& path, const std::string& file) {
    const std::string bytes = read_bytes(path);
    const PlyLayout layout = read_layout(bytes, [&](const std::string& problem) { throw Error(file + ": " + problem); });
    const auto strips = find_element(layout.elements, "tristrips");
    if (strips == layout.elements.end()) throw Error(file + ": PLY has no tristrips element");
    PlyStripMesh mesh;
    BodyReader body(bytes, layout, file);
    for (auto e = layout.elements.begin(); e != std::next(strips); ++e) {
        if (e->properties.empty()) continue;  // nothing to read, however many it declares
        const bool is_vertex = e->name == "vertex", is_strips = e == strips;
        // Where x, y, z and nx, ny, nz are among the vertex's properties.
        auto index_of = [&](const char* name) {
            for (size_t k = 0; k < e->properties.size(); ++k)
                if (!e->properties[k].list && e->properties[k].name == name) return int(k);
            return -1;
        };
        const int position[3] = {index_of("x"), index_of("y"), index_of("z")};
        const int normal[3] = {index_of("nx"), index_of("ny"), index_of("nz")};
        const bool normals = is_vertex && normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0;
        if (is_vertex && (position[0] < 0 || position[1] < 0 || position[2] < 0))
            throw Error(file + ": PLY vertex element has no x, y and z properties");
        std::vector<double> values(e->properties.size());
        std::vector<int64_t> strip;
        for (unsigned long long i = 0; i < e->count; ++i) {
            bool first_list = true;
            for (size_t k = 0; k < e->properties.size(); ++k) {
                const PlyProperty& prop = e->properties[k];
                if (!prop.list) {
                    values[k] = body.next(prop.type, prop.size, *e, i);
                    continue;
                }
                const double n = body.next(prop.count_type, prop.count_size, *e, i);
                if (!(n >= 0.0) || n > double(bytes.size()))
                    throw Error(file + ": PLY element " + e->name + " " + std::to_string(i) + ": bad list length");
                const bool indices = is_strips && first_list;  // a strip's vertex_indices
                first_list = false;
                if (indices) strip.clear();
                for (unsigned long long j = 0; j < (unsigned long long)n; ++j) {
                    const double v = body.next(prop.type, prop.size, *e, i);
                    if (indices) strip.push_back(strip_index(v, prop, file, i));
                }
            }
            if (is_vertex) {
                for (const int k : {position[0], position[1], position[2], normal[0], normal[1], normal[2]})
                    if (k >= 0 && !(std::abs(values[size_t(k)]) <= double(std::numeric_limits<float>::max())))
                        throw Error(file + ": PLY vertex " + std::to_string(i) + " has a coordinate that is not a finite float");
                mesh.positions.push_back(glm::vec3(values[size_t(position[0])], values[size_t(position[1])], values[size_t(position[2])]));
                if (normals)
                    mesh.normals.push_back(glm::vec3(values[size_t(normal[0])], values[size_t(normal[1])], values[size_t(normal[2])]));
            }
            if (is_strips) {
                for (const int64_t v : strip)
                    if (v >= int64_t(mesh.positions.size()))
                        throw Error(file + ": PLY tristrips " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                                    " of " + std::to_string(mesh.positions.size()));
                strip_triangles(strip, mesh.indices);
            }
        }
    }
    return mesh;
}

}  // namespace lw
