// Exemplar images (PNG through libpng; other formats through OpenImageIO): the ribbon exemplar and the SLAM exemplar's ink.
#include "core/error.h"
#include "fuzz_support.h"
#include "io/image_io.h"
#include "ribbon/exemplar.h"
#include "slam_synth/slam_builder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const lw::fuzz::InputFile input(data, size, ".png");
    const std::filesystem::path& path = input.path();
    try {
        const lw::ImageRGBA8 image = lw::read_image_rgba8(path);
        (void)lw::make_exemplar(image, path.string());
        (void)lw::synth::exemplar_ink(image);
    } catch (const lw::Error&) {
    }
    return 0;
}
