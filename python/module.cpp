// python/module.cpp — `import linework`: the module's entry point. The pieces are bound in
// session.cpp (scenes made live: lines, renders, sequences) and synthesizers.cpp (SLAMs,
// ribbons, stroke patterns, hatching); python/linework.pyi is the typed surface.
//
// Errors: a bad argument or bad input (a scene key, a model file, an exemplar) raises
// ValueError with the command line's message; a failure while running (Vulkan, a
// validation message with LINEWORK_VALIDATION=1) raises RuntimeError.
#include "convert.h"
#include "core/text.h"

#include <pybind11/stl/filesystem.h>

#include "core/memory.h"
#include "io/image_io.h"

PYBIND11_MODULE(linework, m) {
    m.doc() =
        "Linework: feature lines, stylized renders and stroke synthesizers, with NumPy arrays in and out.\n\n"
        "  s = linework.Session('scenes/spot.json', device='cpu')\n"
        "  lines = s.lines()          # {'silhouette': [Polyline, ...], ...}\n"
        "  image = s.render()         # H x W x 4 uint8\n";
    m.attr("__version__") = LW_VERSION;
    // As the command line does (engine/core/memory.h): lavapipe's per-draw allocations would
    // otherwise fault in fresh pages every frame.
    lw::keep_freed_memory();
    pybind11::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const lw::ParameterError& e) {
            PyErr_SetString(PyExc_ValueError, lw::py::printable(e.what()).c_str());
        } catch (const lw::Error& e) {
            PyErr_SetString(PyExc_RuntimeError, lw::py::printable(e.what()).c_str());
        }
    });
    // Images as the command line reads and writes them (io/image_io.h), so that a script needs
    // no imaging library to compare with or feed the command line.
    m.def(
        "read_image",
        [](const std::filesystem::path& path) {
            return lw::py::image_to_array(lw::py::reading_input([&] { return lw::read_image_rgba8(path); }));
        },
        pybind11::arg("path"), "An image file (PNG, EXR, JPEG, …) as H×W×4 uint8, as the command line reads it.");
    m.def(
        "write_png",
        [](const std::filesystem::path& path, const pybind11::array& image) {
            // A PNG whatever the name says: a .jpg name would hold a PNG no reader expects.
            if (lw::lower(path.extension().string()) != ".png")
                throw pybind11::value_error("path: " + path.string() + ": write_png writes .png files");
            lw::py::check_output_folder(path);
            const lw::ImageRGBA8 pixels = lw::py::array_to_image(image, "image");
            lw::write_png(path, pixels);
        },
        pybind11::arg("path"), pybind11::arg("image"), "Write an H×W×4 (or ×3, or grey) uint8 array as a PNG.");
    lw::py::bind_session(m);
    lw::py::bind_synthesizers(m);
}
