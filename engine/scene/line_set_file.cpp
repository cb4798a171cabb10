// The "line_sets" key of scene files (README "Line sets"): Freestyle's line sets — a
// selection, a style with modifiers, coherence settings — read into `LineSetDesc`.
#include "scene/line_set_file.h"

#include <algorithm>
#include <cctype>
#include <numeric>

#include "core/text.h"
#include "scene/object_reader.h"

namespace lw {

using scene_detail::json;
using scene_detail::ObjectReader;

namespace {

std::vector<std::string> strings(ObjectReader& r, const std::string& key) {
    const json& v = r.at(key);
    if (!v.is_array()) r.fail_key(key, "expected an array of strings");
    std::vector<std::string> out;
    for (const json& item : v) {
        if (!item.is_string()) r.fail_key(key, "expected an array of strings");
        out.push_back(item.get<std::string>());
    }
    return out;
}

// "range": required for distance (scene units) and curvature (1/px), whose values have no
// scale a default could fit (a [0, 1] in scene units put every depth of a scene past it);
// refused for along, which is 0 to 1 along each path already.
std::pair<float, float> range(ObjectReader& r, ModifierInput input) {
    if (input == ModifierInput::Along) {
        // [0, 1] is what views saved before this rule wrote for every along modifier.
        if (r.has("range")) {
            const json& v = r.at("range");
            if (!(v.is_array() && v.size() == 2 && v[0] == 0 && v[1] == 1))
                r.fail_key("range", "along runs from 0 at a path's start to 1 at its end: no range applies");
        }
        return {0.0f, 1.0f};
    }
    if (!r.has("range"))
        r.fail_key("range", input == ModifierInput::Distance
                                ? "required for distance: [near, far], the eye depths (scene units) mapped to 0 and 1"
                                : "required for curvature: [min, max], the curvatures (1/px) mapped to 0 and 1");
    const json& v = r.at("range");
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
        !(v[1].get<double>() > v[0].get<double>()))
        r.fail_key("range", "expected [min, max] with max > min");
    return {v[0].get<float>(), v[1].get<float>()};
}

ModifierInput input(ObjectReader& r) {
    if (!r.has("input")) r.fail_key("input", "required: along, distance or curvature");
    const std::string s = r.string_of("input", {"along", "distance", "curvature"});
    return s == "along" ? ModifierInput::Along : s == "distance" ? ModifierInput::Distance : ModifierInput::Curvature;
}

// A ramp point's x: in [0, 1] and not below the point before it (`previous`, if any). The
// scalar and the colour ramps share it.
float ramp_x(ObjectReader& r, const json& value, const float* previous) {
    const float x = value.get<float>();
    if (!(x >= 0.0f && x <= 1.0f) || (previous && !(x >= *previous))) r.fail_key("ramp", "x must increase within [0, 1]");
    return x;
}

// "ramp": [[x, y], ...] with x increasing in [0, 1].
Ramp scalar_ramp(ObjectReader& r) {
    Ramp ramp;
    const json& v = r.at("ramp");
    if (!v.is_array() || v.empty()) r.fail_key("ramp", "expected [[x, value], ...]");
    for (const json& p : v) {
        if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
            r.fail_key("ramp", "expected [[x, value], ...] with numbers");
        const float x = ramp_x(r, p[0], ramp.points.empty() ? nullptr : &ramp.points.back().x);
        ramp.points.push_back({x, p[1].get<float>()});
    }
    return ramp;
}

std::vector<ScalarModifier> scalar_modifiers(ObjectReader& style, const std::string& key,
                                             const std::filesystem::path& file) {
    const json& list = style.at(key);
    if (!list.is_array()) style.fail_key(key, "expected an array of modifiers");
    std::vector<ScalarModifier> out;
    for (size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(list[i], style.path(key) + "[" + std::to_string(i) + "]", file);
        ScalarModifier m{.input = input(r)};
        std::tie(m.range_min, m.range_max) = range(r, m.input);
        if (!r.has("ramp")) r.fail_key("ramp", "required: [[x, value], ...]");
        m.ramp = scalar_ramp(r);
        if (r.has("blend")) {
            const std::string b = r.string_of("blend", {"multiply", "replace", "add"});
            m.blend = b == "multiply" ? ModifierBlend::Multiply : b == "replace" ? ModifierBlend::Replace : ModifierBlend::Add;
        }
        // A factor or value below 0 drew nothing, and an alpha replaced by more than 1 was
        // clamped, in silence. `add` may take some away; `multiply` may scale an alpha up (the
        // result is clamped once, after every modifier).
        const bool alpha = key == "alpha_modifiers";
        for (const glm::vec2& point : m.ramp.points) {
            if (m.blend != ModifierBlend::Add && point.y < 0.0f)
                r.fail_key("ramp", std::string(alpha ? "alphas" : "widths") + " are 0 or more, got " +
                                       number_text(point.y) + " (blend add takes values below 0)");
            if (alpha && m.blend == ModifierBlend::Replace && point.y > 1.0f)
                r.fail_key("ramp", "an alpha that replaces is in [0, 1], got " + number_text(point.y));
        }
        r.reject_unknown();
        out.push_back(std::move(m));
    }
    return out;
}

std::vector<ColorModifier> color_modifiers(ObjectReader& style, const std::filesystem::path& file) {
    const json& list = style.at("color_modifiers");
    if (!list.is_array()) style.fail_key("color_modifiers", "expected an array of modifiers");
    std::vector<ColorModifier> out;
    for (size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(list[i], style.path("color_modifiers") + "[" + std::to_string(i) + "]", file);
        ColorModifier m{.input = input(r)};
        std::tie(m.range_min, m.range_max) = range(r, m.input);
        if (!r.has("ramp")) r.fail_key("ramp", "required: [[x, [r, g, b]], ...]");
        if (!r.at("ramp").is_array()) r.fail_key("ramp", "expected [[x, [r, g, b]], ...]");
        for (const json& p : r.at("ramp")) {
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_array() || p[1].size() != 3)
                r.fail_key("ramp", "expected [[x, [r, g, b]], ...]");
            const float x = ramp_x(r, p[0], m.ramp.points.empty() ? nullptr : &m.ramp.points.back().first);
            glm::vec3 c(0.0f);
            for (int k = 0; k < 3; ++k) {
                if (!p[1][k].is_number()) r.fail_key("ramp", "colours are three numbers in [0, 1]");
                c[k] = p[1][k].get<float>();
                if (!(c[k] >= 0.0f && c[k] <= 1.0f)) r.fail_key("ramp", "colours are three numbers in [0, 1]");
            }
            m.ramp.points.push_back({x, c});
        }
        if (m.ramp.points.empty()) r.fail_key("ramp", "expected at least one point");
        if (r.has("influence")) m.influence = float(r.number("influence", 0.0, 1.0));
        // (Not a no-op even so: a set with modifiers is drawn as strokes, not as plain lines.)
        if (!(m.influence > 0.0f)) r.fail_key("influence", "0: the modifier would change nothing (leave it out)");
        r.reject_unknown();
        out.push_back(std::move(m));
    }
    return out;
}

std::vector<GeometryModifier> geometry_modifiers(ObjectReader& style, const std::filesystem::path& file) {
    const json& list = style.at("geometry");
    if (!list.is_array()) style.fail_key("geometry", "expected an array of modifiers");
    std::vector<GeometryModifier> out;
    using Kind = GeometryModifier::Kind;
    for (size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(list[i], style.path("geometry") + "[" + std::to_string(i) + "]", file);
        if (!r.has("kind")) r.fail_key("kind", "required");
        std::set<std::string> names;
        for (const GeometryKindKeys& g : kGeometryKinds) names.insert(g.name);
        const std::string k = r.string_of("kind", names);
        const GeometryKindKeys& kind =
            *std::find_if(kGeometryKinds.begin(), kGeometryKinds.end(), [&](const GeometryKindKeys& g) { return k == g.name; });
        GeometryModifier m{.kind = kind.kind};
        // Each kind's own keys (another kind's were taken and changed nothing). Another kind's
        // key at its default is what views saved before this rule wrote.
        const std::vector<std::string> own(kind.keys.begin(), kind.keys.begin() + std::ptrdiff_t(kind.count));
        const GeometryModifier defaults;
        for (const GeometryKindKeys& other : kGeometryKinds)
            for (size_t i = 0; i < other.count; ++i) {
                const char* key = other.keys[i];
                if (r.has(key) && std::find(own.begin(), own.end(), key) == own.end() &&
                    !(r.at(key).is_number() && r.at(key).get<double>() == geometry_key_value(defaults, key)))
                    r.fail_key(key, "is not a key of " + k + " (its keys: " +
                                        std::accumulate(std::next(own.begin()), own.end(), own.front(),
                                                        [](const std::string& a, const std::string& b) { return a + ", " + b; }) +
                                        ")");
            }
        if (r.has("wavelength")) m.wavelength_px = float(r.number("wavelength", 0.5, 1e5));
        if (r.has("amplitude")) m.amplitude_px = float(r.number("amplitude", 0.0, 1e4));
        if (r.has("phase")) m.phase = float(r.number("phase", -1e4, 1e4));
        if (r.has("seed")) m.seed = uint64_t(r.number("seed", 0, 4294967295.0));
        if (r.has("length")) m.length_px = float(r.number("length", 0.0, 1e5));
        if (r.has("tolerance")) m.tolerance_px = float(r.number("tolerance", 0.0, 1e4));
        r.reject_unknown();
        out.push_back(m);
    }
    return out;
}

LineSelection read_selection(ObjectReader& set, const std::filesystem::path& file) {
    LineSelection select;
    if (!set.has("select")) return select;
    ObjectReader r(set.at("select"), set.path("select"), file);
    if (r.has("types")) {
        select.types = 0;
        for (const std::string& name : strings(r, "types")) {
            const std::optional<LineType> type = line_type_from_name(name);
            if (!type) r.fail_key("types", "unknown line type \"" + name + "\" (" + line_type_names() + ")");
            select.types |= 1u << uint32_t(*type);
        }
        if (select.types == 0) r.fail_key("types", "selects no line type");
    }
    if (r.has("visibility")) {
        const std::string v = r.string_of("visibility", {"visible", "hidden", "any"});
        select.visibility = v == "visible" ? Visibility::Visible : v == "hidden" ? Visibility::Hidden : Visibility::Any;
    }
    if (r.has("qi")) {
        if (r.has("visibility")) r.fail_key("qi", "give either \"qi\" or \"visibility\", not both");
        const json& q = r.at("qi");
        const auto level = [](const json& v) { return v.is_number_integer() && v.get<int64_t>() >= 0 && v.get<int64_t>() <= 1000; };
        if (!q.is_array() || q.size() != 2 || !level(q[0]) || !level(q[1]) || q[0].get<int64_t>() > q[1].get<int64_t>())
            r.fail_key("qi", "expected [min, max]: occlusion levels 0 to 1000 (0 visible, 1 behind one surface), min <= max; "
                             "got " + q.dump());
        select.qi = LevelRange{q[0].get<uint32_t>(), q[1].get<uint32_t>()};
    }
    if (r.has("models")) select.models = strings(r, "models");
    if (r.has("materials")) select.materials = strings(r, "materials");
    r.reject_unknown();
    return select;
}

void read_shape(ObjectReader& r, LineSetStyle& style) {
    if (r.has("cap")) {
        const std::string c = r.string_of("cap", {"butt", "round", "square"});
        style.cap = c == "butt" ? Cap::Butt : c == "round" ? Cap::Round : Cap::Square;
    }
    if (r.has("join")) style.join = r.string_of("join", {"mitre", "round"}) == "round" ? Join::Round : Join::Mitre;
    if (r.has("taper")) style.taper_in_px = style.taper_out_px = float(r.number("taper", 0.0, 4096.0));
    if (r.has("taper_in")) style.taper_in_px = float(r.number("taper_in", 0.0, 4096.0));
    if (r.has("taper_out")) style.taper_out_px = float(r.number("taper_out", 0.0, 4096.0));
    if (r.has("dashes")) {
        const json& d = r.at("dashes");
        if (!d.is_array() || d.empty()) r.fail_key("dashes", "expected [dash, gap, ...] in pixels");
        float total = 0.0f;
        for (const json& v : d) {
            if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= 1e5))
                r.fail_key("dashes", "lengths are pixels, 0 to 100000");
            style.dashes.push_back(v.get<float>());
            total += style.dashes.back();
        }
        if (!(total > 0.0f)) r.fail_key("dashes", "the pattern has no length");
    }
}

// A ribbon set draws its exemplar along the paths (engine/ribbon): the stroke builder's keys
// change nothing there. Scenes written by earlier builds carry them at their defaults, which
// are not mentioned; the others are named as written.
void warn_stroke_keys_of_ribbon_set(ObjectReader& r, const LineSetStyle& style) {
    const LineSetStyle plain;
    std::string keys;
    const auto note = [&](bool differs, std::initializer_list<const char*> names) {
        if (!differs) return;
        for (const char* key : names)
            if (r.has(key)) keys += (keys.empty() ? "" : ", ") + std::string(key);
    };
    note(style.alpha != plain.alpha, {"alpha"});
    note(style.fade != plain.fade, {"fade"});
    note(style.cap != plain.cap, {"cap"});
    note(style.join != plain.join, {"join"});
    note(style.taper_in_px != plain.taper_in_px || style.taper_out_px != plain.taper_out_px,
         {"taper", "taper_in", "taper_out"});
    note(!style.dashes.empty(), {"dashes"});
    note(!style.width_modifiers.empty(), {"width_modifiers"});
    note(!style.alpha_modifiers.empty(), {"alpha_modifiers"});
    note(!style.color_modifiers.empty(), {"color_modifiers"});
    note(!style.geometry.empty(), {"geometry"});
    if (!keys.empty())
        r.warn(keys + ": a ribbon set draws its exemplar along the paths, and stroke keys change nothing there "
                      "(width and ribbon_scale size the ribbon; color colours the SVG's centre lines)");
}

LineSetStyle read_style(ObjectReader& set, const std::filesystem::path& file) {
    LineSetStyle style;
    if (!set.has("style")) return style;
    ObjectReader r(set.at("style"), set.path("style"), file);
    if (r.has("color")) style.color = r.color("color");
    if (r.has("alpha")) style.alpha = float(r.number("alpha", 0.0, 1.0));
    if (r.has("width")) style.width = float(r.number("width", 0.1, 256.0));
    if (r.has("fade")) style.fade = r.boolean("fade");
    if (r.has("slam")) style.slam = r.file_path("slam", "a SLAM file (.exr)");
    if (r.has("ribbon")) style.ribbon = r.file_path("ribbon", "a ribbon exemplar image (.png)");
    if (!style.slam.empty() && !style.ribbon.empty()) r.fail_key("ribbon", "a set is drawn with a SLAM or a ribbon, not both");
    if (r.has("ribbon_scale")) style.ribbon_scale = float(r.number("ribbon_scale", 1.0, 4096.0));
    if (r.has("ribbon_scale") && style.ribbon.empty())
        r.fail_key("ribbon_scale", "sizes a ribbon's exemplar, and this set has no \"ribbon\"");
    read_shape(r, style);
    if (!style.slam.empty()) style.cap = r.has("cap") ? style.cap : Cap::Butt;  // SLAM strokes end at their ends
    if (r.has("width_modifiers")) style.width_modifiers = scalar_modifiers(r, "width_modifiers", file);
    if (r.has("alpha_modifiers")) style.alpha_modifiers = scalar_modifiers(r, "alpha_modifiers", file);
    if (r.has("color_modifiers")) style.color_modifiers = color_modifiers(r, file);
    if (r.has("geometry")) style.geometry = geometry_modifiers(r, file);
    // As the renderer decides (it skips such a set): alpha 0 with no alpha modifier draws
    // nothing; with one (a fade-in) it may, and a ribbon does not read it.
    if (!(style.alpha > 0.0f) && style.alpha_modifiers.empty() && style.ribbon.empty())
        r.fail_key("alpha", "0 and no alpha_modifiers: the set would draw nothing");
    if (r.has("chaining")) {
        ObjectReader c(r.at("chaining"), r.path("chaining"), file);
        if (c.has("split_angle")) style.chaining.split_angle_deg = float(c.number("split_angle", 0.0, 180.0));
        if (c.has("min_length")) style.chaining.min_length_px = float(c.number("min_length", 0.0, 1e6));
        if (c.has("max_length")) style.chaining.max_length_px = float(c.number("max_length", 1.0, 1e6));
        if (c.has("outline")) style.chaining.outline = c.boolean("outline");
        // Runs are cut to max_length and then dropped under min_length: nothing would be drawn.
        if (style.chaining.max_length_px > 0.0f && style.chaining.min_length_px > style.chaining.max_length_px)
            c.fail_key("min_length", "is over max_length (" + number_text(style.chaining.max_length_px) +
                                         " px): every run would be cut shorter than it and dropped");
        c.reject_unknown();
    }
    r.reject_unknown();
    if (!style.ribbon.empty()) warn_stroke_keys_of_ribbon_set(r, style);
    return style;
}

LineSetCoherence read_coherence(ObjectReader& set, const std::filesystem::path& file) {
    LineSetCoherence coherence;
    if (!set.has("coherence")) return coherence;
    ObjectReader r(set.at("coherence"), set.path("coherence"), file);
    if (r.has("policy")) {
        coherence.policy = param_policy_named(r.string_of("policy", kParamPolicyNameSet));
    }
    if (r.has("length_scale"))
        coherence.length_scale = float(r.number("length_scale", kLengthScaleRange.min, kLengthScaleRange.max));
    if (r.has("sample_spacing")) coherence.sample_spacing_px = float(r.number("sample_spacing", 0.25, 64.0));
    r.reject_unknown();
    return coherence;
}

// Letters, digits, _ and -, not starting with a digit or -: an SVG (XML) id.
bool is_svg_id(const std::string& name) {
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

}  // namespace

std::vector<LineSetDesc> read_line_sets(scene_detail::ObjectReader& scene, const std::filesystem::path& file) {
    const json& list = scene.at("line_sets");
    if (!list.is_array() || list.empty()) scene.fail_key("line_sets", "expected a non-empty array of line sets");
    std::vector<LineSetDesc> sets;
    for (size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(list[i], "line_sets[" + std::to_string(i) + "]", file);
        LineSetDesc set;
        if (!r.has("name")) r.fail_key("name", "required (it names the set's SVG group and dump entries)");
        set.name = r.string_of("name");
        if (!is_svg_id(set.name)) r.fail_key("name", "letters, digits, _ and - (an SVG id), got \"" + set.name + "\"");
        // The SVG export names a set's hidden lines and centre lines NAME-hidden and NAME-centerlines.
        for (const std::string suffix : {"-hidden", "-centerlines"})
            if (set.name.size() > suffix.size() && set.name.ends_with(suffix))
                r.fail_key("name", "\"" + set.name + "\": names may not end in -hidden or -centerlines (the SVG's groups of a set)");
        for (const LineSetDesc& other : sets)
            if (other.name == set.name) r.fail_key("name", "\"" + set.name + "\" is used by an earlier set");
        if (r.has("enabled")) set.enabled = r.boolean("enabled");
        set.select = read_selection(r, file);
        set.style = read_style(r, file);
        // "fade" scales by the alpha extraction gives a line (rtsc's fades); the types without
        // one have alpha 1 throughout, and the key changed nothing for them, in silence.
        constexpr LineType kFaded[] = {LineType::Suggestive, LineType::SuggestiveHighlight, LineType::Ridge,
                                       LineType::Valley, LineType::ApparentRidge, LineType::PrincipalHighlight};
        if (r.has("style") && r.at("style").is_object() && r.at("style").contains("fade") &&
            std::none_of(std::begin(kFaded), std::end(kFaded), [&](LineType t) { return set.select.has_type(t); }))
            r.warn("style.fade: none of the set's types fades (suggestive contours and highlights, ridges, valleys "
                   "and apparent ridges do): it changes nothing");
        // Ribbons are synthesized along the visible runs only (the hidden ones were dropped).
        if (!set.style.ribbon.empty() && set.select.selects_hidden())
            r.fail_key("select", "a ribbon set draws visible lines only; select the hidden lines in a set of their "
                                 "own, with a stroke style");
        set.coherence = read_coherence(r, file);
        r.reject_unknown();
        sets.push_back(std::move(set));
    }
    return sets;
}

}  // namespace lw
