#include "convert.h"

#include <map>
#include <mutex>
#include <tuple>
#include <type_traits>

namespace lw::py {

namespace {

// The array as C-contiguous values of T (pybind11 converts other dtypes and strides), with
// `dims` dimensions; ValueError naming the argument otherwise.
template <typename T>
pyb::array_t<T, pyb::array::c_style | pyb::array::forcecast> checked(const pyb::array& array, const std::string& name,
                                                                     pyb::ssize_t dims) {
    auto a = pyb::array_t<T, pyb::array::c_style | pyb::array::forcecast>::ensure(array);
    if (!a) throw pyb::value_error(name + ": expected a numeric array");
    if (a.ndim() != dims)
        throw pyb::value_error(name + ": expected " + std::to_string(dims) + " dimensions, got " + std::to_string(a.ndim()));
    return a;
}

std::string shape_text(const pyb::array& a) {
    std::string s = "(";
    for (pyb::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
    return s + ")";
}

template <int N>
std::vector<glm::vec<N, float>> array_to_points(const pyb::array& array, const std::string& name) {
    auto a = checked<float>(array, name, 2);
    if (a.shape(1) != N) throw pyb::value_error(name + ": expected an N×" + std::to_string(N) + " array, got " + shape_text(a));
    std::vector<glm::vec<N, float>> points(size_t(a.shape(0)));
    const float* p = a.data();
    for (size_t i = 0; i < points.size(); ++i)
        for (int c = 0; c < N; ++c) points[i][c] = p[i * N + size_t(c)];
    return points;
}

}  // namespace

pyb::array_t<uint8_t> image_to_array(ImageRGBA8&& image) {
    const pyb::ssize_t h = image.height, w = image.width;
    return to_array(std::move(image.pixels), {h, w, 4});
}

ImageRGBA8 array_to_image(const pyb::array& array, const std::string& name) {
    if (array.ndim() != 2 && array.ndim() != 3)
        throw pyb::value_error(name + ": expected an H×W, H×W×3 or H×W×4 image, got " + shape_text(array));
    if (!pyb::isinstance<pyb::array_t<uint8_t>>(array))
        throw pyb::value_error(name + ": expected uint8 pixels (0..255), got dtype " +
                               std::string(pyb::str(array.dtype())));
    auto a = checked<uint8_t>(array, name, array.ndim());
    const int channels = a.ndim() == 2 ? 1 : int(a.shape(2));
    if (channels != 1 && channels != 3 && channels != 4)
        throw pyb::value_error(name + ": expected 3 or 4 channels, got " + std::to_string(channels));
    if (a.shape(0) < 1 || a.shape(1) < 1) throw pyb::value_error(name + ": the image is empty");
    ImageRGBA8 image{.width = int(a.shape(1)), .height = int(a.shape(0))};
    image.pixels.resize(size_t(image.width) * size_t(image.height) * 4);
    const uint8_t* p = a.data();
    for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i) {
        uint8_t* out = &image.pixels[i * 4];
        const uint8_t* in = p + i * size_t(channels);
        out[0] = in[0];
        out[1] = channels >= 3 ? in[1] : in[0];
        out[2] = channels >= 3 ? in[2] : in[0];
        out[3] = channels == 4 ? in[3] : 255;
    }
    return image;
}

std::vector<glm::vec3> array_to_vec3(const pyb::array& array, const std::string& name) {
    return array_to_points<3>(array, name);
}

std::vector<glm::vec2> array_to_vec2(const pyb::array& array, const std::string& name) {
    return array_to_points<2>(array, name);
}

namespace {

// Indices of a signed or unsigned integer type T, each in [0, 2³²).
template <typename T>
std::vector<uint32_t> indices_of(const pyb::array& array, const std::string& name) {
    auto a = checked<T>(array, name, 2);
    if (a.shape(1) != 3) throw pyb::value_error(name + ": expected an M×3 array of triangles, got " + shape_text(a));
    std::vector<uint32_t> indices(size_t(a.size()));
    for (size_t i = 0; i < indices.size(); ++i) {
        const T v = a.data()[i];
        bool negative = false;
        if constexpr (std::is_signed_v<T>) negative = v < 0;
        if (negative || uint64_t(v) > uint64_t(UINT32_MAX))
            throw pyb::value_error(name + ": index " + std::to_string(v) + " of triangle " + std::to_string(i / 3) +
                                   " is out of range");
        indices[i] = uint32_t(v);
    }
    return indices;
}

}  // namespace

std::vector<uint32_t> array_to_indices(const pyb::array& array, const std::string& name) {
    const char kind = array.dtype().kind();
    if (kind == 'u') return indices_of<uint64_t>(array, name);
    if (kind == 'i') return indices_of<int64_t>(array, name);
    throw pyb::value_error(name + ": expected integer vertex indices, got dtype " + std::string(pyb::str(array.dtype())));
}

void warn_in_python(const std::string& message, PyObject* category) {
    if (PyErr_WarnEx(category, printable(message).c_str(), 1) != 0) throw pyb::error_already_set();
}

void check_output_folder(const std::filesystem::path& path) {
    if (const std::filesystem::path folder = path.parent_path(); !folder.empty() && !std::filesystem::is_directory(folder))
        throw pyb::value_error("path: " + path.string() + ": the folder " + folder.string() + " does not exist");
}

std::string printable(const std::string& message) {
    std::string out;
    out.reserve(message.size());
    for (size_t i = 0; i < message.size();) {
        const auto c = static_cast<unsigned char>(message[i]);
        const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        bool valid = n > 0 && i + n <= message.size();
        for (size_t k = 1; valid && k < n; ++k) valid = (static_cast<unsigned char>(message[i + k]) >> 6) == 0x2;
        if (valid && (n > 1 || c >= 0x20 || c == '\n' || c == '\t')) {
            out.append(message, i, n);
            i += n;
        } else {
            out += '?';
            ++i;
        }
    }
    return out;
}

glm::vec3 to_vec3(const pyb::object& value, const std::string& name) {
    pyb::array a = pyb::array::ensure(value);
    if (!a || a.size() != 3) throw pyb::value_error(name + ": expected three numbers (x, y, z)");
    auto f = checked<float>(a.reshape({1, 3}), name, 2);
    const glm::vec3 v(f.data()[0], f.data()[1], f.data()[2]);
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw pyb::value_error(name + ": expected finite numbers");
    return v;
}

std::shared_ptr<Context> shared_context(const std::string& device, const std::string& compute,
                                        std::optional<bool> validation) {
    const bool on = validation.value_or(validation_from_environment());
    static std::mutex mutex;
    static std::map<std::tuple<std::string, std::string, bool>, std::weak_ptr<Context>> contexts;
    const std::lock_guard lock(mutex);
    const auto key = std::make_tuple(device, compute, on);
    if (std::shared_ptr<Context> ctx = contexts[key].lock()) return ctx;
    auto ctx = arguments_named({{"device", "device"}, {"compute", "compute"}}, [&] {
        return std::make_shared<Context>(
            ContextDesc{.device = parse_device_choice(device), .validation = on, .compute_site = parse_compute_site(compute)});
    });
    contexts[key] = ctx;
    return ctx;
}

std::mutex& gpu_mutex() {
    static std::mutex mutex;
    return mutex;
}

void check_validation(Context& ctx) {
    const std::vector<std::string> messages = ctx.validation_messages();
    if (messages.empty()) return;
    ctx.clear_validation_messages();
    throw std::runtime_error(std::to_string(messages.size()) + " validation message(s); the first: " + messages.front());
}

}  // namespace lw::py
