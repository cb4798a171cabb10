// engine/stroke/slam_texture.h — a SLAM on the GPU: one 3D texture, trilinear filtering.
//
// Width = texture length (repeats: levels tile seamlessly), height = across the stroke
// (clamped), depth = levels 0.5 … 1.0 (clamped). Ink is stored as R8_UNORM, the format
// every Vulkan device can filter linearly.
#pragma once

#include "gpu/context.h"
#include "gpu/resources.h"
#include "stroke/slam.h"

namespace lw {

class SlamTexture {
public:
    SlamTexture(const Context& ctx, const Slam& slam);

    VkImageView view() const { return image_.view(); }
    VkSampler sampler() const { return sampler_; }
    int levels() const { return levels_; }
    int length() const { return length_; }

private:
    Image image_;
    Handle<VkSampler> sampler_;
    int levels_ = 0;
    int length_ = 0;
};

}  // namespace lw
