#include "io/image_io.h"

#include <dlfcn.h>

#include <algorithm>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include "core/color.h"
#include "core/error.h"
#include "core/text.h"
#include "io/file_signature.h"
#include "io/openimageio/read_image.h"
#include "io/png_file.h"

namespace lw {

namespace {

// A SLAM file (io/slam_io.h) would open as an image of its first level: as a ribbon exemplar
// it gave an opaque 1024-texel pattern whose DP ran for many minutes, in diff it compared one
// level of many.
void refuse_slam(const std::filesystem::path& path) {
    int levels = 0, width = 0, height = 0;
    try {
        Imf::MultiPartInputFile file(path.string().c_str());
        const Imf::Header& header = file.header(0);
        if (const auto* attribute = header.findTypedAttribute<Imf::IntAttribute>("linework:levels"))
            levels = attribute->value();
        width = header.dataWindow().max.x - header.dataWindow().min.x + 1;
        height = header.dataWindow().max.y - header.dataWindow().min.y + 1;
    } catch (const std::exception&) {
        return;  // not a readable EXR: the general reader says why
    }
    if (levels > 0)
        throw Error(path.string() + ": a SLAM file (" + std::to_string(levels) + " levels of " + std::to_string(width) +
                    "x" + std::to_string(height) + "), not an image: a SLAM goes in a style's \"slam\" or --slam");
}

// Formats other than PNG (JPEG, TIFF, an EXR that is no SLAM, …) go through OpenImageIO, loaded
// on first use from a module beside the program: linked in, its 260 shared libraries cost
// every process 0.3 s of CPU at start, whether it read an image or not (README "Dependencies").
using ReadThroughOpenImageIO = bool (*)(const char* path, ImageRGBA8* image, std::string* error);

// Where the module may be, absolute paths only (dlopen searches the library path for a bare
// name): beside the executable (/proc/self/exe: argv[0] may be a bare name or a link), beside
// the shared object holding this code (the Python module), and where the build put it.
std::vector<std::filesystem::path> openimageio_module_candidates() {
    std::vector<std::filesystem::path> candidates;
    std::error_code ec;
    if (const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec); !ec)
        candidates.push_back(exe.parent_path() / kOpenImageIOModuleName);
    Dl_info self{};
    if (dladdr(reinterpret_cast<void*>(&openimageio_module_candidates), &self) && self.dli_fname &&
        std::filesystem::path(self.dli_fname).is_absolute())
        candidates.push_back(std::filesystem::path(self.dli_fname).parent_path() / kOpenImageIOModuleName);
    candidates.emplace_back(LW_OPENIMAGEIO_MODULE);
    return candidates;
}

// The module's entry, or why there is none.
struct OpenImageIOReader {
    ReadThroughOpenImageIO read = nullptr;
    std::string why_not;
};

OpenImageIOReader load_openimageio_reader() {
    std::string failures;  // of candidates that exist: why each did not load
    std::string looked;
    const auto add = [](std::string& list, const std::string& item) { list += (list.empty() ? "" : "; ") + item; };
    for (const std::filesystem::path& candidate : openimageio_module_candidates()) {
        add(looked, candidate.parent_path().string());
        if (!std::filesystem::exists(candidate)) continue;
        if (void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL)) {
            if (void* entry = dlsym(module, kOpenImageIOEntry)) return {reinterpret_cast<ReadThroughOpenImageIO>(entry), ""};
            add(failures, candidate.string() + " has no " + kOpenImageIOEntry);
        } else {
            add(failures, one_line(dlerror()));
        }
    }
    return {nullptr, failures.empty() ? "not found in " + looked : failures};
}

}  // namespace

ImageRGBA8 read_image_rgba8(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw Error(path.string() + ": no such file");
    if (std::filesystem::is_directory(path)) throw Error(path.string() + ": a folder, not an image");
    const FileKind kind = file_kind(path);
    if (kind == FileKind::Png) return read_png(path);
    if (kind == FileKind::Exr) refuse_slam(path);
    return read_image_rgba8_through_openimageio(path);
}

ImageRGBA8 read_image_rgba8_through_openimageio(const std::filesystem::path& path) {
    static const OpenImageIOReader reader = load_openimageio_reader();  // once, on first use
    if (!reader.read)
        throw Error(path.string() + ": cannot read image: it is not a PNG, and the reader of other formats (" +
                    kOpenImageIOModuleName + ") could not be loaded: " + reader.why_not);
    ImageRGBA8 image;
    std::string error;
    if (!reader.read(path.string().c_str(), &image, &error)) throw Error(path.string() + ": " + one_line(error));
    return image;
}

void write_exr(const std::filesystem::path& path, const ImageRGBA8& color, const std::vector<float>& z) {
    const size_t pixels = size_t(color.width) * color.height;
    if (z.size() != pixels) throw Error(path.string() + ": depth size does not match the image");
    constexpr size_t kChannels = 5;  // R G B A Z, interleaved
    std::vector<float> data(pixels * kChannels);
    for (size_t p = 0; p < pixels; ++p) {
        const float alpha = color.pixels[p * 4 + 3] / 255.0f;
        for (size_t c = 0; c < 3; ++c) {
            // Straight, decoded, premultiplied again: linear light as compositing adds it.
            const float straight = alpha > 0.0f ? std::min(1.0f, color.pixels[p * 4 + c] / 255.0f / alpha) : 0.0f;
            data[p * kChannels + c] = srgb_to_linear(straight) * alpha;
        }
        data[p * kChannels + 3] = alpha;
        data[p * kChannels + 4] = z[p];
    }
    try {
        Imf::Header header(color.width, color.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        const char* names[kChannels] = {"R", "G", "B", "A", "Z"};
        for (size_t c = 0; c < kChannels; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(data.data() + c),
                                              sizeof(float) * kChannels, sizeof(float) * kChannels * color.width));
        }
        Imf::OutputFile file(path.string().c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(color.height);
    } catch (const std::exception& e) {
        throw Error(path.string() + ": cannot write: " + one_line(e.what()));
    }
}

}  // namespace lw
