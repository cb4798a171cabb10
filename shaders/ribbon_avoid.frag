#version 450
// Avoidance map (Zhou et al. 2013, §3.1): every covered pixel adds 1/255 to the red channel
// (additive blending into RGBA8), so red × 255 counts how often the ribbon covers it; more
// than once marks a fold-over or a self-overlap.
layout(location = 0) out vec4 out_color;

void main() { out_color = vec4(1.0 / 255.0, 0.0, 0.0, 1.0 / 255.0); }
