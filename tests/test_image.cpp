// Image comparison, image files and SLAM files.
#include <cmath>
#include <csetjmp>
#include <fstream>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <png.h>

#include "core/error.h"
#include "core/image.h"
#include "io/image_io.h"
#include "io/slam_io.h"
#include "test_support.h"

namespace lw {
namespace {

namespace fs = std::filesystem;

ImageRGBA8 solid(int w, int h, uint8_t v) { return ImageRGBA8{w, h, std::vector<uint8_t>(size_t(w) * h * 4, v)}; }

TEST(CompareImages, IdenticalImagesHaveInfinitePsnr) {
    const auto d = compare_images(solid(8, 8, 100), solid(8, 8, 100));
    EXPECT_EQ(d.max_abs_error, 0);
    EXPECT_TRUE(std::isinf(d.psnr_db));
    EXPECT_EQ(d.differing_fraction, 0.0);
}

TEST(CompareImages, KnownDifference) {
    ImageRGBA8 a = solid(10, 10, 50), b = solid(10, 10, 50);
    b.at(3, 4)[1] = 50 + 40;  // one channel of one pixel off by 40
    const auto d = compare_images(a, b, 16);
    EXPECT_EQ(d.max_abs_error, 40);
    EXPECT_DOUBLE_EQ(d.differing_fraction, 0.01);
    const double rmse = std::sqrt(40.0 * 40.0 / 400.0);
    EXPECT_NEAR(d.rmse, rmse, 1e-12);
    EXPECT_NEAR(d.psnr_db, 20.0 * std::log10(255.0 / rmse), 1e-9);
    EXPECT_EQ(d.diff.at(3, 4)[1], 255);  // 40 × 8 clamped
    EXPECT_EQ(d.diff.at(0, 0)[1], 0);
    EXPECT_EQ(compare_images(a, b, 40).differing_fraction, 0.0);
}

TEST(CompareImages, SizeMismatchIsAnError) { EXPECT_THROW((void)compare_images(solid(4, 4, 0), solid(4, 5, 0)), Error); }

TEST(ImageFiles, PngRoundTrip) {
    ImageRGBA8 image = solid(7, 5, 0);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<uint8_t>(i * 37 % 256);
    const auto path = test::temp_dir() / "x.png";
    write_png(path, image);
    const ImageRGBA8 back = read_image_rgba8(path);
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.pixels, image.pixels);
}

TEST(ImageFiles, MissingOrBadFileNamesIt) {
    const auto dir = test::temp_dir();
    try {
        (void)read_image_rgba8(dir / "missing.png");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png: no such file"), std::string::npos) << e.what();
    }
    std::ofstream(dir / "junk.png") << "not a png";
    try {
        (void)read_image_rgba8(dir / "junk.png");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("junk.png: "), std::string::npos) << e.what();
    }
}

// The last bytes of a PNG reach the disk when the file is closed: a full disk is an error
// there, not a short file in silence.
TEST(ImageFiles, AFullDiskIsAnError) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
    // Small enough to sit in the stdio buffer until the end, and large enough to fail inside libpng.
    ImageRGBA8 noise = solid(512, 512, 0);
    for (size_t i = 0; i < noise.pixels.size(); ++i) noise.pixels[i] = static_cast<uint8_t>(i * 2654435761u >> 13);
    for (const ImageRGBA8& image : {solid(64, 64, 7), noise}) {
        try {
            write_png("/dev/full", image);
            FAIL() << "wrote to a full disk";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("/dev/full: cannot write: No space left on device"), std::string::npos)
                << e.what();
        }
    }
}

// One PNG of the given kind: rows of packed samples as PNG stores them (big-endian 16-bit).
struct PngKind {
    const char* name;
    int color_type;
    int bit_depth;
    bool interlaced = false;
    bool transparency = false;  // a tRNS chunk: palette alphas, or the grey/RGB colour that is transparent
};

std::vector<uint8_t> sample_rows(const PngKind& kind, int width, int height) {
    const int channels = kind.color_type == PNG_COLOR_TYPE_GRAY || kind.color_type == PNG_COLOR_TYPE_PALETTE ? 1
                         : kind.color_type == PNG_COLOR_TYPE_GRAY_ALPHA                                       ? 2
                         : kind.color_type == PNG_COLOR_TYPE_RGB                                              ? 3
                                                                                                              : 4;
    const size_t row_bytes = (size_t(width) * channels * kind.bit_depth + 7) / 8;
    std::vector<uint8_t> rows(row_bytes * height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c) {
                const unsigned value = unsigned(x * 37 + y * 11 + c * 71) * 2654435761u >> 7;  // scrambled, 25 bits
                const unsigned sample = value & ((1u << kind.bit_depth) - 1);
                const size_t bit = (size_t(x) * channels + c) * kind.bit_depth;
                uint8_t* row = &rows[row_bytes * y];
                if (kind.bit_depth == 16) {
                    row[bit / 8] = uint8_t(sample >> 8);
                    row[bit / 8 + 1] = uint8_t(sample);
                } else {
                    row[bit / 8] |= uint8_t(sample << (8 - kind.bit_depth - bit % 8));
                }
            }
    return rows;
}

void write_png_of_kind(const fs::path& path, const PngKind& kind, int width, int height) {
    std::vector<uint8_t> rows = sample_rows(kind, width, height);
    std::vector<png_bytep> row_pointers(height);
    for (int y = 0; y < height; ++y) row_pointers[y] = rows.data() + rows.size() / height * y;
    std::vector<png_color> palette(16);
    for (int i = 0; i < 16; ++i) palette[i] = png_color{uint8_t(i * 16), uint8_t(255 - i * 9), uint8_t(i * i)};
    std::vector<png_byte> palette_alpha = {0, 40, 80, 120, 160, 200, 240, 255};
    png_color_16 transparent{};
    transparent.gray = transparent.red = 3;  // colour (3, 0, 0) or grey 3 is transparent

    FILE* file = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(file);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), kind.bit_depth, kind.color_type,
                 kind.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (kind.color_type == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette.data(), int(palette.size()));
    if (kind.transparency)
        png_set_tRNS(png, info, palette_alpha.data(), kind.color_type == PNG_COLOR_TYPE_PALETTE ? int(palette_alpha.size()) : 0,
                     &transparent);
    png_write_info(png, info);
    png_write_image(png, row_pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
}

// PNGs are read through libpng; until this change OpenImageIO read them, and it still reads
// every other format. Both give the same bytes for every kind of PNG (16-bit samples may
// round differently by one).
TEST(ImageFiles, EveryKindOfPngReadsAsOpenImageIOReadsIt) {
    const std::vector<PngKind> kinds = {
        {"grey1", PNG_COLOR_TYPE_GRAY, 1},
        {"grey4", PNG_COLOR_TYPE_GRAY, 4},
        {"grey8", PNG_COLOR_TYPE_GRAY, 8},
        {"grey8_trns", PNG_COLOR_TYPE_GRAY, 8, false, true},
        {"grey16", PNG_COLOR_TYPE_GRAY, 16},
        {"grey_alpha8", PNG_COLOR_TYPE_GRAY_ALPHA, 8},
        {"grey_alpha16", PNG_COLOR_TYPE_GRAY_ALPHA, 16},
        {"rgb8", PNG_COLOR_TYPE_RGB, 8},
        {"rgb8_trns", PNG_COLOR_TYPE_RGB, 8, false, true},
        {"rgb8_interlaced", PNG_COLOR_TYPE_RGB, 8, true},
        {"rgb16", PNG_COLOR_TYPE_RGB, 16},
        {"rgba8", PNG_COLOR_TYPE_RGB_ALPHA, 8},
        {"rgba8_interlaced", PNG_COLOR_TYPE_RGB_ALPHA, 8, true},
        {"rgba16", PNG_COLOR_TYPE_RGB_ALPHA, 16},
        {"palette4", PNG_COLOR_TYPE_PALETTE, 4},
        {"palette4_trns", PNG_COLOR_TYPE_PALETTE, 4, false, true},
    };
    const fs::path dir = test::temp_dir();
    for (const PngKind& kind : kinds) {
        SCOPED_TRACE(kind.name);
        const fs::path path = dir / (std::string(kind.name) + ".png");
        write_png_of_kind(path, kind, 13, 7);
        const ImageRGBA8 ours = read_image_rgba8(path);
        const ImageRGBA8 theirs = read_image_rgba8_through_openimageio(path);
        ASSERT_EQ(ours.width, 13);
        ASSERT_EQ(ours.height, 7);
        ASSERT_EQ(theirs.width, 13);
        ASSERT_EQ(theirs.height, 7);
        int largest = 0;
        for (size_t i = 0; i < ours.pixels.size(); ++i) largest = std::max(largest, std::abs(ours.pixels[i] - theirs.pixels[i]));
        EXPECT_LE(largest, kind.bit_depth == 16 ? 1 : 0);
        // Not both wrong alike: pixel (1, 0) of a few kinds, from sample_rows' values.
        if (std::string(kind.name) == "grey1") {
            EXPECT_TRUE(ours.at(1, 0)[0] == 0 || ours.at(1, 0)[0] == 255);
        }
        if (std::string(kind.name) == "rgb8") {
            EXPECT_EQ(ours.at(0, 0)[3], 255);
        }
    }
}

// A BMP, written here byte by byte: formats other than PNG and EXR go through the module that
// links OpenImageIO, loaded on first use.
TEST(ImageFiles, OtherFormatsReadThroughOpenImageIO) {
    const int width = 3, height = 2;
    const int row = 12;  // 3 × 3 bytes, padded to 4
    std::vector<uint8_t> bmp = {'B', 'M'};
    auto put32 = [&](uint32_t v) { for (int i = 0; i < 4; ++i) bmp.push_back(uint8_t(v >> (8 * i))); };
    auto put16 = [&](uint16_t v) { bmp.push_back(uint8_t(v)); bmp.push_back(uint8_t(v >> 8)); };
    put32(54 + row * height); put32(0); put32(54);                          // file header
    put32(40); put32(width); put32(height); put16(1); put16(24); put32(0);  // info header: 24-bit, no compression
    put32(row * height); put32(2835); put32(2835); put32(0); put32(0);
    for (int y = height - 1; y >= 0; --y) {  // bottom row first, BGR
        for (int x = 0; x < width; ++x) {
            bmp.push_back(uint8_t(10 * x + 1));    // B
            bmp.push_back(uint8_t(100 + y));       // G
            bmp.push_back(uint8_t(200 + x + y));   // R
        }
        for (int pad = width * 3; pad < row; ++pad) bmp.push_back(0);
    }
    const fs::path path = test::temp_dir() / "three.bmp";
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bmp.data()), std::streamsize(bmp.size()));
    const ImageRGBA8 image = read_image_rgba8(path);
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint8_t* p = image.at(x, y);
            EXPECT_EQ(p[0], 200 + x + y);
            EXPECT_EQ(p[1], 100 + y);
            EXPECT_EQ(p[2], 10 * x + 1);
            EXPECT_EQ(p[3], 255);
        }
}

// The chunks after the pixels change nothing read: a PNG whose IEND is missing reads (as it
// did through OpenImageIO).
TEST(ImageFiles, APngWithoutItsEndChunkReads) {
    ImageRGBA8 image = solid(9, 4, 0);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<uint8_t>(i * 29 % 256);
    const fs::path path = test::temp_dir() / "noend.png";
    write_png(path, image);
    fs::resize_file(path, fs::file_size(path) - 12);  // IEND: length, type, CRC
    EXPECT_EQ(read_image_rgba8(path).pixels, image.pixels);
}

// The parts of a SLAM file as another tool might write them: one float channel named `channel`,
// over `window`, with only linework:levels among our attributes.
std::vector<Imf::Header> slam_part_headers(int levels, const Imath::Box2i& window, const char* channel) {
    std::vector<Imf::Header> headers;
    for (int i = 0; i < levels; ++i) {
        Imf::Header header(window, window);
        header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
        header.setName("level" + std::to_string(i));
        header.setType(Imf::SCANLINEIMAGE);
        header.insert("linework:levels", Imf::IntAttribute(levels));
        headers.push_back(header);
    }
    return headers;
}

// A SLAM written by another tool: parts whose data window starts far from the origin (the
// pointer arithmetic to its corner overflowed: UBSan stopped there) and whose one channel is
// not named "Y" (read by position, as OpenImageIO read it).
TEST(SlamFiles, AnotherToolsLayoutReads) {
    const int levels = 2, length = 64, height = 4;
    std::vector<float> ink(size_t(levels) * length * height);
    for (size_t i = 0; i < ink.size(); ++i) ink[i] = float(i % 97) / 96.0f;
    const Imath::Box2i window({5, 1000000000}, {5 + length - 1, 1000000000 + height - 1});
    const std::vector<Imf::Header> headers = slam_part_headers(levels, window, "ink");
    const fs::path path = test::temp_dir() / "other.exr";
    {
        Imf::MultiPartOutputFile file(path.c_str(), headers.data(), levels);
        for (int i = 0; i < levels; ++i) {
            Imf::OutputPart part(file, i);
            Imf::FrameBuffer frame;
            frame.insert("ink", Imf::Slice::Make(Imf::FLOAT, ink.data() + size_t(i) * length * height, window,
                                                 sizeof(float), sizeof(float) * length));
            part.setFrameBuffer(frame);
            part.writePixels(height);
        }
    }
    const Slam slam = read_slam(path);
    EXPECT_EQ(slam.levels, levels);
    EXPECT_EQ(slam.length, length);
    EXPECT_EQ(slam.height, height);
    EXPECT_EQ(slam.ink, ink);
}

// Each size bound alone allowed 256 GiB of texels: a file of a few headers claiming 64 levels
// of 65536 × 1024 is refused before anything is allocated.
TEST(SlamFiles, AHeaderClaimingTooManyTexelsIsRefused) {
    const int levels = 64;
    const std::vector<Imf::Header> headers = slam_part_headers(levels, Imath::Box2i({0, 0}, {65535, 1023}), "Y");
    const fs::path path = test::temp_dir() / "huge.exr";
    { Imf::MultiPartOutputFile file(path.c_str(), headers.data(), levels); }  // headers only: no pixels written
    try {
        (void)read_slam(path);
        FAIL() << "read a SLAM claiming 2^32 texels";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("64 levels of 65536x1024 is out of range"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lw
