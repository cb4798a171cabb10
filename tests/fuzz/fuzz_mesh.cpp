// OBJ and PLY loader (Assimp, then our checks), then the flattened mesh. PLY files start with
// "ply"; anything else is read as OBJ.
#include "core/error.h"
#include "fuzz_support.h"
#include "scene/model.h"
#include "scene/triangle_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool ply = size >= 3 && data[0] == 'p' && data[1] == 'l' && data[2] == 'y';
    const lw::fuzz::InputFile input(data, size, ply ? ".ply" : ".obj");
    const std::filesystem::path& path = input.path();
    try {
        const lw::Model model = lw::load_model(path);
        (void)lw::flatten(model, lw::world_transforms(model));
    } catch (const lw::Error&) {
    }
    return 0;
}
