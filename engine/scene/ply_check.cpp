// engine/scene/ply_check.cpp — check_ply_structure: what Assimp 5.2's PLY reader trusts.
//
// Assimp (Debian 12's 5.2.5) reads a PLY's element counts and list lengths and allocates and
// fills that many values before it looks at what the file holds: a header that never ends
// loops for ever, "element vertex 4000000000" reserves tens of GB, and in ASCII a list length
// of 10^70 fills memory until the process is killed (found by tests/fuzz/fuzz_mesh). This
// pass reads only the structure — the header, and for ASCII the list lengths — so that such
// a file is refused in one pass over its bytes; Assimp still reads the values.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
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

}  // namespace

void check_ply_structure(const std::filesystem::path& path, const std::string& file) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto fail = [&](const std::string& problem) { throw Error(file + ": " + problem); };
    if (bytes.rfind("ply\n", 0) != 0 && bytes.rfind("ply\r\n", 0) != 0) fail("not a PLY file (the first line is not \"ply\")");
    size_t header_end = std::string::npos;
    for (size_t at = bytes.find("end_header"); at != std::string::npos; at = bytes.find("end_header", at + 1))
        if (bytes[at - 1] == '\n' && (at + 10 == bytes.size() || bytes[at + 10] == '\n' || bytes[at + 10] == '\r')) {
            header_end = bytes.find('\n', at);
            header_end = header_end == std::string::npos ? bytes.size() : header_end + 1;
            break;
        }
    if (header_end == std::string::npos) fail("PLY header has no end_header line before the end of the file");

    std::istringstream header(bytes.substr(0, header_end));
    std::string line, format;
    std::vector<PlyElement> elements;
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
                if (p.count_size == 0 || p.size == 0) fail("PLY header: bad list property \"" + line + "\"");
            } else {
                p.size = type_size(type);
                if (p.size == 0) fail("PLY header: unknown property type \"" + type + "\"");
            }
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
    if (format != "ascii") return;

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
        for (unsigned long long i = 0; i < e.count; ++i)
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
}

}  // namespace lw
