// python/synthesizers.h — what the two synthesizer binding files share: synthesizers.cpp
// (SLAMs, ribbons; bind_synthesizers, declared in convert.h) and synthesizers_2d.cpp (stroke
// patterns, hatching), plus the argument checks both make the way the command line's flags do.
#pragma once

#include <optional>
#include <string>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "convert.h"
#include "vector/curve.h"

namespace lw::py {

// Binds linework.pattern and linework.hatch (synthesizers_2d.cpp); called by bind_synthesizers.
void bind_stroke_synthesizers(pyb::module_& m);

// A str or os.PathLike: the file's path (os.fspath); nullopt for anything else.
std::optional<std::string> file_path(const pyb::handle& value);

// A curve as `linework ribbon --curve` and `linework pattern --path` take it: a curve file
// (JSON or SVG, engine/vector/curve.h), or an N×2 array of points in output pixels. `name`
// is the argument; `where` gets the name its errors go under (the file, or the argument).
Curve2D curve_argument(const pyb::handle& value, const std::string& name, std::string* where);

// Runs f, whose engine errors are about the input named `where` (a file or an argument):
// they become ValueError with `where` in front unless the message starts with it already
// (tools/linework/commands.h, naming). ParameterErrors pass through for arguments_named.
template <typename F>
auto naming_input(const std::string& where, F&& f) {
    try {
        return f();
    } catch (const ParameterError&) {
        throw;
    } catch (const Error& e) {
        const std::string m = e.what();
        if (m.rfind(where, 0) == 0) throw pyb::value_error(m);
        throw pyb::value_error(where + ": " + m);
    }
}

// ValueError "NAME: V is not in the range LO to HI" (the command line's CLI::Range).
void check_range(double value, double lo, double hi, const char* name);
// ValueError "NAME: must be a positive number, got V" (CLI::PositiveNumber).
void check_positive(double value, const char* name);
// ValueError "size: must be between 1x1 and LxL, got (W, H)" past kLargestImageSide.
void check_image_size(int width, int height);
// A seed taken as a Python int: ValueError "seed: must be a whole number from 0 to MAX, got V"
// for a negative one or one past `max` (as an unsigned argument pybind11 gave a TypeError
// listing every signature), as the command line's --seed says.
uint64_t seed_argument(const pyb::object& seed, uint64_t max = UINT64_MAX);

}  // namespace lw::py
