// python/synthesizers_2d.cpp — the stroke synthesizers: linework.pattern (Barla et al. 2006)
// and linework.hatch (Jodoin et al. 2002), with strokes as Python data. Each makes the engine
// calls its command does (tools/linework/pattern_command.cpp, hatch_command.cpp), with the
// same defaults, so that the strokes returned are the ones the command writes.
//
// A stroke in: an N×2 array of points (width 1, black, open), or a dict with the keys of a
// JSON stroke file (engine/vector/stroke.h): "points" (N×2), "width" (a number) or "widths"
// (N numbers), "color" ((r, g, b) in [0, 1] or "#rrggbb"), "closed" (bool). Strokes out are
// such dicts, always with "widths" (float32 array), "color" (a tuple) and "closed".
// A list of strokes may also be given as a stroke file (SVG or JSON), read as the command
// line reads it.
#include <algorithm>
#include <cmath>

#include "synthesizers.h"

#include "core/color.h"
#include "hatch/hatching.h"
#include "pattern/synthesis.h"
#include "vector/stroke_io.h"

namespace lw::py {

using namespace pybind11::literals;

namespace {

// ---- Strokes in and out -----------------------------------------------------------------

std::vector<glm::vec2> points_argument(const pyb::handle& value, const std::string& what) {
    const pyb::array a = pyb::array::ensure(value);
    if (!a) throw pyb::value_error(what + ": expected an N×2 array of points");
    return array_to_vec2(a, what);
}

float number_argument(const pyb::handle& value, const std::string& what) {
    if (pyb::isinstance<pyb::bool_>(value) || !PyNumber_Check(value.ptr()))
        throw pyb::value_error(what + ": expected a number");
    return value.cast<float>();
}

// The checks and messages of the stroke file reader (engine/vector/stroke_io.cpp).
void check_stroke(const Stroke& s, const std::string& what) {
    if (s.points.empty()) throw pyb::value_error(what + ": a stroke needs at least one point");
    for (const glm::vec2& p : s.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 1e6f || std::abs(p.y) > 1e6f)
            throw pyb::value_error(what + ": coordinates must be finite and within ±1e6");
    for (float w : s.widths)
        if (!std::isfinite(w) || w <= 0.0f || w > 1e4f) throw pyb::value_error(what + ": widths must be positive and finite");
    for (int c = 0; c < 3; ++c)
        if (!(s.color[c] >= 0.0f && s.color[c] <= 1.0f))
            throw pyb::value_error(what + ": colour components must lie in [0, 1]");
}

Stroke stroke_argument(const pyb::handle& item, const std::string& what) {
    Stroke s;
    if (!pyb::isinstance<pyb::dict>(item)) {
        s.points = points_argument(item, what);
        s.widths.assign(s.points.size(), 1.0f);
        check_stroke(s, what);
        return s;
    }
    const pyb::dict d = pyb::reinterpret_borrow<pyb::dict>(item);
    for (const auto& [key, value] : d) {
        const std::string k = pyb::str(key);
        if (k != "points" && k != "width" && k != "widths" && k != "color" && k != "closed")
            throw pyb::value_error(what + "." + k + ": unknown key");
    }
    if (!d.contains("points")) throw pyb::value_error(what + ".points: missing (an N×2 array of points)");
    s.points = points_argument(d["points"], what + ".points");
    if (d.contains("width") && d.contains("widths"))
        throw pyb::value_error(what + ": give either width or widths, not both");
    s.widths.assign(s.points.size(), d.contains("width") ? number_argument(d["width"], what + ".width") : 1.0f);
    if (d.contains("widths")) {
        const auto w = pyb::array_t<float, pyb::array::c_style | pyb::array::forcecast>::ensure(d["widths"]);
        if (!w || w.ndim() != 1 || size_t(w.size()) != s.points.size())
            throw pyb::value_error(what + ".widths: expected one number per point");
        s.widths.assign(w.data(), w.data() + w.size());
    }
    if (d.contains("color")) {
        const pyb::object c = d["color"];
        if (pyb::isinstance<pyb::str>(c)) {
            s.color = reading_input([&] { return parse_color(c.cast<std::string>(), what + ".color"); });
        } else {
            const auto a = pyb::array_t<float, pyb::array::c_style | pyb::array::forcecast>::ensure(c);
            if (!a || a.ndim() != 1 || a.size() != 3)
                throw pyb::value_error(what + ".color: expected (r, g, b) in [0, 1] or \"#rrggbb\"");
            s.color = {a.data()[0], a.data()[1], a.data()[2]};
        }
    }
    if (d.contains("closed")) {
        if (!pyb::isinstance<pyb::bool_>(d["closed"])) throw pyb::value_error(what + ".closed: expected True or False");
        s.closed = d["closed"].cast<bool>();
    }
    check_stroke(s, what);
    return s;
}

// A stroke file or a sequence of strokes; `where` gets the name errors go under.
std::vector<Stroke> strokes_argument(const pyb::handle& value, const std::string& name, std::string* where) {
    if (const std::optional<std::string> path = file_path(value)) {
        *where = *path;
        return reading_input([&] { return load_strokes(*path); }).strokes;
    }
    *where = name;
    if (pyb::isinstance<pyb::array>(value) && pyb::reinterpret_borrow<pyb::array>(value).ndim() == 2)
        throw pyb::value_error(name + ": expected a list of strokes, got one N×2 array (put it in a list)");
    if (pyb::isinstance<pyb::dict>(value) || !pyb::isinstance<pyb::sequence>(value))
        throw pyb::value_error(name + ": expected a list of strokes (N×2 arrays or dicts) or a stroke file");
    std::vector<Stroke> strokes;
    size_t i = 0;
    for (const pyb::handle item : value) strokes.push_back(stroke_argument(item, name + "[" + std::to_string(i++) + "]"));
    return strokes;
}

pyb::list strokes_value(const std::vector<Stroke>& strokes) {
    pyb::list out;
    for (const Stroke& s : strokes) {
        std::vector<float> xy;
        xy.reserve(2 * s.points.size());
        for (const glm::vec2& p : s.points) xy.insert(xy.end(), {p.x, p.y});
        const pyb::ssize_t n = pyb::ssize_t(s.points.size());
        out.append(pyb::dict("points"_a = to_array(std::move(xy), {n, 2}),
                             "widths"_a = to_array(std::vector<float>(s.widths), {pyb::ssize_t(s.widths.size())}),
                             "color"_a = pyb::make_tuple(s.color.r, s.color.g, s.color.b), "closed"_a = s.closed));
    }
    return out;
}

template <typename T>
pyb::array_t<T> vector_array(std::vector<T> v) {
    const pyb::ssize_t n = pyb::ssize_t(v.size());
    return to_array(std::move(v), {n});
}

// ---- Stroke patterns --------------------------------------------------------------------

// The command line's load_frame: a path, or a region (a polygon of at least three points).
PatternFrame frame_argument(const pyb::handle& value, const std::string& name, bool along_path, bool closed,
                            std::string* where) {
    PatternFrame f;
    f.along_path = along_path;
    f.curve = curve_argument(value, name, where);
    if (along_path) {
        f.curve.closed = f.curve.closed || closed;
    } else {
        if (f.curve.points.size() < 3) throw pyb::value_error(*where + ": a region needs at least three points");
        f.curve.closed = true;
    }
    if (naming_input(*where, [&] { return frame_measure(f); }) <= 0.0f)
        throw pyb::value_error(*where + (along_path ? ": the path has no length" : ": the region has no area"));
    return f;
}

pyb::object pattern(const pyb::object& reference, const pyb::object& path, const pyb::object& region,
                    const pyb::object& ref_path, const pyb::object& ref_region, bool closed, std::optional<float> scale,
                    std::optional<int> rings, float variation, const std::string& fit, int lloyd, const pyb::object& seed,
                    bool return_info) {
    const bool along_path = !path.is_none();
    if (along_path == !region.is_none()) throw pyb::value_error("give exactly one of path and region");
    if (!ref_path.is_none() && !along_path) throw pyb::value_error("ref_path goes with path (use ref_region with region)");
    if (!ref_region.is_none() && along_path) throw pyb::value_error("ref_region goes with region (use ref_path with path)");
    if (scale) check_positive(*scale, "scale");
    if (rings) check_range(*rings, 1, 12, "rings");
    check_range(variation, 0, 1, "variation");
    if (fit != "skeleton" && fit != "contour")
        throw pyb::value_error("fit: expected skeleton or contour, got \"" + fit + "\"");
    check_range(lloyd, 0, 1000, "lloyd");

    std::string reference_where, target_where, ref_frame_where;
    std::vector<Stroke> strokes = strokes_argument(reference, "reference", &reference_where);
    const PatternFrame target = frame_argument(along_path ? path : region, along_path ? "path" : "region", along_path,
                                               closed, &target_where);
    const pyb::object& ref_frame_value = along_path ? ref_path : ref_region;
    const PatternFrame ref_frame =
        ref_frame_value.is_none()
            ? bounding_frame(strokes, along_path)
            : frame_argument(ref_frame_value, along_path ? "ref_path" : "ref_region", along_path, false, &ref_frame_where);

    PatternDesc desc;
    desc.epsilon = scale.value_or(0.0f);
    desc.fit = fit == "skeleton" ? FitMode::Skeleton : FitMode::Contour;
    desc.rings = rings.value_or(0);
    desc.variation = variation;
    desc.seed = seed_argument(seed);
    desc.lloyd_iterations = lloyd;
    PatternSynthesis s;
    size_t elements = 0;
    float epsilon = 0.0f;
    std::string warning;
    {
        const pyb::gil_scoped_release released;
        const PatternAnalysis ref =
            naming_input(reference_where, [&] { return analyze_pattern(std::move(strokes), ref_frame, desc); });
        elements = ref.elements.size();
        epsilon = ref.epsilon;
        warning = pattern_analysis_warning(ref);
        s = naming_input(target_where, [&] { return synthesize_pattern(ref, target, desc); });
    }
    if (!warning.empty()) warn_in_python(reference_where + ": " + warning);
    pyb::list out = strokes_value(s.strokes.strokes);
    if (!return_info) return out;
    std::vector<float> centers;
    for (const glm::vec2& c : s.centers) centers.insert(centers.end(), {c.x, c.y});
    std::vector<int64_t> first(s.first_stroke.begin(), s.first_stroke.end());
    const pyb::dict info("reference_elements"_a = elements, "epsilon"_a = epsilon, "rings"_a = s.rings,
                         "matched"_a = s.matched, "fallback"_a = s.fallback, "source"_a = vector_array(s.source),
                         "centers"_a = to_array(std::move(centers), {pyb::ssize_t(s.centers.size()), 2}),
                         "first_stroke"_a = vector_array(std::move(first)), "lloyd_ms"_a = s.lloyd_ms,
                         "match_ms"_a = s.match_ms, "total_ms"_a = s.total_ms);
    return pyb::make_tuple(out, info);
}

// ---- Hatching ---------------------------------------------------------------------------

pyb::object hatch(const pyb::object& training, int count, int window, int block, std::optional<double> threshold,
                  float plausible, const pyb::object& along, const pyb::object& seed, bool return_info) {
    check_range(count, 1, 1000000, "count");
    check_range(window, 1, 1000, "window");
    check_range(block, 2, 100000, "block");
    if (threshold) check_range(*threshold, 0.0, 1e9, "threshold");
    check_range(plausible, 1e-6, 1.0, "plausible");

    std::string training_where;
    std::vector<Stroke> training_strokes = strokes_argument(training, "training", &training_where);
    const HatchTraining t = naming_input(training_where, [&] { return make_training(std::move(training_strokes)); });
    if (window >= int(t.strokes.size()))
        throw pyb::value_error("window: " + std::to_string(window) + " must be smaller than the training size (" +
                               std::to_string(t.strokes.size()) + " strokes in " + training_where + "): give window=" +
                               std::to_string(int(t.strokes.size()) - 1) + " or less");
    std::vector<ArclengthCurve> paths;
    if (!along.is_none()) {
        std::string along_where;
        const std::vector<Stroke> along_strokes = strokes_argument(along, "along", &along_where);
        if (along_strokes.empty()) throw pyb::value_error("along: no strokes");  // as `--along` of an empty file
        paths = naming_input(along_where, [&] { return hatch_paths(along_strokes); });
    }

    HatchDesc desc;
    desc.count = count;
    desc.window = window;
    desc.block = block;
    desc.threshold = threshold.value_or(-1.0);
    desc.plausible = plausible;
    // As the command line: one generator for every path; blocks numbered across paths.
    Rng rng(seed_argument(seed));
    size_t restarts = 0;
    std::vector<HatchBlock> kept;
    auto report = [&](const HatchBlock& b, bool is_kept) {
        if (is_kept) kept.push_back(b);
        else ++restarts;
    };
    Hatching h;
    {
        const pyb::gil_scoped_release released;
        h = hatch(t, desc, paths, rng, report);
    }
    const std::vector<Stroke>& out = h.strokes;
    const double used_threshold = h.threshold;
    pyb::list strokes = strokes_value(out);
    if (!return_info) return strokes;
    pyb::list blocks;
    size_t over = 0;
    for (const HatchBlock& b : kept) {
        over += b.over_threshold ? 1 : 0;
        blocks.append(pyb::dict("index"_a = b.index, "first"_a = b.first, "last"_a = b.last, "window"_a = b.window,
                                "kl2"_a = b.kl2, "attempts"_a = b.attempts, "over_threshold"_a = b.over_threshold,
                                "threshold"_a = b.threshold));
    }
    const pyb::dict info("blocks"_a = blocks, "restarts"_a = restarts, "over_threshold"_a = over,
                         "threshold"_a = used_threshold, "training_strokes"_a = t.strokes.size(),
                         "dimensions"_a = t.vectors.dim);
    return pyb::make_tuple(strokes, info);
}

}  // namespace

void bind_stroke_synthesizers(pyb::module_& m) {
    m.def("pattern", &pattern, "reference"_a, pyb::kw_only(), "path"_a = pyb::none(), "region"_a = pyb::none(),
          "ref_path"_a = pyb::none(), "ref_region"_a = pyb::none(), "closed"_a = false, "scale"_a = pyb::none(),
          "rings"_a = pyb::none(), "variation"_a = 0.0f, "fit"_a = "contour", "lloyd"_a = 30, "seed"_a = int64_t(1),
          "return_info"_a = false,
          R"(A stroke pattern like a reference, synthesized along a path (1D) or in a region (2D)
(Barla, Breslav, Thollot, Sillion & Markosian 2006), as `linework pattern` makes it. The
reference's strokes are grouped into elements at scale ε (proximity and continuation of their
PCA boxes); the elements' arrangement (a chain, or a Delaunay triangulation of unskewed
triangles) is measured; the target is seeded by Lloyd's method and filled from its centre
outward, each seed taking a reference element whose k-ring neighbourhood matches the elements
already placed.

reference: the reference strokes: a list of N×2 arrays or of stroke dicts ("points", "width"
  or "widths", "color", "closed"), or a stroke file (SVG or JSON).
path: synthesize along this path: N×2 points or a curve file (JSON or SVG). region:
  synthesize inside this polygon (N ≥ 3 points, or a curve file). Give exactly one.
ref_path / ref_region: the reference's own path or region (default: the long midline of its
  bounding box, or the box).
closed: close the path given as points.
scale: ε, drawing units (default: twice the median stroke width).
rings: k, neighbourhood size in graph steps, 1–12 (default 3 along a path, 2 in a region).
variation: v in [0, 1]: vary orientation, length, width and position (§3.3).
fit: 'contour' (boxes include the widths) or 'skeleton'. lloyd: Lloyd iterations (0–1000).
seed: seed of the random choices.

Returns the synthesized strokes as a list of dicts {"points": N×2 float32, "widths": N float32,
"color": (r, g, b), "closed": bool} — the strokes `linework pattern` writes; with return_info,
(strokes, info), info holding reference_elements, epsilon, rings, matched, fallback, source
(per target element, the reference element it copies), centers (M×2), first_stroke (element
e owns strokes first_stroke[e] to first_stroke[e + 1]) and timings.)");
    m.def("hatch", &hatch, "training"_a, pyb::kw_only(), "count"_a, "window"_a = 6, "block"_a = 50,
          "threshold"_a = pyb::none(), "plausible"_a = 0.5f, "along"_a = pyb::none(), "seed"_a = int64_t(1),
          "return_info"_a = false,
          R"(Continues a hand-drawn hatching sequence by example (Jodoin, Epstein, Granger-Piché &
Ostromoukhov 2002), as `linework hatch` does. Each next stroke is copied from the training
strokes whose N − 1 predecessors resemble the last N − 1 strokes drawn (an N-gram with a Gibbs
probability and a random pick among the plausible ones). The sequence is made in blocks; a
block whose KL2 divergence from the training passes the threshold is made again with a
window larger by 2.

training: training strokes in drawing order (a list of N×2 arrays or stroke dicts, or a stroke
  file), at least 3.
count: strokes to generate (1–1000000; with along: at most this many per path).
window: N, the N-gram window (1–1000, smaller than the training).
block: strokes per KL2 block (2–100000).
threshold: KL2 above which a block is made again (0: never; default: 3 × the median KL2 of
  blocks drawn from the training at random).
plausible: c in (0, 1]: strokes whose Gibbs probability is at least c times the best.
along: lay one sequence along each of these paths (strokes, or a stroke file), turned with
  the path (the paper's Fig. 8).
seed: seed of the random picks.

Returns the generated strokes as stroke dicts (see linework.pattern) — the strokes
`linework hatch` writes; with return_info, (strokes, info), info holding blocks (one dict per
kept block: index, first, last, window, kl2, attempts, over_threshold, as --kl2 prints, and
threshold, the block's own: a shorter last block has one of its size), restarts (blocks made
again), over_threshold, threshold (the full blocks'), training_strokes and
dimensions (varying vector dimensions).)");
}

}  // namespace lw::py
