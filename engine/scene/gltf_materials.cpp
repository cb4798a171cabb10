// engine/scene/gltf_materials.cpp — glTF materials and their base colour images.
//
// glTF 2.0 §3.9 (materials), §3.8 (textures, images, samplers) and KHR_texture_transform.
// Every reference is checked (texture → image, sampler) and every value the drawing uses
// (factor, cutoff, filter and wrap codes); images are kept encoded and decoded by stb_image
// (through tinygltf, a Debian package) only when a texture is drawn.
#include <cmath>

#include "core/error.h"
#include "core/text.h"
#include "scene/gltf_detail.h"

namespace lw::gltf_detail {

namespace {

TextureWrap parse_wrap(const Source& source, const std::string& what, int code) {
    switch (code) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
        default: fail(source, what + " has unknown wrap mode " + std::to_string(code));
    }
}

void apply_sampler(const Source& source, int index, TextureRef& ref) {
    if (index < 0) return;  // glTF: repeat, with the filters left to the implementation
    const std::string what = "sampler " + std::to_string(index);
    if (size_t(index) >= source.doc.samplers.size())
        fail(source, what + " does not exist (" + std::to_string(source.doc.samplers.size()) + " samplers)");
    const tinygltf::Sampler& s = source.doc.samplers[size_t(index)];
    ref.wrap_s = parse_wrap(source, what, s.wrapS);
    ref.wrap_t = parse_wrap(source, what, s.wrapT);
    switch (s.magFilter) {
        case -1: case TINYGLTF_TEXTURE_FILTER_LINEAR: break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST: ref.nearest_mag = true; break;
        default: fail(source, what + " has unknown magFilter " + std::to_string(s.magFilter));
    }
    switch (s.minFilter) {
        case -1: case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: ref.nearest_mip = true; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: ref.nearest_min = true; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: ref.nearest_min = ref.nearest_mip = true; break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR: ref.mipmaps = false; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST: ref.mipmaps = false; ref.nearest_min = true; break;
        default: fail(source, what + " has unknown minFilter " + std::to_string(s.minFilter));
    }
}

double number_or(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.Has(key) || !object.Get(key).IsNumber()) return fallback;
    return object.Get(key).GetNumberAsDouble();
}

// KHR_texture_transform: uv' = T · R · S · uv, with its own texCoord when it gives one.
void apply_texture_transform(const Source& source, const std::string& what, const tinygltf::ExtensionMap& extensions,
                             TextureRef& ref) {
    const auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end()) return;
    const tinygltf::Value& t = it->second;
    // Each value checked as the double the file holds: converting one outside float's range
    // (or an int's, for texCoord) is undefined behaviour.
    const auto value = [&](double v) {
        if (!(std::abs(v) <= 1e30)) fail(source, what + ": KHR_texture_transform has a value that is not finite or too large");
        return float(v);
    };
    glm::vec2 offset(0.0f), scale(1.0f);
    if (t.Has("offset") && t.Get("offset").ArrayLen() == 2)
        offset = {value(t.Get("offset").Get(0).GetNumberAsDouble()), value(t.Get("offset").Get(1).GetNumberAsDouble())};
    if (t.Has("scale") && t.Get("scale").ArrayLen() == 2)
        scale = {value(t.Get("scale").Get(0).GetNumberAsDouble()), value(t.Get("scale").Get(1).GetNumberAsDouble())};
    const float rotation = value(number_or(t, "rotation", 0.0));
    const float c = std::cos(rotation), s = std::sin(rotation);
    // Columns: the spec's rotation matrix [c s; −s c] composed after the scale, then the offset.
    ref.uv_transform = glm::mat3(glm::vec3(c * scale.x, -s * scale.x, 0.0f), glm::vec3(s * scale.y, c * scale.y, 0.0f),
                                 glm::vec3(offset, 1.0f));
    const double texcoord = number_or(t, "texCoord", double(ref.texcoord));
    if (!(texcoord >= 0 && texcoord <= 255) || texcoord != std::floor(texcoord))
        fail(source, what + ": KHR_texture_transform has texCoord " + std::to_string(texcoord));
    ref.texcoord = int(texcoord);
}

TextureRef convert_texture(const Source& source, const std::string& what, const tinygltf::TextureInfo& info) {
    TextureRef ref;
    if (info.index < 0) return ref;
    const tinygltf::Model& doc = source.doc;
    if (size_t(info.index) >= doc.textures.size())
        fail(source, what + " names texture " + std::to_string(info.index) + " but the file has " +
                         std::to_string(doc.textures.size()));
    if (info.texCoord < 0) fail(source, what + " has texCoord " + std::to_string(info.texCoord));
    ref.texcoord = info.texCoord;
    const tinygltf::Texture& texture = doc.textures[size_t(info.index)];
    if (texture.source >= 0 && size_t(texture.source) >= doc.images.size())
        fail(source, "texture " + std::to_string(info.index) + " names image " + std::to_string(texture.source) +
                         " but the file has " + std::to_string(doc.images.size()));
    // No source: the image is in an extension's format (KHR_texture_basisu, EXT_texture_webp),
    // which stb_image cannot read; the factor alone colours the material, with a warning when
    // it is drawn (scene_materials).
    ref.image = texture.source;
    if (texture.source < 0)
        ref.problem = source.file + ": texture " + std::to_string(info.index) +
                      " has no image Linework reads (only an extension's, such as KTX2 or WebP)";
    apply_sampler(source, texture.sampler, ref);
    apply_texture_transform(source, what, info.extensions, ref);
    return ref;
}

}  // namespace

Material convert_material(const Source& source, size_t material_index) {
    const tinygltf::Material& in = source.doc.materials[material_index];
    const std::string what = "material " + std::to_string(material_index) +
                             (in.name.empty() ? std::string() : " (\"" + in.name + "\")");
    Material out;
    out.name = in.name;
    const std::vector<double>& factor = in.pbrMetallicRoughness.baseColorFactor;
    if (factor.size() != 4)
        fail(source, what + ": baseColorFactor has " + std::to_string(factor.size()) + " values (expected 4)");
    for (int c = 0; c < 4; ++c) {
        const double v = factor[size_t(c)];
        if (!(v >= 0.0 && v <= 1.0))
            fail(source, what + ": baseColorFactor value " + std::to_string(v) + " is outside [0, 1]");
        out.base_color[c] = float(v);
    }
    out.base_color_texture = convert_texture(source, what + " baseColorTexture", in.pbrMetallicRoughness.baseColorTexture);
    if (in.alphaMode == "OPAQUE" || in.alphaMode.empty()) {
        out.alpha_mode = AlphaMode::Opaque;
    } else if (in.alphaMode == "MASK") {
        out.alpha_mode = AlphaMode::Mask;
    } else if (in.alphaMode == "BLEND") {
        out.alpha_mode = AlphaMode::Blend;
    } else {
        fail(source, what + " has unknown alphaMode \"" + in.alphaMode + "\" (expected OPAQUE, MASK or BLEND)");
    }
    if (!(in.alphaCutoff >= 0.0) || !std::isfinite(in.alphaCutoff))
        fail(source, what + ": alphaCutoff " + std::to_string(in.alphaCutoff) + " is not a number >= 0");
    out.alpha_cutoff = float(in.alphaCutoff);
    return out;
}

}  // namespace lw::gltf_detail

namespace lw {

ImageRGBA8 decode_model_image(const Model& model, int image) {
    const std::string file = model.path.string();
    if (image < 0 || size_t(image) >= model.images.size())
        throw Error(file + ": image " + std::to_string(image) + " does not exist");
    const ModelImage& source = model.images[size_t(image)];
    const std::string what = file + ": image " + std::to_string(image) +
                             (source.name.empty() ? std::string() : " (" + source.name + ")");
    if (source.bytes.empty()) throw Error(what + ": " + (source.problem.empty() ? "no data" : source.problem));
    tinygltf::Image decoded;
    std::string err, warn;
    // RGBA8 or RGBA16 whatever the file's channels (tinygltf's default request is 4).
    if (!tinygltf::LoadImageData(&decoded, image, &err, &warn, 0, 0, source.bytes.data(), int(source.bytes.size()),
                                 nullptr) ||
        decoded.width <= 0 || decoded.height <= 0 || decoded.component != 4)
        throw Error(what + ": cannot decode the image" + (err.empty() ? std::string() : ": " + one_line(err)));
    ImageRGBA8 out{decoded.width, decoded.height, {}};
    const size_t values = size_t(decoded.width) * size_t(decoded.height) * 4;
    out.pixels.resize(values);
    if (decoded.bits == 8 && decoded.image.size() == values) {
        out.pixels.assign(decoded.image.begin(), decoded.image.end());
    } else if (decoded.bits == 16 && decoded.image.size() == 2 * values) {
        for (size_t i = 0; i < values; ++i) {  // the high byte, rounded: 16-bit PNGs are rare for colour
            const unsigned v = unsigned(decoded.image[2 * i]) | unsigned(decoded.image[2 * i + 1]) << 8;
            out.pixels[i] = uint8_t((v * 255u + 32767u) / 65535u);
        }
    } else {
        throw Error(what + ": decoded to " + std::to_string(decoded.bits) + "-bit samples, which are not read");
    }
    return out;
}

}  // namespace lw
