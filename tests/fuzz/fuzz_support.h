// tests/fuzz/fuzz_support.h — shared by the fuzz targets.
//
// Each target defines LLVMFuzzerTestOneInput: it feeds the bytes to one of our readers and
// accepts lw::Error (a clear message for bad input) as the only way to fail. Anything else —
// another exception, a crash, a sanitizer report — is a bug the fuzzer reports. Built with
// libFuzzer under clang (-DLINEWORK_FUZZ=ON, tools/fuzz.sh); built with replay_main.cpp in
// the normal build, the same targets replay tests/fuzz/corpus/ in the test suite.
#pragma once

#include <cstdint>
#include <cstdio>
#include <system_error>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lw::fuzz {

// Readers that take a path (image files, tinygltf's file loader): the bytes go to a
// per-process file whose extension picks the format, removed when the input is done (the
// test suite replays the corpus on every run and left ten files in the temp folder each time).
class InputFile {
public:
    InputFile(const uint8_t* data, size_t size, const std::string& extension)
        : path_(std::filesystem::temp_directory_path() / ("linework-fuzz-" + std::to_string(getpid()) + extension)) {
        std::ofstream(path_, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    ~InputFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace lw::fuzz
