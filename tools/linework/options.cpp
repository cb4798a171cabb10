#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <unistd.h>

#include "commands.h"
#include "core/text.h"
#include "core/error.h"
#include "gpu/context.h"
#include "scene/style.h"
#include "scene/triangle_mesh.h"

namespace lw::cli {

namespace {
bool parse_float(const std::string& text, float* out) {
    char* end = nullptr;
    const float value = std::strtof(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) return false;
    *out = value;
    return true;
}

// The file part of an output path: not a folder (an existing one, or a name ending in "/").
std::string file_name_problem(const std::string& text, const std::string& extension) {
    std::error_code error;
    if (!std::filesystem::path(text).has_filename() || std::filesystem::is_directory(text, error))
        return text + ": is a folder; give a file name";
    if (!extension.empty() && lower(std::filesystem::path(text).extension().string()) != extension)
        return text + ": the file is written as " + extension + "; give a name ending in " + extension;
    return {};
}
}  // namespace

CLI::Validator output_file(const std::string& extension) {
    return CLI::Validator(
        [extension](const std::string& text) -> std::string {
            if (std::string problem = file_name_problem(text, extension); !problem.empty()) return problem;
            const std::filesystem::path folder = std::filesystem::path(text).parent_path();
            const std::filesystem::path where = folder.empty() ? "." : folder;
            std::error_code error;
            const bool is_folder = std::filesystem::is_directory(where, error);
            if (!is_folder) {
                if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory)
                    return text + ": " + where.string() + ": " + error.message();
                if (std::filesystem::exists(where, error)) return text + ": " + where.string() + " is not a folder";
                return text + ": the folder " + where.string() + " does not exist";
            }
            if (::access(where.c_str(), W_OK | X_OK) != 0)
                return text + ": the folder " + where.string() + " cannot be written to (" + std::strerror(errno) + ")";
            if (std::filesystem::exists(text, error) && ::access(text.c_str(), W_OK) != 0)
                return text + ": cannot be replaced (" + std::strerror(errno) + ")";
            return {};
        },
        "", "output file");
}

std::string frame_name(int frame, const char* extension) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%04d.%s", frame, extension);
    return name;
}

void refuse_writing_over_input(const std::string& output, std::initializer_list<std::string> inputs,
                               const std::string& option) {
    for (const std::string& input : inputs) {
        if (input.empty()) continue;
        std::error_code error;
        const bool same = std::filesystem::exists(output, error)
                              ? std::filesystem::equivalent(output, input, error)
                              : std::filesystem::weakly_canonical(output, error) == std::filesystem::weakly_canonical(input, error);
        if (same && !error)
            throw usage_error(option + ": " + output + " is the input " + input +
                              ", which it would be written over; name another file");
    }
}

CLI::Validator output_file_name(const std::string& extension) {
    return CLI::Validator([extension](const std::string& text) { return file_name_problem(text, extension); }, "",
                          "output file name");
}

glm::vec3 parse_vec3(const std::string& text, const std::string& option) {
    std::stringstream stream(text);
    std::string part;
    glm::vec3 v{0.0f};
    int i = 0;
    while (std::getline(stream, part, ',')) {
        if (i >= 3 || !parse_float(part, &v[i])) i = 4;
        ++i;
    }
    if (i != 3) throw usage_error(option + ": expected three numbers x,y,z, got \"" + text + "\"");
    // Past this a squared length overflows a float, and the camera's directions come out NaN
    // ("up is parallel to the view direction", said of an eye at 1e30).
    constexpr float kLargest = 1e18f;
    for (int k = 0; k < 3; ++k)
        if (!(std::fabs(v[k]) <= kLargest))
            throw usage_error(option + ": " + text + ": each coordinate must be within ±1e18");
    return v;
}

glm::ivec2 parse_size(const std::string& text, const std::string& option, glm::ivec2 smallest, glm::ivec2 largest) {
    const auto x = text.find('x');
    int w = 0, h = 0;
    try {
        size_t used_w = 0, used_h = 0;
        if (x == std::string::npos) throw 0;
        w = std::stoi(text.substr(0, x), &used_w);
        h = std::stoi(text.substr(x + 1), &used_h);
        if (used_w != x || used_h != text.size() - x - 1) throw 0;
    } catch (...) {
        throw usage_error(option + ": expected WIDTHxHEIGHT such as 1920x1080, got \"" + text + "\"");
    }
    if (w < smallest.x || h < smallest.y || w > largest.x || h > largest.y)
        throw usage_error(option + ": must be between " + std::to_string(smallest.x) + "x" + std::to_string(smallest.y) +
                          " and " + std::to_string(largest.x) + "x" + std::to_string(largest.y) + ", got \"" + text +
                          "\"");
    return {w, h};
}

void use_slam_strokes(LinesDesc& lines, const std::string& slam, float width) {
    // Line sets: every set that draws silhouettes or suggestive contours.
    for (LineSetDesc& set : lines.sets)
        if (set.select.has_type(LineType::Silhouette) || set.select.has_type(LineType::Suggestive)) {
            set.style.slam = slam;
            set.style.ribbon.clear();
            set.style.width = width;
            set.style.taper_in_px = set.style.taper_out_px = 2.0f * width;
            set.style.cap = Cap::Butt;
        }
    for (LineType type : {LineType::Silhouette, LineType::Suggestive}) {
        LineStyle& style = lines.styles[size_t(type)];
        style.slam = slam;
        style.ribbon.clear();
        style.width = width;
        style.taper_px = 2.0f * width;
    }
}

void print_bounds(const Bounds& b) {
    const glm::vec3 c = b.center();
    std::printf("bounds: min (%.4g, %.4g, %.4g), max (%.4g, %.4g, %.4g), centre (%.4g, %.4g, %.4g), radius %.4g\n",
                double(b.min.x), double(b.min.y), double(b.min.z), double(b.max.x), double(b.max.y), double(b.max.z),
                double(c.x), double(c.y), double(c.z), double(b.radius()));
}

int exit_code_after_validation(const Context& ctx, bool validation) {
    if (!validation || ctx.validation_messages().empty()) return 0;
    std::fprintf(stderr, "linework: error: %zu validation message(s); see above\n", ctx.validation_messages().size());
    return 1;
}

}  // namespace lw::cli
