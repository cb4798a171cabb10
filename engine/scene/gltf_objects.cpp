// engine/scene/gltf_objects.cpp — skins, animations and cameras from a parsed glTF.
//
// Each object's references are checked (joint and target nodes, samplers) and its data read
// through the checked accessor reader; key times must be finite and strictly increasing,
// since animation evaluation searches them by bisection.
#include <algorithm>
#include <cmath>
#include <optional>

#include "scene/gltf_detail.h"

namespace lw::gltf_detail {

namespace {

using Normalized = AccessorRule::Normalized;

AnimationChannel::Path parse_path(const Source& source, const std::string& what, const std::string& path) {
    if (path == "translation") return AnimationChannel::Path::Translation;
    if (path == "rotation") return AnimationChannel::Path::Rotation;
    if (path == "scale") return AnimationChannel::Path::Scale;
    if (path == "weights") return AnimationChannel::Path::Weights;
    fail(source, what + " has unknown target path \"" + path + "\"");
}

AnimationSampler::Interpolation parse_interpolation(const Source& source, const std::string& what,
                                                    const std::string& name) {
    if (name == "LINEAR") return AnimationSampler::Interpolation::Linear;
    if (name == "STEP") return AnimationSampler::Interpolation::Step;
    if (name == "CUBICSPLINE") return AnimationSampler::Interpolation::CubicSpline;
    fail(source, what + " has unknown interpolation \"" + name + "\"");
}

AnimationSampler convert_sampler(const Source& source, const std::string& what, const tinygltf::AnimationSampler& in,
                                 std::optional<AnimationChannel::Path> path) {
    AnimationSampler out;
    out.interpolation = parse_interpolation(source, what, in.interpolation);
    const std::string input_role = "input of " + what;
    const AccessorData input = read_accessor(source, in.input, {input_role, {TINYGLTF_TYPE_SCALAR}, {kFloat}});
    out.times.resize(input.count);
    for (size_t k = 0; k < input.count; ++k) {
        const double t = input.values[k];
        if (!std::isfinite(t))
            fail(source, accessor_label(in.input, input_role) + ": key time " + std::to_string(k) + " is not finite");
        if (k > 0 && !(t > input.values[k - 1]))
            fail(source, accessor_label(in.input, input_role) + ": key times are not strictly increasing (key " +
                             std::to_string(k) + ": " + std::to_string(t) + " after " +
                             std::to_string(input.values[k - 1]) + ")");
        out.times[k] = static_cast<float>(t);
    }

    // Output element type by target path (glTF 2.0 animation samplers): quantized rotations and weights
    // may be normalized integers. A sampler no channel uses is read as any float type.
    AccessorRule rule{"output of " + what, {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, {kFloat}};
    if (path == AnimationChannel::Path::Translation || path == AnimationChannel::Path::Scale)
        rule = {rule.role, {TINYGLTF_TYPE_VEC3}, {kFloat}};
    else if (path == AnimationChannel::Path::Rotation)
        rule = {rule.role, {TINYGLTF_TYPE_VEC4}, {kFloat, kByte, kUByte, kShort, kUShort}, Normalized::Required};
    else if (path == AnimationChannel::Path::Weights)
        rule = {rule.role, {TINYGLTF_TYPE_SCALAR}, {kFloat, kByte, kUByte, kShort, kUShort}, Normalized::Required};
    const AccessorData output = read_accessor(source, in.output, rule);
    require_finite(source, accessor_label(in.output, rule.role), output);

    // Cubic splines store in-tangent, value and out-tangent per key.
    const size_t per_key = out.interpolation == AnimationSampler::Interpolation::CubicSpline ? 3 : 1;
    const size_t slots = input.count * per_key;
    if (path == AnimationChannel::Path::Weights) {
        if (output.count % slots != 0)
            fail(source, accessor_label(in.output, rule.role) + " has " + std::to_string(output.count) +
                             " weights, not a multiple of the " + std::to_string(slots) + " key slots");
        out.components = static_cast<int>(output.count / slots);
    } else {
        if (output.count != slots)
            fail(source, accessor_label(in.output, rule.role) + " has " + std::to_string(output.count) +
                             " elements for " + std::to_string(input.count) + " key times (expected " +
                             std::to_string(slots) + ")");
        out.components = output.components;
    }
    out.values.resize(output.values.size());
    std::transform(output.values.begin(), output.values.end(), out.values.begin(),
                   [](double v) { return static_cast<float>(v); });
    return out;
}

}  // namespace

Skin convert_skin(const Source& source, size_t skin_index) {
    const tinygltf::Skin& in = source.doc.skins[skin_index];
    const std::string what = "skin " + std::to_string(skin_index);
    const size_t node_count = source.doc.nodes.size();
    Skin out;
    out.name = in.name;
    if (in.joints.empty()) fail(source, what + " has no joints");
    for (int joint : in.joints)
        if (joint < 0 || static_cast<size_t>(joint) >= node_count)
            fail(source, what + " joint refers to node " + std::to_string(joint) +
                             ", which does not exist (the file has " + std::to_string(node_count) + ")");
    out.joints = in.joints;
    if (in.skeleton != -1 && (in.skeleton < 0 || static_cast<size_t>(in.skeleton) >= node_count))
        fail(source, what + " skeleton refers to node " + std::to_string(in.skeleton) + ", which does not exist");
    out.skeleton = in.skeleton;
    out.inverse_bind.assign(in.joints.size(), glm::mat4(1.0f));
    if (in.inverseBindMatrices != -1) {
        const std::string role = "inverse bind matrices of " + what;
        const AccessorData matrices =
            read_accessor(source, in.inverseBindMatrices, {role, {TINYGLTF_TYPE_MAT4}, {kFloat}});
        require_finite(source, accessor_label(in.inverseBindMatrices, role), matrices);
        if (matrices.count < in.joints.size())
            fail(source, accessor_label(in.inverseBindMatrices, role) + " has " + std::to_string(matrices.count) +
                             " matrices for " + std::to_string(in.joints.size()) + " joints");
        for (size_t j = 0; j < in.joints.size(); ++j)
            for (int k = 0; k < 16; ++k) out.inverse_bind[j][k / 4][k % 4] = static_cast<float>(matrices.at(j, k));
    }
    return out;
}

Animation convert_animation(const Source& source, size_t animation_index) {
    const tinygltf::Animation& in = source.doc.animations[animation_index];
    const std::string what = "animation " + std::to_string(animation_index);
    Animation out;
    out.name = in.name;

    // Channels first: they decide what each sampler's output must hold.
    std::vector<std::optional<AnimationChannel::Path>> sampler_path(in.samplers.size());
    for (size_t c = 0; c < in.channels.size(); ++c) {
        const tinygltf::AnimationChannel& channel = in.channels[c];
        const std::string channel_what = what + " channel " + std::to_string(c);
        if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= in.samplers.size())
            fail(source, channel_what + " refers to sampler " + std::to_string(channel.sampler) +
                             ", which does not exist (the animation has " + std::to_string(in.samplers.size()) + ")");
        // No target node: the target is defined by an extension we do not support.
        if (channel.target_node == -1) continue;
        if (channel.target_node < 0 || static_cast<size_t>(channel.target_node) >= source.doc.nodes.size())
            fail(source, channel_what + " targets node " + std::to_string(channel.target_node) +
                             ", which does not exist (the file has " + std::to_string(source.doc.nodes.size()) + ")");
        const AnimationChannel::Path path = parse_path(source, channel_what, channel.target_path);
        auto& used = sampler_path[static_cast<size_t>(channel.sampler)];
        const auto vec3 = [](AnimationChannel::Path p) {
            return p == AnimationChannel::Path::Translation || p == AnimationChannel::Path::Scale;
        };
        if (used && *used != path && !(vec3(*used) && vec3(path)))
            fail(source, channel_what + " uses sampler " + std::to_string(channel.sampler) +
                             " for a different kind of value than another channel does");
        if (!used) used = path;
        out.channels.push_back({channel.target_node, path, channel.sampler});
    }
    for (size_t s = 0; s < in.samplers.size(); ++s) {
        out.samplers.push_back(
            convert_sampler(source, what + " sampler " + std::to_string(s), in.samplers[s], sampler_path[s]));
        out.duration = std::max(out.duration, out.samplers.back().times.back());
    }
    return out;
}

Camera convert_camera(const Source& source, size_t camera_index) {
    const tinygltf::Camera& in = source.doc.cameras[camera_index];
    const std::string what = "camera " + std::to_string(camera_index);
    Camera out;
    out.name = in.name;
    const auto finite = [](std::initializer_list<double> values) {
        return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
    };
    if (in.type == "perspective") {
        const auto& p = in.perspective;
        if (!finite({p.yfov, p.aspectRatio, p.znear, p.zfar}) || !(p.yfov > 0.0) || !(p.znear > 0.0) ||
            p.aspectRatio < 0.0 || (p.zfar != 0.0 && !(p.zfar > p.znear)))
            fail(source, what + " has invalid perspective parameters (yfov " + std::to_string(p.yfov) + ", znear " +
                             std::to_string(p.znear) + ", zfar " + std::to_string(p.zfar) + ")");
        out.type = Camera::Type::Perspective;
        out.yfov = static_cast<float>(p.yfov);
        out.aspect = static_cast<float>(p.aspectRatio);
        out.znear = static_cast<float>(p.znear);
        out.zfar = static_cast<float>(p.zfar);
    } else if (in.type == "orthographic") {
        const auto& o = in.orthographic;
        if (!finite({o.xmag, o.ymag, o.znear, o.zfar}) || o.xmag == 0.0 || o.ymag == 0.0 || o.znear < 0.0 ||
            !(o.zfar > o.znear))
            fail(source, what + " has invalid orthographic parameters");
        out.type = Camera::Type::Orthographic;
        out.xmag = static_cast<float>(o.xmag);
        out.ymag = static_cast<float>(o.ymag);
        out.znear = static_cast<float>(o.znear);
        out.zfar = static_cast<float>(o.zfar);
    } else {
        fail(source, what + " has unknown type \"" + in.type + "\"");
    }
    return out;
}

}  // namespace lw::gltf_detail
