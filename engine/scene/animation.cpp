// engine/scene/animation.cpp — samplers, poses, skinning and clip lookups.
#include "scene/animation.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lw {

namespace {

using Interpolation = AnimationSampler::Interpolation;

// Where `time` falls among the keys: the key k before it and the fraction u ∈ [0, 1) of the
// way to key k + 1. `clamped` when time is outside (or at the ends of) the keys: then key k
// alone gives the value (glTF 2.0 §3.11 leaves times outside the keys to the client; holding
// the end values is what viewers do, and it keeps a one-key sampler meaningful).
struct KeySpan {
    size_t k = 0;
    float u = 0.0f;
    float interval = 0.0f;  // t_{k+1} − t_k
    bool clamped = true;
};

KeySpan find_span(const std::vector<float>& times, float time) {
    KeySpan span;
    if (times.empty() || !(time > times.front())) return span;  // also NaN → first key
    if (time >= times.back()) {
        span.k = times.size() - 1;
        return span;
    }
    // First key after `time`; the loader checked that times strictly increase.
    const auto next = std::upper_bound(times.begin(), times.end(), time);
    span.k = static_cast<size_t>(next - times.begin()) - 1;
    span.interval = times[span.k + 1] - times[span.k];
    span.u = (time - times[span.k]) / span.interval;
    span.clamped = false;
    return span;
}

// Component c of the value stored for key k. CUBICSPLINE stores (in-tangent a, value v,
// out-tangent b) per key (Appendix C), other modes just the value. `slot` picks among them.
enum class Slot { InTangent = 0, Value = 1, OutTangent = 2 };

float stored(const AnimationSampler& s, size_t k, int c, Slot slot = Slot::Value) {
    const size_t n = static_cast<size_t>(s.components);
    const size_t element = s.interpolation == Interpolation::CubicSpline ? 3 * k + static_cast<size_t>(slot) : k;
    return s.values[element * n + static_cast<size_t>(c)];
}

// The sampler's N components at `time`, interpolated component by component: right for
// vectors, and for rotations before normalization (CUBICSPLINE); LINEAR rotations go
// through slerp instead (sample_rotation).
template <int N>
glm::vec<N, float> sample_components(const AnimationSampler& s, float time) {
    const KeySpan span = find_span(s.times, time);
    glm::vec<N, float> out;
    for (int c = 0; c < N; ++c) {
        const float v0 = stored(s, span.k, c);
        if (span.clamped || s.interpolation == Interpolation::Step) {
            out[c] = v0;
            continue;
        }
        const float v1 = stored(s, span.k + 1, c);
        if (s.interpolation == Interpolation::Linear) {
            out[c] = v0 + (v1 - v0) * span.u;
            continue;
        }
        // Cubic Hermite spline (Appendix C): the tangents are derivatives per second, so
        // they are scaled by the key interval t_d to become derivatives per unit u.
        const float t = span.u, t2 = t * t, t3 = t2 * t;
        const float b0 = stored(s, span.k, c, Slot::OutTangent);
        const float a1 = stored(s, span.k + 1, c, Slot::InTangent);
        out[c] = (2.0f * t3 - 3.0f * t2 + 1.0f) * v0 + span.interval * (t3 - 2.0f * t2 + t) * b0 +
                 (-2.0f * t3 + 3.0f * t2) * v1 + span.interval * (t3 - t2) * a1;
    }
    return out;
}

void check_sampler(const AnimationSampler& s, int components, const char* what) {
    if (s.components != components)
        throw Error(std::string("animation sampler: ") + what + " needs " + std::to_string(components) +
                    " components per key, the sampler has " + std::to_string(s.components));
    const size_t per_key = s.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (s.times.empty() || s.values.size() != s.times.size() * per_key * static_cast<size_t>(components))
        throw Error(std::string("animation sampler: ") + what + " has " + std::to_string(s.values.size()) +
                    " values for " + std::to_string(s.times.size()) + " keys");
}

// glTF stores quaternions as (x, y, z, w); glm::quat's constructor takes w first.
glm::quat to_quat(const glm::vec4& xyzw) { return glm::quat(xyzw.w, xyzw.x, xyzw.y, xyzw.z); }

glm::quat normalized(const glm::quat& q, const glm::quat& fallback) {
    const float length = glm::length(q);
    return length > 0.0f && std::isfinite(length) ? q / length : fallback;
}

// World transforms from the pose's local TRS (matrix nodes use their matrix), parents first.
// Guarded like world_transforms: a bad parent index makes a root, a cycle cannot loop.
void compose_world(const Model& model, Pose& pose) {
    pose.world = lw::compose_world(model, [&](size_t n) {
        const Node& node = model.nodes[n];
        return node.has_matrix ? node.matrix : trs_matrix(pose.translation[n], pose.rotation[n], pose.scale[n]);
    });
}

std::string clip_list(const Model& model) {
    if (model.animations.empty()) return "the model has no animation clips";
    // A run of unnamed clips is one entry: exporters write one per animated node, and
    // CesiumMan's 19 would fill the screen one by one.
    std::string list;
    const size_t count = model.animations.size();
    for (size_t a = 0; a < count; ++a) {
        list += list.empty() ? "" : ", ";
        if (!model.animations[a].name.empty()) {
            list += std::to_string(a) + " \"" + model.animations[a].name + "\"";
            continue;
        }
        size_t last = a;
        while (last + 1 < count && model.animations[last + 1].name.empty()) ++last;
        list += std::to_string(a) + (last > a ? " to " + std::to_string(last) : "") + " (unnamed)";
        a = last;
    }
    return "clips: " + list;
}

}  // namespace

std::string unplayed_clips_warning(const Model& model) {
    if (model.animations.empty()) return {};
    return model.path.string() + ": its animation clips are not played (" + clip_list(model) +
           "): every frame draws the rest pose; a scene file's \"animation\" key plays them";
}

glm::vec3 sample_vec3(const AnimationSampler& sampler, float time_seconds) {
    check_sampler(sampler, 3, "a translation or scale");
    return sample_components<3>(sampler, time_seconds);
}

glm::quat sample_rotation(const AnimationSampler& sampler, float time_seconds) {
    check_sampler(sampler, 4, "a rotation");
    const KeySpan span = find_span(sampler.times, time_seconds);
    const glm::quat first = normalized(
        to_quat({stored(sampler, span.k, 0), stored(sampler, span.k, 1), stored(sampler, span.k, 2),
                 stored(sampler, span.k, 3)}),
        glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    if (span.clamped || sampler.interpolation == Interpolation::Step) return first;
    if (sampler.interpolation == Interpolation::Linear) {
        const size_t k = span.k + 1;
        const glm::quat second = normalized(
            to_quat({stored(sampler, k, 0), stored(sampler, k, 1), stored(sampler, k, 2), stored(sampler, k, 3)}),
            first);
        return slerp_shortest(first, second, span.u);
    }
    // CUBICSPLINE: the spline runs through 4D space; Appendix C normalizes the result.
    return normalized(to_quat(sample_components<4>(sampler, time_seconds)), first);
}

glm::quat slerp_shortest(const glm::quat& a, glm::quat b, float u) {
    float d = glm::dot(a, b);
    // q and −q are the same rotation; the arc through the nearer one is the short way round.
    if (d < 0.0f) {
        b = -b;
        d = -d;
    }
    if (d > 0.9995f) return normalized(a * (1.0f - u) + b * u, a);  // sin θ ≈ 0: lerp is exact enough
    const float theta = std::acos(d);
    const float sin_theta = std::sin(theta);
    return normalized(a * (std::sin((1.0f - u) * theta) / sin_theta) + b * (std::sin(u * theta) / sin_theta), a);
}

namespace {

// Every node's own TRS; world transforms not yet composed.
Pose rest_trs(const Model& model) {
    Pose pose;
    const size_t count = model.nodes.size();
    pose.translation.resize(count);
    pose.rotation.resize(count);
    pose.scale.resize(count);
    for (size_t n = 0; n < count; ++n) {
        pose.translation[n] = model.nodes[n].translation;
        pose.rotation[n] = model.nodes[n].rotation;
        pose.scale[n] = model.nodes[n].scale;
    }
    return pose;
}

}  // namespace

Pose rest_pose(const Model& model) { return evaluate_pose(model, {}, 0.0f); }

Pose evaluate_pose(const Model& model, const std::vector<int>& clips, float time_seconds) {
    Pose pose = rest_trs(model);
    for (int clip : clips) {
        const Animation& animation = model.animations[static_cast<size_t>(find_clip(model, clip))];
        for (const AnimationChannel& channel : animation.channels) {
            if (channel.node < 0 || static_cast<size_t>(channel.node) >= model.nodes.size() || channel.sampler < 0 ||
                static_cast<size_t>(channel.sampler) >= animation.samplers.size())
                throw Error(model.path.string() + ": animation " + std::to_string(clip) +
                            " has a channel with a bad node or sampler index");
            const size_t n = static_cast<size_t>(channel.node);
            if (model.nodes[n].has_matrix) continue;  // not animatable (§3.5.2): keep the matrix
            const AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
            switch (channel.path) {
                case AnimationChannel::Path::Translation:
                    pose.translation[n] = sample_vec3(sampler, time_seconds);
                    break;
                case AnimationChannel::Path::Rotation: pose.rotation[n] = sample_rotation(sampler, time_seconds); break;
                case AnimationChannel::Path::Scale: pose.scale[n] = sample_vec3(sampler, time_seconds); break;
                case AnimationChannel::Path::Weights: break;  // morph targets are not drawn (header)
            }
        }
    }
    compose_world(model, pose);
    return pose;
}

std::vector<std::vector<glm::mat4>> joint_matrices(const Model& model, const std::vector<glm::mat4>& world) {
    std::vector<std::vector<glm::mat4>> out(model.skins.size());
    for (size_t s = 0; s < model.skins.size(); ++s) {
        const Skin& skin = model.skins[s];
        out[s].resize(skin.joints.size());
        for (size_t j = 0; j < skin.joints.size(); ++j) {
            const int node = skin.joints[j];
            if (node < 0 || static_cast<size_t>(node) >= world.size())
                throw Error(model.path.string() + ": skin " + std::to_string(s) + " joint " + std::to_string(j) +
                            " is node " + std::to_string(node) + ", which the pose does not have");
            // The inverse bind matrix takes the mesh from bind space into the joint's space;
            // the joint's current world transform takes it back out, posed (§3.7.3).
            out[s][j] = world[static_cast<size_t>(node)] *
                        (j < skin.inverse_bind.size() ? skin.inverse_bind[j] : glm::mat4(1.0f));
        }
    }
    return out;
}

TriangleMesh flatten_posed(const Model& model, const Pose& pose) {
    return flatten(model, pose.world, joint_matrices(model, pose.world));
}

int find_clip(const Model& model, const std::string& name) {
    for (size_t a = 0; a < model.animations.size(); ++a)
        if (model.animations[a].name == name) return static_cast<int>(a);
    throw Error(model.path.string() + ": no animation clip named \"" + name + "\" (" + clip_list(model) + ")");
}

int find_clip(const Model& model, int index) {
    if (index < 0 || static_cast<size_t>(index) >= model.animations.size())
        throw Error(model.path.string() + ": no animation clip " + std::to_string(index) + " (" + clip_list(model) +
                    ")");
    return index;
}

std::vector<int> select_clips(const Model& model, const ClipChoice& choice) {
    switch (choice.kind) {
        case ClipChoice::Kind::Name: return {find_clip(model, choice.name)};
        case ClipChoice::Kind::Index: return {find_clip(model, choice.index)};
        case ClipChoice::Kind::All: break;
    }
    std::vector<int> all(model.animations.size());
    for (size_t a = 0; a < all.size(); ++a) all[a] = static_cast<int>(a);
    return all;
}

float clip_duration(const Model& model, int clip) {
    return model.animations[static_cast<size_t>(find_clip(model, clip))].duration;
}

float clips_duration(const Model& model, const std::vector<int>& clips) {
    float longest = 0.0f;
    for (int clip : clips) longest = std::max(longest, clip_duration(model, clip));
    return longest;
}

}  // namespace lw
