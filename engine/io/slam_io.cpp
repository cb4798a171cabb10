#include "io/slam_io.h"

#include <vector>

#include <OpenImageIO/imageio.h>

#include "core/error.h"
#include "core/text.h"

namespace lw {

void write_slam(const std::filesystem::path& path, const Slam& slam) {
    const std::string name = path.string();
    auto out = OIIO::ImageOutput::create(name);
    if (!out) throw Error(name + ": cannot write: " + one_line(OIIO::geterror()));
    if (!out->supports("multiimage")) throw Error(name + ": SLAM files must be OpenEXR (.exr)");
    std::vector<OIIO::ImageSpec> specs(size_t(slam.levels));
    for (int i = 0; i < slam.levels; ++i) {
        OIIO::ImageSpec& spec = specs[size_t(i)];
        spec = OIIO::ImageSpec(slam.length, slam.height, 1, OIIO::TypeDesc::FLOAT);
        spec.channelnames = {"Y"};
        spec.attribute("compression", "zip");
        spec.attribute("linework:levels", slam.levels);
        spec.attribute("linework:length", slam.length);
        spec.attribute("linework:exemplar", slam.exemplar);
        spec.attribute("linework:seed", int(slam.seed));
        spec.attribute("linework:level", slam.level_value(i));
        spec.attribute("name", "level" + std::to_string(i));
    }
    if (!out->open(name, int(specs.size()), specs.data()))
        throw Error(name + ": cannot open for writing: " + one_line(out->geterror()));
    const size_t part = size_t(slam.length) * slam.height;
    for (int i = 0; i < slam.levels; ++i) {
        if (i > 0 && !out->open(name, specs[size_t(i)], OIIO::ImageOutput::AppendSubimage))
            throw Error(name + ": cannot append level " + std::to_string(i) + ": " + one_line(out->geterror()));
        if (!out->write_image(OIIO::TypeDesc::FLOAT, slam.ink.data() + part * size_t(i)))
            throw Error(name + ": write failed: " + one_line(out->geterror()));
    }
    if (!out->close()) throw Error(name + ": close failed: " + one_line(out->geterror()));
}

Slam read_slam(const std::filesystem::path& path) {
    const std::string name = path.string();
    if (!std::filesystem::exists(path)) throw Error(name + ": no such SLAM file");
    if (std::filesystem::is_directory(path)) throw Error(name + ": a folder, not a SLAM file (.exr)");
    auto in = OIIO::ImageInput::open(name);
    if (!in) throw Error(name + ": cannot read SLAM: " + one_line(OIIO::geterror()));
    Slam slam;
    const OIIO::ImageSpec& first = in->spec();
    slam.levels = first.get_int_attribute("linework:levels", 0);
    slam.length = first.width;
    slam.height = first.height;
    slam.exemplar = first.get_string_attribute("linework:exemplar", "");
    slam.seed = uint32_t(first.get_int_attribute("linework:seed", 0));
    if (slam.levels < 2) throw Error(name + ": not a SLAM file (no linework:levels ≥ 2 in its metadata)");
    // Before allocating: metadata and headers may claim anything.
    if (slam.levels > 1024 || slam.length < 1 || slam.length > 65536 || slam.height < 1 || slam.height > 1024)
        throw Error(name + ": a SLAM of " + std::to_string(slam.levels) + " levels of " + std::to_string(slam.length) +
                    "x" + std::to_string(slam.height) + " is out of range (at most 1024 levels of 65536x1024)");
    const size_t part = size_t(slam.length) * slam.height;
    slam.ink.resize(part * size_t(slam.levels));
    for (int i = 0; i < slam.levels; ++i) {
        if (!in->seek_subimage(i, 0))
            throw Error(name + ": has fewer parts than its " + std::to_string(slam.levels) + " levels");
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width != slam.length || spec.height != slam.height)
            throw Error(name + ": level " + std::to_string(i) + " is " + std::to_string(spec.width) + "x" +
                        std::to_string(spec.height) + ", level 0 is " + std::to_string(slam.length) + "x" +
                        std::to_string(slam.height));
        if (!in->read_image(i, 0, 0, 1, OIIO::TypeDesc::FLOAT, slam.ink.data() + part * size_t(i)))
            throw Error(name + ": cannot read level " + std::to_string(i) + ": " + one_line(in->geterror()));
    }
    return slam;
}

}  // namespace lw
