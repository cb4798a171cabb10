// SLAM files (multi-part OpenEXR).
#include "core/error.h"
#include "fuzz_support.h"
#include "io/slam_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto path = lw::fuzz::write_input(data, size, ".exr");
    try {
        (void)lw::read_slam(path);
    } catch (const lw::Error&) {
    }
    return 0;
}
