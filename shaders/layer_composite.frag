#version 450
// Layer composite, fragment stage: the coverage layer's premultiplied texel at this pixel
// (engine/gpu/coverage_layer.h), blended `over` the target (src + dst·(1 − α)).
layout(binding = 0) uniform sampler2D layer;

layout(location = 0) out vec4 out_color;

void main() {
    out_color = texelFetch(layer, ivec2(gl_FragCoord.xy), 0);
}
