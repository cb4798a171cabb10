// Scene files (JSON): every key, value and layer.
#include <string>

#include "core/error.h"
#include "fuzz_support.h"
#include "scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)lw::parse_scene_json(std::string(reinterpret_cast<const char*>(data), size), "/fuzz/scene.json");
    } catch (const lw::Error&) {
    }
    return 0;
}
