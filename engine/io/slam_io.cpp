#include "io/slam_io.h"

#include <cstdint>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "core/error.h"
#include "core/text.h"
#include "io/file_signature.h"

namespace lw {

namespace {

// One level's float channel as OpenEXR addresses it: rows of `length` floats from the data
// window's corner (0, 0 for files we write; read_slam checks others by size only). Slice::Make
// offsets the pointer in integers: a corner far from the origin overflowed pointer arithmetic.
Imf::FrameBuffer level_frame(const char* channel, float* ink, const Imath::Box2i& window, int length) {
    Imf::FrameBuffer frame;
    frame.insert(channel, Imf::Slice::Make(Imf::FLOAT, ink, window, sizeof(float), sizeof(float) * size_t(length)));
    return frame;
}

template <typename Attribute, typename Value>
Value attribute_or(const Imf::Header& header, const char* name, Value fallback) {
    const auto* attribute = header.findTypedAttribute<Attribute>(name);
    return attribute ? Value(attribute->value()) : fallback;
}

}  // namespace

void write_slam(const std::filesystem::path& path, const Slam& slam) {
    const std::string name = path.string();
    try {
        std::vector<Imf::Header> headers;
        for (int i = 0; i < slam.levels; ++i) {
            Imf::Header header(slam.length, slam.height);
            header.compression() = Imf::ZIP_COMPRESSION;
            header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
            header.setName("level" + std::to_string(i));
            header.setType(Imf::SCANLINEIMAGE);
            header.insert("linework:levels", Imf::IntAttribute(slam.levels));
            header.insert("linework:length", Imf::IntAttribute(slam.length));
            header.insert("linework:exemplar", Imf::StringAttribute(slam.exemplar));
            header.insert("linework:seed", Imf::IntAttribute(int(slam.seed)));
            header.insert("linework:level", Imf::FloatAttribute(slam.level_value(i)));
            headers.push_back(header);
        }
        Imf::MultiPartOutputFile file(name.c_str(), headers.data(), int(headers.size()));
        const size_t part = size_t(slam.length) * slam.height;
        for (int i = 0; i < slam.levels; ++i) {
            Imf::OutputPart level(file, i);
            // OpenEXR only reads through the frame buffer's pointer when writing.
            float* ink = const_cast<float*>(slam.ink.data() + part * size_t(i));
            level.setFrameBuffer(level_frame("Y", ink, headers[size_t(i)].dataWindow(), slam.length));
            level.writePixels(slam.height);
        }
    } catch (const std::exception& e) {
        throw Error(name + ": cannot write: " + one_line(e.what()));
    }
}

Slam read_slam(const std::filesystem::path& path) {
    const std::string name = path.string();
    if (!std::filesystem::exists(path)) throw Error(name + ": no such SLAM file");
    if (std::filesystem::is_directory(path)) throw Error(name + ": a folder, not a SLAM file (.exr)");
    if (file_kind(path) != FileKind::Exr)
        throw Error(name + ": not a SLAM file (not an OpenEXR file; `linework slam` and `linework slam-pattern` make SLAMs)");
    Slam slam;
    try {
        Imf::MultiPartInputFile file(name.c_str());
        const Imf::Header& first = file.header(0);
        const Imath::Box2i& window = first.dataWindow();
        slam.levels = attribute_or<Imf::IntAttribute>(first, "linework:levels", 0);
        slam.length = window.max.x - window.min.x + 1;
        slam.height = window.max.y - window.min.y + 1;
        slam.exemplar = attribute_or<Imf::StringAttribute>(first, "linework:exemplar", std::string());
        slam.seed = uint32_t(attribute_or<Imf::IntAttribute>(first, "linework:seed", 0));
        if (slam.levels < 2) throw Error(name + ": not a SLAM file (no linework:levels ≥ 2 in its metadata)");
        // Before allocating: metadata and headers may claim anything.
        // Each bound alone still allowed 256 GiB; the texels in all are capped at 1 GiB of floats.
        constexpr int64_t kMostTexels = int64_t(1) << 28;
        if (slam.levels > 1024 || slam.length < 1 || slam.length > 65536 || slam.height < 1 || slam.height > 1024 ||
            int64_t(slam.levels) * slam.length * slam.height > kMostTexels)
            throw Error(name + ": a SLAM of " + std::to_string(slam.levels) + " levels of " + std::to_string(slam.length) +
                        "x" + std::to_string(slam.height) +
                        " is out of range (at most 1024 levels of 65536x1024, 2^28 texels in all)");
        if (file.parts() < slam.levels)
            throw Error(name + ": has fewer parts than its " + std::to_string(slam.levels) + " levels");
        const size_t part = size_t(slam.length) * slam.height;
        slam.ink.resize(part * size_t(slam.levels));
        for (int i = 0; i < slam.levels; ++i) {
            const Imf::Header& header = file.header(i);
            const Imath::Box2i& level_window = header.dataWindow();
            const int width = level_window.max.x - level_window.min.x + 1;
            const int height = level_window.max.y - level_window.min.y + 1;
            if (width != slam.length || height != slam.height)
                throw Error(name + ": level " + std::to_string(i) + " is " + std::to_string(width) + "x" +
                            std::to_string(height) + ", level 0 is " + std::to_string(slam.length) + "x" +
                            std::to_string(slam.height));
            // The ink is channel "Y" as written here; a part of one channel named otherwise (another
            // tool's file) is read as OpenImageIO read it, by position.
            const Imf::ChannelList& channels = header.channels();
            const char* channel = "Y";
            if (!channels.findChannel("Y")) {
                auto second = channels.begin();
                if (second != channels.end()) ++second;
                if (channels.begin() == channels.end() || second != channels.end())
                    throw Error(name + ": level " + std::to_string(i) + " has no channel \"Y\" (the ink)");
                channel = channels.begin().name();
            }
            Imf::InputPart level(file, i);
            level.setFrameBuffer(level_frame(channel, slam.ink.data() + part * size_t(i), level_window, slam.length));
            level.readPixels(level_window.min.y, level_window.max.y);
        }
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(name + ": cannot read SLAM: " + one_line(e.what()));
    }
    return slam;
}

}  // namespace lw
