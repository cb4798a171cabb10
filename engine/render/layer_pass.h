// engine/render/layer_pass.h — vector-art layers drawn by the stroke renderer of 3D lines.
//
// Input:  per layer, its style (set once: SLAM or solid ink, taper, fill colour, the
//         coherence parameters of its SLAM) and, per frame, its `LayerFrame`
//         (vector/layer.h: strokes as screen paths, fill triangles, the 2D transform as
//         camera matrices).
// Output: fills, then strokes, alpha-blended over the frame's colour target after the 3D
//         lines, in layer order; each SLAM layer's paths parameterized coherently from frame
//         to frame by its own tracker (§4 of Bénard et al. 2010; the reprojection is the
//         previous frame's 2D transform), which is what keeps the texture's on-screen
//         period steady through a zoom (the paper's Fig. 5).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "coherence/coherence.h"
#include "gpu/context.h"
#include "gpu/render_target.h"
#include "stroke/slam.h"
#include "stroke/slam_texture.h"
#include "stroke/stroke_pass.h"
#include "vector/layer.h"

namespace lw {

struct LayerStyle {
    std::optional<Slam> slam;       // textured, coherent strokes; absent: solid ink
    float taper_px = 0.0f;
    bool strokes = true;            // false: paths only (a ribbon layer draws them after readback)
    glm::vec3 fill_color{0.0f};
    CoherenceParams coherence;      // its slam_length_px and length_scale match `slam`
};

// What a layer drew this frame (dumps and ribbons read it): its paths after the tracker
// (fragments dropped, merged paths split), and their parameters (default, ρ = 0, for solid
// strokes).
using LayerResult = ParameterizedPaths;

class LayerPass {
public:
    LayerPass(const Context& ctx, uint32_t width, uint32_t height, std::vector<LayerStyle> styles);

    size_t layer_count() const { return layers_.size(); }

    // Parameterizes the layers' paths (SLAM layers; `coherent` off: T = s·κ/Lmax, tiling)
    // and builds their triangles. `frames` has one entry per layer; paths are resampled at
    // fixed texture phases every `spacing` pixels, as 3D strokes are.
    std::vector<LayerResult> prepare(std::vector<LayerFrame>& frames, bool coherent, float spacing);

    // Records the draws of the last prepare(), their vertices put in `arena`.
    void record(const Context& ctx, VkCommandBuffer cmd, const RenderTarget& target, const StrokePass& strokes,
                UploadArena& arena) const;

    // The SLAM layers' tracker states (absent for solid layers), for --resume.
    [[nodiscard]] std::vector<std::optional<CoherenceTracker::State>> states() const;
    void restore(const std::vector<std::optional<CoherenceTracker::State>>& states);

private:
    struct Layer {
        LayerStyle style;
        std::unique_ptr<SlamTexture> texture;       // null: the solid texture
        std::unique_ptr<CoherenceTracker> tracker;  // SLAM layers only
        // This frame's triangles, fill first, then the strokes in file order: runs of
        // textured strokes and, in a SLAM layer, of strokes too short for its texture, which
        // are drawn solid as the same layer without "slam" draws them (dots, short dashes).
        struct Run {
            bool solid = false;
            std::vector<StrokeVertex> vertices;
        };
        std::vector<StrokeVertex> fill;
        std::vector<Run> runs;
    };
    std::vector<Layer> layers_;
    std::unique_ptr<SlamTexture> solid_;  // full ink everywhere: fills and plain strokes
};

}  // namespace lw
