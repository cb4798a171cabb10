// SLAM files (multi-part OpenEXR).
#include "core/error.h"
#include "fuzz_support.h"
#include "io/slam_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const lw::fuzz::InputFile input(data, size, ".exr");
    const std::filesystem::path& path = input.path();
    try {
        (void)lw::read_slam(path);
    } catch (const lw::Error&) {
    }
    return 0;
}
