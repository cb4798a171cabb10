// Image comparison and image files.
#include <cmath>
#include <fstream>

#include "core/error.h"
#include "core/image.h"
#include "io/image_io.h"
#include "test_support.h"

namespace lw {
namespace {

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

}  // namespace
}  // namespace lw
