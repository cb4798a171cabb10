#include "io/file_signature.h"

#include <algorithm>
#include <array>
#include <fstream>

namespace lw {

namespace {

template <size_t N>
bool starts_with(const std::filesystem::path& path, const std::array<unsigned char, N>& bytes) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, N> head{};
    in.read(head.data(), N);
    return in.gcount() == std::streamsize(N) &&
           std::equal(bytes.begin(), bytes.end(), head.begin(), [](unsigned char a, char b) { return a == static_cast<unsigned char>(b); });
}

}  // namespace

bool has_png_signature(const std::filesystem::path& path) {
    return starts_with(path, std::array<unsigned char, 8>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
}

bool has_exr_signature(const std::filesystem::path& path) {
    return starts_with(path, std::array<unsigned char, 4>{0x76, 0x2f, 0x31, 0x01});
}

}  // namespace lw
