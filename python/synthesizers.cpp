// python/synthesizers.cpp — the synthesizers that make images and SLAMs: linework.slam,
// slam_pattern, read_slam, write_slam (Bénard et al. 2010), linework.ribbon and
// ribbon_exemplar (Zhou et al. 2013). Each makes the engine calls its command does
// (tools/linework/slam_command.cpp, slam_pattern_command.cpp, ribbon_command.cpp), with the
// same defaults, so that the arrays returned equal the files the command writes.
// The stroke synthesizers (pattern, hatch) are in synthesizers_2d.cpp.
#include "synthesizers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <tuple>

#include "core/text.h"
#include "core/image.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "ribbon/avoidance.h"
#include "ribbon/dp.h"
#include "ribbon/exemplar.h"
#include "ribbon/exemplar_gen.h"
#include "ribbon/problem.h"
#include "ribbon/synthesize.h"
#include "slam_synth/slam_builder.h"
#include "stroke/slam.h"

namespace lw::py {

using namespace pybind11::literals;

std::optional<std::string> file_path(const pyb::handle& value) {
    if (!pyb::isinstance<pyb::str>(value) && !pyb::hasattr(value, "__fspath__")) return std::nullopt;
    const pyb::object path = pyb::module_::import("os").attr("fspath")(value);
    if (!pyb::isinstance<pyb::str>(path)) throw pyb::value_error("expected a str path, got bytes");
    return path.cast<std::string>();
}

Curve2D curve_argument(const pyb::handle& value, const std::string& name, std::string* where) {
    if (const std::optional<std::string> path = file_path(value)) {
        *where = *path;
        return reading_input([&] { return load_curve(*path); });
    }
    *where = name;
    const pyb::array a = pyb::array::ensure(value);
    if (!a) throw pyb::value_error(name + ": expected an N×2 array of points or a curve file");
    Curve2D curve{.points = array_to_vec2(a, name)};
    for (const glm::vec2& p : curve.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 1e6f || std::abs(p.y) > 1e6f)
            throw pyb::value_error(name + ": coordinates must be finite and within ±1e6");
    return curve;
}

void check_range(double value, double lo, double hi, const char* name) {
    if (!(value >= lo && value <= hi))
        throw pyb::value_error(std::string(name) + ": " + number_text(value) + " is not in the range " + number_text(lo) +
                               " to " + number_text(hi));
}

uint64_t seed_argument(const pyb::object& seed, uint64_t max) {
    // Any integer, NumPy's included (operator.index), but not a bool or a float.
    if (PyBool_Check(seed.ptr()) || !PyIndex_Check(seed.ptr()))
        throw pyb::type_error("seed: expected a whole number, got " +
                              pyb::str(pyb::type::handle_of(seed).attr("__name__")).cast<std::string>());
    const auto value = pyb::reinterpret_steal<pyb::int_>(PyNumber_Index(seed.ptr()));
    if (!value) throw pyb::error_already_set();
    if (value < pyb::int_(0) || value > pyb::int_(max))
        throw pyb::value_error("seed: must be a whole number from 0 to " + std::to_string(max) + ", got " +
                               pyb::str(static_cast<const pyb::handle&>(value)).cast<std::string>());
    return value.cast<uint64_t>();
}

void check_positive(double value, const char* name) {
    if (!(value > 0.0) || std::isinf(value))
        throw pyb::value_error(std::string(name) + ": must be a positive number, got " + number_text(value));
}

void check_image_size(int width, int height) {
    if (width < 1 || height < 1 || width > kLargestImageSide || height > kLargestImageSide) {
        const std::string side = std::to_string(kLargestImageSide);
        throw pyb::value_error("size: must be between 1x1 and " + side + "x" + side + ", got (" + std::to_string(width) +
                               ", " + std::to_string(height) + ")");
    }
}

namespace {

// ---- SLAMs ------------------------------------------------------------------------------

pyb::array_t<float> slam_array(Slam&& slam) {
    const pyb::ssize_t levels = slam.levels, height = slam.height, length = slam.length;
    return to_array(std::move(slam.ink), {levels, height, length});
}

// An image file (read as the command line reads it) or an H×W(×3/×4) uint8 array; `where`
// gets the name its errors go under (the file, or "exemplar").
ImageRGBA8 exemplar_argument(const pyb::handle& value, std::string* where) {
    if (const std::optional<std::string> path = file_path(value)) {
        *where = *path;
        return reading_input([&] { return read_image_rgba8(*path); });
    }
    *where = "exemplar";
    const pyb::array a = pyb::array::ensure(value);
    if (!a) throw pyb::value_error("exemplar: expected an H×W, H×W×3 or H×W×4 uint8 image, or an image file");
    return array_to_image(a, "exemplar");
}

pyb::array_t<float> slam(const pyb::object& exemplar, int levels, int length, int iterations, const pyb::object& seed,
                         bool global_statistics, int threads) {
    check_range(levels, 2, 256, "levels");
    check_range(length, 16, 16384, "length");
    check_range(iterations, 1, 1000, "iterations");
    check_range(threads, 0, 256, "threads");
    std::string where;
    const synth::Plane ink = synth::exemplar_ink(exemplar_argument(exemplar, &where));
    const synth::SlamSynthesisDesc desc{
        .levels = levels,
        .length = length,
        .iterations = iterations,
        .seed = uint32_t(seed_argument(seed, UINT32_MAX)),
        .scope = global_statistics ? synth::StatisticsScope::Global : synth::StatisticsScope::Rows,
        .threads = threads,
        .exemplar_name = where,
        .on_level = {}};
    // The exemplar's problems name it (ValueError); the length's and the levels' the argument.
    Slam out = reading_input([&] {
        return arguments_named({{"SLAM length", "length"}, {"SLAM levels", "levels"}}, [&] {
            const pyb::gil_scoped_release released;
            return std::move(synth::synthesize_slam(ink, desc).slam);
        });
    });
    return slam_array(std::move(out));
}

pyb::array_t<float> slam_pattern(const std::string& name, int levels, int length, int height, const pyb::object& seed) {
    if (name != "dots" && name != "dashes" && name != "pencil")
        throw pyb::value_error("name: expected dots, dashes or pencil, got \"" + name + "\"");
    check_range(levels, 2, 256, "levels");
    check_range(length, 16, 16384, "length");
    check_range(height, 1, 1024, "height");
    if (length % 2 != 0) throw pyb::value_error("length: must be even (level 0.5 is half of it)");
    const SlamPattern pattern = name == "dots"     ? SlamPattern::Dots
                                : name == "dashes" ? SlamPattern::Dashes
                                                   : SlamPattern::Pencil;
    return slam_array(make_procedural_slam(pattern, levels, length, height, uint32_t(seed_argument(seed, UINT32_MAX))));
}

pyb::array_t<float> read_slam_file(const std::filesystem::path& path) {
    return slam_array(reading_input([&] { return read_slam(path); }));
}

void write_slam_file(const std::filesystem::path& path, const pyb::array& ink, const std::string& exemplar_name,
                     const pyb::object& seed) {
    if (path.extension() != ".exr") throw pyb::value_error("path: " + path.string() + ": a SLAM file is OpenEXR (.exr)");
    check_output_folder(path);
    const auto a = pyb::array_t<float, pyb::array::c_style | pyb::array::forcecast>::ensure(ink);
    if (!a || a.ndim() != 3) throw pyb::value_error("ink: expected a float array of shape (levels, height, length)");
    if (a.shape(0) < 2 || a.shape(1) < 1 || a.shape(2) < 1)
        throw pyb::value_error("ink: a SLAM needs at least 2 levels and one texel per level");
    Slam slam{.levels = int(a.shape(0)), .length = int(a.shape(2)), .height = int(a.shape(1)),
              .ink = std::vector<float>(a.data(), a.data() + a.size()), .exemplar = exemplar_name,
              .seed = uint32_t(seed_argument(seed, UINT32_MAX))};
    for (float v : slam.ink)
        if (!(v >= 0.0f && v <= 1.0f)) throw pyb::value_error("ink: values must lie in [0, 1]");
    write_slam(path, slam);
}

// ---- Ribbons ----------------------------------------------------------------------------

// Over white unless the background should stay transparent: what `linework ribbon` writes.
ImageRGBA8 composite(ImageRGBA8&& image, bool transparent) {
    if (!transparent) composite_over_white(image);
    return std::move(image);
}

template <typename T>
pyb::array_t<T> vector_array(const std::vector<T>& v) {
    return to_array(std::vector<T>(v), {pyb::ssize_t(v.size())});
}

pyb::dict ribbon_info(const RibbonSynthesis& s, const RibbonSynthesisDesc& desc, const Context& ctx) {
    std::vector<int32_t> positions;
    for (const glm::ivec2& u : s.solution.positions) positions.insert(positions.end(), {u.x, u.y});
    const LooserRows looser = looser_rows(s.solution);
    pyb::list empty = pyb::cast(looser.empty), cut = pyb::cast(looser.cut);
    pyb::dict info("device"_a = ctx.info().describe(), "width"_a = desc.params.width, "piece"_a = desc.params.piece,
                   "scale"_a = desc.params.scale, "size"_a = pyb::make_tuple(desc.width, desc.height),
                   "pieces"_a = s.solution.positions.size(),
                   "positions"_a = to_array(std::move(positions), {pyb::ssize_t(s.solution.positions.size()), 2}),
                   "seam_costs"_a = vector_array(s.solution.seam_costs), "total_cost"_a = s.solution.total_cost,
                   "greedy_cost"_a = s.greedy_cost, "random_cost"_a = s.random_cost,
                   "valid_counts"_a = vector_array(s.solution.valid_counts), "row_ms"_a = vector_array(s.solution.row_ms),
                   "empty_pieces"_a = empty, "cut_pieces"_a = cut, "forbidden"_a = s.forbidden.count(),
                   "closed"_a = s.ribbon.closed, "closed_by_first_dp"_a = s.solution.closed_by_first_dp,
                   "dp_ms"_a = s.dp_ms, "stitch_ms"_a = s.stitch_ms);
    if (s.stitch) {
        info["stitch_before"] = s.stitch->total_before();
        info["stitch_after"] = s.stitch->total_after();
    }
    return info;
}

// The engine's names of the ribbon's parameters → the Python arguments.
constexpr std::initializer_list<std::pair<const char*, const char*>> kRibbonNames = {
    {"ribbon width", "width"}, {"ribbon piece", "piece"}, {"ribbon scale", "scale"}, {"ribbon size", "size"},
    {"device", "device"}};

pyb::object ribbon(const pyb::object& exemplar_value, const pyb::object& curve_value, bool closed,
                   std::optional<float> piece, std::optional<float> width, std::optional<float> scale, const pyb::object& seed,
                   bool stitch, std::optional<std::tuple<int, int>> size_value, const pyb::object& avoid,
                   bool transparent, bool reference, const std::string& device, bool return_info) {
    // Arguments first, then the inputs, as the command line does.
    if (piece) check_positive(*piece, "piece");
    if (width) check_positive(*width, "width");
    if (scale) check_positive(*scale, "scale");
    std::optional<glm::ivec2> size;
    if (size_value) {
        size = glm::ivec2(std::get<0>(*size_value), std::get<1>(*size_value));
        check_image_size(size->x, size->y);
    }
    (void)arguments_named(kRibbonNames, [&] { return parse_device_choice(device); });

    std::string exemplar_where, curve_where;
    const ImageRGBA8 image = exemplar_argument(exemplar_value, &exemplar_where);
    const Exemplar exemplar =
        with_python_warnings([&] { return reading_input([&] { return make_exemplar(image, exemplar_where); }); });
    Curve2D points = curve_argument(curve_value, "curve", &curve_where);
    points.closed = points.closed || closed;
    const ArclengthCurve curve = naming_input(curve_where, [&] { return ArclengthCurve(points); });

    RibbonSynthesisDesc desc;
    desc.params.scale = scale.value_or(default_ribbon_scale(exemplar));
    desc.params.width = width.value_or(desc.params.scale);
    desc.params.piece = piece.value_or(std::max(1.0f, std::round(desc.params.width / 2.0f)));
    desc.seed = seed_argument(seed);
    desc.stitch = stitch;
    if (reference) desc.site = ComputeSite::Host;  // else the device's choice: the host on CPU devices
    const Ribbon built = arguments_named(kRibbonNames, [&] { return build_ribbon(curve, desc.params); });
    if (!size)
        size = reading_input([&] { return default_ribbon_size(built, points.page, curve_where); });
    else
        arguments_named(kRibbonNames, [&] { check_ribbon_in_image(built, size->x, size->y); });
    desc.width = size->x;
    desc.height = size->y;
    ForbiddenMask user;
    if (!avoid.is_none()) {
        std::string avoid_where = "avoid";
        ImageRGBA8 map;
        if (const std::optional<std::string> path = file_path(avoid)) {
            avoid_where = *path;
            map = reading_input([&] { return read_image_rgba8(*path); });
        } else {
            map = array_to_image(pyb::array::ensure(avoid), "avoid");
        }
        user = forbidden_from_image(map);
        if (user.width != size->x || user.height != size->y)
            throw pyb::value_error(avoid_where + ": the avoidance map is " + std::to_string(user.width) + "x" +
                                   std::to_string(user.height) + " but the output is " + std::to_string(size->x) + "x" +
                                   std::to_string(size->y));
        desc.user_forbidden = &user;
    }

    const std::shared_ptr<Context> ctx = shared_context(device);
    RibbonSynthesis s = arguments_named(kRibbonNames, [&] {
        const pyb::gil_scoped_release released;
        const std::lock_guard lock(gpu_mutex());
        return synthesize_ribbon(*ctx, exemplar, curve, desc);
    });
    check_validation(*ctx);

    const LooserRows looser = looser_rows(s.solution);
    const size_t cut = looser.cut.size(), empty = looser.empty.size();
    if (const std::optional<std::string> blank = blank_ribbon_reason(s.solution, user.pixels.empty() ? "" : "`avoid`"))
        throw pyb::value_error("curve: " + *blank);
    if (empty > 0) {  // as the command prints it
        const std::string warning = std::to_string(empty) + " of " + std::to_string(s.solution.rules.size()) +
                                    " pieces lie where no ink can avoid the overlap and are left empty "
                                    "(info['empty_pieces'])";
        warn_in_python(warning, PyExc_RuntimeWarning);
    }
    if (cut > 0) {
        const std::optional<ScaleShortfall> shortfall = scale_shortfall(exemplar, s.ribbon.scale);
        const std::string pieces = std::to_string(cut) + " of " + std::to_string(s.solution.rules.size()) + " pieces";
        const std::string warning =
            shortfall ? pieces + " cannot hold the whole pattern and may cut it (info['cut_pieces']): scale " +
                            number_text(s.ribbon.scale) + " is too small for the pattern's " +
                            std::to_string(shortfall->band_rows) + " rows and one above and below (scale " +
                            std::to_string(shortfall->least_scale) + " holds them); leave scale out for the default, " +
                            number_text(shortfall->default_scale)
                : pieces + " cannot hold the whole pattern where the curve bends this tightly and may cut it "
                           "(info['cut_pieces']); a shorter piece or a wider scale helps";
        warn_in_python(warning, PyExc_RuntimeWarning);
    }
    pyb::dict info = return_info ? ribbon_info(s, desc, *ctx) : pyb::dict();
    pyb::array_t<uint8_t> out = image_to_array(composite(std::move(s.image), transparent));
    if (!return_info) return out;
    return pyb::make_tuple(out, info);
}

pyb::array_t<uint8_t> ribbon_exemplar(const std::string& name, int width, int height, const pyb::object& seed) {
    const std::vector<std::string>& names = exemplar_names();
    if (std::find(names.begin(), names.end(), name) == names.end())
        throw pyb::value_error("name: unknown exemplar \"" + name + "\" (chain, lace, zigzag, beads or rope)");
    if (width < 16 || height < 16 || width > 4096 || height > 4096)
        throw pyb::value_error("width, height: the exemplar size must be between 16x16 and 4096x4096");
    return image_to_array(generate_exemplar(name, width, height, seed_argument(seed)));
}

}  // namespace

void bind_synthesizers(pyb::module_& m) {
    m.def("slam", &slam, "exemplar"_a, pyb::kw_only(), "levels"_a = 17, "length"_a = 1024, "iterations"_a = 15,
          "seed"_a = int64_t(1), "global_statistics"_a = false, "threads"_a = 0,
          R"(A self-similar line artmap (SLAM) synthesized from one stroke exemplar (Bénard et al. 2010,
§3.2), as `linework slam` makes it. Each level A_l, l = 0.5 … 1, is a Portilla–Simoncelli
texture synthesized at length l·Lmax from a seed W_l of a seed pyramid built so that
A_1.0 = [A_0.5 A_0.5] and adjacent levels differ little. Rows across the stroke keep the
exemplar's mean and variance (1.5D) unless global_statistics.

exemplar: H×W, H×W×3 or H×W×4 uint8 image (or an image file path), H = 4–64 rows across the
  stroke; its alpha is the ink when any pixel is translucent, else 1 − luminance.
levels: levels from 0.5 to 1.0 (2–256).
length: Lmax, texels of level 1.0 and of every stored level (16–16384; a multiple of twice the
  pyramid unit, 64 for a 32-row exemplar).
iterations: synthesis iterations per level (1–1000).
seed: seed of the white noise W_source.
global_statistics: impose every statistic per texture (the 1D model).
threads: levels synthesized in parallel (0: one per core).

Returns float32 ink in [0, 1] of shape (levels, H, length), [level][row][x], levels ordered
0.5 … 1.0: what `linework slam` writes (write it with linework.write_slam).
Raises ValueError for a bad argument or exemplar, with the command line's message.)");
    m.def("slam_pattern", &slam_pattern, "name"_a, pyb::kw_only(), "levels"_a = 17, "length"_a = 1024, "height"_a = 32,
          "seed"_a = int64_t(1),
          R"(A procedural, exactly self-similar SLAM as `linework slam-pattern` writes it: a periodic
pattern P at level 0.5, P(2u) at level 1.0, and between them, for dots and dashes, whole
elements (each element of level 0.5 moves to its place in P(2u), the others grow from
nothing, linearly in α = 2l − 1); pencil's grain is blended, A_l = (1 − α)·P(u) + α·P(2u).

name: 'dots', 'dashes' or 'pencil'. levels: 2–256. length: texels along the stroke (16–16384,
even). height: texels across (1–1024). seed: jitter of the elements' sizes and positions.
Returns float32 ink of shape (levels, height, length).)");
    m.def("read_slam", &read_slam_file, "path"_a,
          R"(Reads a SLAM file (multi-part OpenEXR, engine/io/slam_io.h) as float32 ink of shape
(levels, height, length), levels ordered 0.5 … 1.0. Raises ValueError naming the file for a
missing or malformed one.)");
    m.def("write_slam", &write_slam_file, "path"_a, "ink"_a, pyb::kw_only(), "exemplar_name"_a = "python",
          "seed"_a = int64_t(0),
          R"(Writes ink of shape (levels ≥ 2, height, length), values in [0, 1], as a SLAM file (.exr) that
scene files can name as a style's "slam"; exemplar_name and seed go into its metadata.)");
    m.def("ribbon", &ribbon, "exemplar"_a, "curve"_a, pyb::kw_only(), "closed"_a = false, "piece"_a = pyb::none(),
          "width"_a = pyb::none(), "scale"_a = pyb::none(), "seed"_a = int64_t(1), "stitch"_a = false,
          "size"_a = pyb::none(), "avoid"_a = pyb::none(), "transparent"_a = false, "reference"_a = false,
          "device"_a = "auto", "return_info"_a = false,
          R"(A structured pattern synthesized along a curve (Zhou, Lasram & Lefebvre 2013), as
`linework ribbon` makes it. The ribbon of width b around the curve is cut into pieces of
length δ; each piece copies a part of the exemplar (rotated to follow the curve, never
stretched), chosen by dynamic programming (on the host on CPU devices such as lavapipe, else on the GPU) so that
neighbouring pieces match along their shared edge; where the ribbon folds over or overlaps
itself the pattern is kept out.

exemplar: H×W×4 uint8 image (or an image file): alpha ≥ 128 is the pattern.
curve: N×2 float points in output pixels (x right, y down), or a curve file (JSON or SVG).
closed: close the curve (the last piece connects back to the first, §1.5).
piece: δ, output pixels (default: b / 2). width: b, output pixels (default: scale).
scale: s, exemplar pixels across the ribbon (default: the exemplar's band of opaque rows
  + 2 + 30 %).
seed: breaks ties among equally cheap results (rare but for periodic exemplars along straight
stretches), and draws the random baseline.
stitch: deform pieces so that their edges align better (§3.2, P = 32).
size: output (width, height) (default: the ribbon's extent from the origin, and at least an SVG curve's page).
avoid: H×W(×4) uint8 avoidance map of the output size (or a PNG): alpha ≥ 128 is forbidden (§3.1).
transparent: keep the transparent background (default: composited over white).
reference: run the DP and stitching with the plain C++ reference whatever the device.
device: 'auto', 'cpu' (lavapipe), 'gpu' or a device index.

Returns the H×W×4 uint8 image `linework ribbon` writes to its PNG; with return_info, a tuple
(image, info): info holds what --dump-dp writes (pieces, positions (rows×2 int32),
seam_costs, total_cost, greedy_cost, random_cost, valid_counts, row_ms) and the width,
piece, scale and size used, empty_pieces and cut_pieces (rows whose validity rule was
loosened; cut pieces also raise a RuntimeWarning), forbidden (pixels avoided), closed,
closed_by_first_dp, dp_ms, stitch_ms, device, and with stitch stitch_before/stitch_after.
Raises ValueError naming the argument for bad values, RuntimeError for a failed run or a
validation message (LINEWORK_VALIDATION=1).)");
    m.def("ribbon_exemplar", &ribbon_exemplar, "name"_a, pyb::kw_only(), "width"_a = 192, "height"_a = 64,
          "seed"_a = int64_t(1),
          R"(A procedural structured-pattern exemplar for linework.ribbon, as `linework ribbon-exemplar`
writes it: 'chain', 'lace', 'zigzag', 'beads' or 'rope', drawn from signed distances with
sizes and spacings varied by seed; width and height 16–4096. Returns H×W×4 uint8 (straight
alpha; transparent pixels are black).)");
    bind_stroke_synthesizers(m);
}

}  // namespace lw::py
