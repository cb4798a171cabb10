// engine/scene/material.h — what a model says its surfaces look like, as plain data.
//
// Input:  a glTF material's `pbrMetallicRoughness.baseColorFactor` and `baseColorTexture`,
//         its `alphaMode` and `alphaCutoff` (glTF 2.0 §3.9); the images the textures name,
//         kept encoded (PNG, JPEG) until someone draws with them.
// Output: `Material` per model material and `decode_model_image` (RGBA8, sRGB as stored).
//
// Only what a line drawing's backdrop needs is read: the base colour and its alpha. Metal,
// roughness, normal and occlusion maps are PBR lighting, which flat and toon shading do not
// model. OBJ and PLY materials are names only (line sets select by them); their colours come
// from the scene.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"

namespace lw {

// glTF 2.0 §3.9.4 "Alpha Coverage".
enum class AlphaMode {
    Opaque,  // alpha ignored
    Mask,    // alpha < cutoff: no surface there at all (no colour, no depth: lines show through)
    Blend,   // composited over what is behind; does not hide lines (glass, lenses)
};

enum class TextureWrap { Repeat, MirroredRepeat, ClampToEdge };

// A material's base colour texture (glTF textureInfo + its sampler).
struct TextureRef {
    int image = -1;        // index into Model::images; -1: no texture
    int texcoord = 0;      // TEXCOORD_n it reads
    TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat;
    bool nearest_mag = false;  // magnification filter NEAREST (else LINEAR)
    bool nearest_min = false;  // minification within a level NEAREST (else LINEAR)
    bool mipmaps = true;       // the minification filter reads mip levels
    bool nearest_mip = false;  // ... the nearest one (*_MIPMAP_NEAREST), else a blend of two
    glm::mat3 uv_transform{1.0f};  // KHR_texture_transform (offset · rotation · scale)
    std::string problem;           // why a texture the material names has no image (warned when drawn)
};

struct Material {
    std::string name;           // "" when unnamed
    bool has_color = true;      // false: the scene's colour (OBJ/PLY materials are names only)
    glm::vec4 base_color{1.0f}; // linear RGBA factor
    TextureRef base_color_texture;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;  // Mask only
};

// An image of a model as the file holds it: decoded only when a texture is drawn.
struct ModelImage {
    std::string name;  // its name or URI, for messages
    std::vector<unsigned char> bytes;  // the encoded file (empty: could not be read)
    std::string problem;               // why `bytes` is empty, for the message
};

// The materials a shaded mesh is drawn with: what the surface pass takes.
struct SurfaceMaterials {
    std::vector<Material> materials;
    std::vector<ImageRGBA8> images;      // the decoded base colour images (sRGB texels), each once
    std::vector<int32_t> material_image; // per material: its texture's index in `images`, -1: none
    std::vector<int32_t> face_material;  // per triangle of the mesh: index in `materials`, -1: the scene colour
};

}  // namespace lw
