#include "ribbon/exemplar.h"

#include <algorithm>

#include "core/error.h"
#include "core/log.h"

namespace lw {

Exemplar make_exemplar(const ImageRGBA8& image, const std::string& where) {
    if (image.width < 1 || image.height < 1) throw Error(where + ": the exemplar is empty");
    if (image.width > 4096 || image.height > 4096)
        throw Error(where + ": the exemplar is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    "; at most 4096 pixels per side");
    Exemplar e;
    e.width = image.width;
    e.height = image.height;
    e.texels.resize(size_t(e.width) * size_t(e.height));
    for (size_t i = 0; i < e.texels.size(); ++i) {
        const uint8_t* p = &image.pixels[i * 4];
        e.texels[i] = pack_rgba(p[0], p[1], p[2], p[3]);
    }
    if (std::none_of(e.texels.begin(), e.texels.end(), texel_opaque))
        throw Error(where + ": no opaque pixel (alpha >= 128): the exemplar's alpha must outline the pattern");
    // Allowed (a band of texture is a pattern too), but an image saved without alpha reads so,
    // and its background then draws as part of the pattern.
    if (std::all_of(e.texels.begin(), e.texels.end(), texel_opaque))
        log_warning(where + ": opaque everywhere (an image without alpha reads so): the whole image, background "
                            "and all, is the pattern; give the background alpha 0 to outline the pattern in it");
    return e;
}

ImageRGBA8 exemplar_image(const Exemplar& e) {
    ImageRGBA8 image{e.width, e.height, std::vector<uint8_t>(e.texels.size() * 4)};
    for (size_t i = 0; i < e.texels.size(); ++i)
        for (int c = 0; c < 4; ++c) image.pixels[i * 4 + size_t(c)] = uint8_t((e.texels[i] >> (8 * c)) & 0xffu);
    return image;
}

}  // namespace lw
