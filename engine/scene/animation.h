// engine/scene/animation.h — glTF 2.0 animation evaluation and skinning (pipeline step 1).
//
// Input:  a validated `Model`, the animation clips to play and a time in seconds.
// Output: `Pose` — every node's local translation/rotation/scale and world transform at
//         that time; `flatten_posed` turns a pose into the world-space `TriangleMesh`, with
//         skinned primitives deformed by linear blend skinning.
//
// Semantics (glTF 2.0 §3.11 "Animations", Appendix C "Interpolation"):
// - Every node starts from its rest TRS; each channel of each selected clip overrides one
//   property of one node. Clips play together from t = 0 (CesiumMan's 19 clips each drive
//   one joint); where two selected clips drive the same property, the later in `clips`
//   wins.
// - Time is clamped per sampler: before its first key the first value holds, after its last
//   key the last value holds. Nothing loops here; to loop, pass fmod(t, duration).
// - LINEAR interpolates translation and scale linearly and rotation by slerp along the
//   shorter arc; STEP holds a key's value until the next key; CUBICSPLINE is the Hermite
//   spline of Appendix C with the in/out tangents scaled by the key interval. Rotations are
//   normalized after every kind of interpolation.
// - A node with a `matrix` keeps it: the spec forbids animating such nodes (§3.5.2), and a
//   channel that targets one anyway is ignored.
// - Morph target weights ("weights" channels) are ignored: meshes are drawn without their
//   morph targets, so there is nothing for the weights to blend.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/model.h"
#include "scene/triangle_mesh.h"

namespace lw {

// Node transforms at one instant, indexed by node like `Model::nodes`.
struct Pose {
    std::vector<glm::vec3> translation;  // local TRS (a matrix node keeps its rest TRS here)
    std::vector<glm::quat> rotation;
    std::vector<glm::vec3> scale;
    std::vector<glm::mat4> world;        // parent world × local, from the roots down
};

// The rest pose: every node's own transform, no animation.
[[nodiscard]] Pose rest_pose(const Model& model);

// The pose at `time_seconds` with the given clips (indices into model.animations) playing
// together; `clips` empty gives the rest pose. Throws lw::Error for a clip index out of range.
[[nodiscard]] Pose evaluate_pose(const Model& model, const std::vector<int>& clips, float time_seconds);

// One sampler's value at a time, clamped to its first and last keys. `sample_vec3` wants
// 3 components (translation, scale); `sample_rotation` wants 4 (x, y, z, w as glTF stores
// them) and returns a unit quaternion. Both throw lw::Error on another component count.
[[nodiscard]] glm::vec3 sample_vec3(const AnimationSampler& sampler, float time_seconds);
[[nodiscard]] glm::quat sample_rotation(const AnimationSampler& sampler, float time_seconds);

// Spherical linear interpolation along the shorter arc (q and -q are the same rotation),
// normalized; nearly parallel quaternions fall back to normalized lerp.
[[nodiscard]] glm::quat slerp_shortest(const glm::quat& a, glm::quat b, float u);

// Joint matrices of every skin, [skin][joint] = world(joint) × inverse bind matrix.
[[nodiscard]] std::vector<std::vector<glm::mat4>> joint_matrices(const Model& model,
                                                                 const std::vector<glm::mat4>& world);

// The posed model in world space: `flatten` with the pose's world transforms and linear
// blend skinning (see triangle_mesh.h). Vertex and triangle order are those of `flatten`,
// the same for every pose of a model.
[[nodiscard]] TriangleMesh flatten_posed(const Model& model, const Pose& pose);

// Which clips play: every clip, one by name, or one by index.
struct ClipChoice {
    enum class Kind { All, Name, Index };
    Kind kind = Kind::All;
    std::string name;  // Kind::Name
    int index = -1;    // Kind::Index
};

// Clip lookups. Not found: lw::Error("<file>: ... (clips: 0 \"Survey\", 1 \"Walk\", ...)").
// Names are matched exactly; with duplicate names the first clip wins.
[[nodiscard]] int find_clip(const Model& model, const std::string& name);
[[nodiscard]] int find_clip(const Model& model, int index);
// Kind::All gives every clip (none for a model without animations).
[[nodiscard]] std::vector<int> select_clips(const Model& model, const ClipChoice& choice);

// What to say of a model whose clips a scene does not play (no "animation" key) over several
// frames: every frame draws the rest pose. Empty for a model without clips.
[[nodiscard]] std::string unplayed_clips_warning(const Model& model);

// A clip's length in seconds (its last key time); of several clips, the longest.
[[nodiscard]] float clip_duration(const Model& model, int clip);
[[nodiscard]] float clips_duration(const Model& model, const std::vector<int>& clips);

}  // namespace lw
