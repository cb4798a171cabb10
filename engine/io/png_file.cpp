#include "io/png_file.h"

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include <png.h>

#include "core/error.h"
#include "core/text.h"
#include "io/image_io.h"

namespace lw {

namespace {

// libpng reports errors through a callback that must not return: it records the message and
// jumps back to the setjmp of the phase that called libpng. The functions holding a setjmp
// create no object with a destructor after it (C++ forbids jumping over one), so all state
// lives in a PngStream, constructed by the caller before any jump.
struct PngStream {
    bool writing = false;
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::string error;  // libpng's error pointer

    ~PngStream() {
        if (png && writing) png_destroy_write_struct(&png, info ? &info : nullptr);
        if (png && !writing) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        if (file) std::fclose(file);
    }
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = message ? message : "unknown error";
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // e.g. an iCCP profile libpng dislikes: the pixels are fine

// libpng's own reader says only "Read Error" at the end of a file cut short.
void read_bytes(png_structp png, png_bytep data, size_t length) {
    auto* reader = static_cast<PngStream*>(png_get_io_ptr(png));
    if (std::fread(data, 1, length, reader->file) != length)
        png_error(png, std::ferror(reader->file) ? "the file could not be read" : "the file ends before its image does");
}

// libpng's own writer says only "Write Error"; the system's reason (a full disk) is kept.
void write_bytes(png_structp png, png_bytep data, size_t length) {
    auto* writer = static_cast<PngStream*>(png_get_io_ptr(png));
    if (std::fwrite(data, 1, length, writer->file) != length) png_error(png, std::strerror(errno));
}

void flush_bytes(png_structp png) {
    auto* writer = static_cast<PngStream*>(png_get_io_ptr(png));
    if (std::fflush(writer->file) != 0) png_error(png, std::strerror(errno));
}

// Reads the header and sets the transforms to 8-bit RGBA. False with reader.error set on failure.
bool read_header(PngStream& reader, png_uint_32& width, png_uint_32& height) {
    if (setjmp(png_jmpbuf(reader.png))) return false;
    png_set_read_fn(reader.png, &reader, read_bytes);
    png_read_info(reader.png, reader.info);
    width = png_get_image_width(reader.png, reader.info);
    height = png_get_image_height(reader.png, reader.info);
    png_set_expand(reader.png);    // palette → RGB, grey under 8 bits → 8, tRNS → alpha
    png_set_scale_16(reader.png);  // 16-bit → 8, rounded (not the high byte alone)
    png_set_gray_to_rgb(reader.png);
    png_set_add_alpha(reader.png, 0xff, PNG_FILLER_AFTER);  // only where there is no alpha
    png_set_interlace_handling(reader.png);
    png_read_update_info(reader.png, reader.info);
    if (png_get_rowbytes(reader.png, reader.info) != size_t(width) * 4) {
        reader.error = "unexpected row layout after conversion to RGBA";
        return false;
    }
    return true;
}

bool read_rows(PngStream& reader, png_bytepp rows) {
    if (setjmp(png_jmpbuf(reader.png))) return false;
    // Not png_read_end: the chunks after the pixels (IEND, text) change nothing read, and
    // OpenImageIO read a file whose IEND was missing.
    png_read_image(reader.png, rows);
    return true;
}

// 8-bit RGBA as given, tagged sRGB (which the bytes are), zlib level 6 and no row filter: a
// line drawing's flat runs compress best unfiltered (the default scene's frame 0 at 960×720:
// 82 kB in 44 ms, against 108 kB in 95 ms with libpng's adaptive filters; OpenImageIO wrote
// 98 kB).
bool write_rows(PngStream& writer, const ImageRGBA8& image) {
    if (setjmp(png_jmpbuf(writer.png))) return false;
    png_set_write_fn(writer.png, &writer, write_bytes, flush_bytes);
    png_set_compression_level(writer.png, 6);
    png_set_filter(writer.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(writer.png, writer.info, png_uint_32(image.width), png_uint_32(image.height), 8,
                 PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(writer.png, writer.info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(writer.png, writer.info);
    for (int y = 0; y < image.height; ++y)  // libpng only reads the row
        png_write_row(writer.png, const_cast<png_bytep>(image.pixels.data() + size_t(y) * image.width * 4));
    png_write_end(writer.png, nullptr);
    return true;
}

}  // namespace

ImageRGBA8 read_png(const std::filesystem::path& path) {
    const std::string name = path.string();
    PngStream reader;
    reader.file = std::fopen(name.c_str(), "rb");
    if (!reader.file) throw Error(name + ": cannot read image: cannot open the file");
    reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader.error, on_png_error, on_png_warning);
    if (reader.png) reader.info = png_create_info_struct(reader.png);
    if (!reader.png || !reader.info) throw Error(name + ": cannot read image: out of memory");
    png_uint_32 width = 0, height = 0;
    if (!read_header(reader, width, height)) throw Error(name + ": cannot read image: " + one_line(reader.error));
    // Before allocating: a header may claim any size (found by tests/fuzz/fuzz_image).
    if (width > png_uint_32(kLargestImageSide) || height > png_uint_32(kLargestImageSide))
        throw Error(name + ": image of " + std::to_string(width) + "x" + std::to_string(height) + " is too large (at most " +
                    std::to_string(kLargestImageSide) + "x" + std::to_string(kLargestImageSide) + ")");
    ImageRGBA8 image{int(width), int(height), std::vector<uint8_t>(size_t(width) * height * 4)};
    std::vector<png_bytep> rows(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.pixels.data() + size_t(y) * width * 4;
    if (!read_rows(reader, rows.data())) throw Error(name + ": cannot read image: " + one_line(reader.error));
    return image;
}

void write_png(const std::filesystem::path& path, const ImageRGBA8& image) {
    const std::string name = path.string();
    PngStream writer{.writing = true};
    writer.file = std::fopen(name.c_str(), "wb");
    if (!writer.file) throw Error(name + ": cannot write: " + std::strerror(errno));
    writer.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &writer.error, on_png_error, on_png_warning);
    if (writer.png) writer.info = png_create_info_struct(writer.png);
    if (!writer.png || !writer.info) throw Error(name + ": cannot write: out of memory");
    if (!write_rows(writer, image)) throw Error(name + ": cannot write: " + one_line(writer.error));
    // The last bytes reach the disk at fflush or fclose: a full disk is said here too.
    const bool flushed = std::fflush(writer.file) == 0;
    const int flush_error = errno;
    const bool closed = std::fclose(std::exchange(writer.file, nullptr)) == 0;
    if (!flushed || !closed) throw Error(name + ": cannot write: " + std::strerror(flushed ? errno : flush_error));
}

}  // namespace lw
