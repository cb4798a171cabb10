// glTF loader: .gltf (JSON) or .glb (by the magic bytes), then the flattened mesh and the
// base colour textures decoded (stb_image through tinygltf) as a drawn frame decodes them.
#include "core/error.h"
#include "core/image.h"
#include "fuzz_support.h"
#include "scene/model.h"
#include "scene/triangle_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
    const lw::fuzz::InputFile input(data, size, binary ? ".glb" : ".gltf");
    const std::filesystem::path& path = input.path();
    try {
        const lw::Model model = lw::load_gltf(path);
        (void)lw::flatten(model, lw::world_transforms(model));
        for (const lw::Material& material : model.materials) {
            if (material.base_color_texture.image < 0) continue;
            try {
                (void)lw::srgb_mip_chain(lw::decode_model_image(model, material.base_color_texture.image));
            } catch (const lw::Error&) {
            }
        }
    } catch (const lw::Error&) {
    }
    return 0;
}
