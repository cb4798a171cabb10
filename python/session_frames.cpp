// python/session_frames.cpp — a Python session's frames: renders, lines and sequences as
// NumPy data, drawn exactly as `linework render` draws frame f (frame_time over the range,
// ribbon seed f + 1).
#include <algorithm>
#include <cctype>
#include <cmath>

#include "session.h"

#include "core/image.h"

namespace lw::py {

namespace {

// Appends the run's samples to the store; the Polyline names their range.
Polyline polyline(const ScreenPath& path, const std::string& line_set, const std::shared_ptr<LineStore>& store) {
    LineStore& d = *store;
    const size_t first = d.fade.size();
    for (const ScreenSample& p : path.samples) {
        d.points.insert(d.points.end(), {p.pixel.x, p.pixel.y});
        // A run has one visibility (visibility splits paths into runs); per point for the
        // caller's convenience when runs are joined.
        d.visible.push_back(path.visible ? 1 : 0);
        d.fade.push_back(p.alpha);
        d.depth.push_back(p.depth);
        d.s.push_back(p.s);
        d.position.insert(d.position.end(), {p.position.x, p.position.y, p.position.z});
    }
    return {.store = store,
            .first = first,
            .count = path.samples.size(),
            .closed = path.closed,
            .qi = path.qi,
            .type = line_type_name(path.type),
            .line_set = line_set};
}

pyb::dict timings_of(const FrameTimings& t) {
    pyb::dict d;
    d["total_ms"] = t.total_ms;
    d["extract_ms"] = t.extract_ms;
    d["chain_ms"] = t.chain_ms;
    d["visibility_ms"] = t.visibility_ms;
    d["coherence_ms"] = t.coherence_ms;
    for (const PassTime& p : t.gpu) {
        if (p.ms < 0.0) continue;
        std::string key = "gpu_" + p.name + "_ms";  // "gpu_lines_draw_ms", as the keys above
        std::replace_if(key.begin(), key.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
        d[pyb::str(key)] = p.ms;
    }
    return d;
}

pyb::array_t<float> depth_array(std::vector<float>&& depth, int width, int height) {
    return to_array(std::move(depth), {pyb::ssize_t(height), pyb::ssize_t(width)});
}

}  // namespace

PathTime Session::time_of(std::optional<int> frame, std::optional<float> seconds, uint64_t& seed) const {
    if (frame && seconds) throw pyb::value_error("frame and t: give one");
    const FrameRange range = this->range();
    if (seconds) {
        if (!std::isfinite(*seconds) || std::abs(*seconds * fps()) > float(kMaxFrame))
            throw pyb::value_error("t: expected a finite time within " + std::to_string(kMaxFrame) + " frames of 0");
        // The frame number it falls on sets the ribbon seed; progress runs over the range.
        const float f = *seconds * fps();
        seed = uint64_t(std::max(0L, std::lround(f))) + 1;
        const float span = float(range.last - range.first);
        return {.progress = span > 0.0f ? (f - float(range.first)) / span : 0.0f, .seconds = *seconds};
    }
    check_frame(frame.value_or(range.first), "frame");
    const int f = frame.value_or(range.first);
    seed = uint64_t(std::max(f, 0)) + 1;
    return frame_time(f, range, fps());
}

Frame Session::draw(const PathTime& when, uint64_t seed, const FrameOutputs& outputs) {
    Frame frame;
    {
        const pyb::gil_scoped_release unlocked;
        const std::lock_guard lock(gpu_mutex());
        frame = session_->frame({.when = when, .camera = camera_ ? camera_ : scene_camera_, .outputs = outputs, .seed = seed});
    }
    last_when_ = when;
    check_validation(*ctx_);
    return frame;
}

pyb::dict Session::lines_of(const Frame& frame, bool hidden) const {
    const std::vector<SvgGroup> svg = session_->svg_groups(frame, false);  // the paths, not the shapes
    auto store = std::make_shared<LineStore>();
    size_t samples = 0;
    for (const SvgGroup& group : svg)
        for (const ScreenPath& path : group.paths ? *group.paths : std::vector<ScreenPath>{}) samples += path.samples.size();
    LineStore& d = *store;
    for (std::vector<float>* v : {&d.fade, &d.depth, &d.s}) v->reserve(samples);
    d.points.reserve(2 * samples);
    d.position.reserve(3 * samples);
    d.visible.reserve(samples);
    pyb::dict groups;
    for (const SvgGroup& group : svg) {
        pyb::list paths;
        if (group.paths)
            for (const ScreenPath& path : *group.paths)
                if ((path.visible || hidden) && path.samples.size() >= 2)
                    paths.append(pyb::cast(polyline(path, group.id, store)));
        groups[pyb::str(group.id)] = paths;
    }
    return groups;
}

pyb::object Session::render(std::optional<int> frame, std::optional<float> seconds, bool depth) {
    uint64_t seed = 1;
    const PathTime when = time_of(frame, seconds, seed);
    Frame f = draw(when, seed, {.color = true, .depth = depth});
    const int w = f.image.color.width, h = f.image.color.height;
    pyb::object image = image_to_array(straight_alpha(f.image.color));
    if (!depth) return image;
    return pyb::make_tuple(image, depth_array(std::move(f.image.depth), w, h));
}

pyb::dict Session::lines(std::optional<int> frame, std::optional<float> seconds, bool hidden) {
    uint64_t seed = 1;
    const PathTime when = time_of(frame, seconds, seed);
    return lines_of(draw(when, seed, {.color = false}), hidden);
}

FrameResult Session::result(int index, const PathTime& when, uint64_t seed, bool image, bool depth, bool lines,
                            bool hidden) {
    Frame f = draw(when, seed, {.color = image, .depth = depth});
    FrameResult r{.index = index, .seconds = when.seconds, .timings = timings_of(f.timings)};
    if (lines) r.lines = lines_of(f, hidden);
    const auto [w, h] = size();
    if (depth) r.depth = depth_array(std::move(f.image.depth), w, h);
    if (image) r.image = image_to_array(straight_alpha(f.image.color));
    return r;
}

FrameResult Session::frame_result(int index, const FrameRange& range, bool image, bool depth, bool lines, bool hidden) {
    return result(index, frame_time(index, range, fps()), uint64_t(std::max(index, 0)) + 1, image, depth, lines, hidden);
}

FrameResult Session::frame_at(std::optional<int> frame, std::optional<float> seconds, bool image, bool depth, bool lines,
                              bool hidden) {
    uint64_t seed = 1;
    const PathTime when = time_of(frame, seconds, seed);
    return result(frame.value_or(int(seed) - 1), when, seed, image, depth, lines, hidden);
}

}  // namespace lw::py
