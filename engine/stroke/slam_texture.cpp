#include "stroke/slam_texture.h"

#include <algorithm>
#include <cmath>

#include "core/color.h"
#include "core/error.h"

namespace lw {

SlamTexture::SlamTexture(const Context& ctx, const Slam& slam)
    : image_(ctx, {.width = uint32_t(slam.length),
                   .height = uint32_t(slam.height),
                   .depth = uint32_t(slam.levels),
                   .format = VK_FORMAT_R8_UNORM,
                   .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                   .name = "slam"}),
      sampler_(create_sampler(ctx, {})),
      levels_(slam.levels),
      length_(slam.length) {
    if (slam.ink.size() != size_t(slam.levels) * slam.height * slam.length)
        throw Error("SLAM texture: ink size does not match levels × height × length");
    std::vector<std::byte> texels(slam.ink.size());
    for (size_t i = 0; i < texels.size(); ++i)
        texels[i] = std::byte(unit_to_byte(slam.ink[i]));
    upload_image(ctx, image_, texels);
}

}  // namespace lw
