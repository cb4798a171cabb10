// python/convert.h — what every binding file of the `linework` module shares: NumPy arrays
// to and from the engine's images and point lists, the Vulkan contexts Python objects hold,
// and how engine errors become Python exceptions.
//
// Arrays out are zero-copy: a vector the engine filled is moved into a capsule that the
// array owns. Arrays in are read through pybind11's converting casts (any numeric dtype, any
// strides), checked for shape with a ValueError naming the argument.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/error.h"
#include "core/log.h"
#include "core/image.h"
#include "gpu/context.h"

namespace lw::py {

namespace pyb = pybind11;

// A vector moved into a NumPy array of `shape` without a copy (the array owns it).
template <typename T>
pyb::array_t<T> to_array(std::vector<T>&& data, std::vector<pyb::ssize_t> shape) {
    auto* owned = new std::vector<T>(std::move(data));
    pyb::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return pyb::array_t<T>(shape, owned->data(), free_when_done);
}

// H×W×4 uint8, rows top to bottom: the layout of the PNG `linework render` writes.
pyb::array_t<uint8_t> image_to_array(ImageRGBA8&& image);
// H×W×4 (or H×W×3, alpha 255; or H×W grey) uint8 → an image; `name` is the argument.
ImageRGBA8 array_to_image(const pyb::array& array, const std::string& name);
// N×3 (or N×2) float → points; `columns` is 3 or 2.
std::vector<glm::vec3> array_to_vec3(const pyb::array& array, const std::string& name);
std::vector<glm::vec2> array_to_vec2(const pyb::array& array, const std::string& name);
// M×3 non-negative integers, flattened.
std::vector<uint32_t> array_to_indices(const pyb::array& array, const std::string& name);
glm::vec3 to_vec3(const pyb::object& value, const std::string& name);

// One Vulkan context per (device, compute site, validation) while any Python object holds it:
// sessions and GPU synthesizers on the same device share it. `validation` absent: the
// LINEWORK_VALIDATION environment variable decides, as for the command line.
std::shared_ptr<Context> shared_context(const std::string& device, const std::string& compute = "auto",
                                        std::optional<bool> validation = std::nullopt);
// The module's GPU work takes turns: a Vulkan queue needs external synchronization, and the
// GIL is released around frames and syntheses so that other Python threads go on. Taken
// after the GIL is released (and released before it is taken back), so it cannot deadlock.
std::mutex& gpu_mutex();

// With validation on, a call that made the layer speak raises RuntimeError with its first
// message (the command line exits 1), and the messages are cleared.
void check_validation(Context& ctx);

// The message as valid UTF-8 (Python's text): bytes that are not (an error quoting a binary
// file's bytes) become '?', where pybind11 would otherwise raise with an empty message.
std::string printable(const std::string& message);

// ValueError "path: P: the folder F does not exist" for a file to write whose folder is missing,
// as the command line's -o says it (the writers' own messages differ: libpng's and OpenEXR's).
void check_output_folder(const std::filesystem::path& path);

// Runs f; an engine ParameterError about one of `names` (engine name → Python argument,
// e.g. {"ribbon piece", "piece"}) becomes a ValueError naming the argument, others keep
// the engine's name. Any other engine error is re-thrown as it is (RuntimeError).
template <typename F>
auto arguments_named(std::initializer_list<std::pair<const char*, const char*>> names, F&& f) {
    try {
        return f();
    } catch (const ParameterError& e) {
        for (const auto& [engine, argument] : names)
            if (e.name() == engine) throw pyb::value_error(printable(argument + e.rest()));
        throw pyb::value_error(printable(e.what()));
    }
}

// Runs f, which reads the user's input (a scene, a model, an exemplar): its engine errors are
// about that input and become ValueError, with the command line's message.
template <typename F>
auto reading_input(F&& f) {
    try {
        return f();
    } catch (const Error& e) {
        throw pyb::value_error(printable(e.what()));
    }
}

// `message` as a Python warning of `category` (pyb::error_already_set where the filter makes
// it an error). Call with the GIL held.
void warn_in_python(const std::string& message, PyObject* category = PyExc_UserWarning);

// Runs f with the engine's warnings on this thread captured (core/log.h), then gives each
// to Python's `warnings` as a UserWarning (a script can filter or catch them; stderr would
// not let it). With the warnings filter set to "error" the first one raises.
template <typename F>
auto with_python_warnings(F&& f) {
    WarningCapture capture;
    const auto raise = [&] {
        for (const std::string& message : capture.messages()) warn_in_python(message);
    };
    if constexpr (std::is_void_v<decltype(f())>) {
        f();
        raise();
    } else {
        auto result = f();
        raise();
        return result;
    }
}

// The pieces of the module, one per binding file.
void bind_session(pyb::module_& m);
void bind_synthesizers(pyb::module_& m);

}  // namespace lw::py
