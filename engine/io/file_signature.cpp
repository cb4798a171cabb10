#include "io/file_signature.h"

#include <algorithm>
#include <array>
#include <fstream>

namespace lw {

FileKind file_kind(const std::filesystem::path& path) {
    constexpr std::array<unsigned char, 8> kPng = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    constexpr std::array<unsigned char, 4> kExr = {0x76, 0x2f, 0x31, 0x01};
    std::array<unsigned char, 8> head{};
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    const auto got = size_t(in.gcount());
    if (got >= kPng.size() && std::equal(kPng.begin(), kPng.end(), head.begin())) return FileKind::Png;
    if (got >= kExr.size() && std::equal(kExr.begin(), kExr.end(), head.begin())) return FileKind::Exr;
    return FileKind::Other;
}

}  // namespace lw
